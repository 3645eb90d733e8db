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
#include <limits>

#include "cyclone/hbm/HarmonicBalanceSystem.hpp"

namespace cyclone::hbm {

struct FloquetExponents {
  Eigen::VectorXcd exponents;  ///< the Floquet exponents picked (2 n in the matrix form), by decreasing real part
  /// Every eigenvalue of the truncated Hill problem, or where only those nearest zero were
  /// computed (HillOptions::denseUpTo), those: every eigenvalue of modulus up to `covered`.
  Eigen::VectorXcd all;
  double covered = std::numeric_limits<double>::infinity();  ///< 1/s; infinity: `all` is every eigenvalue
  double maxRealPart = 0;      ///< -infinity when none is picked
  bool stable = false;
};

struct HillOptions {
  /// The receptance form's Hill problem (2 m unknowns for m modal coordinates over the
  /// harmonics' blocks) is solved whole (LAPACK) up to this size. Above it only its
  /// eigenvalues nearest zero are computed (ARPACK, shift-invert at zero), as many as it
  /// takes to reach `coverage` w: the exponents sit in the strip |Im| <= w / 2, so every
  /// one whose real part is within sqrt(coverage^2 - 1/4) w of zero is found (0.87 w, a
  /// growth or decay of e^5.4 a period, at coverage 1). At H = 7 on the default disc (600
  /// unknowns, 14 exponents) the whole problem's eigenvalues took 0.38 s, the 34 nearest
  /// zero 0.02 s (docs/solvers.md).
  int denseUpTo = 400;
  double coverage = 1.0;
};

/// Whether a matrix system's mass operator over the harmonics (D2, with the next sector's
/// coupling of a cyclic system) can be inverted, as Hill's method needs: its reciprocal
/// condition number above 1e-14. Known before any trace (it does not depend on the
/// solution). True for a receptance system (its modal realization has M = I).
bool hillMassInvertible(const HarmonicBalanceSystem& system);

/// The size of the eigenproblem Hill's method solves at a point of this system, and whether
/// it is solved whole (LAPACK) or only for the eigenvalues nearest zero (ARPACK): 2 m for
/// the receptance form's m modal coordinates over the harmonics' blocks, 2 n nc for the
/// matrix form (always whole). Depends on the system alone, not on the point, so a curve's
/// cost is known before any point is checked. 0 for a receptance model without a modal
/// realization.
struct HillProblemSize {
  int unknowns = 0;
  bool whole = true;
};
HillProblemSize hillProblemSize(const HarmonicBalanceSystem& system, const HillOptions& options = {});

/// Throws InputError for velocity-dependent elements (not supported yet), singular M, or a
/// receptance without a modal realization.
FloquetExponents hillStability(const HarmonicBalanceSystem& system, const Eigen::VectorXd& X, double omega,
                               const HillOptions& options = {});

}  // namespace cyclone::hbm
