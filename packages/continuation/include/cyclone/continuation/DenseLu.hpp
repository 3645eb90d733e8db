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
#include <Eigen/Core>
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

private:
  Eigen::VectorXd solveWith(char trans, const Eigen::VectorXd& b) const;
  bool refinedSolve(char trans, const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
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
};

}  // namespace cyclone::continuation
