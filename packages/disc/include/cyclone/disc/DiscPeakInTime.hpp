#pragma once
// The friction-damped peak checked in the time domain: the ring of reduced sectors
// integrated in time at the headline's frequency (hbm::integrateTravellingWave: every
// sector the engine order tells apart, each with its own shroud contacts, the contact law
// one step at a time, every harmonic the contacts make), started from the harmonic
// balance's periodic state there.
//
// Why: where the shroud hammers (every pair opening each period) the harmonic balance
// cannot bound its error: the contact forces' spectrum does not decay, and its periodic
// solution near the peak can be one the disc does not settle on (a complex pair of
// Floquet exponents: the motion is modulated; docs/studies/time_domain_disc.md). The
// time domain keeps every harmonic and follows whatever the motion does, so it says
// whether the periodic peak is the disc's amplitude, and if not, what the amplitude is.
//
// The time domain needs a causal, explicit model: the hybrid models' modes, their static
// correction realized by modes at `residualHz` and the loss factor as modal viscous
// damping (hbm::causalModalModel). That realization is its own model: on the default disc
// at the demo's preload its peak lies 2.8 % above the hybrid one's
// (docs/studies/time_domain_disc.md), so a difference of a few percent where the motion is
// steady is the two models', not the harmonics'.
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cyclone/hbm/TravellingWaveIntegration.hpp"

namespace cyclone::response {
struct ForcedResponseSetup;
}

namespace cyclone::disc {

/// How the peak is integrated in time; every field has the scenes' default.
struct PeakInTimeOptions {
  int stepsPerPeriod = 1024;  ///< raised to the central difference's stability limit where it needs more
  int maxPeriods = 600;
  /// The hybrid models' static correction realized by modes at this frequency (Hz).
  double residualHz = 50000;
  /// The run ends where the output DOF's amplitude stayed within this over 50 periods.
  double amplitudeTolerance = 1e-3;
};

/// The time domain at the harmonic balance's peak.
struct PeakInTime {
  double hz = 0;                ///< the traced curve's largest point's frequency
  double harmonicBalance = 0;   ///< its max |x(t)| of the output DOF (mm)
  hbm::TravellingWaveResponse::Ending ending = hbm::TravellingWaveResponse::Ending::NotSteady;
  int periods = 0, stepsPerPeriod = 0, sectors = 0;
  /// max |x(t)| of the output DOF per period: over the last period, and the largest and
  /// smallest over the last quarter of the run (at least 50 periods; where it is not steady: the
  /// modulation's range).
  double lastAmplitude = 0, largest = 0, smallest = 0;
  std::vector<double> amplitudeHistory;  ///< per period, from the start
  double seconds = 0;
  std::string text;  ///< the summary's line
  bool steady() const { return ending != hbm::TravellingWaveResponse::Ending::NotSteady; }
  /// The time domain's amplitude against the harmonic balance's: largest / harmonicBalance - 1.
  double difference() const { return harmonicBalance > 0 ? largest / harmonicBalance - 1 : 0; }
  /// Steady within kPeakInTimeModelDifference of the harmonic balance: what the causal model's
  /// own difference allows. Beyond it (a hammering shroud: the disc started on the periodic
  /// peak settled a factor of three below it) the periodic peak is not the disc's amplitude.
  bool agrees() const;
};

/// The causal model's own difference from the hybrid one is a few percent (2.8 % at the
/// default disc's peak); a steady amplitude farther than this from the harmonic balance's
/// is another motion.
constexpr double kPeakInTimeModelDifference = 0.05;

inline bool PeakInTime::agrees() const { return steady() && std::abs(difference()) <= kPeakInTimeModelDifference; }

/// The system the time domain integrates: setup's with its receptance replaced by the
/// causal modal model of the phases `sectors` and `engineOrder` reach (the static
/// correction realized by modes at residualHz). InputError naming `key` where setup's
/// system has no modal receptance model.
std::unique_ptr<hbm::HarmonicBalanceSystem> causalTimeSystem(const response::ForcedResponseSetup& setup, long sectors,
                                                             int engineOrder, double residualHz, const std::string& key);

/// The integration's options for setup's first output DOF (the one whose amplitude must
/// be steady) and excitation scale.
hbm::TravellingWaveOptions travellingWaveOptions(const response::ForcedResponseSetup& setup, int stepsPerPeriod,
                                                 int maxPeriods, double amplitudeTolerance);

/// max |x(t)| per period over the last quarter of a run that did not settle (at least 50
/// periods: past the transient, two cycles of the hammering disc's 45-period modulation):
/// {largest, smallest}.
std::pair<double, double> modulationRange(const std::vector<double>& amplitudeHistory);

/// The largest run asked for: periods x steps per period steps (the default's 600 x 1024 is
/// 614 400, about 70 s on the default disc at mesh size 12), and the steps per period (the
/// ring's motion over a period is held twice: 2 x steps x DOFs doubles).
constexpr long kPeakInTimeMaxSteps = 20'000'000;
constexpr int kPeakInTimeMaxStepsPerPeriod = 65536;

/// The options' limits, checked before any work: InputError naming the key under
/// disc_response/time_domain_check ("periods" or "steps_per_period") where periods < 100
/// (the steadiness is judged over the last 50), steps_per_period < 16 or above
/// kPeakInTimeMaxStepsPerPeriod, or periods x steps_per_period above kPeakInTimeMaxSteps
/// (a steps_per_period of 1e9 ran out of memory after the curve; periods 2e9 of a motion
/// that does not settle would have run for ever; issue 49's sixth probe).
void checkPeakInTimeOptions(const PeakInTimeOptions& options);

/// The ring integrated in time at the point `x` (a solution of setup's system at
/// `omega`), from that periodic state; `sectors` and `engineOrder` give the phases the
/// excitation and contacts reach (multiples of gcd(engine order, sectors)). InputError
/// where the system has no modal receptance model (a full FE or matrix system).
PeakInTime integratePeakInTime(const response::ForcedResponseSetup& setup, const Eigen::VectorXd& x, double omega,
                               long sectors, int engineOrder, const PeakInTimeOptions& options = {});

}  // namespace cyclone::disc
