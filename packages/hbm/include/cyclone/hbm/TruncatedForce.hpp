#pragma once
// How much of the nonlinear elements' force a harmonic balance leaves out: the sampled
// force of every element at a solution (the AFT's time samples, the element's own law)
// split by FFT into the harmonics the set keeps and those it drops (every other harmonic
// the samples resolve). The Galerkin projection sees only the kept ones, so a dropped
// part comparable with the kept one says that the truncation, not only the last change
// of a peak, is far from converged (the a-posteriori indicator of adaptive harmonic
// balance: Jaumouille, Sinou and Petitjean 2010; Grolet and Thouverez 2012). A contact
// that opens each period makes force pulses whose spectrum decays slowly: the default
// disc's shroud at 5 N preload (docs/scenes.md).
#include <Eigen/Dense>

#include "cyclone/hbm/HarmonicBalanceSystem.hpp"

namespace cyclone::hbm {

struct TruncatedForce {
  bool known = false;     ///< false: no elements, or no dynamic force in the set
  double kept = 0;        ///< sqrt of the sum over elements, components and kept harmonics h >= 1 of c_h^2 + s_h^2
  double dropped = 0;     ///< the same over the harmonics 1 .. N/2 - 1 the set leaves out
  double share = 0;       ///< dropped / kept
  int largestDropped = 0; ///< the dropped harmonic with the most force (0: none)
  double largestDroppedShare = 0;  ///< its amplitude over `kept`
};

/// At the solution x (the system's coefficients) and frequency omega.
TruncatedForce truncatedForce(const HarmonicBalanceSystem& system, const Eigen::VectorXd& x, double omega);

}  // namespace cyclone::hbm
