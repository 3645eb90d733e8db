#include "cyclone/fe/LinearAlgebra.hpp"

#include <Tpetra_Core.hpp>

namespace cyclone::linalg {

CommPtr worldComm() { return Tpetra::getDefaultComm(); }

}  // namespace cyclone::linalg
