#pragma once
// The resonances of a forced response's linear part, known before its curve is traced:
// what a frequency curve's steps must not pass over (ContinuationOptions::parameterMarks).
#include <vector>

#include "cyclone/hbm/HarmonicBalanceSystem.hpp"

namespace cyclone::response {

/// The natural frequencies (rad/s, ascending) of a matrix system's linear part, both
/// without the nonlinear elements (K, M) and with them linearised about rest (their
/// stiffness at zero motion added: stuck friction contacts, closed preloaded gaps). Empty
/// for a receptance or cyclic system, a mass matrix that is not positive definite, or a
/// stiffness that is not symmetric.
std::vector<double> linearResonances(const hbm::HarmonicBalanceSystem& system);

}  // namespace cyclone::response
