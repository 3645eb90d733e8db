#pragma once
// The distributed linear algebra types Cyclone assembles into: Tpetra with its
// default (double, int, long long, Serial) instantiation, the only one Debian's
// Trilinos 13.2 provides. Forward declarations only: including this is cheap.
#include <Teuchos_RCP.hpp>
#include <Tpetra_CrsMatrix_fwd.hpp>
#include <Tpetra_Map_fwd.hpp>
#include <Tpetra_MultiVector_fwd.hpp>
#include <Tpetra_Vector_fwd.hpp>

namespace Teuchos {
template <class Ordinal>
class Comm;
}

namespace cyclone::linalg {

using Comm = Teuchos::Comm<int>;
using CommPtr = Teuchos::RCP<const Comm>;
using Map = Tpetra::Map<>;
using Matrix = Tpetra::CrsMatrix<>;
using MultiVector = Tpetra::MultiVector<>;
using Vector = Tpetra::Vector<>;
using GlobalIndex = long long;

/// MPI_COMM_WORLD as a Teuchos communicator (a serial one when run without mpirun).
CommPtr worldComm();

}  // namespace cyclone::linalg
