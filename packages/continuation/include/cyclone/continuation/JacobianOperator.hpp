#pragma once
// A Jacobian applied to vectors instead of formed, with a preconditioner (an
// approximate inverse) beside it: what a continuation's Newton steps solve with by
// GMRES (KrylovSolve.hpp) where a dense LU of the Jacobian would cost too much (a
// harmonic balance with tens of harmonics on hundreds of contact coordinates).
#include <Eigen/Core>
#include <memory>
#include <vector>

namespace cyclone::continuation {

class JacobianOperator {
public:
  virtual ~JacobianOperator() = default;
  virtual int size() const = 0;
  /// y = J v.
  virtual void apply(const Eigen::VectorXd& v, Eigen::VectorXd& y) const = 0;
  /// Makes the preconditioner (factors its blocks); called once before precondition().
  virtual void preparePreconditioner() = 0;
  /// z = P^-1 r, P an approximation of J.
  virtual void precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z) const = 0;
  /// Rows i in `rows` become scale J_i + shift e_i^T, in the operator and in its
  /// preconditioner alike (a homotopy that switches equations on: HomotopySolve.hpp);
  /// called before preparePreconditioner. False where the operator cannot: its caller
  /// then modifies the products and keeps the preconditioner as it is.
  virtual bool blendRows(const std::vector<int>& rows, double scale, double shift) {
    (void)rows, (void)scale, (void)shift;
    return false;
  }
};

/// J s for a scalar s: the Jacobian of F(s y) in y, where the continuation works on
/// unknowns scaled by 1 / s.
class ScaledJacobianOperator final : public JacobianOperator {
public:
  ScaledJacobianOperator(std::shared_ptr<JacobianOperator> J, double s) : J_(std::move(J)), s_(s) {}
  int size() const override { return J_->size(); }
  void apply(const Eigen::VectorXd& v, Eigen::VectorXd& y) const override {
    J_->apply(v, y);
    y *= s_;
  }
  void preparePreconditioner() override { J_->preparePreconditioner(); }
  void precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z) const override {
    J_->precondition(r, z);
    z /= s_;
  }
  bool blendRows(const std::vector<int>& rows, double scale, double shift) override {
    return J_->blendRows(rows, scale, shift / s_);  // (scale J_i s + shift e_i) = s (scale J_i + shift / s e_i)
  }

private:
  std::shared_ptr<JacobianOperator> J_;
  double s_;
};

/// An owned object with the same operations (size, apply, factorPreconditioner,
/// precondition, blendRows: hbm::JacobianBlocks) as a JacobianOperator.
template <class Blocks>
class JacobianOperatorOf final : public JacobianOperator {
public:
  explicit JacobianOperatorOf(std::unique_ptr<Blocks> blocks) : blocks_(std::move(blocks)) {}
  int size() const override { return blocks_->size(); }
  void apply(const Eigen::VectorXd& v, Eigen::VectorXd& y) const override { blocks_->apply(v, y); }
  void preparePreconditioner() override { blocks_->factorPreconditioner(); }
  void precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z) const override { blocks_->precondition(r, z); }
  bool blendRows(const std::vector<int>& rows, double scale, double shift) override {
    blocks_->blendRows(rows, scale, shift);
    return true;
  }

private:
  std::unique_ptr<Blocks> blocks_;
};

}  // namespace cyclone::continuation
