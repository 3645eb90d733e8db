#pragma once
// Hill's method for the receptance form (a reduced model: no M, C, K), from
// the modal realization of every harmonic's phase (ReceptanceModel.hpp).
#include "cyclone/hbm/HillStability.hpp"

namespace cyclone::hbm {

/// InputError when the receptance has no modal realization for some harmonic.
FloquetExponents receptanceHillStability(const HarmonicBalanceSystem& system, const Eigen::VectorXd& X, double omega,
                                         const HillOptions& options);

}  // namespace cyclone::hbm
