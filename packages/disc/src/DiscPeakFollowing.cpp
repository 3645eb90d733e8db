#include "cyclone/disc/DiscPeakFollowing.hpp"

#include "cyclone/disc/ShroudContactLaw.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/continuation/PeakContinuation.hpp"
#include "cyclone/hbm/TruncatedForce.hpp"
#include "cyclone/rom/HybridFrfModel.hpp"

namespace cyclone::disc {

namespace {

// The grid: n values evenly in log over the range (evenly for a parameter that may be zero
// or negative: the clearance, whose negative values are interferences), with the
// reference value and the extra values inside it, sorted, without repeats.
std::vector<double> followedValues(double from, double to, int n, double reference, const std::vector<double>& extra,
                                   bool linear) {
  std::vector<double> v;
  if (linear)
    for (int i = 0; i < n; ++i) v.push_back(from + (to - from) * double(i) / double(n - 1));
  else
    v = continuation::logarithmicValues(from, to, n);
  v.push_back(reference);
  for (double x : extra)
    if (x >= from && x <= to) v.push_back(x);
  std::sort(v.begin(), v.end());
  const double span = std::abs(to - from);
  v.erase(std::unique(v.begin(), v.end(),
                      [linear, span](double a, double b) {
                        return std::abs(a - b) <= 1e-12 * (linear ? span : std::abs(b));
                      }),
          v.end());
  return v;
}

// From the reference value down and up the grid, joined in parameter order; the
// optimum by the result's merit over the whole.
void followBothWays(const continuation::PeakTrackingProblem& problem,
                    const std::vector<continuation::PeakStart>& starts, continuation::PeakFollowingOptions o,
                    DiscPeakFollowing& out) {
  Timer timer;
  continuation::FollowedPeakCurve& whole = out.curve;
  std::vector<double> up, down;
  for (double v : out.grid) (v >= out.referenceValue ? up : down).push_back(v);
  std::reverse(down.begin(), down.end());
  if (up.front() != out.referenceValue) up.insert(up.begin(), out.referenceValue);
  down.insert(down.begin(), out.referenceValue);
  for (const auto* part : {&down, &up}) {
    if (part->size() < 2) continue;
    o.parameters = *part;
    const auto c = continuation::followPeaks(problem, starts, o);
    whole.sweeps += c.sweeps, whole.searches += c.searches, whole.solves += c.solves;
    if (!c.complete) {
      whole.stopReason += (whole.stopReason.empty() ? "" : "; ") + c.stopReason;
      if (whole.end == continuation::PeakFollowingEnd::Running) whole.end = c.end, whole.branchEnd = c.branchEnd;
    }
    auto points = c.points;
    if (part == &down) std::reverse(points.begin(), points.end());
    if (part == &up && !whole.points.empty()) points.erase(points.begin());  // the reference, already there
    whole.points.insert(whole.points.end(), points.begin(), points.end());
    if (c.optimumLocated) whole.optimumLocated = true;
  }
  whole.seconds = timer.seconds();
  whole.complete = whole.stopReason.empty();
  if (whole.complete) whole.end = continuation::PeakFollowingEnd::RangeEnd;
  for (std::size_t i = 0; i < whole.points.size(); ++i)
    if (whole.optimum < 0 || out.merit(whole.points[i]) < out.merit(whole.points[std::size_t(whole.optimum)]))
      whole.optimum = int(i);
}

// The peak continued by LOCA from the reference value down to the range's start and up to
// its end, joined in parameter order; the optimum by the result's merit over the whole
// (located by continuePeak where it is the smallest peak inside a run).
void continueBothWays(const continuation::PeakTrackingProblem& problem, const continuation::PeakStart& start,
                      const DiscPeakFollowingSpec& following, bool linear, double tolerance, DiscPeakFollowing& out) {
  Timer timer;
  continuation::FollowedPeakCurve& whole = out.curve;
  continuation::PeakContinuationOptions c;
  c.logarithmic = !linear;
  c.phaseStep = following.phaseStep;
  c.tolerance = tolerance;
  c.locateOptimum = !out.byForce;  // over the force the merit is the peak per unit force
  // Steps of at most a twelfth of the whole range, not of each run's part: a part of a
  // tenth of the range (400..500 N of 400..4000) took 13 steps of its own twelfth.
  c.maxStep = linear ? std::abs(following.to - following.from) / 12
                     : std::abs(std::log(following.to) - std::log(following.from)) / 12;
  c.initialStep = c.maxStep / 2;
  bool located = false;
  double locatedAt = 0;
  for (const double end : {following.from, following.to}) {
    if (end == out.referenceValue) continue;
    c.from = out.referenceValue, c.to = end;
    const auto run = continuation::continuePeak(problem, start.x, start.frequency, c);
    whole.searches += run.searches, whole.solves += run.solves;
    if (!run.complete) {
      whole.stopReason += (whole.stopReason.empty() ? "" : "; ") + run.stopReason;
      if (whole.end == continuation::PeakFollowingEnd::Running) whole.end = run.end, whole.branchEnd = run.branchEnd;
    }
    if (run.optimumLocated && run.optimum >= 0)
      located = true, locatedAt = run.points[std::size_t(run.optimum)].parameter;
    auto points = run.points;
    if (end < out.referenceValue)
      std::reverse(points.begin(), points.end());
    else if (!whole.points.empty() && !points.empty())
      points.erase(points.begin());  // the reference value's peak, already there
    whole.points.insert(whole.points.end(), points.begin(), points.end());
  }
  whole.seconds = timer.seconds();
  whole.complete = whole.stopReason.empty() && !whole.points.empty();
  if (whole.complete) whole.end = continuation::PeakFollowingEnd::RangeEnd;
  else if (whole.end == continuation::PeakFollowingEnd::Running) whole.end = continuation::PeakFollowingEnd::NoPeakAtStart;
  for (std::size_t i = 0; i < whole.points.size(); ++i)
    if (whole.optimum < 0 || out.merit(whole.points[i]) < out.merit(whole.points[std::size_t(whole.optimum)]))
      whole.optimum = int(i);
  whole.optimumLocated =
      located && whole.optimum >= 0 && whole.points[std::size_t(whole.optimum)].parameter == locatedAt;
  out.grid.clear();
  for (const auto& p : whole.points) out.grid.push_back(p.parameter);
}

// The models' loss factor (one for all diameters, as the scene builds them).
// What the harmonics leave out at every followed peak (one AFT each), and the optimum's
// peak found again with `raises` harmonics more: how far the study's H is from converged
// where it matters most.
void harmonicsAtThePeaks(response::ForcedResponseSetup& setup, int raises, DiscPeakFollowing& out) {
  const auto& points = out.curve.points;
  out.forceBeyond.assign(points.size(), -1.0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    setup.apply(points[i].parameter);
    const auto t = hbm::truncatedForce(*setup.system, points[i].x, points[i].frequency);
    if (t.known) out.forceBeyond[i] = t.share;
  }
  if (raises <= 0 || out.curve.optimum < 0) return;
  const auto& o = points[std::size_t(out.curve.optimum)];
  const int H = setup.system->aft().harmonics().maxHarmonic();
  auto& check = out.optimumCheck;
  try {
    check.levels = response::peakByRaisedHarmonics(setup, o.parameter, o.x, o.frequency, H + raises);
  } catch (const std::exception& e) {  // e.g. no reduced model for a raised harmonic's nodal diameter
    out.warnings.push_back(std::string("the optimum's harmonics check was not possible (") + e.what() + ")");
    log::warn("peak following: " + out.warnings.back());
    return;
  }
  const bool all = int(check.levels.size()) == raises + 1 && check.levels.back().peak.found;
  check.change = all ? 0.0 : -1.0;
  for (std::size_t l = 1; all && l < check.levels.size(); ++l)
    check.change =
        std::max(check.change, std::abs(check.levels[l].peak.value / check.levels[l - 1].peak.value - 1));
}

double modelsLossFactor(const DiscReducedModels& models) {
  double eta = -1;
  for (const auto& [k, m] : models.models) {
    const auto* h = dynamic_cast<const rom::HybridFrfModel*>(m.get());
    if (!h) throw InputError("peak following/loss_factor", "needs hybrid or truncation models (their loss factor)");
    if (eta >= 0 && h->lossFactor() != eta)
      throw InputError("peak following/loss_factor", "the nodal diameters' models have different loss factors");
    eta = h->lossFactor();
  }
  return eta;
}

}  // namespace

double discReferenceValue(const DiscResponseSpec& spec, DiscStudyParameter parameter) {
  switch (parameter) {
    case DiscStudyParameter::Preload: return spec.contact.preload;
    case DiscStudyParameter::FrictionCoefficient: return spec.contact.mu;
    case DiscStudyParameter::ContactStiffness:
      // Followed as the value-list study varies it: kn = kt = the value.
      if (spec.contact.kn != spec.contact.kt)
        throw InputError("peak following/contact_stiffness",
                         "varies kn and kt together from one value: the scene's kn and kt must be equal");
      return spec.contact.kt;
    case DiscStudyParameter::Force: return 1.0;
    case DiscStudyParameter::Clearance:
      if (spec.gap.pairs.empty())
        throw InputError("peak following/clearance", "needs gap elements (disc_response/gap/pairs)");
      return spec.gap.clearance;
    case DiscStudyParameter::LossFactor:
      throw InputError("peak following/loss_factor", "its reference value is the reduced models' (followDiscPeak)");
    case DiscStudyParameter::Speed:
      throw InputError("peak following/speed", "its reference value is the reduced models' (followDiscPeak)");
    default:
      throw InputError("peak following", "follows the preload, mu, contact_stiffness, force, loss_factor, clearance or speed, not " +
                                             discStudyParameterName(parameter));
  }
}

DiscPeakFollowing followDiscPeak(const mesh::Mesh& mesh, const DiscReducedModels& models, const DiscResponseSpec& spec,
                                 const response::ForcedResponseSetup& reference,
                                 const response::ForcedResponseResult& referenceCurve, double bandFromHz,
                                 double bandToHz, const DiscPeakFollowingSpec& following) {
  const std::string name = discStudyParameterName(following.parameter);
  DiscPeakFollowing out;
  const bool byLossFactor = following.parameter == DiscStudyParameter::LossFactor;
  const bool bySpeed = following.parameter == DiscStudyParameter::Speed;
  out.referenceValue = byLossFactor ? modelsLossFactor(models)
                       : bySpeed    ? models.rpm
                                    : discReferenceValue(spec, following.parameter);
  const bool byClearance = following.parameter == DiscStudyParameter::Clearance;
  if (byClearance ? !(std::isfinite(following.from) && std::isfinite(following.to) && following.to > following.from)
      : bySpeed   ? !(following.from >= 0 && std::isfinite(following.to) && following.to > following.from)
                  : !(following.from > 0 && following.to > following.from))
    throw InputError("peak following/" + name, byClearance ? "needs a range from < to (mm; negative: interference)"
                                               : bySpeed   ? "needs a range 0 <= from < to (rpm)"
                                                           : "needs a range 0 < from < to");
  if (bySpeed && !following.modelsAtSpeed)
    throw InputError("peak following/speed", "needs the models at each speed (DiscPeakFollowingSpec::modelsAtSpeed)");
  if (!(out.referenceValue >= following.from && out.referenceValue <= following.to))
    throw InputError("peak following/" + name, "the range must contain the scene's value " +
                                                   std::to_string(out.referenceValue));
  if (following.values < 3 || following.values > 400)
    throw InputError("peak following/" + name, "values must lie in 3..400");
  const bool byContinuation = following.method == DiscPeakFollowingSpec::Method::Continuation;
  out.continued = byContinuation;
  if (byContinuation && (byLossFactor || bySpeed))
    throw InputError("peak following/" + name + "/method",
                     "continuation follows the contact parameters, the clearance and the force, not the " + name +
                         " (its system is rebuilt per value: use the peak search)");
  if (byContinuation && !(following.phaseStep > 0 && following.phaseStep < 0.5))
    throw InputError("peak following/" + name + "/phase_step", "must lie in (0, 0.5) rad");
  if (referenceCurve.branch.points.empty())
    throw SolverError("peak following/" + name + ": the reference curve has no point to start from");
  // An incomplete reference (a stretch left untraced) may have no true peak among its
  // points: its largest local maximum can be where the traced part turned back, and the
  // following then starts from that point, not from the resonance. Said, not hidden.
  if (!referenceCurve.branch.finished)
    out.warnings.push_back("the reference curve is incomplete (" + referenceCurve.branch.stopReason +
                           "), so the peak followed may not be its resonance");
  for (const auto& w : out.warnings) log::warn("peak following over the " + name + ": " + w);

  out.setup = makeDiscForcedResponse(mesh, models, spec);
  auto& setup = out.setup;
  setup.outputDofs = reference.outputDofs;
  out.byForce = following.parameter == DiscStudyParameter::Force;
  if (out.byForce) {
    setup.parameter = response::ForcedResponseSetup::Parameter::ForceScale;
  } else if (byLossFactor) {
    // The damping lives in the reduced models' receptance: the system is made again from
    // the models at each value (the condensed disc at H = 1: well under the peak search's
    // cost per value).
    setup.parameter = response::ForcedResponseSetup::Parameter::Rebuilt;
    setup.rebuiltParameter = name;
    setup.rebuiltAt = out.referenceValue;
    setup.rebuild = [&mesh, &models, spec](double eta) {
      if (!(eta >= 0)) throw InputError("peak following/loss_factor", "must be >= 0");
      return makeDiscForcedResponse(mesh, variedModels(models, eta, 0), spec).system;
    };
  } else if (bySpeed) {
    // The prestress, the modes and so the reduced models change with the speed: built
    // again at each value of the grid (no interpolation between speeds, so no
    // interpolation error), each speed's once (the searches come back to a value).
    setup.parameter = response::ForcedResponseSetup::Parameter::Rebuilt;
    setup.rebuiltParameter = name;
    setup.rebuiltAt = out.referenceValue;
    auto built = std::make_shared<std::map<double, std::shared_ptr<const DiscReducedModels>>>();
    (*built)[out.referenceValue] = std::make_shared<const DiscReducedModels>(models);
    setup.rebuild = [&mesh, spec, built, modelsAtSpeed = following.modelsAtSpeed](double rpm) {
      if (!(rpm >= 0)) throw InputError("peak following/speed", "must be >= 0");
      auto& m = (*built)[rpm];
      if (!m) {
        log::info("peak following over the speed: the reduced models at " + std::to_string(rpm) + " rpm");
        m = std::make_shared<const DiscReducedModels>(modelsAtSpeed(rpm));
      }
      return makeDiscForcedResponse(mesh, *m, spec).system;
    };
  } else if (byClearance) {
    response::selectElementParameter(setup, "gap", "gap", out.referenceValue);  // the unilateral spring's gap
  } else {
    const bool stiffness = following.parameter == DiscStudyParameter::ContactStiffness;
    // A law per unit area: each contact's preload is its share of the total, its stiffness
    // the value per area times its area; a patch per pair holds its pairs' sum.
    std::vector<double> weights;
    if ((spec.contact.law == ShroudContactSpec::Law::PerArea || spec.contact.patches > 0) &&
        following.parameter != DiscStudyParameter::FrictionCoefficient) {
      const auto values = shroudContactValues(
          mesh, shroudContactPairs(mesh, models.sectors, models.sector.axis, spec.contact), spec.contact);
      std::vector<bool> gap(values.kn.size(), false);
      for (int i : spec.gap.pairs) gap[std::size_t(i)] = true;
      for (std::size_t i = 0; i < gap.size(); ++i)
        if (!gap[i]) weights.push_back(stiffness ? values.stiffnessFactor[i] : values.preloadFactor[i]);
    }
    response::selectElementParameter(setup, "contact", stiffness ? "stiffness" : name, out.referenceValue, weights);
  }
  const auto problem = response::peakFollowingProblem(setup);
  // Every peak of the reference curve that stands out (5 %), so one that overtakes the
  // largest is seen; its frequencies from the curve's parameter (omega / omegaUnit).
  auto starts = continuation::prominentPeaks(referenceCurve.branch, problem.measure);
  if (starts.empty()) throw SolverError("peak following/" + name + ": the reference curve has no peak");
  for (auto& st : starts) st.frequency *= reference.omegaUnit;
  out.startingPeaks = starts.size();
  const double w0 = starts.front().frequency;
  continuation::PeakFollowingOptions o;
  o.search.step = 5e-4 * w0, o.search.maxStep = 5e-3 * w0, o.search.window = 0.15 * w0;
  o.search.parameterTolerance = 1e-7 * w0, o.search.tolerance = reference.continuation.tolerance;
  o.bandFrom = 2 * M_PI * bandFromHz, o.bandTo = 2 * M_PI * bandToHz;
  o.sweep = reference.continuation;
  o.sweep.checkpoints = nullptr;
  o.knownPeaks = following.knownPeaks;
  // Over the force the grid's optimum; over the loss factor the peak falls as the damping
  // grows, so the optimum is the range's end, not located.
  o.locateOptimum = !out.byForce && !byLossFactor && !bySpeed;
  out.grid = followedValues(following.from, following.to, following.values, out.referenceValue, following.extraValues,
                            byClearance || bySpeed);
  if (byContinuation)
    log::info("peak following over the " + name + ": the largest peak of the reference curve (" +
              std::to_string(w0 / (2 * M_PI)) + " Hz) continued by LOCA to both ends of the range");
  else
    log::info("peak following over the " + name + ": " + std::to_string(out.grid.size()) + " values, from the reference "
              "curve's " + std::to_string(starts.size()) + " peak(s), the largest at " + std::to_string(w0 / (2 * M_PI)) +
              " Hz");
  if (byContinuation)
    continueBothWays(problem, starts.front(), following, byClearance, reference.continuation.tolerance, out);
  else
    followBothWays(problem, starts, o, out);
  if (bySpeed) out.curve.optimum = -1;
  harmonicsAtThePeaks(setup, following.optimumRaises, out);
  setup.rebuild = nullptr;  // it refers to the caller's mesh and models; the system stays at the last value
  if (out.curve.points.empty()) throw SolverError("peak following/" + name + ": " + out.curve.stopReason);
  return out;
}

bool DiscPeakFollowing::optimumAtRangeEnd() const {
  if (curve.optimum < 0 || grid.empty()) return false;
  const double best = curve.points[std::size_t(curve.optimum)].parameter;
  return best == grid.front() || best == grid.back();
}

PeakAgreement DiscPeakFollowing::agreementWith(const std::vector<continuation::KnownPeak>& curvePeaks) const {
  PeakAgreement agreement;
  for (const auto& known : curvePeaks)
    for (const auto& p : curve.points)
      if (std::abs(p.parameter - known.parameter) <= 1e-12 * std::max(std::abs(known.parameter), 1e-6) &&
          known.peak.measure > 0) {
        agreement.largestRelativeDifference =
            std::max(agreement.largestRelativeDifference, std::abs(p.measure / known.peak.measure - 1));
        ++agreement.compared;
      }
  return agreement;
}

}  // namespace cyclone::disc
