#pragma once
// Stability of a periodic harmonic balance solution by Hill's method: a
// perturbation e^{lambda t} p(t), p periodic and expanded on the same
// harmonics, gives the quadratic eigenproblem
//   (lambda^2 D2 + lambda D1 + J) P = 0,  D2 = M (x) I,  D1 = 2 M (x) wD + C (x) I,
// with J the harmonic balance Jacobian and wD the time derivative in coefficient
// space. Of its 2 n nc eigenvalues the 2 n with the smallest |Im| are the
// Floquet exponents (the others repeat them shifted by multiples of i w and are
// spoiled by the truncation); the solution is stable when all have Re < 0.
// A receptance (reduced) model has no M, C, K: its modal realization takes
// their place (ReceptanceHill.cpp), and the exponents are the eigenvalues in
// the strip |Im lambda| <= w / 2 (why there: ReceptanceHill.cpp).
#include <Eigen/Dense>

#include "cyclone/hbm/HarmonicBalanceSystem.hpp"

namespace cyclone::hbm {

struct FloquetExponents {
  Eigen::VectorXcd exponents;  ///< the Floquet exponents picked (2 n in the matrix form), by decreasing real part
  Eigen::VectorXcd all;        ///< every eigenvalue of the truncated Hill problem
  double maxRealPart = 0;      ///< -infinity when none is picked
  bool stable = false;
};

/// Throws InputError for velocity-dependent elements (not supported yet), singular M, or a
/// receptance without a modal realization.
FloquetExponents hillStability(const HarmonicBalanceSystem& system, const Eigen::VectorXd& X, double omega);

}  // namespace cyclone::hbm
