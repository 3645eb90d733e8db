#pragma once
// The friction-damped forced response of a bladed disc as one library call: the
// sector's harmonic balance over its reduced models (DiscHarmonicBalance.hpp), the
// frequency range from the resonance estimate unless given, the curve traced with the
// disc's continuation defaults, its checks, and the headline peak: the harmonics
// check's highest level found, converged to 1 % or labelled an estimate.
#include <cmath>
#include <complex>
#include <optional>
#include <string>
#include <vector>

#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/disc/DiscHarmonicBalance.hpp"
#include "cyclone/disc/DiscPeakInTime.hpp"
#include "cyclone/disc/DiscReducedModels.hpp"
#include "cyclone/disc/DiscSweepInTime.hpp"
#include "cyclone/response/ForcedResponse.hpp"

namespace cyclone::mesh {
class Mesh;
}

namespace cyclone::disc {

/// How a disc's frequency curve is traced; every field has the scenes' default.
struct DiscSweepOptions {
  int family = 1;  ///< which natural frequency of the engine order's nodal diameter (from 1) sets the range
  double fromHz = 0, toHz = 0;  ///< 0, 0: 0.9 x the lower and 1.1 x the higher of the estimate's two frequencies
  /// A frequency the curve must reach (the peak stress asked at a frequency, > 0): checked
  /// against the range, given or estimated, before the trace (InputError naming
  /// disc_response/peak_stress/at_hz).
  double mustCoverHz = 0;
  response::ForcedResponseSetup::Stability stability = response::ForcedResponseSetup::Stability::Auto;
  /// The highest harmonic the harmonics check raises H to (0: H + 1; < 0: no check).
  int harmonicsCheckTo = 0;
  /// Harmonics by an error target (ForcedResponseSetup::harmonicsTolerance; 0: off): the
  /// check stops where the peak met it and the curve is traced again with those harmonics.
  double harmonicsTolerance = 0;
  continuation::ContinuationOptions continuation = discContinuationOptions();
  /// Retraces a curve `continuation` leaves incomplete (none: not retraced).
  std::optional<continuation::ContinuationOptions> fallback =
      discContinuationOptions(continuation::ContinuationOptions::Engine::Loca);
  /// The peak checked in the time domain (DiscPeakInTime.hpp; none: not checked).
  std::optional<PeakInTimeOptions> peakInTime;
  /// The band swept in the time domain (DiscSweepInTime.hpp; none: not swept) after the
  /// curve, at each of `sweepPreloads` (empty: the spec's preload). A band of 0, 0: 0.9 to
  /// 1.01 times the estimate's stuck frequency (the hammering shroud's resonance lies
  /// below the stuck one: 8 % below it with no preload on the default disc), else the
  /// curve's range.
  std::optional<SweepInTimeOptions> sweepInTime;
  std::vector<double> sweepPreloads;
};

/// The peak a disc run reports: the harmonics check's highest level found.
struct DiscHeadline {
  /// NotFound: the harmonics check found no peak. Converged: its change from the level
  /// below is at most 1 %, and no level above failed; with an error target on the
  /// harmonics, the target met (its last two raises within it). Estimate: found, not that.
  enum class Convergence { NotFound, Estimate, Converged };
  Convergence convergence = Convergence::NotFound;
  bool found() const { return convergence != Convergence::NotFound; }
  bool converged() const { return convergence == Convergence::Converged; }
  response::HarmonicsConvergedPeak peak;
  /// Hill's verdict at the traced curve's largest point, where that is the headline's peak
  /// (within 1 % in frequency). A complex pair of exponents with Re > 0 there (the
  /// hammering shroud's resonance) means the disc does not settle on the periodic
  /// response: its amplitude is modulated (docs/studies/time_domain_disc.md); a real one,
  /// that the response jumps to another branch.
  enum class PeakStability { NotComputed, Stable, Undetermined, UnstableReal, UnstableComplex };
  PeakStability stability = PeakStability::NotComputed;
  std::complex<double> leadingExponent;  ///< 1/s, where Hill's pick left one
  std::string text;  ///< "friction-damped peak: max|x(t)| ... converged ... / an estimate ..."
};
/// The headline of a traced curve (NotFound when the harmonics check found no peak).
DiscHeadline discHeadline(const response::ForcedResponseResult& curve);
/// "not found", "estimate", "converged".
const char* convergenceName(DiscHeadline::Convergence convergence);

/// Patches (ShroudContactSpec::patches) against every node pair, where both can be
/// compared cheaply: the stuck system's resonance (harmonic 1, the contacts linear), the
/// patches' discretisation error where they do not slip or open.
struct PatchesCheck {
  double stuckHz = 0, everyPairStuckHz = 0;
  double stuckAmplitude = 0, everyPairStuckAmplitude = 0;  ///< mm
  /// |patches / every pair - 1| of the frequency and of the amplitude.
  double frequencyChange() const { return std::abs(stuckHz / everyPairStuckHz - 1); }
  double amplitudeChange() const { return std::abs(stuckAmplitude / everyPairStuckAmplitude - 1); }
};

struct DiscForcedResponse {
  std::optional<ResonanceEstimate> estimate;  ///< none when it failed and the range was given
  std::optional<PatchesCheck> patchesCheck;   ///< with patches and an estimate
  std::string estimateText;  ///< what the estimate found (and the patches against every pair), or why it failed
  double fromHz = 0, toHz = 0;
  response::ForcedResponseSetup setup;  ///< the system as traced (its state at the curve's end)
  response::ForcedResponseResult curve;
  DiscHeadline headline;
  std::vector<std::string> warnings;  ///< e.g. the largest response at the end of the sweep
  /// The time domain at the traced curve's largest point, where DiscSweepOptions::peakInTime
  /// asks for it and the headline was found.
  std::optional<PeakInTime> peakInTime;
  /// The band swept in time, where DiscSweepOptions::sweepInTime asks for it.
  std::optional<PreloadSweepsInTime> sweepsInTime;
  double sectorSize = 0;  ///< the mesh's bounding box's diagonal (mm)
  /// The contacts' normal stiffness over the sector's own at their pairs, the largest
  /// (kn times the structure's compliance along the contact's normal, the engine order's
  /// phase, at half the free resonance): far above 1, the contacts are rigid and only make
  /// the balance stiff (kn = 1e8 N/mm^3 on the default disc found no first point, and the
  /// failure did not say why). 0 where the system has no receptance model.
  double contactStiffnessRatio = 0;
  /// The same for kt along the contacts' tangential coordinates (kt = 1e12 N/mm^3 on the
  /// default disc, 9e10 times the sector's own, traced 286 points without a peak, exit 0,
  /// and named neither kt nor its size).
  double contactTangentialStiffnessRatio = 0;
  /// The headline's peak beyond 1 % of the sector's size: the reduced models are linear
  /// elasticity about the prestressed state, small displacements (an excitation of 1e5 N
  /// gave a peak of 550 mm on a 60 mm blade).
  bool beyondSmallDisplacements() const { return headline.found() && headline.peak.value > 0.01 * sectorSize; }
};

/// InputError naming reduced_model/modes where the engine order's nodal diameter's model
/// keeps no natural frequency at or above `toHz` (the curve's range's top): its resonances
/// above the modes kept would be missing from the response.
void checkModesCoverRange(const DiscReducedModels& models, const DiscResponseSpec& spec, double toHz);

/// The largest DiscForcedResponse::contactStiffnessRatio solveDiscForcedResponse traces
/// (an InputError naming disc_response/contact/kn above it).
constexpr double kRigidContactRatio = 1e6;
/// The largest contactTangentialStiffnessRatio it traces (an InputError naming
/// disc_response/contact/kt above it). Far higher than kn's: a rigid tangential contact is
/// Coulomb's law, which the balance still solves. Measured on the default disc at mesh
/// size 12 (its kt 461 times the sector's own): 1e6 to 9e7 times traced a peak converged in
/// the harmonics, 9e8 times an estimate (H = 2 not found), 9e10 times no peak (exit 0).
constexpr double kRigidTangentialContactRatio = 1e10;

/// The frequency curve of the disc `spec` describes over `models` (InputError for an
/// engine order its sectors cannot carry, a family out of range, or no resonance of the
/// stuck system in the estimate's scan when no range is given).
DiscForcedResponse solveDiscForcedResponse(const mesh::Mesh& mesh, const DiscReducedModels& models,
                                           const DiscResponseSpec& spec, const DiscSweepOptions& options = {});

/// `setup` traced over fromHz..toHz with `options`' continuation, stability and harmonics
/// check (a parameter study's curves share the reference's range); warnings where the
/// largest response lies at an end of the sweep.
response::ForcedResponseResult sweepDisc(response::ForcedResponseSetup& setup, double fromHz, double toHz,
                                         const DiscSweepOptions& options, std::vector<std::string>& warnings);

}  // namespace cyclone::disc
