#include "cyclone/response/ForcedResponseChecks.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include "cyclone/continuation/HomotopySolve.hpp"
#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/NumberText.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"

namespace cyclone::response {

namespace {
// The arclength trace past a fold in a level's peak search (findPeakPastFold): a bound on its
// points, so that a level whose path wanders costs a bounded share of the check.
constexpr int kPastFoldPoints = 400;

// The checks' Newton tolerance at a point of excitation scale s: the force-scale form's
// residual is relative to the forces at scale 1, so above it the trace's tolerance is
// asked of the forces at s (a force curve over 1e-3..1e6 is traced so, in ln s: at 1e6
// the unscaled tolerance asked 1e-16 of the force, and both checks found "no solution").
double toleranceAtScale(const ForcedResponseSetup& setup, double scale) {
  return setup.continuation.tolerance * std::max(1.0, std::abs(scale));
}
}  // namespace

SamplesCheck checkSamples(ForcedResponseSetup& setup, const continuation::BranchPoint& pt, double peak) {
  const auto [w, scale] = setup.apply(pt.parameter);
  const auto& hb = *setup.system;
  const int N = hb.aft().numSamples(), dof = setup.outputDofs.front(), nc = hb.numCoefficients();
  const auto doubled = hbm::withHarmonics(hb, hb.aft().harmonics(), 2 * N);
  // The force-scale form at this frequency: the same row scaling as the trace.
  const auto problem = continuationProblem(*doubled, ForcedResponseSetup::Parameter::ForceScale, w);
  Eigen::VectorXd X = pt.x;
  const auto newton = continuation::solveNewton(problem, X, scale, toleranceAtScale(setup, scale));
  SamplesCheck check;
  check.samples = N;
  std::ostringstream out;
  if (!newton.converged) {
    check.residual = newton.residualNorm;
    out << "samples check: no solution with " << 2 * N << " samples at the peak (residual " << newton.residualNorm
        << "); the sample count " << N << " may be too small";
    log::warn(out.str());
    check.text = out.str();
    return check;
  }
  check.solved = true;
  const double after = hbm::peakMagnitude(hb.aft().harmonics(), Eigen::VectorXd(X.segment(dof * nc, nc)));
  check.change = std::abs(after / peak - 1);
  out << "samples check: " << N << " -> " << 2 * N << " samples changes the peak max|x| of DOF " << dof << " by "
      << check.change << " (relative)";
  if (check.change > 1e-2) log::warn(out.str() + ": raise `samples`");
  check.text = out.str();
  return check;
}

// The dense solvers hold about four matrices of the unknowns' size (the Jacobian, the
// bordered one and the factors of two of them): refused where they would not fit in
// this machine's memory, a warning where each Newton iteration takes seconds (one
// Jacobian and LU took about 1 s at 2349 unknowns on the default disc). Krylov steps
// (the Jacobian's blocks) hold per harmonic two matrices of its 1 or 2 coefficients of
// every DOF (the linear block and its LU), the elements' own Jacobians and GMRES's basis.
// Krylov's preconditioner factors the linear block of every harmonic, dense over the
// DOFs: (2/3) (2 DOFs)^3 flops each (a 3000-DOF matrix scene at H = 7 spent minutes on
// its first one without a word; issue 49). About 10 Gflop/s here in single precision.
// Each element's Jacobian is its sampled sensitivities projected onto the harmonics, a
// dense product of 2 N (d nc)^2 flops, at about 4.5 Gflop/s (the default disc's 43
// contacts at H = 48, 1024 samples: 1.6 s).
int recommendedSamples(const hbm::HarmonicSet& harmonics,
                       const std::vector<std::shared_ptr<const hbm::NonlinearElement>>& elements) {
  int recommended = std::max(64, 4 * harmonics.maxHarmonic() + 1);
  for (const auto& element : elements)
    if (element->recommendedSamples() > 0)
      recommended = std::max({recommended, element->recommendedSamples(), harmonics.nonsmoothSamples()});
  return recommended;
}

double elementJacobianSeconds(int samples, int numCoefficients, const std::vector<int>& elementDimensions) {
  constexpr double kFlopsPerSecond = 4.5e9;
  double flops = 0;
  for (int d : elementDimensions) flops += 2 * double(samples) * std::pow(double(d) * numCoefficients, 2);
  return flops / kFlopsPerSecond;
}

NewtonStepEstimate estimateNewtonStep(int dofs, const hbm::HarmonicSet& harmonics, int samples,
                                      const std::vector<int>& elementDimensions, bool hasJacobianBlocks,
                                      continuation::ContinuationOptions::LinearSolver solver) {
  NewtonStepEstimate e;
  const double nc = harmonics.numCoefficients(), n = double(dofs) * nc;
  e.unknowns = n;
  using S = continuation::ContinuationOptions::LinearSolver;
  e.krylov = hasJacobianBlocks && solver != S::Dense &&
             (solver == S::Krylov || n >= continuation::ContinuationOptions::krylovFrom);
  e.gigabytes = 4 * 8 * n * n / 1e9;
  double elements = 0;
  for (int d : elementDimensions) elements += std::pow(double(d) * nc, 2);
  e.jacobianSeconds = elementJacobianSeconds(samples, harmonics.numCoefficients(), elementDimensions);
  if (e.krylov) {
    e.gigabytes = 8 * (2 * 4 * double(dofs) * dofs * harmonics.size() + elements +
                       (continuation::KrylovOptions{}.restart + 10) * n) / 1e9;
    e.solveSeconds = harmonics.size() * (2.0 / 3.0) * std::pow(2.0 * dofs, 3) / 1e10;
  } else {
    e.solveSeconds = std::pow(n / 2349.0, 3);
  }
  return e;
}

void checkSolverSize(const hbm::HarmonicBalanceSystem& hb, const std::string& harmonicsKey,
                     continuation::ContinuationOptions::LinearSolver solver) {
  constexpr double kMaxGigabytes = kMaxSolverGigabytes, kSlowUnknowns = 5000;
  std::vector<int> dimensions;
  for (const auto& e : hb.elements()) dimensions.push_back(e.element->dimension());
  const auto estimate = estimateNewtonStep(hb.numDofs(), hb.aft().harmonics(), hb.aft().numSamples(), dimensions,
                                           hb.hasJacobianBlocks(), solver);
  const double n = estimate.unknowns, gigabytes = estimate.gigabytes;
  const bool krylov = estimate.krylov;
  std::ostringstream what;
  what.precision(3);
  what << hb.aft().harmonics().size() << " harmonics (up to " << hb.aft().harmonics().maxHarmonic() << ") on "
       << hb.numDofs() << " DOFs make " << hb.numUnknowns() << " unknowns";
  if (gigabytes > kMaxGigabytes) {
    what << ": the " << (krylov ? "Jacobian's blocks and GMRES's basis" : "dense Jacobian and its factors")
         << " would take " << gigabytes << " GB (at most " << kMaxGigabytes << " here); use fewer harmonics";
    throw InputError(harmonicsKey, what.str());
  }
  if (krylov) {
    const double dofs = hb.numDofs();
    const double seconds = estimate.solveSeconds;
    if (seconds > 600)
      throw InputError(harmonicsKey, what.str() + ": the Newton steps' preconditioner factors a dense " +
                                         std::to_string(2 * int(dofs)) + "-square block per harmonic, about " +
                                         std::to_string(int(seconds)) + " s each time; use fewer DOFs (a reduced "
                                         "model at the nonlinear DOFs) or fewer harmonics");
    if (seconds > 2)
      log::warn(what.str() + ": the Newton steps' preconditioner factors a dense " + std::to_string(2 * int(dofs)) +
                "-square block per harmonic, about " + std::to_string(int(std::ceil(seconds))) +
                " s each time (a reduced model at the nonlinear DOFs would make it small)");
  }
  if (!krylov && n > kSlowUnknowns)
    log::warn(what.str() + ": each Newton iteration factors a dense Jacobian of that size (about " +
              std::to_string(std::max(1, int(estimate.solveSeconds))) + " s each, from 1 s at 2349)");
  checkElementJacobianCost(hb.aft().numSamples(), hb.numCoefficients(), dimensions, what.str(), harmonicsKey);
}

// Each element's Jacobian is its sampled sensitivities projected onto the harmonics, a
// dense product of 2 N (d nc)^2 flops: the cost that grows fastest with H (issue 49:
// harmonics 0..5000 on one DOF spent minutes on one Jacobian, silently). About 4.5
// Gflop/s here (the default disc's 43 contacts at H = 48, 1024 samples: 1.6 s).
void checkElementJacobianCost(int samples, int numCoefficients, const std::vector<int>& elementDimensions,
                              const std::string& what, const std::string& harmonicsKey) {
  // Said from 2 s an iteration: a harmonics check up to H = 100 on the coarsest demo disc,
  // 7 s an iteration at its top level, ran for minutes without a word (issue 49).
  constexpr double kSlowSeconds = 2, kRefusedSeconds = 600;
  const double seconds = elementJacobianSeconds(samples, numCoefficients, elementDimensions);
  if (seconds <= kSlowSeconds) return;
  std::ostringstream text;
  text.precision(3);
  text << what << " and " << samples << " time samples: the elements' Jacobians alone take about " << seconds
       << " s a Newton iteration (2 N (d nc)^2 flops each at about 4.5 Gflop/s)";
  if (seconds > kRefusedSeconds) throw InputError(harmonicsKey, text.str() + "; use fewer harmonics");
  log::warn(text.str());
}

namespace {

// `set` and one harmonic more (h), with at least the system's samples.
hbm::HarmonicSet withHarmonic(const hbm::HarmonicSet& set, int h) {
  std::vector<int> list = set.harmonics();
  list.push_back(h);
  return hbm::HarmonicSet(list);
}

// `set` and every harmonic above its highest up to H.
hbm::HarmonicSet withHarmonicsUpTo(const hbm::HarmonicSet& set, int H) {
  std::vector<int> list = set.harmonics();
  for (int h = set.maxHarmonic() + 1; h <= H; ++h) list.push_back(h);
  return hbm::HarmonicSet(list);
}
// The samples of a raised level: the system's, or more where the raised harmonics need them.
int raisedSamples(const hbm::HarmonicBalanceSystem& hb, const hbm::HarmonicSet& raised) {
  bool nonsmooth = false;  // friction or contacts: samples that grow with the harmonics (HarmonicSet::nonsmoothSamples)
  for (const auto& e : hb.elements()) nonsmooth = nonsmooth || e.element->recommendedSamples() > 0;
  return std::max(hb.aft().numSamples(), nonsmooth ? raised.nonsmoothSamples() : raised.minimumSamples());
}
std::unique_ptr<hbm::HarmonicBalanceSystem> raisedSystem(const hbm::HarmonicBalanceSystem& hb,
                                                         const hbm::HarmonicSet& raised) {
  auto system = hbm::withHarmonics(hb, raised, raisedSamples(hb, raised));
  checkSolverSize(*system, "harmonics_check_to");
  return system;
}

// The largest response of DOF `dof` along a frequency curve near the solution X at
// `hz`: the peak search at fixed frequencies (PeakSearch.hpp), which passes the
// corners of friction paths where an arclength corrector stalls. Its parameter is the
// frequency in Hz (what its messages name). The window (+-5 %, and `offset` more for
// a start that far from the peak it seeks) holds the shift of a friction-damped peak
// between harmonic truncations.
continuation::PeakSearchResult searchPeak(const hbm::HarmonicBalanceSystem& system, const Eigen::VectorXd& X,
                                          double hz, double excitationScale, int dof, double tolerance,
                                          double offset = 0) {
  const auto byOmega = continuationProblem(system, ForcedResponseSetup::Parameter::Omega, 0, excitationScale);
  continuation::ContinuationProblem problem = byOmega;
  problem.residual = [byOmega](const Eigen::VectorXd& x, double f, Eigen::VectorXd& R) {
    byOmega.residual(x, 2 * M_PI * f, R);
  };
  problem.jacobian = [byOmega](const Eigen::VectorXd& x, double f, Eigen::MatrixXd& J) {
    byOmega.jacobian(x, 2 * M_PI * f, J);
  };
  if (byOmega.jacobianOperator)
    problem.jacobianOperator = [byOmega](const Eigen::VectorXd& x, double f) {
      return byOmega.jacobianOperator(x, 2 * M_PI * f);
    };
  const int nc = system.numCoefficients();
  const auto& H = system.aft().harmonics();
  continuation::PeakSearchOptions o;
  o.step = 1e-3 * hz, o.maxStep = 5e-3 * hz, o.minStep = 1e-8 * hz;
  o.window = 0.05 * hz + std::abs(offset), o.parameterTolerance = 1e-5 * hz;
  o.tolerance = tolerance;
  // From a neighbour's prediction Newton converges in a few iterations; one that does not
  // within 20 is cut (a step) or replaced (a flank start at a level's start), not waited for.
  o.maxNewtonIterations = 20;
  const auto measure = [&](const Eigen::VectorXd& x) {
    return hbm::peakMagnitude(H, Eigen::VectorXd(x.segment(dof * nc, nc)));
  };
  // A search stopped by a fold (the hammering shroud's curves fold near their tops) is
  // traced on past it by arclength.
  return continuation::findPeakPastFold(problem, continuation::findLocalPeak(problem, X, hz, measure, o), measure, o,
                                        kPastFoldPoints);
}

// The solution X of the level below, carried to `system` (the harmonics `newHarmonics`
// more), solved at `hz`: Newton, or where it stalls the homotopy that switches the new
// harmonics' equations on (HomotopySolve.hpp). X is updated in place.
continuation::HomotopyResult solveCarried(const hbm::HarmonicBalanceSystem& system, Eigen::VectorXd& X, double hz,
                                          double excitationScale, const std::vector<int>& newHarmonics,
                                          double tolerance) {
  const auto byOmega = continuationProblem(system, ForcedResponseSetup::Parameter::Omega, 0, excitationScale);
  const auto& set = system.aft().harmonics();
  std::vector<int> kept;
  for (int h : set.harmonics())
    if (std::find(newHarmonics.begin(), newHarmonics.end(), h) == newHarmonics.end()) kept.push_back(h);
  return continuation::solveByHomotopy(byOmega, X, 2 * M_PI * hz,
                                       hbm::addedCoefficients(system.numDofs(), hbm::HarmonicSet(kept), set), tolerance);
}


}  // namespace

double levelsMeetTarget(const std::vector<HarmonicsLevel>& levels, double target) {
  const std::size_t n = levels.size();
  if (n < 3 || !(levels[n - 1].peak.found && levels[n - 2].peak.found && levels[n - 3].peak.found)) return -1;
  const double last = std::abs(levels[n - 1].peak.value / levels[n - 2].peak.value - 1),
               before = std::abs(levels[n - 2].peak.value / levels[n - 3].peak.value - 1);
  return std::max(last, before) <= target ? std::max(last, before) : -1;
}

namespace {

// Solutions of one harmonic set at frequencies (Hz) near its peak: the traced curve's
// points, a peak search's path.
using SolvedPoints = std::vector<std::pair<double, Eigen::VectorXd>>;

// A start for the raised system on the level below's flank, where the two differ
// less than at a peak that moves with H: the level below's solutions (`lower`) at
// least 0.5 % of the frequency from its peak, nearest first, each carried up and
// solved at its frequency (at most 6 tried). Empty when none converges.
std::pair<double, Eigen::VectorXd> flankStart(const hbm::HarmonicBalanceSystem& lowerSystem,
                                              const hbm::HarmonicBalanceSystem& raised, SolvedPoints lower,
                                              double peakHz, double scale, double tolerance) {
  const auto byOmega = continuationProblem(raised, ForcedResponseSetup::Parameter::Omega, 0, scale);
  std::sort(lower.begin(), lower.end(), [peakHz](const auto& a, const auto& b) {
    return std::abs(a.first - peakHz) < std::abs(b.first - peakHz);
  });
  int tried = 0;
  for (const auto& [f, x] : lower) {
    if (std::abs(f - peakHz) < 5e-3 * peakHz) continue;
    if (++tried > 6) break;
    Eigen::VectorXd y =
        hbm::transferCoefficients(x, lowerSystem.numDofs(), lowerSystem.aft().harmonics(), raised.aft().harmonics());
    if (continuation::solveNewton(byOmega, y, 2 * M_PI * f, tolerance, 10).converged) return {f, y};
  }
  return {0, Eigen::VectorXd()};
}

// The next level of the harmonics check: one harmonic more up to 8, then a quarter more
// (10, 12, 15, 18, 22, 27, 33, 41, 51, ...: a hammering contact's peak needs tens of
// harmonics, and one level costs a peak search), never beyond upTo.
int nextHarmonicLevel(int H, int upTo) {
  if (H >= upTo) return upTo + 1;
  return std::min(upTo, H < 8 ? H + 1 : H + H / 4);
}

// The peak of the curve with H, then with the next levels (nextHarmonicLevel) up to
// `upTo`, each level's search started from the one below's peak (its solution carried
// to the raised harmonics), or from the level below's flank when Newton finds nothing there (its
// search path; for the first raised level also `curve`, the traced points). Stops at
// a level whose peak is not found (a fold, no solution).
std::vector<HarmonicsLevel> peakByHarmonics(const hbm::HarmonicBalanceSystem& hb, const Eigen::VectorXd& x, double hz,
                                       double scale, int dof, double tolerance, int upTo, const SolvedPoints& curve,
                                       double target) {
  std::vector<HarmonicsLevel> levels;
  std::unique_ptr<hbm::HarmonicBalanceSystem> lowerSystem, current;
  const hbm::HarmonicBalanceSystem* system = &hb;
  hbm::HarmonicSet set = hb.aft().harmonics();
  Eigen::VectorXd X = x;
  SolvedPoints lowerPoints;
  int below = set.maxHarmonic();
  for (int H = set.maxHarmonic(); H <= upTo; below = H, H = nextHarmonicLevel(H, upTo)) {
    Timer timer;
    const hbm::HarmonicBalanceSystem* lower = system;
    std::vector<int> newHarmonics;
    if (H > set.maxHarmonic()) {
      for (int h = set.maxHarmonic() + 1; h <= H; ++h) newHarmonics.push_back(h);
      const hbm::HarmonicSet raised = withHarmonicsUpTo(set, H);
      lowerSystem = std::move(current);  // keeps `lower` alive
      current = raisedSystem(hb, raised);
      X = hbm::transferCoefficients(X, hb.numDofs(), set, raised);
      set = raised, system = current.get();
    }
    HarmonicsLevel level;
    level.maxHarmonic = H;
    level.harmonics = set.harmonics(), level.samples = system->aft().numSamples();
    level.startHz = hz;
    bool started = true;  // X solves this level at hz (the search's own Newton would only repeat a failure)
    if (system != lower) {
      const auto carried = solveCarried(*system, X, hz, scale, newHarmonics, tolerance);
      started = carried.newton.converged;
      if (carried.blockStart || carried.byHomotopy) {
        const std::string how = carried.blockStart ? "the added harmonics solved with the others held, then " : "";
        log::info("harmonics check: H " + std::to_string(H) + " at " + std::to_string(hz) + " Hz " +
                  (started ? "solved from H " + std::to_string(below) + " by " + how +
                                 (carried.byHomotopy ? "the homotopy (" + std::to_string(carried.points) + " points)"
                                                     : "Newton")
                           : "not solved: " + carried.reason));
      }
      if (!started) level.peak.reason = "no solution at the start (" + carried.reason + ")";
    }
    if (started) level.peak = searchPeak(*system, X, hz, scale, dof, tolerance);
    if (level.peak.x.size() == 0 && system != lower) {
      const auto [f, start] = flankStart(*lower, *system, lowerPoints, hz, scale, tolerance);
      if (start.size() > 0) {
        level.startHz = f;
        level.peak = searchPeak(*system, start, f, scale, dof, tolerance, f - hz);
      } else {
        level.peak.reason += ", nor from the level below's solutions on its flank";
      }
    }
    if (level.peak.found) level.truncated = hbm::truncatedForce(*system, level.peak.x, 2 * M_PI * level.peak.parameter);
    level.seconds = timer.seconds();
    levels.push_back(level);
    if (!level.peak.found) break;
    if (target > 0 && levelsMeetTarget(levels, target) >= 0) break;
    X = level.peak.x, hz = level.peak.parameter;
    lowerPoints = level.peak.path;
    if (levels.size() == 1) lowerPoints.insert(lowerPoints.end(), curve.begin(), curve.end());
  }
  return levels;
}

// The response at the point itself with harmonics 0..H+1: Newton from its solution
// carried over, at the same parameter.
std::string pointHarmonicsCheck(ForcedResponseSetup& setup, const continuation::BranchPoint& pt, double peak) {
  const auto [w, scale] = setup.apply(pt.parameter);
  const auto& hb = *setup.system;
  const auto& H = hb.aft().harmonics();
  const int dof = setup.outputDofs.front(), next = H.maxHarmonic() + 1;
  std::ostringstream out;
  out << "harmonics check: H " << H.maxHarmonic() << " -> " << next;
  const hbm::HarmonicSet raised = withHarmonic(H, next);
  const auto refined = raisedSystem(hb, raised);
  const auto problem = continuationProblem(*refined, ForcedResponseSetup::Parameter::ForceScale, w);
  Eigen::VectorXd X = hbm::transferCoefficients(pt.x, hb.numDofs(), H, raised);
  const auto newton = continuation::solveNewton(problem, X, scale, toleranceAtScale(setup, scale));
  if (!newton.converged) {
    out << ": no solution at the peak (residual " << newton.residualNorm << ")";
    log::warn(out.str());
    return out.str();
  }
  const int nc = refined->numCoefficients();
  const double after = hbm::peakMagnitude(raised, Eigen::VectorXd(X.segment(dof * nc, nc)));
  const double change = std::abs(after / peak - 1);
  out << " changes the peak max|x| of DOF " << dof << " by " << change << " (relative)";
  if (change > 1e-2) log::warn(out.str() + ": the curve is not converged in the harmonics near its peak");
  return out.str();
}

// The harmonic truncation is checked by raising H: on a frequency curve the peaks
// with H, H + 1, ... (up to setup.harmonicsCheckTo) are compared, each found by the
// peak search (PeakSearch.hpp: fixed-frequency steps uphill, then golden section). A
// peak that moves in frequency changes the response at a fixed frequency far more
// than the peak itself, so the change at the traced point alone says little there.
// Other parameters (force, preload, ...), and a frequency curve whose largest point is
// no interior peak (it rises at the end of the range), compare the point with
// harmonics 0..H+1. Not possible when the system has nothing for a raised harmonic (a
// reduced model without that nodal diameter): said so.
}  // namespace

HarmonicsCheck checkHarmonics(ForcedResponseSetup& setup, const continuation::Branch& branch, std::size_t ip,
                              double peak) {
  const auto& pt = branch.points[ip];
  HarmonicsCheck check;
  check.dof = setup.outputDofs.front();
  auto& best = check.converged;
  try {
    if (setup.parameter != ForcedResponseSetup::Parameter::Omega) {
      check.text = pointHarmonicsCheck(setup, pt, peak);
      return check;
    }
    Timer timer;
    const auto [w, scale] = setup.apply(pt.parameter);
    const auto& hb = *setup.system;
    const int dof = setup.outputDofs.front();
    const int upTo = std::max(setup.harmonicsCheckTo, hb.aft().harmonics().maxHarmonic() + 1);
    // The traced points within 5 % of the peak: flank starts for the first raised level.
    SolvedPoints curve;
    for (const auto& p : branch.points) {
      const double f = setup.apply(p.parameter).first / (2 * M_PI);
      if (std::abs(f / (w / (2 * M_PI)) - 1) <= 0.05) curve.emplace_back(f, p.x);
    }
    setup.apply(pt.parameter);
    const auto levels = peakByHarmonics(hb, pt.x, w / (2 * M_PI), scale, dof, setup.continuation.tolerance, upTo,
                                        curve, setup.harmonicsTolerance);
    check.levels = levels;
    if (!levels.front().peak.found) {  // no interior peak with the curve's own harmonics
      check.text = pointHarmonicsCheck(setup, pt, peak) + " (no peak search: " + levels.front().peak.reason + ")";
      return check;
    }
    std::ostringstream out;
    out << "harmonics check: peak max|x| of DOF " << dof << " by harmonics:";
    out.precision(6);
    for (std::size_t i = 0; i < levels.size(); ++i) {
      const auto& l = levels[i];
      out << (i ? "; " : " ") << "H " << l.maxHarmonic << " ";
      if (l.peak.found) {
        out << l.peak.value << " at " << l.peak.parameter << " Hz";
        if (i > 0 && l.startHz != levels[i - 1].peak.parameter)
          out << " (searched from the flank at " << l.startHz << " Hz)";
      } else if (l.peak.x.size() == 0) {
        out << "not found (" << l.peak.reason << ")";
      } else {
        out << "not found (" << l.peak.reason << "; best point " << l.peak.value << " at " << l.peak.parameter
            << " Hz)";
      }
    }
    // The change between the last two levels whose peaks were both found.
    std::size_t j = levels.size() - 1;
    while (j >= 1 && !(levels[j].peak.found && levels[j - 1].peak.found)) --j;
    std::size_t reached = 0;
    for (; reached < levels.size() && levels[reached].peak.found; ++reached) {
      best.found = true;
      best.maxHarmonic = levels[reached].maxHarmonic, best.value = levels[reached].peak.value,
      best.hz = levels[reached].peak.parameter;
      best.x = levels[reached].peak.x, best.harmonics = levels[reached].harmonics, best.samples = levels[reached].samples;
      best.truncated = levels[reached].truncated;
    }
    if (best.found && reached < levels.size()) best.notFoundHarmonic = levels[reached].maxHarmonic;
    if (j >= 1) {
      const auto &before = levels[j - 1].peak, &after = levels[j].peak;
      const double change = std::abs(after.value / before.value - 1);
      if (levels[j].maxHarmonic == best.maxHarmonic) best.belowHarmonic = levels[j - 1].maxHarmonic, best.change = change;
      out << "; H " << levels[j - 1].maxHarmonic << " -> " << levels[j].maxHarmonic << " changes the peak by "
          << change << " (relative), its frequency by " << std::abs(after.parameter / before.parameter - 1) << "; "
          << timer.seconds() << " s";
      if (change > 1e-2) log::warn(out.str() + ": the curve is not converged in the harmonics near its peak");
      else log::info(out.str());
    } else {
      out << "; " << timer.seconds() << " s";
      log::warn(out.str() + ": the harmonic convergence of the peak is not known");
    }
    check.text = out.str();
  } catch (const std::exception& e) {
    check.text = std::string("harmonics check: not possible (") + e.what() + ")";
  }
  return check;
}

std::vector<HarmonicsLevel> peakByRaisedHarmonics(ForcedResponseSetup& setup, double value, const Eigen::VectorXd& x,
                                                  double omega, int upTo) {
  const double scale = setup.apply(value).second;
  return peakByHarmonics(*setup.system, x, omega / (2 * M_PI), scale, setup.outputDofs.front(),
                         setup.continuation.tolerance, upTo, SolvedPoints{}, 0);
}

void checkExcitationSize(const ForcedResponseSetup& setup) {
  if (setup.parameter == ForcedResponseSetup::Parameter::ForceScale) return;
  const double force = std::abs(setup.excitationScale) * setup.system->excitation().cwiseAbs().maxCoeff();
  if (!(force < kLargestTraceable))
    throw InputError("excitation", "its largest coefficient is " + numberText(force) + ", beyond " +
                                       numberText(kLargestTraceable) +
                                       ": the trace's products of it (an element's force of the response cubed, the "
                                       "squared norms) overflow double precision; scale the force down");
}

void checkResponseScale(const ForcedResponseSetup& setup, const Eigen::VectorXd& start) {
  if (setup.parameter == ForcedResponseSetup::Parameter::ForceScale || start.size() == 0) return;
  const double force = std::abs(setup.excitationScale) * setup.system->excitation().cwiseAbs().maxCoeff();
  if (force == 0)
    throw InputError("excitation", "is zero (every force's coefficients times the scale): the response is the same "
                                   "at every frequency, with no resonance to find; give a force");
  // The vibration's size: the oscillating coefficients (a static offset, a preload's
  // deformation, is no measure of it).
  const auto& H = setup.system->aft().harmonics();
  const int nc = setup.system->numCoefficients();
  double response = 0;
  for (Eigen::Index i = 0; i < start.size(); ++i)
    if (!(H.contains(0) && int(i % nc) == H.cosIndex(0))) response = std::max(response, std::abs(start(i)));
  if (response >= kSmallestTraceable) return;
  std::ostringstream why;
  why << "the response to it is " << response << " at the first point (largest coefficient), below "
      << kSmallestTraceable << ": too small to trace in double precision (its square underflows); the force's "
      << "largest coefficient is " << force << ", and a response is linear in a force that small: scale the force "
      << "up (by 1e150 gives the response times 1e150)";
  throw InputError("excitation", why.str());
}

namespace {
std::string secondsText(double seconds) {
  std::ostringstream text;
  text.precision(2);
  text << seconds << " s";
  return text.str();
}
}  // namespace

// Samples far above the need multiply every residual and Jacobian of the elements and buy
// nothing once the events of the element laws are placed: the excess and its cost, by the
// elements' Jacobian model above (issue 49: samples 65536 ran for a long time without a
// word).
void checkSamplesCost(int samples, int needed, const std::string& neededWhy, const hbm::HarmonicSet& harmonics,
                      const std::vector<int>& elementDimensions, const std::string& samplesKey) {
  if (needed <= 0 || samples < kSamplesExcessFactor * needed) return;
  const int nc = harmonics.numCoefficients();
  const double at = elementJacobianSeconds(samples, nc, elementDimensions),
               atNeeded = elementJacobianSeconds(needed, nc, elementDimensions);
  std::ostringstream text;
  text << samplesKey << ": " << samples << " time samples per period are " << samples / needed
       << " times the " << needed << " " << neededWhy
       << "; every residual and Jacobian of the elements costs in proportion to the samples: the elements' Jacobians "
       << "about " << secondsText(at) << " a Newton iteration against " << secondsText(atNeeded) << " with "
       << needed << " (an estimate, 2 N (d nc)^2 flops each at about 4.5 Gflop/s), and each curve point takes one "
       << "Newton iteration or more; the samples check solves the peak again with " << 2 * samples;
  if (at >= kSamplesSlowSeconds)
    log::warn(text.str() + ": fewer samples, or leave samples out for the default");
  else
    log::info(text.str());
}

// The harmonics check's top level, from the same estimates as checkSolverSize: said before
// the trace where the check goes beyond H + 1 (issue 49: harmonics_check_to 100 was
// accepted without a word), refused where the level would not fit in memory or one Newton
// iteration there would pass 10 minutes.
void checkHarmonicsCheckCost(const ForcedResponseSetup& setup) {
  if (setup.harmonicsCheckTo < 0 || setup.parameter != ForcedResponseSetup::Parameter::Omega ||
      setup.outputDofs.empty())
    return;
  const auto& hb = *setup.system;
  const auto& set = hb.aft().harmonics();
  const int top = std::max(setup.harmonicsCheckTo, set.maxHarmonic() + 1);
  if (top <= set.maxHarmonic() + 1) return;  // one raise: about the curve's own cost
  int levels = 0;
  for (int H = set.maxHarmonic(); H <= top; H = nextHarmonicLevel(H, top)) ++levels;
  const hbm::HarmonicSet raised = withHarmonicsUpTo(set, top);
  const int samples = raisedSamples(hb, raised);
  std::vector<int> dimensions;
  for (const auto& e : hb.elements()) dimensions.push_back(e.element->dimension());
  const auto e = estimateNewtonStep(hb.numDofs(), raised, samples, dimensions, hb.hasJacobianBlocks(),
                                    setup.continuation.linearSolver);
  std::ostringstream what;
  what.precision(3);
  what << "the harmonics check up to H = " << top
       << (setup.harmonicsTolerance > 0 ? " at most (harmonics: auto stops where the target is met)" : "") << " (" << levels
       << " levels from H = " << set.maxHarmonic() << ", each a peak search of Newton solves) has at its top "
       << raised.size() << " harmonics on " << hb.numDofs() << (hb.numDofs() == 1 ? " DOF, " : " DOFs, ") << long(e.unknowns) << " unknowns with "
       << samples << " samples";
  if (e.gigabytes > kMaxSolverGigabytes) {
    what << ": the " << (e.krylov ? "Jacobian's blocks and GMRES's basis" : "dense Jacobian and its factors")
         << " would take " << e.gigabytes << " GB (at most " << kMaxSolverGigabytes
         << " here); check to a lower harmonic";
    throw InputError(setup.harmonicsCheckKey, what.str());
  }
  std::ostringstream cost;
  cost << ": a Newton iteration there about " << secondsText(e.jacobianSeconds + e.solveSeconds)
       << " (an estimate: the elements' Jacobians " << secondsText(e.jacobianSeconds)
       << " by 2 N (d nc)^2 flops each at about 4.5 Gflop/s, ";
  if (e.krylov)
    cost << "Krylov's preconditioner " << secondsText(e.solveSeconds) << " by a dense " << 2 * hb.numDofs()
         << "-square LU per harmonic at about 10 Gflop/s)";
  else
    cost << "the dense LU " << secondsText(e.solveSeconds) << " by (n / 2349)^3 s, from 1 s at 2349 unknowns)";
  const double seconds = e.jacobianSeconds + e.solveSeconds;
  if (e.jacobianSeconds > 600 || (e.krylov && e.solveSeconds > 600)) {
    throw InputError(setup.harmonicsCheckKey, what.str() + cost.str() + "; check to a lower harmonic");
  }
  const std::string said = setup.harmonicsCheckKey + ": " + what.str() + cost.str();
  if (seconds > 2)
    log::warn(said + "; a lower harmonic to check to keeps each level's Newton solves shorter");
  else
    log::info(said);
}

}  // namespace cyclone::response
