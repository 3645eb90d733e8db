#include "cyclone/continuation/HomotopySolve.hpp"

#include <cmath>
#include <sstream>

namespace cyclone::continuation {

namespace {

// The added rows' block J_aa of dF/dx: from the formed Jacobian, or, where the problem's
// steps are Krylov solves (useKrylov), from products of its operator with unit vectors
// (the dense Jacobian of a large harmonic balance is what Krylov avoids forming).
Eigen::MatrixXd addedBlock(const ContinuationProblem& problem, const Eigen::VectorXd& y, double p,
                           const std::vector<int>& added) {
  const int na = int(added.size());
  Eigen::MatrixXd Jaa(na, na);
  if (useKrylov(problem, ContinuationOptions{})) {
    const std::shared_ptr<JacobianOperator> op = problem.jacobianOperator(y, p);
    Eigen::VectorXd e = Eigen::VectorXd::Zero(problem.size), column;
    for (int j = 0; j < na; ++j) {
      e(added[j]) = 1;
      op->apply(e, column);
      e(added[j]) = 0;
      for (int i = 0; i < na; ++i) Jaa(i, j) = column(added[i]);
    }
    return Jaa;
  }
  Eigen::MatrixXd J;
  problem.jacobian(y, p, J);
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < na; ++j) Jaa(i, j) = J(added[i], added[j]);
  return Jaa;
}

// The homotopy's rows on an operator that cannot blend its own (JacobianOperator::
// blendRows false): the products blended, the preconditioner the operator's.
class BlendedRows final : public JacobianOperator {
public:
  BlendedRows(std::shared_ptr<JacobianOperator> J, const std::vector<int>& rows, double scale, double shift)
      : J_(std::move(J)), rows_(rows), scale_(scale), shift_(shift) {}
  int size() const override { return J_->size(); }
  void apply(const Eigen::VectorXd& v, Eigen::VectorXd& y) const override {
    J_->apply(v, y);
    for (int i : rows_) y(i) = scale_ * y(i) + shift_ * v(i);
  }
  void preparePreconditioner() override { J_->preparePreconditioner(); }
  void precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z) const override { J_->precondition(r, z); }

private:
  std::shared_ptr<JacobianOperator> J_;
  std::vector<int> rows_;
  double scale_, shift_;
};

// Newton on the added rows in the added unknowns alone (the others held): true when
// those rows then hold to the tolerance.
bool solveAddedRows(const ContinuationProblem& problem, Eigen::VectorXd& y, double p, const std::vector<int>& added,
                    double tolerance) {
  const int na = int(added.size());
  if (na == 0) return false;
  Eigen::VectorXd F, Fa(na);
  for (int iteration = 0; iteration < 12; ++iteration) {
    problem.residual(y, p, F);
    for (int i = 0; i < na; ++i) Fa(i) = F(added[i]);
    if (!Fa.allFinite()) return false;
    if (Fa.norm() <= tolerance) return true;
    const Eigen::MatrixXd Jaa = addedBlock(problem, y, p, added);
    const Eigen::VectorXd d = Jaa.partialPivLu().solve(-Fa);
    if (!d.allFinite()) return false;
    for (int i = 0; i < na; ++i) y(added[i]) += d(i);
  }
  return false;
}

}  // namespace

HomotopyResult solveByHomotopy(const ContinuationProblem& problem, Eigen::VectorXd& x, double p,
                               const std::vector<int>& added, double tolerance) {
  HomotopyResult result;
  Eigen::VectorXd guess = x;
  result.newton = solveNewton(problem, guess, p, tolerance, 30);
  if (result.newton.converged) {
    x = guess;
    return result;
  }
  // The added unknowns solved with the others held, then Newton on the whole from
  // there: the added harmonic's coefficients start at their own solution instead of
  // zero, which plain Newton reaches only through the coupled rows' kinks.
  if (Eigen::VectorXd y = x; solveAddedRows(problem, y, p, added, tolerance)) {
    result.blockStart = true;
    Eigen::VectorXd z = y;
    result.newton = solveNewton(problem, z, p, tolerance, 30);
    if (result.newton.converged) {
      x = z;
      return result;
    }
    x = y;  // the homotopy's start: the old rows relax around the added unknowns' solution
  }
  result.byHomotopy = true;
  const Eigen::VectorXd x0 = x;
  double c = 0;
  if (!added.empty()) {
    const Eigen::MatrixXd Jaa = addedBlock(problem, x0, p, added);
    c = Jaa.diagonal().cwiseAbs().sum();
  }
  c = added.empty() || c == 0 ? 1.0 : c / double(added.size());
  ContinuationProblem homotopy;
  homotopy.size = problem.size;
  homotopy.scaleGroups = problem.scaleGroups;
  homotopy.residual = [&problem, &added, x0, c, p](const Eigen::VectorXd& y, double s, Eigen::VectorXd& G) {
    problem.residual(y, p, G);
    for (int i : added) G(i) = s * G(i) + (1 - s) * c * (y(i) - x0(i));
  };
  homotopy.jacobian = [&problem, &added, c, p](const Eigen::VectorXd& y, double s, Eigen::MatrixXd& J) {
    problem.jacobian(y, p, J);
    for (int i : added) {
      J.row(i) *= s;
      J(i, i) += (1 - s) * c;
    }
  };
  if (problem.jacobianOperator)
    homotopy.jacobianOperator = [&problem, &added, c, p](const Eigen::VectorXd& y, double s) {
      std::shared_ptr<JacobianOperator> op = problem.jacobianOperator(y, p);
      if (op->blendRows(added, s, (1 - s) * c)) return op;
      return std::shared_ptr<JacobianOperator>(std::make_shared<BlendedRows>(op, added, s, (1 - s) * c));
    };
  ContinuationOptions o;
  o.engine = ContinuationOptions::Engine::PredictorCorrector;
  o.from = 0, o.to = 1;
  o.tolerance = tolerance;
  o.initialStep = 0.05, o.maxStep = 0.2;
  o.turnAngle = 0.12;  // as measured for the harmonics check (docs/scenes.md)
  o.maxSteps = 120;  // a carried start is near: a longer path is another branch, not worth its LUs
  const Branch path = traceBranch(homotopy, x0, o);
  result.points = int(path.points.size());
  if (path.points.empty()) {
    result.reason = "the homotopy to the added equations did not start";
    return result;
  }
  std::size_t far = 0;  // the point nearest s = 1 (a path that folds back still passed it)
  for (std::size_t i = 0; i < path.points.size(); ++i)
    if (path.points[i].parameter > path.points[far].parameter) far = i;
  x = path.points[far].x;
  result.newton = solveNewton(problem, x, p, tolerance, 30);
  if (!result.newton.converged) {
    std::ostringstream why;
    why << "the homotopy to the added equations reached s = " << path.points[far].parameter << " of 1 ("
        << (path.stopReason.empty() ? "no solution beyond" : path.stopReason) << ")";
    result.reason = why.str();
  }
  return result;
}

}  // namespace cyclone::continuation
