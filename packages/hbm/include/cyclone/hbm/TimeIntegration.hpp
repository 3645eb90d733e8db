#pragma once
// The independent check of harmonic balance: the same system and element laws
// integrated in time (Newmark, average acceleration: unconditionally stable,
// second order) until the response repeats from one period to the next, then
// the last period's Fourier coefficients.
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"

namespace cyclone::hbm {

struct TimeIntegrationOptions {
  int stepsPerPeriod = 1024;
  int maxPeriods = 2000;
  double periodTolerance = 1e-9;  ///< max |x(t) - x(t - T)| / max |x| over a period
  double newtonTolerance = 1e-12;
  int maxNewtonIterations = 30;
  double excitationScale = 1.0;  ///< multiplies the excitation (not the static loads), as in residual()
};

struct SteadyState {
  Eigen::VectorXd coefficients;  ///< same layout as the harmonic balance unknowns
  int periods = 0;
  double periodChange = 0;
  bool converged = false;
};

/// Starts from the periodic motion X0 (e.g. a harmonic balance solution, or zeros).
SteadyState integrateToSteadyState(const HarmonicBalanceSystem& system, double omega, const Eigen::VectorXd& X0,
                                   const TimeIntegrationOptions& options = {});

}  // namespace cyclone::hbm
