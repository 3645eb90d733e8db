#pragma once
// Petrov's condensed harmonic balance of a receptance-form system: the unknowns
// are what the elements see (each element's relative coordinates w_e = W_e^T x +
// W_next,e^T x_next) and the DOFs the excitation acts on or the caller watches,
// instead of every retained DOF. The linear part becomes the receptance of those
// coordinates (ProjectedReceptance); every force of the system acts on them, so
// the condensed equations have the same solutions, and the other DOFs follow
// from the forces afterwards (expandToAllDofs). For the FE disc: 3 coordinates
// per shroud contact pair plus the blade node, about half the retained DOFs, and
// a dense Newton factorisation about 8 times cheaper.
#include <memory>
#include <vector>

#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/hbm/ProjectedReceptance.hpp"

namespace cyclone::hbm {

struct CondensedSystem {
  /// Unknowns: the coefficients of q = [the kept DOFs, then each element's coordinates].
  std::unique_ptr<HarmonicBalanceSystem> system;
  std::shared_ptr<const ProjectedReceptance> receptance;
  std::vector<int> keptDofs;           ///< q(i) = x(keptDofs[i]) for i < keptDofs.size()
  std::vector<int> elementCoordinate;  ///< element e acts on q(elementCoordinate[e] + 0..d_e-1)
};

/// The condensed form of `full` (receptance form: InputError otherwise). keptDofs must
/// hold every DOF the excitation or a static load acts on (InputError naming the DOF
/// otherwise); duplicates are dropped, the order kept. InputError when the coordinates
/// are not independent at some harmonic (e.g. a kept DOF that is also an element's
/// coordinate): then solve the full system.
CondensedSystem condenseOntoElements(const HarmonicBalanceSystem& full, const std::vector<int>& keptDofs);

/// The full system's coefficients (every DOF) at a condensed solution Q:
/// X = A(omega) T^H (s F_ex + F_static - F_nl(Q)), harmonic by harmonic.
Eigen::VectorXd expandToAllDofs(const HarmonicBalanceSystem& full, const CondensedSystem& condensed,
                                const Eigen::VectorXd& Q, double omega, double excitationScale = 1.0);

}  // namespace cyclone::hbm
