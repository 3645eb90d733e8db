#pragma once
// Sparse direct solve of (A - sigma B) x = b with CHOLMOD's supernodal
// Cholesky (METIS ordering, OpenBLAS). Chosen by measurement (docs/solvers.md):
// Amesos2 in Debian's Trilinos 13.2 offers only KLU2 (slow in 3D, wrong on
// several ranks) and Tacho (crashes). The matrix is gathered on rank 0, factored
// once, and right-hand sides are gathered/scattered per solve, so results are
// identical on any number of ranks. A - sigma B must be symmetric positive
// definite (for eigenproblems: sigma below the lowest eigenvalue).
#include <memory>

#include "cyclone/fe/LinearAlgebra.hpp"

namespace cyclone::solvers {

class DirectSolver {
public:
  /// Factors A - sigma*B (B may be null). Throws SolverError if not positive definite.
  DirectSolver(const linalg::Matrix& A, const linalg::Matrix* B = nullptr, double sigma = 0.0);
  ~DirectSolver();
  DirectSolver(const DirectSolver&) = delete;
  DirectSolver& operator=(const DirectSolver&) = delete;

  /// x = (A - sigma B)^{-1} b, all columns at once. x and b share A's row map.
  void solve(const linalg::MultiVector& b, linalg::MultiVector& x) const;

  struct Statistics {
    long long rows = 0;
    long long nonzerosA = 0;       ///< stored lower triangle
    double nonzerosFactor = 0;     ///< nnz(L)
    double flops = 0;              ///< factorization flop count
    double gatherSeconds = 0, factorSeconds = 0;
  };
  const Statistics& statistics() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cyclone::solvers
