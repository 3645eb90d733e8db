// The first point of a forced-response curve, found without help from the scene.
//
// Why not simply Newton from the linear solution: with friction elements the
// linear solution without them is far from the response (NLvib example 07 at
// W = 0.5: |X| = 2.1 against 0.12, because the stuck elements add stiffness 20),
// the elements slip over the whole period there, and Newton walks into a spurious
// local minimum of ||R|| (0.27) where the sliders carry a static offset and the
// Jacobian is nearly singular. From rest the first Newton step is the system with
// the friction stuck, within 1e-3 of the answer. Where no Newton start converges,
// the response is followed from rest as the excitation grows.
#include <cmath>
#include <optional>
#include <sstream>

#include "cyclone/continuation/HomotopySolve.hpp"
#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/response/ForcedResponseTrace.hpp"

#include "cyclone/response/LinearResonances.hpp"

namespace cyclone::response {

namespace {

const char* engineName(continuation::ContinuationOptions::Engine engine) {
  return engine == continuation::ContinuationOptions::Engine::Loca ? "LOCA" : "the predictor-corrector";
}

}  // namespace

namespace {

// The start searches a trace has run, so that its passes (each engine, each end of the
// range) do not repeat one: the second engine's pass searches the same far end again,
// and a search's Newton attempts and the predictor-corrector's ramp do not depend on the
// pass (only LOCA's ramp does, through its own options). Keyed by the search's parameter
// value and what was tried; it lives for one trace, over one system.
struct StartSearches {
  struct Entry {
    double from;
    std::string what;  // "newton", or the ramp's engine and the options it reads
    Eigen::VectorXd x;  // empty: failed
    std::string method;  // how it converged, or why not
  };
  std::vector<Entry> entries;
  const Entry* find(double from, const std::string& what) const {
    for (const auto& e : entries)
      if (e.from == from && e.what == what) return &e;
    return nullptr;
  }
};

std::string rampSignature(const continuation::ContinuationOptions& r) {
  if (r.engine != continuation::ContinuationOptions::Engine::Loca) return "ramp: predictor-corrector";
  std::ostringstream s;
  s << "ramp: LOCA " << r.arcLengthScaling << r.stopWhereItTurnsBack << r.restartWhereTheCorrectorJumps
    << int(r.lineSearch);
  return s.str();
}

// Newton on fewer harmonics first: H = 1 from rest or the linear solution, then twice
// as many at each level up to 8 and two more at each after (a raise of eight harmonics
// at once met the impact oscillator's internal resonance near its 14th and stalled), each level's solution carried up and, where
// Newton from it stalls, the added harmonics switched on by a homotopy
// (continuation::solveByHomotopy). With tens of harmonics Newton from rest stalls where
// the first harmonics' answer, carried up, converges (the impact oscillator with
// friction at H = 8 to 32, whose ramp of the excitation took most of its curve's time).
// Empty where a level is not solved or the system has too few harmonics for it to help.
Eigen::VectorXd startFromFewerHarmonics(const hbm::HarmonicBalanceSystem& hb, double omega, double scale,
                                        const continuation::ContinuationOptions& o) {
  const auto& set = hb.aft().harmonics();
  if (set.maxHarmonic() < 4) return {};
  Eigen::VectorXd x;
  std::vector<int> below;  // the last level's harmonics
  for (int level = 1;; level = std::min(level < 8 ? 2 * level : level + 2, set.maxHarmonic())) {
    std::vector<int> harmonics;
    for (int h : set.harmonics())
      if (h <= level) harmonics.push_back(h);
    std::unique_ptr<hbm::HarmonicBalanceSystem> copy;
    if (level < set.maxHarmonic()) {
      try {
        copy = hbm::withHarmonics(hb, hbm::HarmonicSet(harmonics), hb.aft().numSamples());
      } catch (const InputError&) {  // excitation on a harmonic above the level
        continue;
      }
    }
    const hbm::HarmonicBalanceSystem& system = copy ? *copy : hb;
    const auto problem = continuationProblem(system, ForcedResponseSetup::Parameter::ForceScale, omega);
    auto newton = [&](Eigen::VectorXd& y) {
      return continuation::solveNewton(problem, y, scale, o.tolerance, 100, nullptr, o.linearSolver).converged;
    };
    Eigen::VectorXd y;
    bool solved = false;
    if (x.size() == 0) {
      y = Eigen::VectorXd::Zero(system.numUnknowns());
      solved = newton(y);
      if (!solved) y = system.linearSolution(omega, scale), solved = newton(y);
    } else {
      // Newton from the carried solution (up to 100 steps: solveByHomotopy's own first
      // try is shorter and stalls where this converges), else the homotopy.
      const hbm::HarmonicSet from(below);
      y = hbm::transferCoefficients(x, hb.numDofs(), from, system.aft().harmonics());
      const Eigen::VectorXd carried = y;
      solved = newton(y);
      if (!solved) {
        y = carried;
        solved = continuation::solveByHomotopy(problem, y, scale,
                                               hbm::addedCoefficients(hb.numDofs(), from, system.aft().harmonics()),
                                               o.tolerance)
                     .newton.converged;
      }
    }
    if (!solved) return {};
    x = std::move(y), below = harmonics;
    if (level == set.maxHarmonic()) return x;
  }
}

StartingPoint searchStart(ForcedResponseSetup& setup, StartSearches& searches) {
  const auto& hb = *setup.system;
  const auto& o = setup.continuation;
  const auto [omega, scale] = setup.apply(o.from);  // the start's frequency and excitation scale
  const auto problem = continuationProblem(setup);
  Timer timer;
  StartingPoint start;
  auto attempt = [&](Eigen::VectorXd x, const std::string& method) {
    if (!continuation::solveNewton(problem, x, o.from, o.tolerance, 100, nullptr, o.linearSolver).converged) return false;
    start.x = std::move(x);
    start.method = method;
    start.seconds = timer.seconds();
    return true;
  };
  auto reuse = [&](const StartSearches::Entry& e) {
    start.x = e.x;
    start.method = e.method + " (found before in this trace)";
    start.seconds = timer.seconds();
  };
  const auto* newton = searches.find(o.from, "newton");
  if (newton && newton->x.size() > 0) {
    reuse(*newton);
    return start;
  }
  if (!newton) {
    if (attempt(Eigen::VectorXd::Zero(hb.numUnknowns()), "Newton from rest") ||
        attempt(hb.linearSolution(omega, scale), "Newton from the linear solution")) {
      searches.entries.push_back({o.from, "newton", start.x, start.method});
      return start;
    }
    searches.entries.push_back({o.from, "newton", Eigen::VectorXd(), "stagnated"});
  }
  if (const auto* ladder = searches.find(o.from, "ladder")) {
    if (ladder->x.size() > 0) {
      reuse(*ladder);
      return start;
    }
  } else if (const auto x = startFromFewerHarmonics(hb, omega, scale, o); x.size() > 0 &&
             attempt(x, "Newton from the first harmonics' solution carried up")) {
    searches.entries.push_back({o.from, "ladder", start.x, start.method});
    return start;
  } else {
    searches.entries.push_back({o.from, "ladder", Eigen::VectorXd(), "stagnated"});
  }

  // The ramp: the excitation scale from 0 to the start's scale at the start frequency.
  setup.apply(o.from);  // the element or damping value of the start
  const auto ramp = continuationProblem(hb, ForcedResponseSetup::Parameter::ForceScale, omega);
  continuation::ContinuationOptions r = o;
  r.from = 0;
  r.to = scale;
  r.initialStep = 0.05 * std::abs(scale);
  r.maxStep = 0.2 * std::abs(scale);
  r.turnAngle = 0.12;
  r.minStep = 1e-8 * std::abs(scale);
  r.maxSteps = 500;
  // Each engine in turn: the ramp can meet a stretch where the stuck contacts' static
  // state drifts at an almost constant excitation (seen on a coarse 8-sector disc at
  // 4 % of the load), which one engine's steps cross and the other's follow.
  using Engine = continuation::ContinuationOptions::Engine;
  std::string why;
  for (Engine engine : {o.engine, o.engine == Engine::Loca ? Engine::PredictorCorrector : Engine::Loca}) {
    r.engine = engine;
    const std::string name = engineName(engine), what = rampSignature(r);
    if (const auto* earlier = searches.find(o.from, what)) {
      if (earlier->x.size() > 0) {
        reuse(*earlier);
        return start;
      }
      why += (why.empty() ? "" : "; ") + name + ": " + earlier->method;
      continue;
    }
    const auto branch = continuation::traceBranch(ramp, Eigen::VectorXd::Zero(hb.numUnknowns()), r);
    if (!branch.points.empty() && std::abs(branch.points.back().parameter - scale) <= 1e-9 * std::abs(scale) + 1e-12 &&
        attempt(branch.points.back().x, "ramp of the excitation from rest (" + name + ", " +
                                            std::to_string(branch.points.size()) + " points)")) {
      searches.entries.push_back({o.from, what, start.x, start.method});
      return start;
    }
    searches.entries.push_back({o.from, what, Eigen::VectorXd(), branch.stopReason});
    why += (why.empty() ? "" : "; ") + name + ": " + branch.stopReason;
  }
  start.method = "no converged start: Newton from rest and from the linear solution stagnated, and the ramp of the "
                 "excitation from rest stopped (" + why + ")";
  start.seconds = timer.seconds();
  return start;
}

}  // namespace

StartingPoint findStartingPoint(ForcedResponseSetup& setup) {
  StartSearches searches;
  return searchStart(setup, searches);
}

namespace {

// A force scale over decades is traced in q = ln s with the response per unit force
// Y = X / s as unknowns and the residual relative to the force at s. In s and X the
// Duffing over 1e-3..1e6 turned back at its first point (issue 49): each step is a
// fraction of the whole range in s, so the start's decades are crossed in one step, and
// the residual relative to the unit force asks 1e-16 of the force at 1e6. In q and Y a
// linear response is one point and every decade costs alike.
bool tracedInLogForce(const ForcedResponseSetup& setup) {
  const auto& o = setup.continuation;
  return setup.parameter == ForcedResponseSetup::Parameter::ForceScale && o.from > 0 && o.to > 0 &&
         std::max(o.from, o.to) > kLogForceDecadeRatio * std::min(o.from, o.to);
}

continuation::Branch traceInLogForce(ForcedResponseSetup& setup, const Eigen::VectorXd& start) {
  const auto base = continuationProblem(setup);
  continuation::ContinuationProblem log = base;
  log.residual = [base](const Eigen::VectorXd& Y, double q, Eigen::VectorXd& R) {
    const double s = std::exp(q);
    base.residual(s * Y, s, R);
    R /= s;
  };
  log.jacobian = [base](const Eigen::VectorXd& Y, double q, Eigen::MatrixXd& J) {
    const double s = std::exp(q);
    base.jacobian(s * Y, s, J);  // d(R / s)/dY = (dR/dX) s / s
  };
  if (base.jacobianOperator)
    log.jacobianOperator = [base](const Eigen::VectorXd& Y, double q) {
      const double s = std::exp(q);
      return base.jacobianOperator(s * Y, s);
    };
  log.parameterDerivative = nullptr;  // the engines difference it in q
  log.measure = nullptr;              // a force curve has no located peaks
  auto o = setup.continuation;
  o.from = std::log(o.from), o.to = std::log(o.to);
  for (double& mark : o.parameterMarks) mark = mark > 0 ? std::log(mark) : o.from;
  auto branch = continuation::traceBranch(log, start / setup.continuation.from, o);
  for (auto& point : branch.points) {
    const double s = std::exp(point.parameter);
    point.parameter = s, point.x *= s;
  }
  branch.reached = std::exp(branch.reached);
  if (!branch.finished) branch.stopReason += " (traced in ln of the force scale: p there is ln s)";
  return branch;
}

// One arclength run over setup.continuation's range from a converged start.
continuation::Branch traceOneSweep(ForcedResponseSetup& setup, const Eigen::VectorXd& start, double scale) {
  if (tracedInLogForce(setup)) return traceInLogForce(setup, start);
  if (!(scale > 0) || scale == 1) return continuation::traceBranch(continuationProblem(setup), start, setup.continuation);
  // LOCA's arclength mixes the unknowns with the parameter: unknowns of order one keep
  // its steps in proportion (X = scale Y).
  const auto base = continuationProblem(setup);
  continuation::ContinuationProblem scaled = base;
  scaled.residual = [base, scale](const Eigen::VectorXd& Y, double p, Eigen::VectorXd& R) {
    base.residual(scale * Y, p, R);
  };
  scaled.jacobian = [base, scale](const Eigen::VectorXd& Y, double p, Eigen::MatrixXd& J) {
    base.jacobian(scale * Y, p, J);
    J *= scale;
  };
  if (base.jacobianOperator)
    scaled.jacobianOperator = [base, scale](const Eigen::VectorXd& Y, double p) {
      return std::make_shared<continuation::ScaledJacobianOperator>(base.jacobianOperator(scale * Y, p), scale);
    };
  if (base.measure) scaled.measure = [base, scale](const Eigen::VectorXd& Y) { return base.measure(scale * Y); };
  auto branch = continuation::traceBranch(scaled, start / scale, setup.continuation);
  for (auto& point : branch.points) point.x *= scale;
  return branch;
}

// The parameter a sweep from the end of `upward`'s range got closest to its start.
double farthestTowardsTheStart(const continuation::Branch& down, const continuation::ContinuationOptions& upward) {
  double lowest = upward.to;
  for (const auto& pt : down.points)
    lowest = upward.to >= upward.from ? std::min(lowest, pt.parameter) : std::max(lowest, pt.parameter);
  return lowest;
}

// No start at the range's start: the curve from the other end, as far as it goes (a
// start can fail where the response is large and close to a fold or an internal
// resonance, and converge at the other end, off resonance: the default disc at H = 5,
// docs/scenes.md).
continuation::Branch traceFromTheEnd(ForcedResponseSetup& setup, const StartingPoint& failed,
                                     StartSearches& searches) {
  const auto upward = setup.continuation;
  setup.continuation.from = upward.to, setup.continuation.to = upward.from;
  const StartingPoint far = searchStart(setup, searches);
  continuation::Branch down;
  if (far.x.size() > 0) {
    const double scale = setup.unknownScale != 0 ? setup.unknownScale : far.x.cwiseAbs().maxCoeff();
    down = traceOneSweep(setup, far.x, scale);
  }
  setup.continuation = upward;
  setup.apply(upward.from);
  std::ostringstream why;
  why << "no start at the start of the range (" << failed.method << "); from the end of the range ("
      << (far.x.size() > 0 ? far.method : "no start either: " + far.method) << ") ";
  if (down.points.empty()) {
    why << "nothing traced";
    down.end = continuation::BranchEnd::NoStart;
  } else {
    const double lowest = farthestTowardsTheStart(down, upward);
    why << down.points.size() << " points to p = " << lowest << " (" << down.stopReason << ")";
    if (!down.finished) why << "; " << upward.from << " .. " << lowest << " not traced";
  }
  down.stopReason = why.str();
  return down;
}

// The first sweep's points reached setup.continuation.maxSteps (the caller's max_points,
// a sweep's budget): the curve ends there, with neither a sweep from the other end nor
// another engine or sample count (each had the whole budget again: 508 points for 2).
bool pointBudgetSpent(const ForcedResponseSetup& setup, const continuation::Branch& branch) {
  return int(branch.points.size()) >= setup.continuation.maxSteps;
}

// Both sweeps with setup.continuation's engine.
continuation::Branch traceWithOneEngine(ForcedResponseSetup& setup, const StartingPoint& start,
                                        StartSearches& searches) {
  if (start.x.size() == 0) return traceFromTheEnd(setup, start, searches);
  double scale = setup.unknownScale;
  if (scale == 0) scale = start.x.cwiseAbs().maxCoeff();  // automatic: the start's largest coefficient
  auto branch = traceOneSweep(setup, start.x, scale);
  if (branch.finished || branch.points.empty() || pointBudgetSpent(setup, branch)) return branch;

  // The branch folded back to the start, or stopped short of the end: the rest of the
  // range holds another branch, or the same one past what stopped the sweep, which a
  // sweep from the other end finds (as a test rig's downward sweep does).
  const auto upward = setup.continuation;
  double reached = upward.from;  // the farthest the first sweep got
  for (const auto& pt : branch.points)
    reached = upward.to >= upward.from ? std::max(reached, pt.parameter) : std::min(reached, pt.parameter);
  if (branch.returnedToStart) reached = branch.reached;
  setup.continuation.from = upward.to, setup.continuation.to = upward.from;
  const StartingPoint far = searchStart(setup, searches);
  continuation::Branch down;
  if (far.x.size() > 0) down = traceOneSweep(setup, far.x, scale);
  setup.continuation = upward;
  setup.apply(upward.from);
  std::ostringstream why;
  if (branch.returnedToStart)
    why << "two sweeps: from the start the branch turned back at p = " << reached << " and returned to the start";
  else
    why << "two sweeps: from the start the branch stopped at p = " << reached << " (" << branch.stopReason << ")";
  why << "; from the end of the range (" << (far.x.size() > 0 ? far.method : "no start: " + far.method)
      << ") ";
  if (down.points.empty()) {
    why << "nothing traced: " << upward.to << " .. " << reached << " not traced";
  } else {
    const double lowest = farthestTowardsTheStart(down, upward);
    const bool covered = upward.to >= upward.from ? lowest <= reached : lowest >= reached;
    why << down.points.size() << " points to p = " << lowest << " (" << down.stopReason << ")";
    if (!covered) why << "; " << reached << " .. " << lowest << " not traced";
    branch.finished = covered;
    if (covered) branch.end = continuation::BranchEnd::MetFromTheEnd;
    branch.segmentStarts.push_back(branch.points.size());
    for (auto& pt : down.points) branch.points.push_back(std::move(pt));
    branch.failedSteps += down.failedSteps;
  }
  branch.stopReason = why.str();
  return branch;
}

// Where one engine leaves the curve incomplete, the other traces it again (the
// engines fail in different places: the predictor-corrector where a stuck contact's
// static state drifts at an almost constant frequency, LOCA at stick-slip kinks that
// its corrector's plane misses); the complete curve, or else the first, is kept.
continuation::Branch traceWithFallback(ForcedResponseSetup& setup, const StartingPoint& start,
                                       StartSearches& searches) {
  auto branch = traceWithOneEngine(setup, start, searches);
  branch.retraces.engine = setup.continuation.engine;
  if (branch.finished || !setup.fallback || pointBudgetSpent(setup, branch)) return branch;
  const auto primary = setup.continuation;
  continuation::ContinuationOptions other = *setup.fallback;
  other.from = primary.from, other.to = primary.to, other.tolerance = primary.tolerance;
  log::info(std::string("forced response: ") + engineName(primary.engine) + " left the curve incomplete (" +
            branch.stopReason + "); traced again with " + engineName(other.engine));
  setup.continuation = other;
  const StartingPoint again = start.x.size() > 0 ? start : searchStart(setup, searches);
  auto second = traceWithOneEngine(setup, again, searches);
  second.retraces.engine = other.engine;
  branch.retraces.otherEngineTried = second.retraces.otherEngineTried = true;
  setup.continuation = primary;
  setup.apply(primary.from);
  if (second.finished) {
    second.stopReason += std::string(" (traced by ") + engineName(other.engine) + " after " +
                         engineName(primary.engine) + " left it incomplete: " + branch.stopReason + ")";
    return second;
  }
  branch.stopReason += std::string("; ") + engineName(other.engine) + " did not complete it either (" +
                       second.stopReason + ")";
  return branch;
}

// Where an incomplete curve's sweeps stopped: the first sweep's farthest parameter from
// the range's start and the sweep from the end's farthest towards the start (NaN where
// there is none). Empty where the first sweep did not start at the range's start or
// folded back to it (a fold is the curve's shape, and what more samples change there is
// the start at the other end).
std::optional<std::pair<double, double>> sweepStops(const continuation::Branch& b,
                                                    const continuation::ContinuationOptions& o) {
  if (b.returnedToStart || b.points.empty() ||
      std::abs(b.points.front().parameter - o.from) > 1e-9 * std::abs(o.to - o.from))
    return std::nullopt;
  const std::size_t split = b.segmentStarts.empty() ? b.points.size() : b.segmentStarts.front();
  const bool up = o.to >= o.from;
  double first = o.from, far = std::nan("");
  for (std::size_t i = 0; i < b.points.size(); ++i) {
    const double p = b.points[i].parameter;
    if (i < split) first = up ? std::max(first, p) : std::min(first, p);
    else far = std::isnan(far) ? p : (up ? std::min(far, p) : std::max(far, p));
  }
  return std::pair<double, double>{first, far};
}

// The same stops within 1e-3 of the range (both without a sweep from the end, or both
// with one stopped at the same place).
bool sameStops(const std::optional<std::pair<double, double>>& a, const std::optional<std::pair<double, double>>& b,
               double span) {
  if (!a || !b) return false;
  auto same = [span](double x, double y) {
    return (std::isnan(x) && std::isnan(y)) || std::abs(x - y) <= 1e-3 * span;
  };
  return same(a->first, b->first) && same(a->second, b->second);
}

// A curve both engines leave incomplete is traced again with twice the AFT samples,
// then four times, where the system has elements whose sampled law has corners (those
// that recommend a sample count: friction). The residual of a sampled friction law has a
// corner wherever a stick-slip instant crosses a sample, and the corners shrink with the
// samples: the thin 8-sector disc's H = 1 curve (256 samples) had a start at the range's
// end and a kink at 582 Hz that neither engine passed, and is traced whole with 512 or
// 1024 (docs/decisions.md, 2026-11-26). The finer system becomes setup.system (the
// curve's points belong to it); where no retrace completes, the first curve stays.
continuation::Branch traceWithMoreSamples(ForcedResponseSetup& setup, continuation::Branch first) {
  bool cornered = false;
  for (const auto& e : setup.system->elements()) cornered = cornered || e.element->recommendedSamples() > 0;
  if (!cornered) return first;
  const int samples = setup.system->aft().numSamples();
  std::unique_ptr<hbm::HarmonicBalanceSystem> original = std::move(setup.system);
  // Without checkpoints: a trace's key (its problem's residual at the start, the options)
  // does not see the sample count, and at a start from rest the residual is the same at
  // any count, so a retrace would read back the coarser trace saved under that key.
  const auto continuationBefore = setup.continuation;
  const auto fallbackBefore = setup.fallback;
  setup.continuation.checkpoints = nullptr;
  if (setup.fallback) setup.fallback->checkpoints = nullptr;
  std::ostringstream tried;
  std::string notRetried;  // why four times was not tried
  std::vector<int> factorsTried;
  for (const int factor : {2, 4}) {
    factorsTried.push_back(factor);
    setup.system = hbm::withHarmonics(*original, original->aft().harmonics(), factor * samples);
    log::info("forced response: incomplete with " + std::to_string(samples) + " AFT samples; traced again with " +
              std::to_string(factor * samples));
    StartSearches searches;  // a new system: nothing searched yet
    auto again = traceWithFallback(setup, searchStart(setup, searches), searches);
    again.retraces.samplesFactor = factor;
    again.retraces.samplesFactorsTried = factorsTried;
    again.retraces.otherEngineTried = again.retraces.otherEngineTried || first.retraces.otherEngineTried;
    if (again.finished) {
      setup.continuation = continuationBefore, setup.fallback = fallbackBefore;
      again.stopReason += " (with " + std::to_string(factor * samples) + " AFT samples" + tried.str() + ": with " +
                          std::to_string(samples) + " the curve was incomplete: " + first.stopReason + ")";
      return again;
    }
    tried << "; " << factor * samples << " incomplete too";
    // A sampling corner shrinks and moves with the samples; stops that stay where they
    // were with twice the samples are the curve's own (the default disc at H = 5: 1394.4
    // and 1394.0 Hz with 256 and 512), and four times would only cost more.
    const auto before = sweepStops(first, continuationBefore), now = sweepStops(again, continuationBefore);
    if (factor == 2 && sameStops(before, now, std::abs(continuationBefore.to - continuationBefore.from))) {
      std::ostringstream why;
      why << " (its first sweep stopped at p = " << now->first << " against " << before->first << " with " << samples
          << (std::isnan(now->second) ? "" : ", the sweep from the end at the same place too")
          << ": not a sampling corner, four times not tried)";
      notRetried = why.str();
      break;
    }
  }
  setup.continuation = continuationBefore, setup.fallback = fallbackBefore;
  setup.system = std::move(original);
  setup.apply(setup.continuation.from);
  first.retraces.samplesFactorsTried = factorsTried;
  first.stopReason += (notRetried.empty() ? "; traced again with 2 and 4 times the " : "; traced again with 2 times the ") +
                      std::to_string(samples) + " AFT samples, incomplete too" + notRetried;
  return first;
}

}  // namespace

continuation::Branch traceForcedResponse(ForcedResponseSetup& setup, const StartingPoint& start) {
  const long unsettledBefore = hbm::FrictionContact::unsettledEvaluations();
  // A frequency curve's steps land on the linear resonances inside its range (not over them).
  if (setup.parameter == ForcedResponseSetup::Parameter::Omega && setup.continuation.parameterMarks.empty()) {
    const double lo = std::min(setup.continuation.from, setup.continuation.to),
                 hi = std::max(setup.continuation.from, setup.continuation.to);
    for (const double w : linearResonances(*setup.system))
      if (const double p = w / setup.omegaUnit; p > lo && p < hi) setup.continuation.parameterMarks.push_back(p);
  }
  StartSearches searches;
  auto branch = traceWithFallback(setup, start, searches);
  if (!branch.finished && !branch.points.empty() && !pointBudgetSpent(setup, branch))
    branch = traceWithMoreSamples(setup, std::move(branch));
  if (const long n = hbm::FrictionContact::unsettledEvaluations() - unsettledBefore; n > 0)
    log::warn("forced response: " + std::to_string(n) +
              " friction force evaluations ended on a slider state that is not periodic (the period map's "
              "Newton did not settle it); points near them may carry a force error");
  return branch;
}

continuation::Branch traceForcedResponse(ForcedResponseSetup& setup) {
  return traceForcedResponse(setup, findStartingPoint(setup));
}

}  // namespace cyclone::response
