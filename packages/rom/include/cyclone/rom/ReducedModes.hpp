#pragma once
// The natural frequencies and mode shapes of a reduced model given by dense
// K, M (Guyan: on the retained DOFs; Craig-Bampton: on [retained DOFs; modal
// coordinates]), seen at the retained DOFs (the leading rows). Mass-normalised in
// the reduced M, which is the full M on the Ritz subspace, so the shapes compare
// with the full model's modes directly (MAC, modal participation). By the
// Rayleigh-Ritz bound every eigenvalue lies at or above the full model's.
// Also: the check for rigid-body modes before a zero-frequency compliance.
#include <Eigen/Dense>

#include "cyclone/rom/HybridFrfModel.hpp"

namespace cyclone::rom {

/// All eigenpairs of (K, M), ascending; shapes are the first `retained` rows.
/// InputError when M is not positive definite.
RetainedModes reducedModes(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, Eigen::Index retained, int copies);

/// Throws InputError when the reduced stiffness K_g on the retained DOFs is singular
/// (a free sector: rigid-body modes), naming the count. K_g is singular exactly when
/// K is (det K = det K_ii det K_g, K_ii held by the retained DOFs); numerically its
/// eigenvalues below 1e-10 of the largest (round-off of a rigid motion is ~1e-14 of
/// it; a held sector's boundary stiffness is far better conditioned) count as zero.
void requireNonsingularStiffness(const Eigen::MatrixXd& stiffness, const char* kind);

}  // namespace cyclone::rom
