#pragma once
// Hill's method for the receptance form (a reduced model: no M, C, K), from
// the modal realization of every harmonic's phase (ReceptanceModel.hpp).
#include "cyclone/hbm/HillStability.hpp"

namespace cyclone::hbm {

/// The modal coordinates of Hill's problem: per harmonic the modes of its phase's
/// realization, twice for h > 0 (the exponents +h and -h); 0 where a phase has none.
int receptanceModalCoordinates(const HarmonicBalanceSystem& system);

/// InputError when the receptance has no modal realization for some harmonic.
FloquetExponents receptanceHillStability(const HarmonicBalanceSystem& system, const Eigen::VectorXd& X, double omega,
                                         const HillOptions& options);

}  // namespace cyclone::hbm
