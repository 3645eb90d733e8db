// LOCA::LAPACK glue: the only translation unit with LOCA headers. The LOCA engine
// of traceBranch (ContinuationOptions::Engine::Loca).
#include "ContinuationEngines.hpp"

#include <sstream>
#include <stdexcept>

#include "cyclone/continuation/BranchTurn.hpp"
#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"

#include <LOCA.H>
#include <Teuchos_oblackholestream.hpp>
#include <LOCA_LAPACK.H>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
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

// dF/dp from the problem (ContinuationProblem::parameterDerivative) where LOCA would take
// a difference in p: each such difference is a whole evaluation of F, once per Newton
// iteration of LOCA's arclength corrector.
class ProblemParameterDerivative : public LOCA::DerivUtils {
public:
  ProblemParameterDerivative(const Teuchos::RCP<LOCA::GlobalData>& globalData, const ContinuationProblem& problem)
      : LOCA::DerivUtils(globalData), problem_(problem) {}
  Teuchos::RCP<LOCA::DerivUtils> clone(NOX::CopyType) const override {
    return Teuchos::rcp(new ProblemParameterDerivative(*this));
  }
  NOX::Abstract::Group::ReturnType computeDfDp(LOCA::MultiContinuation::AbstractGroup& grp,
                                               const std::vector<int>& paramIds, NOX::Abstract::MultiVector& result,
                                               bool isValidF) const override {
    if (!isValidF) {
      if (grp.computeF() != NOX::Abstract::Group::Ok) return NOX::Abstract::Group::Failed;
      result[0] = grp.getF();
    }
    try {
      const auto& x = dynamic_cast<const NOX::LAPACK::Vector&>(grp.getX());
      Eigen::VectorXd X(x.length()), dFdp;
      for (int i = 0; i < x.length(); ++i) X(i) = x(i);
      problem_.parameterDerivative(X, grp.getParam(paramIds.at(0)), dFdp);
      if (!dFdp.allFinite() || dFdp.size() != X.size()) return NOX::Abstract::Group::Failed;
      auto& column = dynamic_cast<NOX::LAPACK::Vector&>(result[1]);
      for (int i = 0; i < x.length(); ++i) column(i) = dFdp(i);
      return NOX::Abstract::Group::Ok;
    } catch (...) {
      return NOX::Abstract::Group::Failed;
    }
  }

private:
  const ContinuationProblem& problem_;
};

class Interface : public LOCA::LAPACK::Interface {
public:
  /// before: the branch's points before x0 when LOCA resumes a branch (empty at
  /// its start), oldest first, so that a first step back along them, or onto
  /// them, is caught too.
  Interface(const ContinuationProblem& problem, const Eigen::VectorXd& x0, double p0, Branch& branch,
            std::vector<const BranchPoint*> before, double lo, double hi, bool check, bool jumpCheck)
      : problem_(problem), guess_(int(x0.size())), p_(p0), branch_(branch), before_(std::move(before)), lo_(lo),
        hi_(hi), check_(check), jumpCheck_(jumpCheck) {
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
    std::vector<const BranchPoint*> path = before_;
    for (std::size_t i = 0; i + 1 < branch_.points.size(); ++i) path.push_back(&branch_.points[i]);
    // Both steps inside this run: a run's first step (LOCA's initial step) has no
    // relation to the step size the run before it had cut down to, nor to the size it
    // is given (docs/decisions.md, "LOCA's jump checks").
    const std::size_t n = branch_.points.size();
    // A step that lands back on the path far behind (landsOnTracedPath) is not taken for
    // a jump here: that test also stops legitimate tiny steps of an excitation ramp
    // (docs/decisions.md, "LOCA's jump checks"); such a jump shows as a stretch traced
    // twice, and bridgeKink's candidates are checked with it.
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
      kinkPoint_ = kink - int(before_.size());  // index in this run's points (before_ comes first in path)
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
  std::vector<const BranchPoint*> before_;
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
             const ContinuationOptions& o, bool keepStart, Branch& branch, bool& threw, bool& turnedBack,
             bool& stalled) {
  threw = false, turnedBack = false, stalled = false;
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
  // LOCA's own lines ("Step size reached minimum step size bound", printed as errors,
  // which NOX prints whatever the output level) go nowhere: the branch's stop reason
  // says it, once, in the scene's words (issue 20). LOCA's utilities read this sublist.
  params->sublist("NOX").sublist("Printing").set(
      "Error Stream", Teuchos::RCP<std::ostream>(Teuchos::rcp(new Teuchos::oblackholestream)));
  if (o.lineSearch != ContinuationOptions::LineSearch::FullStep)  // else LOCA's default, untouched
    params->sublist("NOX").sublist("Line Search").set(
        "Method", std::string(o.lineSearch == ContinuationOptions::LineSearch::Backtrack ? "Backtrack" : "Polynomial"));
  auto globalData = LOCA::createGlobalData(params);
  {
    LOCA::ParameterVector p;
    p.addParameter("p", p0);
    std::vector<const BranchPoint*> before;  // the branch's last 50 points before x0 (its last point)
    if (!keepStart)
      for (std::size_t i = branch.points.size() > 51 ? branch.points.size() - 51 : 0; i + 1 < branch.points.size(); ++i)
        before.push_back(&branch.points[i]);
    Interface iface(problem, x0, p0, run, before, std::min(o.from, o.to), std::max(o.from, o.to),
                    o.stopWhereItTurnsBack, o.restartWhereTheCorrectorJumps);
    auto group = Teuchos::rcp(new LOCA::LAPACK::Group(globalData, iface));
    group->setParams(p);
    if (problem.parameterDerivative)
      group->setDerivUtils(Teuchos::rcp(new ProblemParameterDerivative(globalData, problem)));
    else if (o.locaParameterPerturbation != 1e-6)
      group->setDerivUtils(Teuchos::rcp(new LOCA::DerivUtils(globalData, o.locaParameterPerturbation)));
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
    // LOCA's step fell below its minimum (not an exception, not the step
    // count): a corner no arclength step passes (bridgeKink).
    stalled = !branch.finished && !threw && !turnedBack && int(branch.points.size() + run.points.size()) < o.maxSteps;
    branch.failedSteps += stepperObject.getNumFailedSteps();
    // A turn back onto the branch or a step below the minimum is a corner no step passes.
    const bool budget = int(branch.points.size() + run.points.size()) >= o.maxSteps && !turnedBack;
    branch.end = branch.finished ? BranchEnd::RangeEnd
                 : threw         ? BranchEnd::EngineStopped
                 : budget        ? BranchEnd::PointBudget
                                 : BranchEnd::Wall;
    // (The budget was said as "the step fell below the minimum or too many steps": issue 49.)
    branch.stopReason = !run.stopReason.empty() ? run.stopReason
                        : branch.finished       ? "end of the parameter range reached"
                        : budget ? "the point budget (max_points " + std::to_string(o.maxSteps) +
                                       ") was reached (the branch so far is kept)"
                                 : "the step size fell below the minimum (the branch so far is kept)";
  }
  LOCA::destroyGlobalData(globalData);
  for (std::size_t i = keepStart ? 0 : 1; i < run.points.size(); ++i) branch.points.push_back(run.points[i]);
}

// The way into a kink where the arclength steps stopped: the last regular step
// length L (the longest of the last 10 steps, through the creeping points at
// the kink), the point a about L before the kink point b, the unit secant a ->
// b, and the path so far (its last 50 segments).
struct KinkApproach {
  double L = 0;
  BranchPoint a, b;
  Eigen::VectorXd tx;
  double tp = 0;
  double lo = 0, hi = 0;
  std::vector<const BranchPoint*> path;
};

std::optional<KinkApproach> approachToKink(const ContinuationOptions& o, const Branch& branch) {
  const auto& pts = branch.points;
  const std::size_t n = pts.size();
  const std::size_t first = n > 11 ? n - 11 : 0;
  KinkApproach k;
  for (std::size_t i = first + 1; i < n; ++i) k.L = std::max(k.L, turnStep(pts[i - 1], pts[i]));
  if (!(k.L > 0)) return std::nullopt;
  std::size_t ia = n - 2;
  while (ia > first && turnStep(pts[ia], pts[n - 1]) < k.L) --ia;
  k.a = pts[ia];
  k.b = pts[n - 1];
  const double chord = turnStep(k.a, k.b);
  k.tx = (k.b.x - k.a.x) / chord;
  k.tp = (k.b.parameter - k.a.parameter) / chord;
  k.lo = std::min(o.from, o.to), k.hi = std::max(o.from, o.to);
  for (std::size_t i = n > 51 ? n - 51 : 0; i < n; ++i) k.path.push_back(&pts[i]);
  return k;
}

// A point past the kink that continues the branch: in the range, not back along
// or onto the path traced (BranchTurn.hpp), and not farther than kJumpRatio
// times the step it was given (that is another branch).
bool continuesPast(const KinkApproach& k, const BranchPoint& c, double step) {
  return c.parameter >= k.lo && c.parameter <= k.hi && retracedFrom(k.path, c) < 0 && !landsOnTracedPath(k.path, c) &&
         turnStep(k.b, c) <= kJumpRatio * step;
}

// One pseudo-arclength step past the kink along the secant: Newton on
// [F(x, p); t . (z - z_pred)] = 0 with dF/dp by central differences, for steps
// L, L/2, 2 L, L/4; the first point that continues the branch. At a fold it
// lands on the other half.
std::optional<BranchPoint> secantStepOverKink(const ContinuationProblem& problem, const ContinuationOptions& o,
                                              const KinkApproach& k) {
  const int m = problem.size;
  for (double h : {k.L, 0.5 * k.L, 2 * k.L, 0.25 * k.L}) {
    Eigen::VectorXd x = k.b.x + h * k.tx;
    double p = k.b.parameter + h * k.tp;
    bool converged = false;
    Eigen::VectorXd F(m), Fp(m), Fm(m);
    Eigen::MatrixXd J(m, m), A(m + 1, m + 1);
    Eigen::VectorXd R(m + 1);
    for (int it = 0; it < 30 && !converged; ++it) {
      const double eps = 1e-7 * std::max(1.0, std::abs(p));
      try {
        problem.residual(x, p, F);
        problem.residual(x, p + eps, Fp);
        problem.residual(x, p - eps, Fm);
        problem.jacobian(x, p, J);
      } catch (...) {
        break;
      }
      const double arc = k.tx.dot(x - k.b.x) + k.tp * (p - k.b.parameter) - h;
      if (F.norm() <= o.tolerance && std::abs(arc) <= 1e-10 * h) {
        converged = true;
        break;
      }
      A.topLeftCorner(m, m) = J;
      A.topRightCorner(m, 1) = (Fp - Fm) / (2 * eps);
      A.bottomLeftCorner(1, m) = k.tx.transpose();
      A(m, m) = k.tp;
      R << F, arc;
      const Eigen::VectorXd dz = A.partialPivLu().solve(R);
      if (!dz.allFinite()) break;
      x -= dz.head(m), p -= dz(m);
    }
    if (converged && continuesPast(k, BranchPoint{p, x}, h)) return BranchPoint{p, x};
  }
  return std::nullopt;
}

// A corner of the path (a friction contact changing state there) that turns by
// more than 90 degrees in (x, p): no hyperplane normal to the incoming
// direction meets the path beyond it, so no arclength corrector converges
// however small the step. Where p still moves on through the corner (the
// default disc at H = 3: dx/dp about 270 before, 60 after), Newton at a fixed p
// just past it does: a step in the natural parameter, of 1/4, 1, 1/16 of the
// secant's change of p. The other direction of p is tried last, for a fold at
// the corner.
std::optional<BranchPoint> fixedParameterStepOverKink(const ContinuationProblem& problem, const ContinuationOptions& o,
                                                      const KinkApproach& k) {
  const double dp = std::abs(k.b.parameter - k.a.parameter);
  const double forward = k.b.parameter >= k.a.parameter ? 1.0 : -1.0;
  if (!(dp > 0)) return std::nullopt;
  for (double sign : {forward, -forward})
    for (double f : {0.25, 1.0, 0.0625}) {
      const double p = k.b.parameter + sign * f * dp;
      if (p < k.lo || p > k.hi) continue;
      Eigen::VectorXd x = k.b.x;
      if (!solveNewton(problem, x, p, o.tolerance, 12, nullptr, o.linearSolver).converged) continue;  // 2-7 iterations where it passes
      if (continuesPast(k, BranchPoint{p, x}, k.L)) return BranchPoint{p, x};
    }
  return std::nullopt;
}

// A step over the kink at the branch's end, appended; false if none is found.
// Where LOCA stalled at tiny steps the arclength corrector already failed close
// by: the fixed-parameter step first; where it turned back, the secant step
// first.
bool bridgeKink(const ContinuationProblem& problem, const ContinuationOptions& o, Branch& branch, bool stalled) {
  const auto k = approachToKink(o, branch);
  if (!k) return false;
  Timer timer;  // each candidate is a Newton solve: seconds to minutes on a large system
  std::ostringstream at;
  at << "continuation: a kink at p = " << k->b.parameter << " (the arclength steps " << (stalled ? "stalled" : "turned back")
     << ")";
  log::info(at.str() + ": trying a step at a fixed parameter, then a secant step");
  auto c = fixedParameterStepOverKink(problem, o, *k);
  if (!c) c = secantStepOverKink(problem, o, *k);
  std::ostringstream result;
  result << at.str() << ": ";
  if (c)
    result << "stepped over to p = " << c->parameter;
  else
    result << "no step over it";
  result << " (" << timer.seconds() << " s)";
  log::info(result.str());
  if (!c) return false;
  branch.points.push_back(*c);
  return true;
}

}  // namespace

namespace {

// LOCA ends a run at the range's bound by a last step that may overshoot it, and a
// corrector that jumps branches can land far outside: such points are not solutions in
// the range asked for.
void dropPointsOutsideRange(Branch& branch, const ContinuationOptions& o) {
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
}

// A branch that folds back and runs out at the bound it started from (LOCA calls that
// the end of its range) has not traced the range beyond its turn.
void markReturnToStart(Branch& branch, const ContinuationOptions& o) {
  if (branch.finished && branch.points.size() >= 2) {
    double reached = o.from;
    for (const auto& pt : branch.points)
      reached = o.to >= o.from ? std::max(reached, pt.parameter) : std::min(reached, pt.parameter);
    const double end = branch.points.back().parameter;
    if (std::abs(end - o.from) < std::abs(end - o.to)) {
      branch.finished = false;
      branch.returnedToStart = true;
      branch.end = BranchEnd::ReturnedToStart;
      branch.reached = reached;
      std::ostringstream why;
      why << "the branch turned back at p = " << reached << " and returned to the start of the range (p = " << end
          << "): " << reached << " .. " << o.to << " not traced (the branch so far is kept)";
      branch.stopReason = why.str();
    }
  }
}

}  // namespace

Branch traceBranchWithLoca(const ContinuationProblem& problem, const Eigen::VectorXd& guess,
                           const ContinuationOptions& o) {
  Branch branch;
  Eigen::VectorXd x0 = guess;
  const auto start = solveNewton(problem, x0, o.from, o.tolerance, 100, nullptr, o.linearSolver);
  if (!start.converged) {
    branch.end = BranchEnd::NoStart;
    branch.stopReason = noConvergedStart(start, o.tolerance);
    return branch;
  }
  // A failed evaluation inside LOCA (e.g. a parameter leaving its domain in a
  // corrector iteration) ends its run by an exception: restart from the last
  // converged point with a quarter of the step, in the direction the branch
  // was moving, a few times, as a step cut. A step below LOCA's minimum is not
  // restarted: at a kink of many friction contacts each restart fails the same way.
  const double forward = o.to >= o.from ? 1.0 : -1.0;
  bool threw = false, turnedBack = false, stalled = false;
  runLoca(problem, x0, o.from, forward * o.initialStep, o, true, branch, threw, turnedBack, stalled);
  double step = o.initialStep;
  int restarts = 0, bridges = 0;
  while ((threw || turnedBack || (stalled && o.stopWhereItTurnsBack)) && branch.points.size() >= 2) {
    const std::size_t before = branch.points.size();
    if (turnedBack || stalled) {
      // Step over the kink (bridgeKink: a secant arclength step or a step at a fixed
      // parameter); LOCA resumes from there.
      if (++bridges > 20 || !bridgeKink(problem, o, branch, stalled)) {
        branch.stopReason +=
            " (a kink the arclength steps could not pass, nor a secant or fixed-parameter step over it): the branch "
            "so far is kept";
        break;
      }
      const auto& last = branch.points.back();
      const double moving = last.parameter - branch.points[branch.points.size() - 2].parameter;
      runLoca(problem, last.x, last.parameter, (moving >= 0 ? 1.0 : -1.0) * o.initialStep, o, false, branch, threw,
              turnedBack, stalled);
      continue;
    }
    if (++restarts > 6) break;
    step /= 4;
    if (step < o.minStep) break;
    const auto& last = branch.points.back();
    const double moving = last.parameter - branch.points[branch.points.size() - 2].parameter;
    runLoca(problem, last.x, last.parameter, (moving >= 0 ? 1.0 : -1.0) * step, o, false, branch, threw, turnedBack,
            stalled);
    if (branch.points.size() > before) step = o.initialStep, restarts = 0;  // progress: the next cut starts afresh
  }
  if (bridges > 0 && branch.finished) {
    std::ostringstream why;
    why << branch.stopReason << " (" << bridges << " kink(s) where the arclength steps turned back or stalled, "
        << "stepped over by a secant or fixed-parameter step)";
    branch.stopReason = why.str();
  }
  dropPointsOutsideRange(branch, o);
  markReturnToStart(branch, o);
  return branch;
}

}  // namespace cyclone::continuation
