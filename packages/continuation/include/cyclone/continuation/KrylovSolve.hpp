#pragma once
// Right-preconditioned flexible GMRES (Belos' block GMRES with one right-hand side) for a
// linear operator and a preconditioner given as functions on Eigen vectors: the
// Newton steps of a large harmonic balance (JacobianOperator.hpp), and of the
// continuation's bordered system [J, b; c^T, d] (BorderedKrylovSolve).
#include <functional>
#include <memory>

#include <Eigen/Core>

#include "cyclone/continuation/JacobianOperator.hpp"

namespace cyclone::continuation {

using VectorFunction = std::function<void(const Eigen::VectorXd& x, Eigen::VectorXd& y)>;

struct KrylovOptions {
  /// ||b - A x|| <= tolerance ||b||. A Newton step needs far less than a direct solve's
  /// accuracy; 1e-8 keeps Newton's convergence quadratic to the continuation's 1e-10.
  double tolerance = 1e-8;
  int maxIterations = 600;
  int restart = 150;  ///< Krylov vectors kept before a restart
};

struct KrylovResult {
  bool converged = false;
  int iterations = 0;
  double relativeResidual = 0;  ///< ||b - A x|| / ||b|| of the returned x
};

/// x = A^-1 b from x = 0 by GMRES right-preconditioned by M^-1 (precondition).
KrylovResult solveKrylov(const VectorFunction& apply, const VectorFunction& precondition, const Eigen::VectorXd& b,
                         Eigen::VectorXd& x, const KrylovOptions& options = {});

/// The bordered system [J, b; c^T, d] [x; y] = [r; s] of a continuation's corrector
/// (b = dF/dp, c^T the arclength row), by GMRES preconditioned with the bordered
/// matrix of J's preconditioner P: [P, b; c^T, d]^-1 by block elimination with P^-1 b
/// made once. The border is kept exact, so folds of the curve in p (J singular there)
/// are no obstacle where P itself is regular.
class BorderedKrylovSolve {
public:
  BorderedKrylovSolve() = default;
  /// J's preconditioner must be prepared.
  BorderedKrylovSolve(std::shared_ptr<const JacobianOperator> J, Eigen::VectorXd b, Eigen::VectorXd c, double d,
                      KrylovOptions options = {});
  bool empty() const { return !J_; }
  int size() const { return J_ ? J_->size() + 1 : 0; }
  /// The solution, or NaNs where GMRES did not converge: to the options' tolerance, or to
  /// `tolerance` where given (> 0; an inexact Newton step's forcing term).
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs, double tolerance = 0) const;
  long iterations() const { return iterations_; }
  int failures() const { return failures_; }

private:
  void applyBordered(const Eigen::VectorXd& v, Eigen::VectorXd& y) const;
  void preconditionBordered(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;
  std::shared_ptr<const JacobianOperator> J_;
  Eigen::VectorXd b_, c_, Pb_;
  double d_ = 0, schur_ = 0;
  KrylovOptions options_;
  mutable Eigen::VectorXd head_, out_;
  mutable long iterations_ = 0;
  mutable int failures_ = 0;
};

}  // namespace cyclone::continuation
