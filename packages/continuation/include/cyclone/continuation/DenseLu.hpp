#pragma once
// The LU factorisation (partial pivoting) of a dense square matrix through LAPACK
// (Teuchos::LAPACK): 2-3x faster than Eigen's PartialPivLU from n ~ 1000 on one core
// with OpenBLAS (docs/solvers.md), and the continuation's correctors factor a
// bordered Jacobian at every Newton iteration.
//
// From n = mixedPrecisionFrom on, the factorisation is made in single precision
// (sgetrf: about 1.9x dgetrf's speed on this machine's OpenBLAS, and at harmonic
// balance sizes the LU is most of a Newton step) and every solve is refined in double
// against the double matrix, LAPACK's dsgesv scheme: refined until the residual is
// at the level of a double LU's backward error (||b - A x||_inf <= ||x||_inf ||A||_inf
// eps sqrt(n)), so the solutions are those of a double LU to rounding. Where the
// refinement does not get there (a matrix too ill-conditioned for single precision,
// cond(A) eps_single not small) or single precision cannot hold the matrix, the
// matrix is factored again in double and the solve made with that.
//
// Factors kept for a later matrix (reuseFactorsFor): a Newton corrector's Jacobian
// changes little from one iteration, or one point of a curve, to the next, and at
// harmonic balance sizes an LU costs as much as 15-25 products with the matrix. The
// solves with the new matrix are then right-preconditioned GMRES with the kept factors,
// run to the same stopping test as the refinement (a double LU's backward error), so
// the answers are still a double LU's to rounding; a solve that does not get there in
// maxKrylovIterations factors the new matrix and solves with that.
#include <Eigen/Core>
#include <algorithm>
#include <vector>

namespace cyclone::continuation {

class DenseLu {
public:
  enum class Precision {
    Double,  ///< dgetrf/dgetrs
    Mixed,   ///< sgetrf, solves refined in double, double where that fails
    Auto     ///< Mixed from n = mixedPrecisionFrom, Double below
  };
  static constexpr int mixedPrecisionFrom = 200;

  DenseLu() = default;
  explicit DenseLu(const Eigen::MatrixXd& A, Precision precision = Precision::Auto) { compute(A, precision); }
  void compute(const Eigen::MatrixXd& A, Precision precision = Precision::Auto);
  /// compute() without a copy of A: takes A's storage and leaves A holding other storage
  /// of unspecified content (the previous matrix's, when the sizes agree, so a caller
  /// that refills a work matrix per Newton iteration allocates nothing).
  void computeTaking(Eigen::MatrixXd& A, Precision precision = Precision::Auto);
  /// Takes A (as computeTaking) as the matrix to solve with, keeping the factors of the
  /// matrix factored last as the solves' preconditioner. False, and nothing done, where
  /// there are no factors of A's size to keep or keeping them did not pay the last time
  /// (a solve with them took more than staleIterationBudget iterations): the caller
  /// then factors A.
  bool reuseFactorsFor(Eigen::MatrixXd& A);
  /// The matrix solved with is not the one factored (reuseFactorsFor).
  bool factorsAreStale() const { return stale_; }
  static constexpr int maxKrylovIterations = 24;
  /// Below this size an LU costs about what a few GMRES iterations do: the
  /// continuation factors every step there (mixedPrecisionFrom's size too).
  static constexpr int reuseFrom = 200;
  /// The GMRES iterations a solve with kept factors may take for them to be kept for
  /// the next matrix: a third of what an LU costs in iterations (each a product with A
  /// and two triangular solves, memory-bound; the LU compute-bound): about n / 60 on
  /// this project's machine (n = 1261: 53 ms against 2.7 ms; n = 1717: 113 against
  /// 3.8). Counted, not timed, so that a trace is the same run after run.
  static int staleIterationBudget(int n) { return std::max(4, n / 180); }
  /// A^-1 b; not finite where A is singular (an exactly zero pivot).
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  /// A^-T b (the same factors).
  Eigen::VectorXd solveTransposed(const Eigen::VectorXd& b) const;

  /// The single-precision factors are in use (none of the solves so far fell back).
  bool singlePrecisionFactors() const { return mixed_ && !doubleFactored_; }
  /// Factorisations in double made because single precision did not serve (0 or 1).
  int doubleFallbacks() const { return mixed_ && doubleFactored_ ? 1 : 0; }
  /// Refinement steps of all solves so far (mixed precision).
  long refinementSteps() const { return refinementSteps_; }
  /// GMRES iterations of the solves with kept factors, and the factorisations made
  /// because a solve with kept factors did not converge (since construction).
  long krylovIterations() const { return krylovIterations_; }
  int staleRefactorizations() const { return staleRefactorizations_; }

private:
  Eigen::VectorXd solveWith(char trans, const Eigen::VectorXd& b) const;
  bool refinedSolve(char trans, const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  bool krylovSolve(char trans, const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  bool applyFactors(char trans, const Eigen::VectorXd& r, Eigen::VectorXd& d) const;
  double residualTolerance() const;
  void factorInDouble() const;
  void factorHeldMatrix(Precision precision);  // matrix_ holds A

  bool mixed_ = false;
  Eigen::MatrixXd matrix_;           // A (mixed: the refinement's residuals; double: kept for a refactor)
  Eigen::MatrixXf singleFactors_;    // LU of A / alpha in single precision
  std::vector<int> singlePivots_;
  double alpha_ = 1, normInf_ = 0;   // the single factors' scale, ||A||_inf
  mutable Eigen::MatrixXd factors_;  // LU in double (Double, or the fallback)
  mutable std::vector<int> pivots_;
  mutable int info_ = 0;
  mutable bool doubleFactored_ = false;
  mutable long refinementSteps_ = 0;
  Precision precision_ = Precision::Auto;
  mutable bool stale_ = false;          // matrix_ is newer than the factors
  mutable int lastStaleIterations_ = 0;  // of the last solve with stale factors
  mutable long krylovIterations_ = 0;
  mutable int staleRefactorizations_ = 0;
};

}  // namespace cyclone::continuation
