#pragma once
// The same system on another harmonic set or sample count, and a solution
// carried over to it: how a solution is refined (raise H, double N) to check
// its truncation, or continued from a cheap H = 1 start.
#include <memory>
#include <vector>

#include "cyclone/hbm/HarmonicBalanceSystem.hpp"

namespace cyclone::hbm {

/// A copy of `system` (matrices, cyclic coupling, elements, excitation and
/// static loads) with `harmonics` and `samples`. Excitation on a harmonic the
/// new set lacks is an InputError (it would be silently dropped).
std::unique_ptr<HarmonicBalanceSystem> withHarmonics(const HarmonicBalanceSystem& system, HarmonicSet harmonics,
                                                     int samples);

/// A copy of the receptance-form `system` (cyclic settings, elements, excitation, static
/// loads, harmonics and samples) over another model of the same DOFs: the same
/// contacts and loads on another linear part (a modal truncation to integrate in time).
std::unique_ptr<HarmonicBalanceSystem> withReceptance(const HarmonicBalanceSystem& system,
                                                      std::shared_ptr<const ReceptanceModel> model);

/// X (laid out for `from`) re-laid out for `to`: shared harmonics copied,
/// new ones zero, dropped ones discarded.
Eigen::VectorXd transferCoefficients(const Eigen::VectorXd& X, int numDofs, const HarmonicSet& from,
                                     const HarmonicSet& to);

/// The unknowns of `to` (numDofs DOFs) that `from` lacks: each DOF's coefficients of
/// the harmonics `to` adds, the equations a homotopy switches on when a solution is
/// carried up (continuation::solveByHomotopy).
std::vector<int> addedCoefficients(int numDofs, const HarmonicSet& from, const HarmonicSet& to);

}  // namespace cyclone::hbm
