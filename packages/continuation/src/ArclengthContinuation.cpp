// LOCA::LAPACK glue: the only translation unit with LOCA headers.
#include "cyclone/continuation/ArclengthContinuation.hpp"

#include <sstream>

#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"

#include <LOCA.H>
#include <LOCA_LAPACK.H>

#include <cmath>

namespace cyclone::continuation {

namespace {

class Interface : public LOCA::LAPACK::Interface {
public:
  Interface(const ContinuationProblem& problem, const Eigen::VectorXd& x0, double p0, Branch& branch)
      : problem_(problem), guess_(int(x0.size())), p_(p0), branch_(branch) {
    for (int i = 0; i < x0.size(); ++i) guess_(i) = x0(i);
  }
  const NOX::LAPACK::Vector& getInitialGuess() override { return guess_; }
  bool computeF(NOX::LAPACK::Vector& f, const NOX::LAPACK::Vector& x) override {
    ++residuals_;
    try {
      Eigen::VectorXd F(problem_.size);
      problem_.residual(toEigen(x), p_, F);
      if (!F.allFinite()) return false;
      for (int i = 0; i < problem_.size; ++i) f(i) = F(i);
      return true;
    } catch (...) {
      return false;  // a failed evaluation: LOCA cuts the step
    }
  }
  bool computeJacobian(NOX::LAPACK::Matrix<double>& J, const NOX::LAPACK::Vector& x) override {
    ++jacobians_;
    try {
      Eigen::MatrixXd Je(problem_.size, problem_.size);
      problem_.jacobian(toEigen(x), p_, Je);
      if (!Je.allFinite()) return false;
      for (int i = 0; i < problem_.size; ++i)
        for (int j = 0; j < problem_.size; ++j) J(i, j) = Je(i, j);
      return true;
    } catch (...) {
      return false;
    }
  }
  void setParams(const LOCA::ParameterVector& p) override { p_ = p.getValue("p"); }
  void printSolution(const NOX::LAPACK::Vector& x, const double conParam) override {
    branch_.points.push_back({conParam, toEigen(x)});
    // Progress for long curves: a line every 10 s.
    if (sinceLog_.seconds() > 10) {
      std::ostringstream msg;
      msg << "continuation: " << branch_.points.size() << " points, parameter " << conParam << ", "
          << total_.seconds() << " s; " << double(residuals_) / double(branch_.points.size() - pointsAtLog_)
          << " residuals and " << double(jacobians_) / double(branch_.points.size() - pointsAtLog_)
          << " Jacobians per point";
      residuals_ = jacobians_ = 0;
      pointsAtLog_ = branch_.points.size();
      log::info(msg.str());
      sinceLog_.restart();
    }
  }

private:
  Eigen::VectorXd toEigen(const NOX::LAPACK::Vector& x) const {
    Eigen::VectorXd v(problem_.size);
    for (int i = 0; i < problem_.size; ++i) v(i) = x(i);
    return v;
  }
  const ContinuationProblem& problem_;
  NOX::LAPACK::Vector guess_;
  double p_;
  Branch& branch_;
  Timer sinceLog_, total_;
  long residuals_ = 0, jacobians_ = 0;
  std::size_t pointsAtLog_ = 0;
};

}  // namespace

namespace {

// One LOCA run from the converged point (x0, p0) over the range of o, its
// first step of size `initialStep` (sign: the direction of p). Appends the
// points (the start itself only when `keepStart`) and sets the stop fields.
void runLoca(const ContinuationProblem& problem, const Eigen::VectorXd& x0, double p0, double initialStep,
             const ContinuationOptions& o, bool keepStart, Branch& branch, bool& threw) {
  threw = false;
  Branch run;
  auto params = Teuchos::rcp(new Teuchos::ParameterList);
  auto& stepper = params->sublist("LOCA").sublist("Stepper");
  stepper.set("Continuation Method", "Arc Length");
  stepper.set("Continuation Parameter", "p");
  stepper.set("Initial Value", p0);
  stepper.set("Max Value", std::max(o.from, o.to));
  stepper.set("Min Value", std::min(o.from, o.to));
  stepper.set("Max Steps", std::max(1, o.maxSteps - int(branch.points.size())));
  stepper.set("Max Nonlinear Iterations", o.maxNewtonIterations);
  stepper.set("Compute Eigenvalues", false);
  params->sublist("LOCA").sublist("Predictor").set("Method", "Tangent");
  params->sublist("LOCA").sublist("Stepper").set("Enable Arc Length Scaling", o.arcLengthScaling);
  auto& step = params->sublist("LOCA").sublist("Step Size");
  step.set("Method", "Adaptive");
  step.set("Initial Step Size", initialStep);
  step.set("Min Step Size", o.minStep);
  step.set("Max Step Size", o.maxStep);
  params->sublist("NOX").sublist("Printing").set("Output Information", 0);
  auto globalData = LOCA::createGlobalData(params);
  {
    LOCA::ParameterVector p;
    p.addParameter("p", p0);
    Interface iface(problem, x0, p0, run);
    auto group = Teuchos::rcp(new LOCA::LAPACK::Group(globalData, iface));
    group->setParams(p);
    auto tests = Teuchos::rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR));
    tests->addStatusTest(Teuchos::rcp(new NOX::StatusTest::NormF(o.tolerance)));
    tests->addStatusTest(Teuchos::rcp(new NOX::StatusTest::MaxIters(o.maxNewtonIterations)));
    LOCA::Stepper stepperObject(globalData, group, tests, params);
    LOCA::Abstract::Iterator::IteratorStatus status = LOCA::Abstract::Iterator::Failed;
    try {
      status = stepperObject.run();
    } catch (const std::exception& e) {
      run.stopReason = std::string("continuation stopped by an exception: ") + e.what();
      threw = true;
    } catch (...) {
      run.stopReason = "continuation stopped: Newton could not start (no converged initial point)";
      threw = true;
    }
    branch.finished = status == LOCA::Abstract::Iterator::Finished;
    branch.failedSteps += stepperObject.getNumFailedSteps();
    branch.stopReason = run.stopReason.empty()
                            ? (branch.finished ? "end of the parameter range reached"
                                               : "step size fell below the minimum or too many steps (the branch so far "
                                                 "is kept)")
                            : run.stopReason;
  }
  LOCA::destroyGlobalData(globalData);
  for (std::size_t i = keepStart ? 0 : 1; i < run.points.size(); ++i) branch.points.push_back(run.points[i]);
}

}  // namespace

Branch traceBranch(const ContinuationProblem& problem, const Eigen::VectorXd& guess, const ContinuationOptions& o) {
  Branch branch;
  Eigen::VectorXd x0 = guess;
  const auto start = solveNewton(problem, x0, o.from, o.tolerance, 100);
  if (!start.converged) {
    std::ostringstream why;
    why << "no converged solution at the start of the range: Newton with line search from the guess stopped at ||R|| = "
        << start.residualNorm << " (tolerance " << o.tolerance
        << "; round-off of very different forces, e.g. a huge preload against a tiny excitation, needs a looser "
           "continuation tolerance)";
    branch.stopReason = why.str();
    return branch;
  }
  // A failed evaluation inside LOCA (e.g. a parameter leaving its domain in a
  // corrector iteration) ends its run by an exception: restart from the last
  // converged point with a quarter of the step, in the direction the branch
  // was moving, a few times, as a step cut. (Restarting also after LOCA's step
  // fell below its minimum at a kink of many friction contacts was tried: each
  // restart failed the same way and the run took minutes longer.)
  const double forward = o.to >= o.from ? 1.0 : -1.0;
  bool threw = false;
  runLoca(problem, x0, o.from, forward * o.initialStep, o, true, branch, threw);
  double step = o.initialStep;
  for (int restart = 0; threw && restart < 6 && branch.points.size() >= 2; ++restart) {
    step /= 4;
    if (step < o.minStep) break;
    const auto& last = branch.points.back();
    const double moving = last.parameter - branch.points[branch.points.size() - 2].parameter;
    const std::size_t before = branch.points.size();
    runLoca(problem, last.x, last.parameter, (moving >= 0 ? 1.0 : -1.0) * step, o, false, branch, threw);
    if (branch.points.size() > before) step = o.initialStep;  // progress: the next cut starts afresh
  }
  // LOCA ends a run at the range's bound by a last step that may overshoot it, and a
  // corrector that jumps branches can land far outside: such points are not solutions
  // in the range asked for.
  const double lo = std::min(o.from, o.to), hi = std::max(o.from, o.to), slack = 1e-9 * (hi - lo);
  std::size_t kept = 0;
  for (auto& pt : branch.points)
    if (pt.parameter >= lo - slack && pt.parameter <= hi + slack) branch.points[kept++] = std::move(pt);
  if (kept < branch.points.size()) {
    std::ostringstream why;
    why << branch.stopReason << "; " << branch.points.size() - kept << " point(s) outside the range dropped";
    branch.points.resize(kept);
    branch.stopReason = why.str();
  }
  return branch;
}

}  // namespace cyclone::continuation
