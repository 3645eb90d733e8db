#pragma once
// The full ring of a cyclic harmonic balance system: all N sectors assembled
// with their couplings and the elements between neighbours, the excitation
// delayed sector by sector. No cyclic reduction is used, so it is the
// independent reference for the engine-order constraint (and what a time
// integration of a cyclic system has to run on).
#include <memory>

#include "cyclone/hbm/HarmonicBalanceSystem.hpp"

namespace cyclone::hbm {

/// N n DOFs, sector j's DOFs at j n .. j n + n - 1. InputError if not cyclic.
std::unique_ptr<HarmonicBalanceSystem> expandToFullRing(const HarmonicBalanceSystem& sector);

/// The ring's coefficient vector of a cyclic solution: sector j = S^j X (S the
/// next-sector map), the layout of expandToFullRing.
Eigen::VectorXd ringCoefficients(const HarmonicBalanceSystem& sector, const Eigen::VectorXd& X);

}  // namespace cyclone::hbm
