#pragma once
// max over the period of |x(t)| from a DOF's harmonic coefficients. The AFT
// samples alone underestimate it (by up to 1 - cos(pi h / N) for harmonic h),
// so the maximum is located on a fine grid and polished by Newton on x'(t) = 0.
#include <Eigen/Dense>

#include "cyclone/hbm/HarmonicSet.hpp"

namespace cyclone::hbm {

/// coefficients: one DOF's, in the HarmonicSet's layout.
double peakMagnitude(const HarmonicSet& harmonics, const Eigen::VectorXd& coefficients);

}  // namespace cyclone::hbm
