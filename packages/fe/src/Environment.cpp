#include "cyclone/fe/Environment.hpp"

#include <Tpetra_Core.hpp>

namespace cyclone {

struct Environment::Guard {
  Tpetra::ScopeGuard scope;
  Guard(int& argc, char**& argv) : scope(&argc, &argv) {}
};

Environment::Environment(int& argc, char**& argv) : guard_(std::make_unique<Guard>(argc, argv)) {}
Environment::~Environment() = default;

linalg::CommPtr Environment::comm() const { return linalg::worldComm(); }
int Environment::rank() const { return comm()->getRank(); }

}  // namespace cyclone
