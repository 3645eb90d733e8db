#pragma once
// Blade-to-blade scatter: a pattern of blade stiffness deviations delta_n, fixed or drawn
// at random (normal, mean 0, a standard deviation, a seed), reproducible bit for bit on
// one machine and standard library.
#include <cstdint>
#include <vector>

namespace cyclone::mistuning {

/// N deviations drawn from the normal distribution N(0, sigma^2) by a 64-bit Mersenne
/// twister seeded with `seed` (pattern i of a Monte Carlo: seed + i). InputError where
/// sigma < 0 or a drawn deviation would make a blade's stiffness not positive (<= -1).
std::vector<double> randomPattern(int blades, double sigma, std::uint64_t seed);

/// The pattern turned by `shift` blades (blade n takes blade n - shift's deviation): the
/// same disc seen from another blade; its statistics must be the same.
std::vector<double> shiftedPattern(const std::vector<double>& delta, int shift);

}  // namespace cyclone::mistuning
