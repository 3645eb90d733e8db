#include "cyclone/disc/DiscForcedResponse.hpp"

#include <cmath>
#include <complex>
#include <sstream>
#include <tuple>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/NumberText.hpp"
#include "cyclone/hbm/FrictionContact.hpp"

namespace cyclone::disc {

namespace {

// Hill's verdict at the curve's largest point, where that is the headline's peak, and
// what it says, for the headline's line.
std::string peakStability(const response::ForcedResponseResult& curve, DiscHeadline& headline) {
  using PS = DiscHeadline::PeakStability;
  const std::size_t i = curve.peakIndex;
  if (!curve.stabilityComputed || i >= curve.stable.size()) return "";
  const double curveHz = curve.peakOmega / (2 * M_PI);
  if (!(std::abs(curveHz - headline.peak.hz) <= 1e-2 * headline.peak.hz)) return "";
  const auto& exponent = curve.leadingExponent[i];
  if (exponent) headline.leadingExponent = *exponent;
  std::ostringstream line;
  line.precision(3);
  switch (curve.stable[i]) {
    case 1:
      headline.stability = PS::Stable;
      return "; stable by Hill's method at the traced curve's top";
    case 2:
      headline.stability = PS::Undetermined;
      return "; its stability at the traced curve's top undetermined (Hill's verdict changes with twice the samples)";
    case 0:
      break;
    default:
      return "";
  }
  const bool complexPair = exponent && std::abs(exponent->imag()) > 1e-6 * curve.peakOmega;
  headline.stability = complexPair ? PS::UnstableComplex : PS::UnstableReal;
  line << "; unstable by Hill's method at the traced curve's top";
  if (complexPair)
    line << " (a complex pair of Floquet exponents, " << exponent->real() << " +- " << std::abs(exponent->imag())
         << "i /s: the disc does not settle on this periodic response there, its amplitude is modulated)";
  else if (exponent)
    line << " (a real Floquet exponent, " << exponent->real() << " /s: the response there jumps to another branch)";
  return line.str();
}

}  // namespace

const char* convergenceName(DiscHeadline::Convergence convergence) {
  switch (convergence) {
    case DiscHeadline::Convergence::NotFound: return "not found";
    case DiscHeadline::Convergence::Estimate: return "estimate";
    case DiscHeadline::Convergence::Converged: break;
  }
  return "converged";
}

DiscHeadline discHeadline(const response::ForcedResponseResult& curve) {
  constexpr double kConverged = 1e-2;
  DiscHeadline headline;
  const auto& best = curve.harmonicsCheck.converged;
  if (!best.found) return headline;
  headline.peak = best;
  using C = DiscHeadline::Convergence;
  headline.convergence =
      best.change >= 0 && best.change <= kConverged && best.notFoundHarmonic < 0 ? C::Converged : C::Estimate;
  const std::string stability = peakStability(curve, headline);
  std::ostringstream line;
  line.precision(6);
  line << "friction-damped peak: max|x(t)| " << best.value << " at " << best.hz << " Hz with harmonics 0.."
       << best.maxHarmonic;
  // What the harmonics leave out of the contact forces at that peak: where it is not small
  // the last change of the peak understates the truncation error (TruncatedForce.hpp).
  std::string dropped;
  if (best.truncated.known) {
    std::ostringstream d;
    d.precision(3);
    d << "; the contact forces' harmonics above " << best.maxHarmonic << " are " << 100 * best.truncated.share
      << " % of those kept (harmonic " << best.truncated.largestDropped << " alone "
      << 100 * best.truncated.largestDroppedShare << " %)";
    dropped = d.str();
  }
  const auto& target = curve.harmonicsTarget;
  if (target.tolerance > 0 && target.reached >= 0) {  // harmonics by an error target, met (two raises)
    headline.convergence = C::Converged;
    line << "; converged in the harmonics to " << 100 * target.tolerance << " % (each of the last two raises of H "
         << "changed it by at most " << 100 * target.change << " %; the curve traced whole with H = " << target.reached
         << ")" << dropped;
    headline.text = line.str() + stability;
    return headline;
  }
  if (target.tolerance > 0) {  // not met: an estimate whatever the last raise alone did
    headline.convergence = C::Estimate;
    line << "; an estimate: the error target " << 100 * target.tolerance
         << " % on the harmonics (harmonics: auto) was not met, each of the last two raises of H must change it "
            "by at most that";
    std::vector<const response::HarmonicsLevel*> found;
    for (const auto& level : curve.harmonicsCheck.levels)
      if (level.peak.found) found.push_back(&level);
    std::vector<std::string> raises;  // the last two raises found
    for (std::size_t i = found.size() >= 3 ? found.size() - 2 : 1; i < found.size(); ++i) {
      std::ostringstream r;
      r.precision(3);
      r << "H " << found[i - 1]->maxHarmonic << " -> " << found[i]->maxHarmonic << " changed it by "
        << 100 * std::abs(found[i]->peak.value / found[i - 1]->peak.value - 1) << " %";
      raises.push_back(r.str());
    }
    for (std::size_t i = 0; i < raises.size(); ++i) line << (i == 0 ? " (" : ", ") << raises[i];
    if (!raises.empty()) line << ")";
    if (best.notFoundHarmonic >= 0)
      line << "; H = " << best.notFoundHarmonic << " was tried and its peak not found";
    line << dropped;
    headline.text = line.str() + stability;
    return headline;
  }
  if (best.change < 0)
    line << "; an estimate: its convergence in the harmonics is not known (no level below it to compare)";
  else if (best.change <= kConverged)
    line << "; converged in the harmonics to " << 100 * kConverged << " % (H " << best.belowHarmonic << " -> "
         << best.maxHarmonic << " changed it by " << 100 * best.change << " %)";
  else
    line << "; an estimate, not converged in the harmonics: H " << best.belowHarmonic << " -> " << best.maxHarmonic
         << " changed it by " << 100 * best.change << " % (disc_frc_harmonics.csv)";
  // A level above that was tried and not found leaves the error unbounded by the last
  // change (the default disc at H = 5: docs/scenes.md).
  if (best.notFoundHarmonic >= 0)
    line << "; H = " << best.notFoundHarmonic << " was tried and its peak not found, so the error may exceed "
         << "the last change";
  line << dropped;
  headline.text = line.str() + stability;
  return headline;
}

response::ForcedResponseResult sweepDisc(response::ForcedResponseSetup& setup, double fromHz, double toHz,
                                         const DiscSweepOptions& options, std::vector<std::string>& warnings) {
  setup.omegaUnit = 2 * M_PI * fromHz;
  setup.stability = options.stability;
  setup.harmonicsKey = "disc_response/harmonics";
  setup.harmonicsCheckKey =
      options.harmonicsTolerance > 0 ? "disc_response/harmonics_max" : "disc_response/harmonics_check_to";
  setup.harmonicsCheckTo = options.harmonicsCheckTo;
  setup.harmonicsTolerance = options.harmonicsTolerance;
  setup.continuation = options.continuation;
  setup.continuation.from = 1.0, setup.continuation.to = toHz / fromHz;
  setup.fallback = options.fallback;
  auto result = response::solveForcedResponse(setup);
  if (!result.branch.points.empty()) {
    const double peakHz = result.peakOmega / (2 * M_PI), span = toHz - fromHz;
    if (peakHz < fromHz + 1e-3 * span || peakHz > toHz - 1e-3 * span) {
      std::ostringstream msg;
      msg << "the largest response is at the end of the sweep (" << peakHz << " Hz): the resonance lies outside "
          << fromHz << ".." << toHz << " Hz";
      log::warn(msg.str());
      warnings.push_back(msg.str());
    }
  }
  return result;
}

namespace {

// kn e^H A e for each friction contact, e its normal coordinate's column (with the next
// sector's at the phase of harmonic 1), and kt e^H A e over its tangential coordinates;
// the largest of each: {normal, tangential}.
std::pair<double, double> contactStiffnessRatios(const response::ForcedResponseSetup& setup, double hz) {
  const auto& hb = *setup.system;
  if (!hb.receptance() || !(hz > 0)) return {0, 0};
  const long phase = hb.phaseIndex(1);
  const Eigen::MatrixXcd A = hb.receptance()->compliance(2 * M_PI * hz, phase);
  const std::complex<double> next =
      std::polar(1.0, hb.isCyclic() ? 2 * M_PI * double(phase) / hb.cyclic().sectors : 0.0);
  double normal = 0, tangential = 0;
  for (const auto& c : hb.elements()) {
    const auto* contact = dynamic_cast<const hbm::FrictionContact*>(c.element.get());
    if (!contact) continue;
    const int n = contact->dimension() - 1;
    for (int j = 0; j <= n; ++j) {
      Eigen::VectorXcd e = c.W.col(j).cast<std::complex<double>>();
      if (c.Wnext.size() > 0) e += next * c.Wnext.col(j).cast<std::complex<double>>();
      const double compliance = std::abs(e.dot(A * e));
      if (j == n)
        normal = std::max(normal, contact->parameters().kn * compliance);
      else
        tangential = std::max(tangential, contact->parameters().kt * compliance);
    }
  }
  return {normal, tangential};
}

}  // namespace

void checkModesCoverRange(const DiscReducedModels& models, const DiscResponseSpec& spec, double toHz) {
  // The hybrid model is exact in statics and keeps each mode below its last: above the
  // highest mode kept, resonances are missing (one mode on the default disc put the stuck
  // resonance at 3079 Hz instead of 1577, and its model check, over the modes kept, passed).
  const int k = nodalDiametersFor(models.sectors, spec.engineOrder, {1}).front();
  const auto it = models.naturalHz.find(k);
  if (it == models.naturalHz.end() || it->second.empty()) return;  // full_fe: every mode
  const double highest = it->second.back();
  if (highest >= toHz) return;
  std::ostringstream why;
  why << "the reduced model of nodal diameter " << k << " keeps natural frequencies up to " << highest
      << " Hz, below the curve's range, which reaches " << toHz
      << " Hz: the modes above are missing from the response there (keep more modes, or narrow "
         "disc_response/frequency_range_hz)";
  throw InputError("reduced_model/modes", why.str());
}

DiscForcedResponse solveDiscForcedResponse(const mesh::Mesh& mesh, const DiscReducedModels& models,
                                           const DiscResponseSpec& spec, const DiscSweepOptions& options) {
  const bool rangeGiven = options.fromHz > 0 || options.toHz > 0;
  if (rangeGiven && !(options.fromHz > 0 && options.toHz > options.fromHz))
    throw InputError("disc_response/frequency_range_hz", "needs two increasing positive frequencies [from, to] in Hz");
  DiscForcedResponse out;
  out.setup = makeDiscForcedResponse(mesh, models, spec);
  // The estimate sets the range unless one is given; then it only informs, and a failed
  // estimate (no stuck peak on its scan) is reported, not fatal.
  try {
    std::ostringstream text;
    // The curve's own system where it has a preload (a second one only to close the
    // contacts of one without).
    out.estimate = spec.contact.preload > 0 ? estimateResonance(out.setup, models, options.family)
                                            : estimateDiscResonance(mesh, models, spec, options.family);
    text << "family " << options.family << " at " << out.estimate->freeHz << " Hz with the shroud free, "
         << out.estimate->stuckHz << " Hz with the contacts stuck"
         << (spec.contact.preload > 0 ? "" : " (closed: no preload holds them so at rest)");
    if (spec.contact.patches > 0 && !models.retainedMeans.empty()) {
      // Every node pair as a contact needs the face nodes retained: models that retain the
      // patches' means have none.
      text << "; " << spec.contact.patches << " contact patches on the models' retained mean motions (patches "
           << "against every node pair not compared: that needs the face nodes retained)";
    } else if (spec.contact.patches > 0) {
      // The same stuck system with every node pair a contact (harmonic 1 alone: cheap).
      auto every = spec;
      every.contact.patches = 0;
      const auto e = estimateDiscResonance(mesh, models, every, options.family);
      PatchesCheck& c = out.patchesCheck.emplace();
      c.stuckHz = out.estimate->stuckHz, c.everyPairStuckHz = e.stuckHz;
      c.stuckAmplitude = out.estimate->stuckAmplitude, c.everyPairStuckAmplitude = e.stuckAmplitude;
      text << "; " << spec.contact.patches << " contact patches against every node pair, the contacts stuck: "
           << c.stuckHz << " against " << c.everyPairStuckHz << " Hz (" << 100 * c.frequencyChange() << " %), peak "
           << c.stuckAmplitude << " against " << c.everyPairStuckAmplitude << " mm (" << 100 * c.amplitudeChange()
           << " %)";
    }
    out.estimateText = text.str();
  } catch (const InputError& e) {
    if (!rangeGiven) throw;
    out.estimateText = std::string("no resonance estimate (") + e.what() + ")";
  }
  if (rangeGiven) {
    out.fromHz = options.fromHz, out.toHz = options.toHz;
  } else {
    out.fromHz = 0.9 * std::min(out.estimate->freeHz, out.estimate->stuckHz);
    out.toHz = 1.1 * std::max(out.estimate->freeHz, out.estimate->stuckHz);
  }
  checkModesCoverRange(models, spec, out.toHz);
  if (out.estimate)
    std::tie(out.contactStiffnessRatio, out.contactTangentialStiffnessRatio) =
        contactStiffnessRatios(out.setup, 0.5 * out.estimate->freeHz);
  log::info("shroud contacts: their normal stiffness up to " + numberText(out.contactStiffnessRatio, 3) +
            " times the sector's own at their pairs, their tangential stiffness up to " +
            numberText(out.contactTangentialStiffnessRatio, 3) + " times");
  // Measured on the default disc: 4e4 times traced, 4e5 found no first point after about a
  // minute of attempts; a penalty that far above the structure holds the faces no better.
  if (out.contactStiffnessRatio > kRigidContactRatio)
    throw InputError("disc_response/contact/kn",
                     "the shroud contacts' normal stiffness is up to " + numberText(out.contactStiffnessRatio, 3) +
                         " times the sector's own at their pairs (above " + numberText(kRigidContactRatio) +
                         "): no stiffer than rigid in effect, it only makes the balance too stiff to solve; lower kn "
                         "and kt (the default disc's are about 200 times the sector's own)");
  if (out.contactTangentialStiffnessRatio > kRigidTangentialContactRatio)
    throw InputError("disc_response/contact/kt",
                     "the shroud contacts' tangential stiffness is up to " +
                         numberText(out.contactTangentialStiffnessRatio, 3) + " times the sector's own at their pairs "
                         "(above " + numberText(kRigidTangentialContactRatio) +
                         "): rigid in effect, the contacts stick and slip within a sliver of a period, which the "
                         "samples cannot place; lower kt (the default disc's is about 500 times the sector's own)");
  if (options.mustCoverHz > 0 && !(options.mustCoverHz >= out.fromHz && options.mustCoverHz <= out.toHz)) {
    std::ostringstream why;
    why << options.mustCoverHz << " Hz lies outside the curve's range " << out.fromHz << ".." << out.toHz
        << " Hz (widen disc_response/frequency_range_hz, or leave at_hz out for the peak)";
    throw InputError("disc_response/peak_stress/at_hz", why.str());
  }
  out.curve = sweepDisc(out.setup, out.fromHz, out.toHz, options, out.warnings);
  out.headline = discHeadline(out.curve);
  if (out.headline.found()) log::info(out.headline.text);
  out.sectorSize = mesh::boundingDiagonal(mesh);
  if (options.peakInTime && out.headline.found() && out.curve.peakIndex < out.curve.branch.points.size()) {
    log::info("time-domain check at the traced curve's largest point (" +
              numberText(out.curve.peakOmega / (2 * M_PI), 6) + " Hz): up to " +
              std::to_string(options.peakInTime->maxPeriods) + " periods");
    out.peakInTime = integratePeakInTime(out.setup, out.curve.branch.points[out.curve.peakIndex].x,
                                         out.curve.peakOmega, models.sectors, spec.engineOrder, *options.peakInTime);
    log::info(out.peakInTime->text);
  }
  if (options.sweepInTime) {
    SweepInTimeOptions band = *options.sweepInTime;
    if (band.fromHz == 0 && band.toHz == 0) {
      band.fromHz = out.estimate ? 0.9 * out.estimate->stuckHz : out.fromHz;
      band.toHz = out.estimate ? 1.01 * out.estimate->stuckHz : out.toHz;
    }
    const auto preloads = options.sweepPreloads.empty() ? std::vector<double>{spec.contact.preload} : options.sweepPreloads;
    log::info("time domain: the ring swept over " + numberText(band.fromHz, 6) + ".." + numberText(band.toHz, 6) +
              " Hz at " + std::to_string(band.frequencies) + " frequencies and " + std::to_string(preloads.size()) +
              " preload(s), up to " + std::to_string(band.periods) + " periods each");
    out.sweepsInTime = sweepPreloadsInTime(mesh, models, spec, preloads, band, [](const SweepInTimePoint& p) {
      log::info("time domain at " + numberText(p.hz, 6) + " Hz: max|x(t)| " + numberText(p.largest) +
                (p.steady() ? " (steady, " : " (not steady: smallest " + numberText(p.smallest) + ", ") +
                std::to_string(p.periods) + " periods, " + std::to_string(std::lround(p.seconds)) + " s)");
    });
    log::info(out.sweepsInTime->text());
  }
  return out;
}

}  // namespace cyclone::disc
