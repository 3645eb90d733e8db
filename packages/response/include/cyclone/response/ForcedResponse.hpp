#pragma once
// The forced response of a harmonic balance problem as a library call: the curve over
// the problem's range (ForcedResponseTrace.hpp), the stability of every point by Hill's
// method where it is affordable, the bifurcation flags, the largest response and the
// samples and harmonics checks there (ForcedResponseChecks.hpp). No files: the writers
// in post/ForcedResponseFiles.hpp take the result.
#include <complex>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/response/ForcedResponseChecks.hpp"
#include "cyclone/response/ForcedResponseSetup.hpp"

namespace cyclone::response {

/// What the error target on the harmonics (setup.harmonicsTolerance) came to.
struct HarmonicsTarget {
  double tolerance = 0;   ///< 0: no target was set
  int tracedHarmonic = 0; ///< the highest harmonic of the curve first traced
  int reached = -1;       ///< the level whose last two raises met the tolerance (-1: none)
  double change = -1;     ///< the larger of those two changes (-1: not reached)
  bool retraced = false;  ///< the curve was traced again with the harmonics 0..reached
  double retraceSeconds = 0;
  std::string text;       ///< one line: reached or not, and why
};

struct ForcedResponseResult {
  continuation::Branch branch;
  std::string startMethod;  ///< how the first point was found (or why none was)

  // Per point of branch.points:
  std::vector<double> omega;    ///< excitation frequency (rad/s)
  std::vector<double> measure;  ///< max |x(t)| of the first output DOF (0 without output DOFs)
  /// Hill's verdict: 1 stable, 0 unstable, 2 undetermined (it changes with twice the
  /// samples, receptance systems), -1 not computed.
  std::vector<int> stable;
  std::vector<std::optional<std::complex<double>>> leadingExponent;  ///< the Floquet exponent of largest real part
  std::vector<std::string> flags;  ///< fold, branch_point, period_doubling, neimark_sacker, turn; "" none
  std::vector<int> segment;        ///< which sweep the point belongs to (0, 1: Branch::segmentStarts)

  bool stabilityComputed = false;
  bool stabilityRechecked = false;  ///< verdicts compared with twice the samples (receptance systems)
  std::string stabilityNote;        ///< why stability was not computed, or how it was

  std::size_t peakIndex = 0;  ///< the point of largest `measure`
  double peak = 0;            ///< largest max |x(t)| of the first output DOF
  double peakParameter = 0;   ///< the continuation parameter there
  double peakOmega = 0;       ///< the frequency there (rad/s)
  SamplesCheck samplesCheck;      ///< at the peak point (empty text: not run)
  /// The headline's: of the curve's prominent peaks (prominentPeaks), the one whose
  /// highest level found is largest (empty text: not run). On a frequency curve every
  /// prominent peak is followed through the raised harmonics, since the peak largest
  /// with few harmonics need not be the largest with enough (a hammering resonance falls
  /// with H where a linear one beside it does not).
  HarmonicsCheck harmonicsCheck;
  std::vector<HarmonicsCheck> otherPeakChecks;  ///< the other prominent peaks' checks
  HarmonicsTarget harmonicsTarget;  ///< setup.harmonicsTolerance's outcome (tolerance 0: not asked)
  double seconds = 0;

  int unstablePoints() const;
  int undeterminedPoints() const;
  std::map<std::string, int> flagCounts() const;
};

/// [begin, end) of each sweep of a branch as consecutive bounds (first 0, last the size):
/// the last point of one sweep and the first of the next are no path.
std::vector<std::size_t> segmentBounds(const continuation::Branch& branch);

/// Finds the first point, traces the curve over setup.continuation's range (with its
/// fallbacks), computes stability (setup.stability), the flags and, when the curve has
/// a point and an output DOF, the checks at its largest response (the harmonics check
/// unless setup.harmonicsCheckTo < 0). With setup.harmonicsTolerance > 0 the check stops
/// where the peak met it and the curve is traced again at that level (setup.system is
/// replaced by it; the result's harmonicsCheck is the first curve's, which found it).
/// An empty branch is returned, not thrown: its
/// stopReason says why. InputError when the harmonic balance would not fit in memory.
ForcedResponseResult solveForcedResponse(ForcedResponseSetup& setup);

}  // namespace cyclone::response
