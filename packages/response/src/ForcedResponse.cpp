#include "cyclone/response/ForcedResponse.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/NumberText.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/continuation/PeakFollowing.hpp"
#include "cyclone/hbm/BifurcationFlags.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/hbm/HillStability.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"
#include "cyclone/response/ForcedResponseChecks.hpp"
#include "cyclone/response/ForcedResponseTrace.hpp"

namespace cyclone::response {

namespace {

using Stability = ForcedResponseSetup::Stability;

void logProblem(const ForcedResponseSetup& setup) {
  const auto& hb = *setup.system;
  const auto& opt = setup.continuation;
  const auto& harmonics = hb.aft().harmonics();
  const bool byOmega = setup.parameter == ForcedResponseSetup::Parameter::Omega;
  std::ostringstream msg;
  msg << "forced response: " << hb.numDofs() << " DOFs, harmonics up to " << harmonics.maxHarmonic() << ", "
      << hb.aft().numSamples() << " samples, " << setup.parameterName() << " "
      << (byOmega ? opt.from * setup.omegaUnit : opt.from) << " -> " << (byOmega ? opt.to * setup.omegaUnit : opt.to);
  if (!byOmega) msg << " at omega " << setup.omega;
  if (hb.isCyclic()) {
    msg << "; cyclic: " << hb.cyclic().sectors << " sectors, engine order " << hb.cyclic().engineOrder
        << ", harmonic -> nodal diameter:";
    for (int h : harmonics.harmonics()) msg << " " << h << "->" << hb.nodalDiameter(h);
  }
  log::info(msg.str());
}

// The inertia forces against the stiffness and damping forces at the curve's highest
// frequency: max|M| w^2 / max(max|K|, w max|C|), on a matrix system (inf otherwise).
// Far below rounding, Hill's method inverts a mass that carries nothing, and its
// exponents are rounding magnified (M = 1e-300 on the Duffing DOF: Re mu = +2e284, 4
// points flagged unstable, exit 0; issue 49 probe).
constexpr double kNegligibleInertia = 1e-12;
double inertiaRatio(const ForcedResponseSetup& setup) {
  const auto& hb = *setup.system;
  if (hb.isReceptance()) return HUGE_VAL;
  const auto& o = setup.continuation;
  const double w = setup.parameter == ForcedResponseSetup::Parameter::Omega
                       ? setup.omegaUnit * std::max(std::abs(o.from), std::abs(o.to))
                       : setup.omega;
  const double inertia = hb.M().cwiseAbs().maxCoeff() * w * w;
  const double other = std::max(hb.K().cwiseAbs().maxCoeff(), w * hb.C().cwiseAbs().maxCoeff());
  return other > 0 ? inertia / other : HUGE_VAL;
}
std::string negligibleInertiaText(double ratio) {
  return "the mass matrix's inertia forces are " + numberText(ratio, 3) +
         " of the stiffness and damping forces at the curve's highest frequency: Hill's method inverts the mass "
         "matrix, and its exponents would be rounding";
}

// Whether Hill's method runs on this curve, and why (not). It needs velocity-free
// elements; on a receptance system the reduced models' modal realizations (the full FE
// compliance has none); and, unless asked for, a size where it is cheap: its dense
// eigenproblem of 2 n nc takes about a second per point at 1200, the receptance form an
// LU of n nc per point.
bool stabilityApplies(const ForcedResponseSetup& setup, std::string& note) {
  const auto& hb = *setup.system;
  if (setup.stability == Stability::Never) {
    note = "stability not asked for";
    return false;
  }
  for (const auto& c : hb.elements())
    if (c.element->usesVelocity()) {
      note = "stability not computed: Hill's method with velocity-dependent elements is not supported yet";
      log::warn(note);
      return false;
    }
  const bool asked = setup.stability == Stability::Always;
  if (hb.isReceptance()) {
    int modes = 0;
    for (int h : hb.aft().harmonics().harmonics()) {
      const auto r = hb.receptance()->modalRealization(hb.phaseIndex(h));
      if (!r) {
        const std::string why = "the model of nodal diameter " + std::to_string(hb.nodalDiameter(h)) +
                                " has no modal form (Hill's method needs one)";
        if (asked) throw InputError("stability", why);
        note = "stability not computed: " + why + "; folds are still flagged from the curve's path";
        log::info(note);
        return false;
      }
      modes += (h == 0 ? 1 : 2) * r->numModes();
    }
    if (!asked && hb.numUnknowns() > 4000) {
      note = "stability not computed: Hill's method on the reduced model needs an LU of " +
             std::to_string(hb.numUnknowns()) + " per point (ask for stability to compute it anyway)";
      log::warn(note);
      return false;
    }
    note = "stability by Hill's method on the reduced model's modal realization (" + std::to_string(modes) +
           " modal coordinates over the harmonics)";
    log::info(note);
    return true;
  }
  if (!hbm::hillMassInvertible(hb)) {  // asked for, refused before the trace (solveForcedResponse)
    note = "stability not computed: the mass matrix is singular (Hill's method needs it invertible)";
    log::warn(note);
    return false;
  }
  if (const double r = inertiaRatio(setup); r < kNegligibleInertia) {  // likewise
    note = "stability not computed: " + negligibleInertiaText(r);
    log::warn(note);
    return false;
  }
  if (!asked && 2 * hb.numUnknowns() > 1200) {
    note = "stability not computed: Hill's eigenproblem has " + std::to_string(2 * hb.numUnknowns()) +
           " unknowns per point (ask for stability to compute it anyway)";
    log::warn(note);
    return false;
  }
  note = "stability by Hill's method";
  return true;
}

// Hill's method's cost a point, in seconds on one core of the machine the project is
// measured on, from its problem's size alone (docs/benchmarks.md, disc_hill_stability:
// a point of the default disc with 440 unknowns takes 0.30 s whole, 0.155 s for the
// eigenvalues nearest zero, which grow as the size to the power 2.55 up to 1720; a
// matrix system's whole problem about 1 s at 1200, as the cube of its size).
double hillSecondsPerPoint(const hbm::HillProblemSize& size, bool receptance) {
  const double n = size.unknowns;
  if (!receptance) return std::pow(n / 1200, 3);
  return size.whole ? 0.30 * std::pow(n / 440, 3) : 0.155 * std::pow(n / 440, 2.55);
}

// Hill's verdict per point. The receptance form's verdicts are checked with twice the
// AFT samples: a friction contact's Jacobian moves with where its stick-slip events fall
// on the sample grid, and near Re = 0 that can flip the sign of an exponent (the default
// disc: +-10 /s at 256..2048 samples on a lightly damped stretch). A point whose verdict
// changes is undetermined (2), not called either way.
// Unless asked for (Stability::Always), Hill's method is left out of a curve whose points
// it would take more than kEstimateUnder seconds for, estimated from the problem's size
// and the points' count: a curve's stability is part of the answer (which stretch of a
// fold is followed, where a periodic response gives way to another), worth a run a
// minute or two longer, not one it multiplies. The estimate, not a clock: the same
// input gives the same outputs however loaded the machine (with the first point timed,
// the demo's curves, 59.7 s against a limit of 60, lost their stability under load).
void computeStability(const ForcedResponseSetup& setup, ForcedResponseResult& result) {
  constexpr double kEstimateUnder = 120;
  const auto& hb = *setup.system;
  std::unique_ptr<hbm::HarmonicBalanceSystem> finer;
  if (hb.isReceptance()) finer = hbm::withHarmonics(hb, hb.aft().harmonics(), 2 * hb.aft().numSamples());
  result.stabilityRechecked = finer != nullptr;
  const std::size_t n = result.branch.points.size();
  const auto size = hbm::hillProblemSize(hb);
  const double estimate = double(n) * (finer ? 2 : 1) * hillSecondsPerPoint(size, hb.isReceptance());
  if (setup.stability == Stability::Auto && estimate > kEstimateUnder) {
    result.stabilityComputed = false;
    std::ostringstream why;
    why << "stability not computed: Hill's method would take about " << numberText(estimate, 2) << " s for the " << n
        << " points (" << size.unknowns << " unknowns a point" << (finer ? ", each checked with twice the samples" : "")
        << "), more than " << kEstimateUnder << " s (ask for stability to compute it anyway)";
    result.stabilityNote = why.str();
    log::warn(result.stabilityNote);
    return;
  }
  Timer timer;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& pt = result.branch.points[i];
    const auto fl = hbm::hillStability(hb, pt.x, result.omega[i]);
    result.stable[i] = fl.stable ? 1 : 0;
    if (finer && hbm::hillStability(*finer, pt.x, result.omega[i]).stable != fl.stable) result.stable[i] = 2;
    if (fl.exponents.size() > 0) result.leadingExponent[i] = fl.exponents(0);
  }
  std::ostringstream msg;
  msg << "stability: " << n << " points by Hill's method in " << timer.seconds() << " s (estimated "
      << numberText(estimate, 2) << " s)";
  log::info(msg.str());
}

// Whether Hill's method would refuse the system's mass matrix, known before the trace
// (HillStability.hpp). Velocity-dependent elements stop it first and are said after the
// trace (the curve is still of use).
bool massSingularForHill(const ForcedResponseSetup& setup) {
  const auto& hb = *setup.system;
  for (const auto& c : hb.elements())
    if (c.element->usesVelocity()) return false;
  return !hbm::hillMassInvertible(hb);
}

// Flags per segment: the last point of one sweep and the first of the next are no path.
// An undetermined point neither loses nor regains stability.
void flagPoints(ForcedResponseResult& result) {
  const auto bounds = segmentBounds(result.branch);
  for (std::size_t s = 0; s + 1 < bounds.size(); ++s) {
    std::vector<hbm::CurvePointStability> part;
    for (std::size_t i = bounds[s]; i < bounds[s + 1]; ++i) {
      hbm::CurvePointStability st;
      st.parameter = result.branch.points[i].parameter;
      st.omega = result.omega[i];
      st.stable = result.stable[i] == 2 ? -1 : result.stable[i];
      if (result.leadingExponent[i]) st.leading = *result.leadingExponent[i], st.hasLeading = true;
      part.push_back(st);
    }
    const auto f = hbm::bifurcationFlags(part);
    result.flags.insert(result.flags.end(), f.begin(), f.end());
    result.segment.insert(result.segment.end(), f.size(), int(s));
  }
}

}  // namespace

std::vector<std::size_t> segmentBounds(const continuation::Branch& branch) {
  std::vector<std::size_t> bounds{0};
  for (std::size_t s : branch.segmentStarts)
    if (s > bounds.back() && s < branch.points.size()) bounds.push_back(s);
  bounds.push_back(branch.points.size());
  return bounds;
}

int ForcedResponseResult::unstablePoints() const { return int(std::count(stable.begin(), stable.end(), 0)); }
int ForcedResponseResult::undeterminedPoints() const { return int(std::count(stable.begin(), stable.end(), 2)); }
std::map<std::string, int> ForcedResponseResult::flagCounts() const {
  std::map<std::string, int> counts;
  for (const auto& f : flags)
    if (!f.empty()) ++counts[f];
  return counts;
}

namespace {

// The curve's frequencies in Hz, per point.
std::vector<double> pointHz(const ForcedResponseResult& result) {
  std::vector<double> hz;
  for (double w : result.omega) hz.push_back(w / (2 * M_PI));
  return hz;
}

// The checks' index whose highest level found is largest (0 when none is found).
std::size_t largestConverged(const std::vector<HarmonicsCheck>& checks) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < checks.size(); ++i)
    if (checks[i].converged.found && (!checks[best].converged.found || checks[i].converged.value > checks[best].converged.value))
      best = i;
  return best;
}

// Makes the largest converged of `checks` the headline's (result.harmonicsCheck), the
// rest the other peaks'.
void chooseHeadline(std::vector<HarmonicsCheck> checks, ForcedResponseResult& result) {
  const std::size_t best = largestConverged(checks);
  result.harmonicsCheck = checks[best];
  result.otherPeakChecks.clear();
  for (std::size_t i = 0; i < checks.size(); ++i)
    if (i != best) result.otherPeakChecks.push_back(std::move(checks[i]));
}

// The harmonics check of the curve's largest point and, on a frequency curve whose
// largest point is an interior peak, of its other prominent peaks (continuation::
// prominentPeaks) at least half as high, not within 0.5 % in frequency of a peak checked
// or within 1 % of one in `followedHz` (already followed), at most 4 checks in all: two
// resonances of similar height need not keep their order as H grows.
std::vector<HarmonicsCheck> checkPeaks(ForcedResponseSetup& setup, const ForcedResponseResult& result,
                                       const std::vector<double>& followedHz = {}) {
  constexpr double kHeight = 0.5, kSamePeak = 5e-3, kFollowed = 1e-2;
  constexpr std::size_t kMostChecks = 4;
  const auto hz = pointHz(result);
  std::vector<double> checkedHz = followedHz;
  auto near = [&](double f) {
    for (std::size_t k = 0; k < checkedHz.size(); ++k)
      if (std::abs(f - checkedHz[k]) <= (k < followedHz.size() ? kFollowed : kSamePeak) * checkedHz[k]) return true;
    return false;
  };
  std::vector<HarmonicsCheck> checks;
  if (followedHz.empty()) {
    checks.push_back(checkHarmonics(setup, result.branch, result.peakIndex, result.peak));
    if (checks.front().levels.empty()) return checks;  // no interior peak, or not a frequency curve
    checkedHz.push_back(hz[result.peakIndex]);
  }
  const auto& hb = *setup.system;
  const int dof = setup.outputDofs.front(), nc = hb.numCoefficients();
  const auto& set = hb.aft().harmonics();
  const auto measure = [&](const Eigen::VectorXd& x) {
    return hbm::peakMagnitude(set, Eigen::VectorXd(x.segment(dof * nc, nc)));
  };
  for (const auto& peak : continuation::prominentPeaks(result.branch, measure)) {
    if (checks.size() + followedHz.size() >= kMostChecks) break;
    const double f = hz[peak.index];
    if (peak.measure < kHeight * result.peak || near(f)) continue;
    checkedHz.push_back(f);
    std::ostringstream msg;
    msg.precision(6);
    msg << "harmonics check: the curve's peak " << peak.measure << " at " << f << " Hz followed as well";
    log::info(msg.str());
    auto check = checkHarmonics(setup, result.branch, peak.index, peak.measure);
    if (!check.levels.empty()) checks.push_back(std::move(check));
  }
  return checks;
}

// Each followed peak's outcome against the target: levelsMeetTarget, -1 where not met.
std::vector<double> peakChanges(const ForcedResponseResult& r, double target) {
  std::vector<double> changes{levelsMeetTarget(r.harmonicsCheck.levels, target)};
  for (const auto& c : r.otherPeakChecks) changes.push_back(levelsMeetTarget(c.levels, target));
  return changes;
}

// Where a followed peak other than the headline's did not meet the target: said.
std::string othersNotMet(const ForcedResponseResult& r, double target) {
  std::ostringstream text;
  text.precision(6);
  for (const auto& c : r.otherPeakChecks) {
    if (levelsMeetTarget(c.levels, target) >= 0) continue;
    text << "; the peak near " << c.levels.front().peak.parameter << " Hz did not meet it";
    if (!c.levels.back().peak.found) text << " (H = " << c.levels.back().maxHarmonic << " not found)";
  }
  return text.str();
}

// The curve traced again, whole, with a level's harmonics and samples (setup.system
// becomes it; no second check: the levels are known), the traced curve's checks kept.
ForcedResponseResult retraceWith(ForcedResponseSetup& setup, const HarmonicsLevel& level, const ForcedResponseResult& traced) {
  setup.system = hbm::withHarmonics(*setup.system, hbm::HarmonicSet(level.harmonics), level.samples);
  const double tolerance = setup.harmonicsTolerance;
  const int checkTo = setup.harmonicsCheckTo;
  setup.harmonicsTolerance = 0, setup.harmonicsCheckTo = -1;
  ForcedResponseResult result = solveForcedResponse(setup);
  setup.harmonicsTolerance = tolerance, setup.harmonicsCheckTo = checkTo;
  result.harmonicsCheck = traced.harmonicsCheck;
  result.otherPeakChecks = traced.otherPeakChecks;
  return result;
}

// Not met: the curve traced again with the highest level whose peak was found, where that
// is above the curve's (the best estimate there is: the curve then shows the peak the
// headline gives, not the first trace's, which with few harmonics can be twice it where
// the shroud hammers), else the curve stays.
ForcedResponseResult notMet(ForcedResponseSetup& setup, ForcedResponseResult traced, HarmonicsTarget target,
                            std::ostringstream& text) {
  const HarmonicsLevel* best = nullptr;
  for (const auto& l : traced.harmonicsCheck.levels)
    if (l.peak.found && (!best || l.maxHarmonic > best->maxHarmonic)) best = &l;
  if (best && best->maxHarmonic > target.tracedHarmonic) {
    Timer timer;
    const HarmonicsLevel level = *best;
    log::info("harmonics by error target: not met; the curve traced again with H = " + std::to_string(level.maxHarmonic) +
              ", the highest whose peak was found");
    ForcedResponseResult result = retraceWith(setup, level, traced);
    target.retraced = true;
    target.retraceSeconds = timer.seconds();
    text << "; the curve traced whole with H = " << level.maxHarmonic << ", the highest whose peak was found ("
         << result.branch.points.size() << " points, " << target.retraceSeconds << " s), its peak an estimate";
    result.seconds += traced.seconds;
    target.text = text.str();
    log::warn(target.text);
    result.harmonicsTarget = target;
    return result;
  }
  text << "; the curve stays the one traced with H = " << target.tracedHarmonic << ", its peak an estimate";
  target.text = text.str();
  log::warn(target.text);
  traced.harmonicsTarget = target;
  return traced;
}

// setup.harmonicsTolerance on a traced curve: met when every followed peak's check
// stopped where its last two raises met the tolerance; the curve is then traced again,
// whole, with the highest of those levels (setup.system becomes it), and the peaks that
// curve shows and no check followed (an internal resonance that only the raised
// harmonics reach) are checked from there. Otherwise notMet.
ForcedResponseResult meetHarmonicsTarget(ForcedResponseSetup& setup, ForcedResponseResult traced) {
  HarmonicsTarget target;
  target.tolerance = setup.harmonicsTolerance;
  target.tracedHarmonic = setup.system->aft().harmonics().maxHarmonic();
  const auto& levels = traced.harmonicsCheck.levels;
  std::ostringstream text;
  text.precision(3);
  const auto changes = peakChanges(traced, target.tolerance);
  if (*std::min_element(changes.begin(), changes.end()) < 0) {
    text << "harmonics by error target " << 100 * target.tolerance << " %: not met";
    if (levels.empty()) text << " (no peak search: " << traced.harmonicsCheck.text << ")";
    else if (changes.front() >= 0) text << " by every peak";
    else if (!levels.back().peak.found) text << ": H = " << levels.back().maxHarmonic << " not found";
    else text << " by H = " << levels.back().maxHarmonic << " (the largest tried)";
    text << othersNotMet(traced, target.tolerance);
    return notMet(setup, std::move(traced), target, text);
  }
  // The highest level any peak needed.
  const HarmonicsLevel* reached = &levels.back();
  for (const auto& c : traced.otherPeakChecks)
    if (c.levels.back().maxHarmonic > reached->maxHarmonic) reached = &c.levels.back();
  target.reached = reached->maxHarmonic;
  target.change = *std::max_element(changes.begin(), changes.end());
  Timer timer;
  const double tolerance = setup.harmonicsTolerance;
  std::ostringstream met;
  met << "harmonics by error target: the peak" << (traced.otherPeakChecks.empty() ? "" : "s") << " met "
      << 100 * tolerance << " % at H = " << target.reached << "; the curve traced again with it";
  log::info(met.str());
  ForcedResponseResult result = retraceWith(setup, *reached, traced);
  target.retraced = true;
  target.retraceSeconds = timer.seconds();
  // Peaks of the retraced curve that no check followed, checked from its harmonics up.
  std::vector<double> followedHz{traced.harmonicsCheck.converged.hz};
  for (const auto& c : traced.otherPeakChecks) followedHz.push_back(c.converged.hz);
  if (!result.branch.points.empty() && !setup.outputDofs.empty()) {
    auto added = checkPeaks(setup, result, followedHz);
    if (!added.empty()) {
      added.push_back(result.harmonicsCheck);
      for (auto& c : result.otherPeakChecks) added.push_back(std::move(c));
      chooseHeadline(std::move(added), result);
    }
  }
  const auto after = peakChanges(result, tolerance);
  text << "harmonics by error target " << 100 * target.tolerance << " %: ";
  if (*std::min_element(after.begin(), after.end()) < 0) {
    // A peak the raised harmonics brought out did not meet the target.
    target.reached = -1, target.change = -1;
    text << "not met" << othersNotMet(result, tolerance) << "; the curve traced with H = "
         << result.harmonicsCheck.converged.maxHarmonic;
  } else {
    text << "met at H = " << target.reached << " (the last two raises changed "
         << (result.otherPeakChecks.empty() ? "the peak" : "each of the curve's " +
                                                                std::to_string(1 + result.otherPeakChecks.size()) + " peaks")
         << " by at most " << 100 * target.change << " %)";
  }
  text << "; the curve traced whole with H = " << reached->maxHarmonic << " (" << result.branch.points.size()
       << " points, " << target.retraceSeconds << " s), its largest point ";
  text.precision(7);
  text << result.peak << " against the peak search's " << result.harmonicsCheck.converged.value << " at "
       << result.harmonicsCheck.converged.hz << " Hz";
  target.text = text.str();
  log::info(target.text);
  result.harmonicsTarget = target;
  result.seconds += traced.seconds;
  return result;
}

}  // namespace

ForcedResponseResult solveForcedResponse(ForcedResponseSetup& setup) {
  Timer timer;
  logProblem(setup);
  // The trace forms the dense Jacobian for LOCA's engine and for a system rebuilt per
  // value (no operator): the memory check is the dense one there.
  const bool formsTheMatrix = setup.continuation.engine == continuation::ContinuationOptions::Engine::Loca ||
                              setup.parameter == ForcedResponseSetup::Parameter::Rebuilt;
  checkSolverSize(*setup.system, setup.harmonicsKey,
                  formsTheMatrix ? continuation::ContinuationOptions::LinearSolver::Dense : setup.continuation.linearSolver);
  checkHarmonicsCheckCost(setup);  // its top level's size and cost, before the trace
  // Stability asked for on a system whose mass matrix Hill's method cannot invert: refused
  // before the trace, not after it (issue 49).
  if (setup.stability == Stability::Always && massSingularForHill(setup))
    throw InputError("stability", "Hill's method needs an invertible mass matrix, and this system's is singular "
                                  "(its reciprocal condition number is below 1e-14): leave stability to auto or "
                                  "false, or give every DOF a mass");
  if (setup.stability == Stability::Always && inertiaRatio(setup) < kNegligibleInertia)
    throw InputError("stability", negligibleInertiaText(inertiaRatio(setup)) + ": leave stability to auto or false");
  checkExcitationSize(setup);
  const StartingPoint start = findStartingPoint(setup);
  checkResponseScale(setup, start.x);
  if (start.x.size() > 0) {
    std::ostringstream msg;
    msg << "forced response: first point by " << start.method << " (" << start.seconds << " s)";
    log::info(msg.str());
  }
  ForcedResponseResult result;
  result.branch = traceForcedResponse(setup, start);
  result.startMethod = start.method;
  const auto& hb = *setup.system;
  const std::size_t n = result.branch.points.size();
  const int nc = hb.numCoefficients();
  for (const auto& pt : result.branch.points) {
    result.omega.push_back(setup.apply(pt.parameter).first);
    const int dof = setup.outputDofs.empty() ? -1 : setup.outputDofs.front();
    result.measure.push_back(
        dof < 0 ? 0.0 : hbm::peakMagnitude(hb.aft().harmonics(), Eigen::VectorXd(pt.x.segment(dof * nc, nc))));
  }
  result.stable.assign(n, -1);
  result.leadingExponent.assign(n, std::nullopt);
  result.stabilityComputed = n > 0 && stabilityApplies(setup, result.stabilityNote);
  if (result.stabilityComputed) computeStability(setup, result);
  flagPoints(result);
  if (!result.branch.finished)
    log::warn("forced response incomplete: " + result.branch.stopReason);
  if (n > 0 && !setup.outputDofs.empty()) {
    result.peakIndex = std::max_element(result.measure.begin(), result.measure.end()) - result.measure.begin();
    const auto& pt = result.branch.points[result.peakIndex];
    result.peak = result.measure[result.peakIndex];
    result.peakParameter = pt.parameter;
    result.peakOmega = result.omega[result.peakIndex];
    result.samplesCheck = checkSamples(setup, pt, result.peak);
    if (setup.harmonicsCheckTo >= 0) chooseHeadline(checkPeaks(setup, result), result);
  }
  result.seconds = timer.seconds();
  if (setup.harmonicsTolerance > 0 && setup.parameter == ForcedResponseSetup::Parameter::Omega &&
      setup.harmonicsCheckTo >= 0 && n > 0 && !setup.outputDofs.empty())
    return meetHarmonicsTarget(setup, std::move(result));
  return result;
}

}  // namespace cyclone::response
