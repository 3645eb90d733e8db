#pragma once
// What each nonlinear element of a harmonic balance system does at a solution: its
// relative motion and force as harmonic coefficients, the energy it dissipates per
// cycle, and both over one period from the sampled law (not the force's truncated
// Fourier series, whose Gibbs ripples would blur a friction loop's stick and slip
// corners): contact energies and hysteresis loops at a friction-damped peak.
#include <vector>

#include <Eigen/Dense>

#include "cyclone/hbm/HarmonicBalanceSystem.hpp"

namespace cyclone::hbm {

struct ElementState {
  Eigen::MatrixXd W;  ///< relative motion, nc x d coefficients (W^T x, plus the next sector's part)
  Eigen::MatrixXd F;  ///< the element's force on it, nc x d coefficients
};

/// Every element's state at the solution x (coefficients of the system) and frequency omega.
std::vector<ElementState> elementStates(const HarmonicBalanceSystem& system, const Eigen::VectorXd& x, double omega);

/// The energy the element dissipates per cycle, sum over h > 0 of pi h (F_ch . W_sh -
/// F_sh . W_ch): exact for the harmonics kept (the work of f on w over one period).
double dissipatedEnergyPerCycle(const HarmonicSet& harmonics, const ElementState& state);

/// The element's relative motion w and force f over one period at the system's samples
/// (N x d each; f from the element's law applied to the sampled motion).
struct ElementPeriod {
  Eigen::MatrixXd w, f;
};
ElementPeriod elementPeriod(const HarmonicBalanceSystem& system, std::size_t element, const ElementState& state,
                            double omega);

}  // namespace cyclone::hbm
