// LOCA::LAPACK glue: the only translation unit with LOCA headers.
#include "cyclone/continuation/ArclengthContinuation.hpp"

#include <sstream>
#include <stdexcept>

#include "cyclone/continuation/BranchTurn.hpp"
#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"

#include <LOCA.H>
#include <LOCA_LAPACK.H>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace cyclone::continuation {

namespace {

// The tangent predictor's orientation can flip at a kink of a nonsmooth system
// (BranchTurn.hpp): the run stops there and traceBranch steps over the kink.
struct BranchTurnedBack : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A corrector that converged far from its predictor (BranchTurn.hpp: branchJump): the
// point is dropped and the run restarts from the last point with a smaller step.
struct CorrectorJumped : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Interface : public LOCA::LAPACK::Interface {
public:
  /// before: the branch's point before x0 when LOCA resumes a branch (nullptr at its start),
  /// so that a first step back along it is caught too.
  Interface(const ContinuationProblem& problem, const Eigen::VectorXd& x0, double p0, Branch& branch,
            const BranchPoint* before, double lo, double hi, bool check, bool jumpCheck)
      : problem_(problem), guess_(int(x0.size())), p_(p0), branch_(branch), before_(before), lo_(lo), hi_(hi),
        check_(check), jumpCheck_(jumpCheck) {
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
    std::vector<const BranchPoint*> path;
    if (before_) path.push_back(before_);
    for (std::size_t i = 0; i + 1 < branch_.points.size(); ++i) path.push_back(&branch_.points[i]);
    // Both steps inside this run: a run's first step (LOCA's initial step) has no
    // relation to the step size the run before it had cut down to. (Measuring it
    // against the initial step was tried: on the default disc at H = 3 the first
    // chord of every restart, at a quarter of the step each time, exceeded 5 times
    // that step: LOCA's first step is not the size it is given.)
    const std::size_t n = branch_.points.size();
    if (jumpCheck_ && n >= 3 && branchJump(branch_.points[n - 3], branch_.points[n - 2], branch_.points[n - 1])) {
      branch_.points.pop_back();
      std::ostringstream msg;
      msg << "the corrector jumped to another branch from p = " << branch_.points.back().parameter << " (to p = "
          << conParam << ")";
      throw CorrectorJumped(msg.str());
    }
    // LOCA's last step overshoots the range's bound and then steps back onto it: not a flip.
    const double last = path.empty() ? p_ : path.back()->parameter;
    const int kink = check_ && last >= lo_ && last <= hi_ ? retracedFrom(path, branch_.points.back()) : -1;
    // LOCA sometimes takes one step back at a kink and turns forward again by
    // itself: only a retrace that goes on for kRetraceSteps points is stopped.
    if (kink < 0) {
      retracing_ = 0;
    } else if (retracing_++ == 0) {
      kinkPoint_ = kink - (before_ ? 1 : 0);  // index in this run's points (path[0] is before_ when given)
    }
    if (retracing_ >= kRetraceSteps) {
      branch_.points.resize(std::size_t(std::max(kinkPoint_ + 1, 1)));
      std::ostringstream msg;
      msg << "the arclength predictor turned back onto the branch at p = " << branch_.points.back().parameter;
      throw BranchTurnedBack(msg.str());
    }
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
  const BranchPoint* before_;
  double lo_, hi_;
  bool check_, jumpCheck_;
  static constexpr int kRetraceSteps = 3;
  int retracing_ = 0, kinkPoint_ = 0;
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
             const ContinuationOptions& o, bool keepStart, Branch& branch, bool& threw, bool& turnedBack) {
  threw = false, turnedBack = false;
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
  if (o.lineSearch != ContinuationOptions::LineSearch::FullStep)  // else LOCA's default, untouched
    params->sublist("NOX").sublist("Line Search").set(
        "Method", std::string(o.lineSearch == ContinuationOptions::LineSearch::Backtrack ? "Backtrack" : "Polynomial"));
  auto globalData = LOCA::createGlobalData(params);
  {
    LOCA::ParameterVector p;
    p.addParameter("p", p0);
    const BranchPoint* before = keepStart || branch.points.size() < 2 ? nullptr : &branch.points[branch.points.size() - 2];
    Interface iface(problem, x0, p0, run, before, std::min(o.from, o.to), std::max(o.from, o.to),
                    o.stopWhereItTurnsBack, o.restartWhereTheCorrectorJumps);
    auto group = Teuchos::rcp(new LOCA::LAPACK::Group(globalData, iface));
    group->setParams(p);
    auto tests = Teuchos::rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR));
    tests->addStatusTest(Teuchos::rcp(new NOX::StatusTest::NormF(o.tolerance)));
    tests->addStatusTest(Teuchos::rcp(new NOX::StatusTest::MaxIters(o.maxNewtonIterations)));
    LOCA::Stepper stepperObject(globalData, group, tests, params);
    LOCA::Abstract::Iterator::IteratorStatus status = LOCA::Abstract::Iterator::Failed;
    try {
      status = stepperObject.run();
    } catch (const BranchTurnedBack& e) {
      run.stopReason = e.what();
      turnedBack = true;
    } catch (const CorrectorJumped& e) {
      run.stopReason = e.what();
      threw = true;  // restarted like a failed evaluation: from the last point, a quarter of the step
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

// One pseudo-arclength step past a kink, predicted along the secant over the
// last regular step length L (through the creeping points at the kink):
// Newton on [F(x, p); t . (z - z_pred)] = 0 with dF/dp by central differences,
// for steps L, L/2, 2 L, L/4. The first converged point that does not go back
// along the traced path (BranchTurn) is appended; at a fold it lands on the
// other half. A point more than kJumpRatio h from the kink is another branch and
// is not taken. False if none does.
bool bridgeKink(const ContinuationProblem& problem, const ContinuationOptions& o, Branch& branch) {
  const auto& pts = branch.points;
  const std::size_t n = pts.size();
  const std::size_t first = n > 11 ? n - 11 : 0;
  double L = 0;
  for (std::size_t i = first + 1; i < n; ++i) L = std::max(L, turnStep(pts[i - 1], pts[i]));
  if (!(L > 0)) return false;
  std::size_t ia = n - 2;
  while (ia > first && turnStep(pts[ia], pts[n - 1]) < L) --ia;
  const BranchPoint& a = pts[ia];
  const BranchPoint b = pts[n - 1];
  const double chord = turnStep(a, b);
  const Eigen::VectorXd tx = (b.x - a.x) / chord;
  const double tp = (b.parameter - a.parameter) / chord;
  const double lo = std::min(o.from, o.to), hi = std::max(o.from, o.to);
  const int m = problem.size;
  std::vector<const BranchPoint*> path;
  for (std::size_t i = n > 51 ? n - 51 : 0; i < n; ++i) path.push_back(&pts[i]);
  for (double h : {L, 0.5 * L, 2 * L, 0.25 * L}) {
    Eigen::VectorXd x = b.x + h * tx;
    double p = b.parameter + h * tp;
    bool converged = false;
    Eigen::VectorXd F(m), Fp(m), Fm(m);
    Eigen::MatrixXd J(m, m), A(m + 1, m + 1);
    Eigen::VectorXd R(m + 1);
    for (int it = 0; it < 30 && !converged; ++it) {
      try {
        problem.residual(x, p, F);
        const double eps = 1e-7 * std::max(1.0, std::abs(p));
        problem.residual(x, p + eps, Fp);
        problem.residual(x, p - eps, Fm);
        problem.jacobian(x, p, J);
      } catch (...) {
        break;
      }
      const double arc = tx.dot(x - b.x) + tp * (p - b.parameter) - h;
      if (F.norm() <= o.tolerance && std::abs(arc) <= 1e-10 * h) {
        converged = true;
        break;
      }
      A.topLeftCorner(m, m) = J;
      A.topRightCorner(m, 1) = (Fp - Fm) / (2 * 1e-7 * std::max(1.0, std::abs(p)));
      A.bottomLeftCorner(1, m) = tx.transpose();
      A(m, m) = tp;
      R << F, arc;
      const Eigen::VectorXd dz = A.partialPivLu().solve(R);
      if (!dz.allFinite()) break;
      x -= dz.head(m), p -= dz(m);
    }
    if (!converged || p < lo || p > hi) continue;
    const BranchPoint c{p, x};
    if (retracedFrom(path, c) >= 0) continue;
    // Newton on the secant's hyperplane can converge far from the step it was given: that
    // is another branch (as for LOCA's steps, BranchTurn.hpp), not the way over the kink.
    if (turnStep(b, c) > kJumpRatio * h) continue;
    branch.points.push_back(c);
    return true;
  }
  return false;
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
  bool threw = false, turnedBack = false;
  runLoca(problem, x0, o.from, forward * o.initialStep, o, true, branch, threw, turnedBack);
  double step = o.initialStep;
  int restarts = 0, bridges = 0;
  while ((threw || turnedBack) && branch.points.size() >= 2) {
    const std::size_t before = branch.points.size();
    if (turnedBack) {
      // Step over the kink by a secant arclength step (bridgeKink); LOCA
      // resumes from there.
      if (++bridges > 20 || !bridgeKink(problem, o, branch)) {
        branch.stopReason += " (a kink the predictor could not pass, nor a secant step over it): the branch so "
                             "far is kept";
        break;
      }
      const auto& last = branch.points.back();
      const double moving = last.parameter - branch.points[branch.points.size() - 2].parameter;
      runLoca(problem, last.x, last.parameter, (moving >= 0 ? 1.0 : -1.0) * o.initialStep, o, false, branch, threw,
              turnedBack);
      continue;
    }
    if (++restarts > 6) break;
    step /= 4;
    if (step < o.minStep) break;
    const auto& last = branch.points.back();
    const double moving = last.parameter - branch.points[branch.points.size() - 2].parameter;
    runLoca(problem, last.x, last.parameter, (moving >= 0 ? 1.0 : -1.0) * step, o, false, branch, threw, turnedBack);
    if (branch.points.size() > before) step = o.initialStep, restarts = 0;  // progress: the next cut starts afresh
  }
  if (bridges > 0 && branch.finished) {
    std::ostringstream why;
    why << branch.stopReason << " (" << bridges << " kink(s) where the predictor turned back, stepped over by a "
        << "secant step)";
    branch.stopReason = why.str();
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
  // A branch that folds back and runs out at the bound it started from (LOCA calls
  // that the end of its range) has not traced the range beyond its turn.
  if (branch.finished && branch.points.size() >= 2) {
    double reached = o.from;
    for (const auto& pt : branch.points)
      reached = o.to >= o.from ? std::max(reached, pt.parameter) : std::min(reached, pt.parameter);
    const double end = branch.points.back().parameter;
    if (std::abs(end - o.from) < std::abs(end - o.to)) {
      branch.finished = false;
      branch.returnedToStart = true;
      branch.reached = reached;
      std::ostringstream why;
      why << "the branch turned back at p = " << reached << " and returned to the start of the range (p = " << end
          << "): " << reached << " .. " << o.to << " not traced (the branch so far is kept)";
      branch.stopReason = why.str();
    }
  }
  return branch;
}

}  // namespace cyclone::continuation
