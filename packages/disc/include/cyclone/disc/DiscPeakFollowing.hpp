#pragma once
// The disc's resonance peak followed over a contact or excitation parameter: a peak
// search per value (continuation::followPeaks) from the reference curve's prominent
// peaks, down and up a grid from the reference value, instead of a frequency curve per
// value; or the largest peak continued by LOCA (continuation::continuePeak). The shroud contacts' Jacobian jumps where a stick-slip instant crosses a time
// sample, and the peak condition's arclength tracking creeps there (docs/decisions.md):
// a fixed-frequency Newton passes those corners.
#include <functional>
#include <string>
#include <vector>

#include "cyclone/continuation/PeakFollowing.hpp"
#include "cyclone/disc/DiscParameterStudy.hpp"
#include "cyclone/response/ForcedResponseChecks.hpp"

namespace cyclone::disc {

struct DiscPeakFollowingSpec {
  /// Preload, FrictionCoefficient, ContactStiffness (kn = kt = the value, as the value-list
  /// study), Force, LossFactor (the reduced models' structural damping, the system made
  /// again from them per value), Clearance (the gap elements') or Speed (the models built
  /// again at each speed by modelsAtSpeed; InputError for another).
  DiscStudyParameter parameter = DiscStudyParameter::Preload;
  /// 0 < from < to (from < to of any sign for the clearance: negative is interference;
  /// 0 <= from < to for the speed), containing the spec's value (1 for Force; the models'
  /// loss factor and speed).
  double from = 0, to = 0;
  int values = 24;  ///< evenly in log over the range (evenly for the clearance and the speed; 3..400)
  /// Speed: the reduced models at a speed (rpm), the same nodal diameters and kind as the
  /// followed ones (e.g. buildDiscReducedModels with their spec at that rpm). Called once
  /// per value of the grid; the reference speed's are the models given.
  std::function<DiscReducedModels(double rpm)> modelsAtSpeed;
  /// Values added to the grid (e.g. a value-list study's, so that the two can be compared).
  std::vector<double> extraValues;
  /// Peaks known at some values (the tops of a value-list study's curves: the point's x,
  /// its frequency in rad/s): Method::PeakSearch searches from them too at those values
  /// and takes the larger (continuation::PeakFollowingOptions::knownPeaks), so a peak that
  /// overtakes the followed one between two values of the grid is not missed there.
  std::vector<continuation::KnownPeak> knownPeaks;
  /// PeakSearch: a peak search per value of the grid. Continuation: the peak continued by
  /// LOCA on the peak condition (continuation::continuePeak, the frequency curve
  /// parametrised by the response's phase) from the reference value to each end of the
  /// range, its points where LOCA's steps fall (`values` and `extraValues` unused; the
  /// optimum located between them). For the contact parameters, the clearance and the
  /// force, not the loss factor or the speed (their systems are rebuilt per value).
  enum class Method { PeakSearch, Continuation };
  Method method = Method::PeakSearch;
  double phaseStep = 0.1;  ///< continuePeak's h (radians)
  /// The optimum's peak found again with this many harmonics more, one at a time (0:
  /// not checked): its harmonic truncation error, as the headline's.
  int optimumRaises = 2;
};

/// The optimum's peak with more harmonics: the study's own harmonics (H) and each raise.
struct OptimumHarmonicsCheck {
  std::vector<response::HarmonicsLevel> levels;  ///< H first; empty: not checked
  /// The largest change of the peak over the raises (relative; -1: a level not found).
  double change = -1;
  bool converged(double tolerance) const { return change >= 0 && change <= tolerance; }
};

/// The followed peaks against the frequency curves' peaks at the values both have.
struct PeakAgreement {
  int compared = 0;                      ///< pairs at one value (within 1e-12 of it)
  double largestRelativeDifference = 0;  ///< max |followed / curve's - 1| over them
};

struct DiscPeakFollowing {
  continuation::FollowedPeakCurve curve;  ///< in parameter order; the optimum by merit()
  std::vector<double> grid;               ///< the values followed
  double referenceValue = 0;              ///< the spec's value, where the following starts
  std::size_t startingPeaks = 0;          ///< the reference curve's prominent peaks followed
  response::ForcedResponseSetup setup;    ///< the system followed (at the last value followed)
  std::vector<std::string> warnings;      ///< e.g. an incomplete reference curve to start from
  /// Over the force the peak grows with it: the optimum is the smallest peak per unit
  /// force (the most friction damping); otherwise the smallest peak. Over the speed, an
  /// operating condition and not a design choice, none (curve.optimum = -1).
  bool byForce = false;
  bool continued = false;  ///< by one LOCA continuation (Method::Continuation), else a peak search per value
  /// Per point of curve.points: the contact forces' harmonics above H over those kept at
  /// the peak (hbm::TruncatedForce::share; -1: not known). Where a contact opens each
  /// period it is tens of percent and the peak is far from converged in H (docs/scenes.md).
  std::vector<double> forceBeyond;
  OptimumHarmonicsCheck optimumCheck;
  double merit(const continuation::FollowedPeak& p) const { return byForce ? p.measure / p.parameter : p.measure; }
  /// The optimum sits at the grid's first or last value: it may lie beyond the range.
  bool optimumAtRangeEnd() const;
  /// Against the peaks of frequency curves traced at some values (a value-list study's
  /// tops, as DiscPeakFollowingSpec::knownPeaks; those without a peak, measure 0, skipped).
  PeakAgreement agreementWith(const std::vector<continuation::KnownPeak>& curvePeaks) const;
};

/// The spec's value of `parameter` (preload, mu, kn = kt; 1 for Force: a scale of the
/// excitation). InputError for contact stiffness when the spec's kn and kt differ, and for
/// the loss factor (the models', not the spec's).
double discReferenceValue(const DiscResponseSpec& spec, DiscStudyParameter parameter);

/// The reference curve's peak followed over `following`: the system is spec's over
/// `models`, with reference's outputs and continuation tolerance; each peak searched to
/// 1e-7 of its frequency, a band sweep over bandFromHz..bandToHz where a followed peak
/// vanishes. InputError for a range or value count out of bounds; SolverError when the
/// reference curve has no peak or nothing could be followed.
DiscPeakFollowing followDiscPeak(const mesh::Mesh& mesh, const DiscReducedModels& models, const DiscResponseSpec& spec,
                                 const response::ForcedResponseSetup& reference,
                                 const response::ForcedResponseResult& referenceCurve, double bandFromHz,
                                 double bandToHz, const DiscPeakFollowingSpec& following);

}  // namespace cyclone::disc
