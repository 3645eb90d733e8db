#pragma once
// The checks of a traced forced-response curve at its largest-response point: the AFT's
// sample count (the point solved again with twice the samples) and the harmonic
// truncation (on a frequency curve the peak found again with H + 1, H + 2, ...; on other
// curves the point solved with one harmonic more). Friction and gaps place their events
// only to within a sample, and a friction-damped peak moves with H, so both are
// measured on every curve rather than assumed.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/continuation/PeakSearch.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/hbm/TruncatedForce.hpp"
#include "cyclone/response/ForcedResponseSetup.hpp"

namespace cyclone::response {

/// The peak of the first output DOF's max |x(t)| solved again with twice the samples.
struct SamplesCheck {
  bool solved = false;  ///< Newton converged with 2N samples
  int samples = 0;      ///< N, the curve's
  double change = -1;   ///< |peak(2N) / peak(N) - 1| when solved
  double residual = 0;  ///< Newton's last residual when not solved
  std::string text;     ///< one line saying the above
};
SamplesCheck checkSamples(ForcedResponseSetup& setup, const continuation::BranchPoint& point, double peak);

/// One level of the harmonics check of a frequency curve.
struct HarmonicsLevel {
  int maxHarmonic = 0;
  std::vector<int> harmonics;  ///< the level's harmonic set
  int samples = 0;             ///< and its samples per period
  continuation::PeakSearchResult peak;  ///< its parameter is the frequency in Hz
  double seconds = 0;
  double startHz = 0;  ///< where the search started (the level below's peak, or its flank)
  /// The elements' force the level's harmonics leave out, at its peak (when found).
  hbm::TruncatedForce truncated;
};

/// The peak at the highest harmonic count the check reached, with the change from the
/// level below: a frequency curve's headline.
struct HarmonicsConvergedPeak {
  bool found = false;
  int maxHarmonic = 0;
  double value = 0, hz = 0;
  int belowHarmonic = -1;     ///< the level compared with (-1: none found)
  double change = -1;         ///< |peak / peak below - 1| (-1: not known)
  int notFoundHarmonic = -1;  ///< the next level, tried and its peak not found (-1: none)
  /// The peak's solution: the curve's system raised to `harmonics` with `samples`
  /// (hbm::withHarmonics), at hz.
  Eigen::VectorXd x;
  std::vector<int> harmonics;
  int samples = 0;
  hbm::TruncatedForce truncated;  ///< the elements' force its harmonics leave out
};

struct HarmonicsCheck {
  int dof = 0;                          ///< the output DOF whose peak is compared
  std::vector<HarmonicsLevel> levels;   ///< a frequency curve's levels H, H + 1, ... (empty: the point check)
  HarmonicsConvergedPeak converged;     ///< the highest level found (frequency curves)
  std::string text;                     ///< one line: the levels, the last change, the time
};
/// The check at `branch.points[ip]` (its max |x(t)| `peak`): on a frequency curve the
/// peaks with H up to max(setup.harmonicsCheckTo, H + 1), each level's peak search from
/// the one below's; otherwise (and where a frequency curve has no interior peak) the
/// point with harmonics 0..H+1. Not possible (said in the text) when the system has
/// nothing for a raised harmonic.
HarmonicsCheck checkHarmonics(ForcedResponseSetup& setup, const continuation::Branch& branch, std::size_t ip,
                              double peak);

/// A peak over the frequency at a value of setup's other parameter (a followed peak: x
/// solves the system at `value` and the frequency omega, rad/s, the largest response
/// there): found again with harmonics 0..H + 1, 0..H + 2, ... up to `upTo`, each level's
/// peak search from the one below's (the frequency curve's harmonics check without a
/// curve). The levels, H's first; they stop at one whose peak is not found.
std::vector<HarmonicsLevel> peakByRaisedHarmonics(ForcedResponseSetup& setup, double value, const Eigen::VectorXd& x,
                                                  double omega, int upTo);

/// The larger of the last two raises' changes of the peak when both are at most `target`
/// (the three last levels found), else -1: where harmonics by an error target stop.
double levelsMeetTarget(const std::vector<HarmonicsLevel>& levels, double target);
/// What the Newton steps' solver holds (the dense one about four matrices of the
/// unknowns' size; Krylov, where the system has Jacobian blocks and `solver` chooses it,
/// per harmonic two blocks over the DOFs and GMRES's basis): an InputError naming
/// `harmonicsKey` where it would not fit in this machine's memory, a warning where each
/// dense Newton iteration, or each factorization of Krylov's preconditioner (a dense block
/// over the DOFs per harmonic), takes seconds (refused beyond 10 minutes).
void checkSolverSize(const hbm::HarmonicBalanceSystem& system, const std::string& harmonicsKey,
                     continuation::ContinuationOptions::LinearSolver solver =
                         continuation::ContinuationOptions::LinearSolver::Auto);

/// What one Newton iteration of a harmonic balance holds and costs, by the models the
/// checks here share (estimates from flop counts at rates measured once on the default
/// disc, not timings of this run): the unknowns; whether its steps are Krylov's (the
/// system has Jacobian blocks and `solver` chooses them, Auto from krylovFrom unknowns);
/// the memory of the dense Jacobian and its factors, or of Krylov's blocks and GMRES's
/// basis; the seconds of the elements' Jacobians (2 N (d nc)^2 flops each at about 4.5
/// Gflop/s) and of the linear solve (the dense LU (n / 2349)^3 s, from 1 s at 2349
/// unknowns; Krylov's preconditioner (2/3) (2 DOFs)^3 flops per harmonic at about 10
/// Gflop/s).
struct NewtonStepEstimate {
  double unknowns = 0;
  bool krylov = false;
  double gigabytes = 0;
  double jacobianSeconds = 0;
  double solveSeconds = 0;
};
NewtonStepEstimate estimateNewtonStep(int dofs, const hbm::HarmonicSet& harmonics, int samples,
                                      const std::vector<int>& elementDimensions, bool hasJacobianBlocks,
                                      continuation::ContinuationOptions::LinearSolver solver);
/// The elements' Jacobians' seconds per Newton iteration: 2 N (d nc)^2 flops each at about
/// 4.5 Gflop/s.
double elementJacobianSeconds(int samples, int numCoefficients, const std::vector<int>& elementDimensions);
/// More memory than this for a Newton step's solver is refused.
constexpr double kMaxSolverGigabytes = 12;

/// The time samples per period a curve of `harmonics` takes by default: at least 64 and
/// 4 H + 1; with a nonsmooth law among `elements` (recommendedSamples() > 0: contacts,
/// friction, gaps, whose events between samples shift with the sampling) also the law's
/// own count and harmonics.nonsmoothSamples(), so the samples grow with the harmonics.
int recommendedSamples(const hbm::HarmonicSet& harmonics,
                       const std::vector<std::shared_ptr<const hbm::NonlinearElement>>& elements);

/// A sample count from kSamplesExcessFactor times `needed` (what the harmonics and the
/// elements need, `neededWhy` saying so) is said with its cost before any work: the
/// elements' Jacobians per Newton iteration at `samples` and at `needed`; a warning where
/// that reaches kSamplesSlowSeconds, else an info line. Messages begin with `samplesKey`.
void checkSamplesCost(int samples, int needed, const std::string& neededWhy, const hbm::HarmonicSet& harmonics,
                      const std::vector<int>& elementDimensions, const std::string& samplesKey);
constexpr int kSamplesExcessFactor = 8;
constexpr double kSamplesSlowSeconds = 0.1;

/// A frequency curve's harmonics check beyond H + 1 (setup.harmonicsCheckTo): its levels
/// and the Newton iteration's cost at its top level (estimateNewtonStep) said before the
/// trace, a warning from 2 s an iteration; an InputError naming setup.harmonicsCheckKey
/// where the top level would not fit in memory or an iteration there would pass 600 s.
void checkHarmonicsCheckCost(const ForcedResponseSetup& setup);

/// The elements' Jacobians' cost per Newton iteration (each element's sampled sensitivities
/// projected onto the harmonics, 2 samples (d numCoefficients)^2 flops): a warning over
/// 10 s, an InputError naming `harmonicsKey` over 600 s. `what` begins the message (the
/// harmonics and DOFs). Known before a system is built (a scene's reader calls it).
void checkElementJacobianCost(int samples, int numCoefficients, const std::vector<int>& elementDimensions,
                              const std::string& what, const std::string& harmonicsKey);

/// The first point's response must be representable. Where the excitation is nonzero and
/// the start's largest coefficient is below kSmallestTraceable (1e-150: its square, which
/// the continuation's norms and scaling take, underflows a double), the curve would come
/// out zeros with "end of the range reached": an InputError naming the excitation and
/// the force it would take. Not for a force-scale curve (its start may be the zero force).
void checkResponseScale(const ForcedResponseSetup& setup, const Eigen::VectorXd& start);
/// Forces from kLargestTraceable (1e100) leave no room in a double for what the trace
/// forms of them (a cubic spring's force of the response cubed, the continuation's
/// squared norms): an InputError naming the excitation, before the first point (a cos of
/// 1e100 on the Duffing DOF ended in "no point of the curve was computed" and a page of
/// solver attempts). Not for a force-scale curve (the scale is its parameter).
void checkExcitationSize(const ForcedResponseSetup& setup);
constexpr double kLargestTraceable = 1e100;
constexpr double kSmallestTraceable = 1e-150;

}  // namespace cyclone::response
