#pragma once
// The sector's K_k, M_k at one nodal diameter reduced onto the retained DOFs
// taken as a boundary b (the rest is the interior i), what Guyan and
// Craig-Bampton models are made of:
//   constraint modes  Psi = [I; -K_ii^{-1} K_ib]  (one factorization of K_ii,
//                     all boundary DOFs as right-hand sides at once),
//   K_g = Psi^T K Psi = (K Psi)_b = K_bb - K_bi K_ii^{-1} K_ib,  M_g = Psi^T M Psi;
//   fixed-interface modes Phi = [0; phi_j] of (K_ii, M_ii), mass-normalised,
//   lambda_j = their eigenvalues, and the coupling M_bm = Psi^T M Phi.
// Psi^T K Phi = 0 because K Psi vanishes on the interior, so the reduced
// stiffness on [boundary; modal coordinates] is block diagonal: diag(K_g, lambda).
// Every retained DOF must be a single unknown (coefficient 1) of the cyclic
// transform: a fixed DOF, or a right-face or axis node (a combination of
// unknowns), cannot be a boundary coordinate and is an InputError.
#include <vector>

#include <Eigen/Dense>

namespace cyclone::rom {

class NodalDiameterModel;

struct BoundaryReduction {
  int copies = 1;                          ///< real-form copies of the nodal diameter
  Eigen::MatrixXd stiffness;               ///< K_g (retained x retained)
  Eigen::MatrixXd mass;                    ///< M_g (retained x retained)
  std::vector<double> interfaceEigenvalues;///< lambda_j of (K_ii, M_ii), ascending; pairs listed twice
  Eigen::MatrixXd massCoupling;            ///< M_bm = Psi^T M Phi (retained x interface modes)
  long long interiorEquations = 0;
  double staticSeconds = 0;                ///< K_ii factorization, constraint modes, K_g and M_g
  double modesSeconds = 0;                 ///< fixed-interface eigen-solution and M_bm

  int numInterfaceModes() const { return int(interfaceEigenvalues.size()); }
};

/// Constraint modes and the lowest `fixedInterfaceModes` distinct fixed-interface
/// natural frequencies (a pair counts once; 0: constraint modes only, i.e. Guyan).
/// InputError naming "retained" for a retained DOF that is fixed or not a single
/// unknown, or when K_ii does not factor (the retained DOFs do not hold the
/// interior); naming "fixed_interface_modes" for a negative count or more than the
/// interior has.
BoundaryReduction reduceOntoRetainedDofs(const NodalDiameterModel& model, int fixedInterfaceModes);

}  // namespace cyclone::rom
