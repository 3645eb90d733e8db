#pragma once
// The time-domain reference of a cyclic receptance system (a bladed disc's sector
// given by its reduced models, friction contacts to the next sector, an engine-order
// excitation): the ring integrated in time to its periodic steady state, with the
// same element laws one step at a time. It checks what the harmonic balance assumes
// and truncates: the travelling wave (every sector integrated, none assumed to lag
// the other), and the harmonics (the contact forces keep all of theirs).
//
// The ring's motion is split by the sectors' discrete Fourier transform,
//   x_j(t) = sum_p e^{-i 2 pi p j / N} x~_p(t),   x~_{N-p} = conj(x~_p),
// and phase p's part is the model's modal realization driven by the phase's force,
//   q_p'' + c q_p' + l q_p = V_p^T f~_p(t),  x~_p = U_p q_p,  f~_p = (1/N) sum_j e^{+i 2 pi p j / N} f_j(t),
// f_j the excitation (sector j's delayed by j 2 pi EO / N) and the static loads less
// the elements' forces on sector j. An engine-order excitation and the contacts reach
// only the phases p that are multiples of g = gcd(EO, N); on those, sector j + N / g
// moves like sector j, so N / g sectors are integrated, each with its own contacts.
// The model must be causal and explicit in time: modes only (no constant part R) and
// viscous modal damping (ModalReceptance's causalModalModel makes one).
//
// Each mode by the central difference (explicit: the contact forces at step n from
// the motion at step n); the step is at most 1 / w_max, w_max the largest frequency of
// the modes with every contact stuck and closed. Periods until the motion of sector 0
// repeats: the change from one period to the next, geometric as the transient decays,
// gives the error left in the last period (change r / (1 - r), r the change's ratio).
// A friction contact that slips a little each period moves its stuck position by a
// little each period (a shakedown over thousands of periods: on the default disc the
// change fell from 6e-5 to 4e-5 over 1200 periods while max |x| stayed within 2e-6), so
// the run also ends where the amplitude max |x(t)| of every DOF watched has stayed within
// `amplitudeTolerance` over the last `window` periods (a drift that slow, 2e-6 a period,
// moves it by less than 1e-2 over the 4000-period shakedown): the amplitude is what is compared.
#include <Eigen/Dense>
#include <vector>

#include "cyclone/hbm/HarmonicBalanceSystem.hpp"

namespace cyclone::hbm {

struct TravellingWaveOptions {
  int stepsPerPeriod = 2048;     ///< raised to the scheme's stability limit where that needs more
  int maxPeriods = 4000;
  double tolerance = 1e-6;       ///< the error left in the last period, relative to max |x|
  double amplitudeTolerance = 1e-4;  ///< spread of the amplitudes over `window` periods, relative to the largest
  int window = 50;
  /// The DOFs whose amplitudes must be steady (empty: every DOF; the contacts' relative
  /// displacements drift with their stuck positions where the response DOFs do not).
  std::vector<int> steadyDofs;
  double excitationScale = 1.0;  ///< multiplies the excitation (not the static loads), as in residual()
};

/// Where a run ended, to start the next frequency from (a sweep in time).
struct TravellingWaveState {
  std::vector<Eigen::VectorXcd> q, velocity;  ///< per phase integrated, its modal coordinates
  std::vector<Eigen::VectorXd> elementStates;  ///< per element and sector (element e, sector j at e * sectors + j)
};

struct TravellingWaveResponse {
  Eigen::MatrixXd motion;  ///< sector 0 over the last period: stepsPerPeriod rows (t = k T / S) x numDofs
  int stepsPerPeriod = 0;
  int periods = 0;
  int sectors = 0;  ///< integrated: N / gcd(EO, N)
  int modes = 0;    ///< complex modal coordinates over the phases
  double periodChange = 0;   ///< max |x(t) - x(t - T)| / max |x| over the last period
  double errorEstimate = 0;  ///< the error left, from the change's geometric decay
  /// How the run ended: the motion repeats (to `tolerance`), its amplitudes are steady
  /// (to `amplitudeTolerance` over `window` periods) while it still drifts, or neither
  /// within maxPeriods.
  enum class Ending { Periodic, SteadyAmplitude, NotSteady } ending = Ending::NotSteady;
  bool converged = false;  ///< Periodic or SteadyAmplitude
  double amplitudeSpread = 0;  ///< over the last window, relative to the largest amplitude
  /// Per period, max |x(t)| of the first DOF watched (steadyDofs, else DOF 0): the
  /// transient's course, and where the motion never settles, what it does instead.
  std::vector<double> amplitudeHistory;
  double seconds = 0;
  TravellingWaveState state;
  /// max |x(t)| of a DOF of sector 0 over the last period.
  double peak(int dof) const;
};

/// The state at t = 0 of the periodic motion whose sector 0 has harmonic balance
/// coefficients X: each phase's modes from the harmonics' forces (excitation and static
/// loads less the elements' forces of X), the elements relaxed. A friction-damped curve
/// folds: where its top lies past a fold, the motion from rest settles on the lower
/// branch, and a time integration started here checks the harmonic balance's own branch.
TravellingWaveState travellingWaveStart(const HarmonicBalanceSystem& system, const Eigen::VectorXd& X, double omega,
                                        double excitationScale = 1.0);

/// The steady state at `omega` from rest, or from `start` (a neighbouring frequency's
/// end). InputError for a system that is not a cyclic receptance system or whose model
/// has a constant part or structural damping; Error where the integration diverges.
TravellingWaveResponse integrateTravellingWave(const HarmonicBalanceSystem& system, double omega,
                                               const TravellingWaveOptions& options = {},
                                               const TravellingWaveState* start = nullptr);

}  // namespace cyclone::hbm
