#pragma once
// MPI and Kokkos for the Python process (the library's Environment), started by the first
// call that needs them (the FE half: meshes' models, modes) and ended when Python exits.
#include "cyclone/fe/LinearAlgebra.hpp"

namespace cyclone::python {

/// The world communicator of the process's Environment, started here if need be.
linalg::CommPtr environmentComm();

}  // namespace cyclone::python
