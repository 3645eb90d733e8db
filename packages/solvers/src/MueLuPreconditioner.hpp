#pragma once
// Internal to the solvers package: the MueLu smoothed-aggregation preconditioner
// (built in IterativeSolver.cpp, the only translation unit with MueLu headers).
#include <Tpetra_Operator_fwd.hpp>

#include "cyclone/fe/LinearAlgebra.hpp"

namespace cyclone::solvers {

/// SA preconditioner of A (symmetric positive definite), rigid-body near null space
/// if given. A must live on an MPI communicator.
Teuchos::RCP<Tpetra::Operator<>> makeMueLuPreconditioner(const linalg::Matrix& A,
                                                          const Teuchos::RCP<const linalg::MultiVector>& nearNullSpace,
                                                          int equationsPerNode);

}  // namespace cyclone::solvers
