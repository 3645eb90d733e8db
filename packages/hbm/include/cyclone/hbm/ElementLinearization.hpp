#pragma once
// An element's coefficient Jacobian dF/dW kept as what makes it, not formed: the
// law's tangent at every time sample, applied to a direction by a march over the
// period (AFT: to time, the tangent, back to harmonics). A formed Jacobian of a contact
// is (d (2H + 1))^2 entries, made by carrying that many sensitivities through the
// march and streamed from memory at every GMRES product; this holds a few numbers per
// sample, and a product costs two FFTs per coordinate and a march (issue 47's
// matrix-free products: what lets a Krylov Newton step carry tens of harmonics).
#include <Eigen/Dense>
#include <vector>

namespace cyclone::hbm {

class ElementLinearization {
public:
  virtual ~ElementLinearization() = default;
  /// dF = J dW, coefficient matrices nc x d (the element's harmonicForce layout):
  /// exactly the formed Jacobian's product (to rounding).
  virtual void apply(const Eigen::MatrixXd& dW, Eigen::MatrixXd& dF) const = 0;
  /// A preconditioner's approximation of J's block coupling the coefficient slots
  /// `slots` (one harmonic's cos[, sin]) to themselves, (d m) x (d m), index k m + r for
  /// coordinate k and the r-th slot: the law's instantaneous tangent at each sample
  /// (its memory of earlier samples left out), projected onto the harmonic.
  virtual Eigen::MatrixXd harmonicBlock(const std::vector<int>& slots) const = 0;
};

/// How a Jacobian kept as blocks holds its elements' Jacobians: Automatic, by an element's
/// linearization where it holds fewer numbers than the formed matrix (at H = 30 and 512
/// samples a 3D contact's tangent holds 12800 against 33489; at H = 5 and 256 samples
/// 6400 against 1089, and the formed block's exact (h, h) blocks precondition better);
/// Formed, every element's formed Jacobian; Tangents, the linearization wherever there is one.
enum class ElementJacobians { Automatic, Formed, Tangents };

}  // namespace cyclone::hbm
