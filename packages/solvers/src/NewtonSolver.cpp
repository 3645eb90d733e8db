// NOX glue: a NOX::Abstract::Group over Tpetra vectors (wrapped as Thyra
// vectors for NOX's vector algebra). The only translation unit with NOX headers.
#include "cyclone/solvers/NewtonSolver.hpp"

#include <NOX.H>
#include <NOX_Thyra_Vector.H>
#include <Teuchos_oblackholestream.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <memory>

#include "cyclone/core/Error.hpp"
#include "cyclone/solvers/DirectSolver.hpp"

namespace cyclone::solvers {

namespace {

using TVector = Tpetra::Vector<>;
using Extract = Thyra::TpetraOperatorVectorExtraction<double, int, long long, TVector::node_type>;

Teuchos::RCP<NOX::Thyra::Vector> wrap(const Teuchos::RCP<TVector>& v) {
  return Teuchos::rcp(new NOX::Thyra::Vector(Thyra::createVector(v)));
}
const TVector& tpetra(const NOX::Abstract::Vector& v) {
  const auto& thyra = dynamic_cast<const NOX::Thyra::Vector&>(v).getThyraRCPVector();
  return *Extract::getConstTpetraVector(thyra);
}
TVector& tpetra(NOX::Abstract::Vector& v) {
  return *Extract::getTpetraVector(dynamic_cast<NOX::Thyra::Vector&>(v).getThyraRCPVector());
}

// Shared by a group and its copies (NOX copies groups in line searches and Broyden).
struct JacobianCount {
  int factored = 0;
  bool approximateUsed = false;
};

class Group : public NOX::Abstract::Group {
public:
  Group(const NewtonProblem& problem, const linalg::MultiVector& u0)
      : problem_(problem), count_(std::make_shared<JacobianCount>()) {
    auto x = Teuchos::rcp(new TVector(u0.getMap()));
    x->assign(*u0.getVector(0));
    x_ = wrap(x);
    f_ = wrap(Teuchos::rcp(new TVector(u0.getMap())));
    newton_ = wrap(Teuchos::rcp(new TVector(u0.getMap())));
  }
  Group(const Group& g, NOX::CopyType type) : problem_(g.problem_), count_(g.count_) {
    x_ = Teuchos::rcp_dynamic_cast<NOX::Thyra::Vector>(g.x_->clone(type));
    f_ = Teuchos::rcp_dynamic_cast<NOX::Thyra::Vector>(g.f_->clone(type));
    newton_ = Teuchos::rcp_dynamic_cast<NOX::Thyra::Vector>(g.newton_->clone(type));
    if (type == NOX::DeepCopy) {
      validF_ = g.validF_, validJ_ = g.validJ_, validNewton_ = g.validNewton_, normF_ = g.normF_;
      J_ = g.J_, factor_ = g.factor_;
    }
  }

  NOX::Abstract::Group& operator=(const NOX::Abstract::Group& source) override {
    const auto& g = dynamic_cast<const Group&>(source);
    *x_ = *g.x_, *f_ = *g.f_, *newton_ = *g.newton_;
    validF_ = g.validF_, validJ_ = g.validJ_, validNewton_ = g.validNewton_, normF_ = g.normF_;
    J_ = g.J_, factor_ = g.factor_;
    return *this;
  }
  void setX(const NOX::Abstract::Vector& y) override {
    *x_ = y;
    invalidate();
  }
  void computeX(const NOX::Abstract::Group& grp, const NOX::Abstract::Vector& d, double step) override {
    const auto& g = dynamic_cast<const Group&>(grp);
    x_->update(1.0, *g.x_, step, d, 0.0);
    invalidate();
  }
  ReturnType computeF() override {
    if (validF_) return Ok;
    problem_.residual(tpetra(*x_), tpetra(*f_));
    normF_ = f_->norm();
    validF_ = true;
    return Ok;
  }
  ReturnType computeJacobian() override {
    if (validJ_) return Ok;
    if (problem_.approximateFactor) {
      // Broyden's first Jacobian is the given approximation, already factored. A
      // restart (the residual fell by less than half) ends the solve unconverged: the
      // caller then solves with Newton.
      if (count_->approximateUsed) return Failed;
      count_->approximateUsed = true;
      J_ = problem_.approximateJacobian;
      factor_ = problem_.approximateFactor;
      validJ_ = true;
      return Ok;
    }
    J_ = problem_.jacobian(tpetra(*x_));
    try {
      factor_ = std::make_shared<DirectSolver>(*J_);
    } catch (const SolverError&) {
      return Failed;  // not positive definite: the caller's step is too large
    }
    ++count_->factored;
    validJ_ = true;
    return Ok;
  }
  int jacobiansFactored() const { return count_->factored; }
  ReturnType computeNewton(Teuchos::ParameterList&) override {
    if (validNewton_) return Ok;
    if (computeF() != Ok || computeJacobian() != Ok) return Failed;
    TVector minusF(tpetra(*f_), Teuchos::Copy);
    minusF.scale(-1.0);
    factor_->solve(minusF, tpetra(*newton_));
    validNewton_ = true;
    return Ok;
  }
  ReturnType applyJacobian(const NOX::Abstract::Vector& input, NOX::Abstract::Vector& result) const override {
    if (!validJ_) return BadDependency;
    J_->apply(tpetra(input), tpetra(result));
    return Ok;
  }
  ReturnType applyJacobianTranspose(const NOX::Abstract::Vector& input,
                                    NOX::Abstract::Vector& result) const override {
    return applyJacobian(input, result);  // symmetric
  }
  ReturnType applyJacobianInverse(Teuchos::ParameterList&, const NOX::Abstract::Vector& input,
                                  NOX::Abstract::Vector& result) const override {
    if (!validJ_) return BadDependency;
    factor_->solve(tpetra(input), tpetra(result));
    return Ok;
  }

  bool isF() const override { return validF_; }
  bool isJacobian() const override { return validJ_; }
  bool isNewton() const override { return validNewton_; }
  const NOX::Abstract::Vector& getX() const override { return *x_; }
  const NOX::Abstract::Vector& getF() const override { return *f_; }
  double getNormF() const override { return normF_; }
  const NOX::Abstract::Vector& getGradient() const override { return *newton_; }  // not computed (no gradient methods used)
  const NOX::Abstract::Vector& getNewton() const override { return *newton_; }
  Teuchos::RCP<const NOX::Abstract::Vector> getXPtr() const override { return x_; }
  Teuchos::RCP<const NOX::Abstract::Vector> getFPtr() const override { return f_; }
  Teuchos::RCP<const NOX::Abstract::Vector> getGradientPtr() const override { return newton_; }
  Teuchos::RCP<const NOX::Abstract::Vector> getNewtonPtr() const override { return newton_; }
  Teuchos::RCP<NOX::Abstract::Group> clone(NOX::CopyType type) const override {
    return Teuchos::rcp(new Group(*this, type));
  }

private:
  void invalidate() { validF_ = validJ_ = validNewton_ = false; }
  const NewtonProblem& problem_;
  Teuchos::RCP<NOX::Thyra::Vector> x_, f_, newton_;
  bool validF_ = false, validJ_ = false, validNewton_ = false;
  double normF_ = 0;
  std::shared_ptr<JacobianCount> count_;
  Teuchos::RCP<const linalg::Matrix> J_;
  std::shared_ptr<const DirectSolver> factor_;  // shared by copies: NOX copies groups in line searches
};

}  // namespace

NewtonReport solveNewton(const NewtonProblem& problem, linalg::MultiVector& u, const NewtonOptions& options) {
  auto group = Teuchos::rcp(new Group(problem, u));
  auto params = Teuchos::rcp(new Teuchos::ParameterList);
  params->set("Nonlinear Solver", "Line Search Based");
  params->sublist("Line Search").set("Method", "Backtrack");
  params->sublist("Line Search").sublist("Backtrack").set("Max Iters", 8);
  params->sublist("Printing").set("Output Information", 0);  // failures are reported by the caller
  // NOX prints its errors whatever the output level (the Broyden direction's "Unable to
  // compute Jacobian" at every intended restart below): they go nowhere, the report says it.
  params->sublist("Printing").set("Error Stream",
                                  Teuchos::RCP<std::ostream>(Teuchos::rcp(new Teuchos::oblackholestream)));
  if (problem.approximateFactor) {
    if (!problem.approximateJacobian) throw Error("solveNewton: an approximate factor needs its matrix");
    // Restarted (with the true Jacobian) only when the residual falls by less than half.
    auto& broyden = params->sublist("Direction").sublist("Broyden");
    broyden.set("Restart Frequency", options.maxIterations + 1);
    broyden.set("Memory", options.maxIterations + 1);
    broyden.set("Max Convergence Rate", 0.5);
    params->sublist("Direction").set("Method", "Broyden");
  } else {
    params->sublist("Direction").set("Method", "Newton");
  }
  auto converged = Teuchos::rcp(new NOX::StatusTest::NormF(options.absoluteTolerance, NOX::StatusTest::NormF::Unscaled));
  auto combo = Teuchos::rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR));
  combo->addStatusTest(converged);
  combo->addStatusTest(Teuchos::rcp(new NOX::StatusTest::MaxIters(options.maxIterations)));
  combo->addStatusTest(Teuchos::rcp(new NOX::StatusTest::FiniteValue));
  auto solver = NOX::Solver::buildSolver(group, combo, params);
  NOX::StatusTest::StatusType status = NOX::StatusTest::Failed;
  try {
    status = solver->solve();
  } catch (...) {
    // NOX throws a bare "NOX Error" string when a direction cannot be computed
    // (e.g. a Jacobian that cannot be factored): a failed solve, not a crash.
    status = NOX::StatusTest::Failed;
  }
  const auto& final = dynamic_cast<const Group&>(solver->getSolutionGroup());
  NewtonReport report;
  report.converged = status == NOX::StatusTest::Converged;
  report.iterations = solver->getNumIterations();
  report.jacobians = group->jacobiansFactored();
  report.residualNorm = final.getNormF();
  u.getVectorNonConst(0)->assign(tpetra(final.getX()));
  return report;
}

}  // namespace cyclone::solvers
