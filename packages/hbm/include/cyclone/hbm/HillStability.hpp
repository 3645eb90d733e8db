#pragma once
// Stability of a periodic harmonic balance solution by Hill's method: a
// perturbation e^{lambda t} p(t), p periodic and expanded on the same
// harmonics, gives the quadratic eigenproblem
//   (lambda^2 D2 + lambda D1 + J) P = 0,  D2 = M (x) I,  D1 = 2 M (x) wD + C (x) I,
// with J the harmonic balance Jacobian and wD the time derivative in coefficient
// space. Of its 2 n nc eigenvalues the 2 n with the smallest |Im| are the
// Floquet exponents (the others repeat them shifted by multiples of i w and are
// spoiled by the truncation); the solution is stable when all have Re < 0.
#include <Eigen/Dense>

#include "cyclone/hbm/HarmonicBalanceSystem.hpp"

namespace cyclone::hbm {

struct FloquetExponents {
  Eigen::VectorXcd exponents;  ///< 2 n, sorted by decreasing real part
  double maxRealPart = 0;
  bool stable = false;
};

/// Throws InputError for velocity-dependent elements (not supported yet) or singular M.
FloquetExponents hillStability(const HarmonicBalanceSystem& system, const Eigen::VectorXd& X, double omega);

}  // namespace cyclone::hbm
