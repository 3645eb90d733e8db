#pragma once
// What a program that calls Cyclone holds for its lifetime: MPI and Kokkos started
// (and finished when it goes out of scope, after every Cyclone object of the program),
// and the world communicator, so an engineering code need not name Tpetra.
//   int main(int argc, char** argv) { cyclone::Environment env(argc, argv); ... env.comm() ... }
#include <memory>

#include "cyclone/fe/LinearAlgebra.hpp"

namespace cyclone {

class Environment {
public:
  Environment(int& argc, char**& argv);
  ~Environment();
  Environment(const Environment&) = delete;
  Environment& operator=(const Environment&) = delete;

  linalg::CommPtr comm() const;  ///< MPI_COMM_WORLD (serial without mpirun)
  int rank() const;

private:
  struct Guard;
  std::unique_ptr<Guard> guard_;
};

}  // namespace cyclone
