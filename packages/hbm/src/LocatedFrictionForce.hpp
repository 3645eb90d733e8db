#pragma once
// A friction contact with one tangential direction (a 2D contact: slip t, normal
// approach n) whose stick, slip, lift-off and closing instants are located between
// the time samples instead of at them.
//
// The sampled law (a return mapping per sample) puts a kink into the force
// coefficients wherever an instant crosses a sample; as a curve is traced through
// hammering every instant crosses every sample, and the kinks fold the curve into
// hairpins no continuation step passes (docs/solvers.md). Here the motion between
// two samples is the cubic Hermite interpolant of the samples' values and slopes
// (C1 over the period, smooth in the coefficients), the contact law is followed in
// continuous time along it with every instant found as a root, and each sample
// takes the hat-weighted integral of the force over its two intervals (exact: the
// force is a cubic between instants). The force is continuous at every instant, so
// these integrals are C1 in the motion's coefficients; the hat's spectral factor
// sinc^2(h pi / N) is divided out of each harmonic. The result converges to the
// Fourier coefficients of the continuous-time law as the samples grow (fourth
// order between instants).
#include <Eigen/Dense>
#include <vector>

#include "cyclone/hbm/Aft.hpp"
#include "cyclone/hbm/FrictionContact.hpp"

namespace cyclone::hbm::detail {

/// F = diag(stiffness) W + preload (the normal mean) minus the harmonics of what the force
/// leaves out of those linear springs, from its hat-weighted integrals (N x d, and their
/// sensitivities: column i of sensitivities[c] is d(remainders(i, c))/dvec(W)).
void assembleFromRemainders(const Aft& aft, const Eigen::MatrixXd& W, const Eigen::VectorXd& stiffness, double preload,
                            const Eigen::MatrixXd& remainders, const std::vector<const Eigen::MatrixXd*>& sensitivities,
                            Eigen::MatrixXd& F, Eigen::MatrixXd* jacobian);

/// F (nc x 2) of the contact with parameters p (tangentialDirections = 1) for the
/// motion's coefficients W (nc x 2, columns t and n) and, if asked, dvec(F)/dvec(W).
/// The slider starts relaxed and is marched until its state at the period's start
/// repeats (a slip or a lift-off erases its memory: two periods at most); false when
/// it did not within four.
bool locatedFrictionForce(const FrictionContactParameters& p, const Aft& aft, const Eigen::MatrixXd& W,
                          Eigen::MatrixXd& F, Eigen::MatrixXd* jacobian);

}  // namespace cyclone::hbm::detail
