#include "cyclone/response/ForcedResponse.hpp"

#include <algorithm>
#include <memory>
#include <sstream>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/BifurcationFlags.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/hbm/HillStability.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"
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
    if (!asked && hb.numUnknowns() > 1500) {
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
  if (!asked && 2 * hb.numUnknowns() > 1200) {
    note = "stability not computed: Hill's eigenproblem has " + std::to_string(2 * hb.numUnknowns()) +
           " unknowns per point (ask for stability to compute it anyway)";
    log::warn(note);
    return false;
  }
  note = "stability by Hill's method";
  return true;
}

// Hill's verdict per point. The receptance form's verdicts are checked with twice the
// AFT samples: a friction contact's Jacobian moves with where its stick-slip events fall
// on the sample grid, and near Re = 0 that can flip the sign of an exponent (the default
// disc: +-10 /s at 256..2048 samples on a lightly damped stretch). A point whose verdict
// changes is undetermined (2), not called either way.
void computeStability(const ForcedResponseSetup& setup, ForcedResponseResult& result) {
  const auto& hb = *setup.system;
  std::unique_ptr<hbm::HarmonicBalanceSystem> finer;
  if (hb.isReceptance()) finer = hbm::withHarmonics(hb, hb.aft().harmonics(), 2 * hb.aft().numSamples());
  result.stabilityRechecked = finer != nullptr;
  Timer timer;
  for (std::size_t i = 0; i < result.branch.points.size(); ++i) {
    const auto& pt = result.branch.points[i];
    const auto fl = hbm::hillStability(hb, pt.x, result.omega[i]);
    result.stable[i] = fl.stable ? 1 : 0;
    if (finer && hbm::hillStability(*finer, pt.x, result.omega[i]).stable != fl.stable) result.stable[i] = 2;
    if (fl.exponents.size() > 0) result.leadingExponent[i] = fl.exponents(0);
  }
  std::ostringstream msg;
  msg << "stability: " << result.branch.points.size() << " points by Hill's method in " << timer.seconds() << " s";
  log::info(msg.str());
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

// setup.harmonicsTolerance on a traced curve: the level the harmonics check stopped at
// when its last two raises met the tolerance, and the curve traced again, whole, with
// that level's harmonics (setup.system becomes it). Otherwise the curve stays, said.
ForcedResponseResult meetHarmonicsTarget(ForcedResponseSetup& setup, ForcedResponseResult traced) {
  HarmonicsTarget target;
  target.tolerance = setup.harmonicsTolerance;
  target.tracedHarmonic = setup.system->aft().harmonics().maxHarmonic();
  const auto& levels = traced.harmonicsCheck.levels;
  std::ostringstream text;
  text.precision(3);
  const double change = levelsMeetTarget(levels, target.tolerance);
  if (change < 0) {
    text << "harmonics by error target " << 100 * target.tolerance << " %: not met";
    if (levels.empty()) text << " (no peak search: " << traced.harmonicsCheck.text << ")";
    else if (!levels.back().peak.found) text << ": H = " << levels.back().maxHarmonic << " not found";
    else text << " by H = " << levels.back().maxHarmonic << " (the largest tried)";
    text << "; the curve stays the one traced with H = " << target.tracedHarmonic << ", its peak an estimate";
    target.text = text.str();
    log::warn(target.text);
    traced.harmonicsTarget = target;
    return traced;
  }
  const auto& reached = levels.back();
  target.reached = reached.maxHarmonic;
  target.change = change;
  Timer timer;
  setup.system = hbm::withHarmonics(*setup.system, hbm::HarmonicSet(reached.harmonics), reached.samples);
  const double tolerance = setup.harmonicsTolerance;
  const int checkTo = setup.harmonicsCheckTo;
  setup.harmonicsTolerance = 0, setup.harmonicsCheckTo = -1;  // the levels are known: no second check
  std::ostringstream met;
  met << "harmonics by error target: the peak met " << 100 * tolerance << " % at H = " << target.reached
      << "; the curve traced again with it";
  log::info(met.str());
  ForcedResponseResult result = solveForcedResponse(setup);
  setup.harmonicsTolerance = tolerance, setup.harmonicsCheckTo = checkTo;
  target.retraced = true;
  target.retraceSeconds = timer.seconds();
  result.harmonicsCheck = traced.harmonicsCheck;
  text << "harmonics by error target " << 100 * target.tolerance << " %: met at H = " << target.reached
       << " (the last two raises changed the peak by at most " << 100 * change << " %); the curve traced whole with "
       << "H = " << target.reached << " (" << result.branch.points.size() << " points, " << target.retraceSeconds
       << " s), its largest point ";
  text.precision(7);
  text << result.peak << " against the peak search's " << reached.peak.value;
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
  const StartingPoint start = findStartingPoint(setup);
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
    if (setup.harmonicsCheckTo >= 0)
      result.harmonicsCheck = checkHarmonics(setup, result.branch, result.peakIndex, result.peak);
  }
  result.seconds = timer.seconds();
  if (setup.harmonicsTolerance > 0 && setup.parameter == ForcedResponseSetup::Parameter::Omega &&
      setup.harmonicsCheckTo >= 0 && n > 0 && !setup.outputDofs.empty())
    return meetHarmonicsTarget(setup, std::move(result));
  return result;
}

}  // namespace cyclone::response
