#pragma once
// Sparse direct solve of (A - sigma B) x = b with CHOLMOD's supernodal
// Cholesky (METIS ordering, OpenBLAS) or, for a shift inside the spectrum, its
// simplicial LDL^T; complex symmetric systems by UMFPACK's LU. Chosen by measurement (docs/solvers.md):
// Amesos2 in Debian's Trilinos 13.2 offers only KLU2 (slow in 3D, wrong on
// several ranks) and Tacho (crashes). The matrix is gathered on rank 0, factored
// once, and right-hand sides are gathered/scattered per solve, so results are
// identical on any number of ranks. A - sigma B must be symmetric positive
// definite (for eigenproblems: sigma below the lowest eigenvalue).
#include <complex>
#include <memory>

#include "cyclone/fe/LinearAlgebra.hpp"

namespace cyclone::solvers {

class DirectSolver {
public:
  /// Positive definite: supernodal LL^T (the default). Indefinite: simplicial LDL^T
  /// without pivoting, for A - sigma B with sigma between eigenvalues (a shift inside
  /// the spectrum); rejected like LL^T when a pivot vanishes or the estimate is singular.
  enum class Definiteness { Positive, Indefinite };
  /// TravellingWavePairs: A and B are a cyclic real form whose unknowns pair as (2m,
  /// 2m+1) with [[P, -Q], [Q, P]] blocks (cyclic::travellingWavePaired), the real form of
  /// the Hermitian H = P + iQ of half the size. A positive definite one is then factored
  /// as H (CHOLMOD's complex supernodal LL^H, SparseCholesky): a factor of about half
  /// the memory and a quarter of the work of the real form's, whose 2 x 2 blocks fill
  /// four times the entries (a two-copy nodal diameter of the seed's 334k-DOF sector
  /// passed 18 GB with the real form). Indefinite ones keep the real LDL^T. The reduced
  /// models' modes and static correction use it (ModalOptions::structure); a singular H
  /// (a free sector's rigid-body modes) is refused below a reciprocal condition of 1e-14,
  /// where its factor could otherwise pass on a pivot of the rounding's size
  /// (docs/studies/thesis_scale_chain.md).
  enum class Structure { General, TravellingWavePairs };

  /// Factors A - sigma*B (B may be null). Throws SolverError if not positive definite
  /// (Positive) or singular (Indefinite).
  DirectSolver(const linalg::Matrix& A, const linalg::Matrix* B = nullptr, double sigma = 0.0,
               Definiteness definiteness = Definiteness::Positive, Structure structure = Structure::General);
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
  /// CHOLMOD's reciprocal condition estimate of the factor (min/max pivot; the complex
  /// factor's, of the Hermitian form, for TravellingWavePairs).
  double reciprocalCondition() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Sparse LU (UMFPACK) of the complex symmetric a A + b B, e.g. (1 + i eta) K - omega^2 M:
/// the full-FE frequency response with structural damping. The matrix is gathered on
/// rank 0 like DirectSolver's.
///
/// TravellingWavePairs: A and B are a cyclic real form whose unknowns pair as
/// (2m, 2m+1) = (x_a, x_b) with [[P, -Q], [Q, P]] blocks (cyclic::travellingWavePaired).
/// Then a A + b B splits into the forward wave's Z = a (P + iQ)_A + b (P + iQ)_B
/// (half the size) and the backward wave's Z^T, and one LU of Z serves both:
///   x_a = u+ + u-, x_b = -i u+ + i u-,  u+ = Z^{-1} (r_a + i r_b)/2, u- = Z^{-T} (r_a - i r_b)/2.
/// About a quarter of the factorization work and half the memory of the full LU.
class ComplexDirectSolver {
public:
  enum class Structure { General, TravellingWavePairs };
  /// Throws SolverError if the matrix is singular.
  ComplexDirectSolver(const linalg::Matrix& A, std::complex<double> a, const linalg::Matrix& B,
                      std::complex<double> b, Structure structure = Structure::General);
  ~ComplexDirectSolver();
  ComplexDirectSolver(const ComplexDirectSolver&) = delete;
  ComplexDirectSolver& operator=(const ComplexDirectSolver&) = delete;

  /// x = (a A + b B)^{-1} rhs for a real right-hand side: real and imaginary parts.
  void solve(const linalg::MultiVector& rhs, linalg::MultiVector& xReal, linalg::MultiVector& xImag) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cyclone::solvers
