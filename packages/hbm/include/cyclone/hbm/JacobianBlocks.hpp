#pragma once
// The Jacobian of a harmonic balance system kept as the blocks it is made of, never
// formed as one dense matrix: the linear part, block diagonal by harmonic (one dense
// block over the DOFs per harmonic), and each nonlinear element's coefficient Jacobian,
// dense over that element's own coordinates and harmonics. A product with it costs
// about (H + 1) n^2 + sum_e (d_e (2H + 1))^2, where the dense matrix holds
// (n (2H + 1))^2 entries and its LU costs their 3/2 power: what lets a Newton step
// carry tens of harmonics on hundreds of contact coordinates (issue 47). A hybrid
// model's linear part is applied in Woodbury's parts (ModalStiffnessBlocks), and an
// element block with few nonzeros as a sparse matrix: what a product reads is what
// sets its time (docs/solvers.md).
//
// The preconditioner is the Jacobian's own block diagonal by harmonic: per harmonic h,
// the linear part's block plus every element's (h, h) block (its coupling of harmonic h
// to itself: the contact's mean tangent and its 2h-th harmonic), each factored by LU in
// single precision. An element applied by its tangent per sample (ElementLinearization)
// gives its instantaneous tangent's (h, h) block there instead of its Jacobian's.
// What it leaves out is the elements' coupling between different harmonics, the part
// that grows where a contact opens and closes within the period.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "cyclone/hbm/ElementLinearization.hpp"
#include "cyclone/hbm/ModalStiffnessBlocks.hpp"

namespace cyclone::hbm {

class HarmonicBalanceSystem;

class JacobianBlocks {
public:
  /// One element's coefficient Jacobian dF_e/dW_e ((nc d) x (nc d), index k nc + c) and
  /// the element's index in the system's elements().
  struct ElementBlock {
    std::size_t element = 0;
    Eigen::MatrixXd jacobian;  ///< empty where `linearization` stands for it
    std::shared_ptr<const ElementLinearization> linearization;
    std::vector<int> support;  ///< the DOFs its W or W_next reach
  };

  /// Made by HarmonicBalanceSystem::jacobianBlocks (the system, whose elements' maps it
  /// applies, must outlive it; its linear part's blocks are copied).
  JacobianBlocks(const HarmonicBalanceSystem& system, double omega, std::vector<ElementBlock> elements);

  int size() const;
  /// Rows scaled: J becomes diag(s) J (the continuation's force-scaled residual rows).
  void scaleRows(Eigen::VectorXd s);
  /// Rows i in `rows` become scale J_i + shift e_i^T (after the row scale: of diag(s) J),
  /// in the products and in the preconditioner's blocks (a homotopy that switches those
  /// equations on). Before factorPreconditioner.
  void blendRows(const std::vector<int>& rows, double scale, double shift);
  /// y = J v.
  void apply(const Eigen::VectorXd& v, Eigen::VectorXd& y) const;
  /// Forms and factors the block diagonal by harmonic (before precondition()).
  void factorPreconditioner();
  /// z = P^-1 r with P the block diagonal by harmonic (factorPreconditioner first).
  void precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;
  /// The dense matrix (tests: the blocks against the system's dense Jacobian).
  Eigen::MatrixXd dense() const;
  /// How many element blocks are held sparse (few nonzeros: a contact stuck or open all period).
  int sparseElements() const;
  /// Harmonic index i's diagonal block (the preconditioner's block before factoring;
  /// local index a m + j for DOF a and its j-th coefficient of the harmonic, m = 1 or 2).
  Eigen::MatrixXd harmonicBlock(std::size_t i) const;

private:
  void gather(std::size_t i, const Eigen::VectorXd& v, Eigen::VectorXd& local) const;
  void scatter(std::size_t i, const Eigen::VectorXd& local, Eigen::VectorXd& v) const;
  void solveBlock(std::size_t i) const;
  const HarmonicBalanceSystem& system_;
  double omega_;
  std::vector<ElementBlock> elements_;
  // Per element: its Jacobian's nonzeros when they are few (a contact stuck or open all
  // period: kt and kn on the diagonal and the mean's rows), else empty and the dense
  // block is applied. Exact: the same products on a fraction of the memory.
  std::vector<Eigen::SparseMatrix<double, Eigen::RowMajor>> sparseElements_;
  std::vector<std::vector<int>> slots_;  // per harmonic index: its coefficient slots (cos[, sin])
  std::vector<Eigen::MatrixXd> linear_;  // per harmonic index: the linear part's block (copied: the
                                         // system's per-frequency cache moves with its residuals)
  Eigen::VectorXd rowScale_;  // empty: 1
  std::vector<int> blendedRows_;  // blendRows: rows i are blendScale_ J_i + blendShift_ e_i^T
  double blendScale_ = 1, blendShift_ = 0;
  std::vector<Eigen::MatrixXcd> linearComplex_;  // the same where it is complex-structured (linear_ then empty)
  // The dynamic-stiffness form's harmonics in Woodbury's parts where the model has them
  // (then linear_ and linearComplex_ are empty for the indices it covers).
  std::shared_ptr<const ModalStiffnessBlocks> woodbury_;
  mutable Eigen::MatrixXcd woodburyIn_, woodburyOut_;
  std::vector<Eigen::PartialPivLU<Eigen::MatrixXf>> blockLu_;  // single precision (solveBlock)
  // Work vectors of precondition() (one harmonic's coefficients): no allocation per call.
  // Per block width (index 0: the mean's n coefficients, 1: a harmonic's 2n), so that
  // alternating widths do not reallocate them at every product.
  int width(std::size_t i) const { return int(slots_[i].size()) - 1; }
  mutable Eigen::VectorXd gathered_[2], solved_[2], unscaled_;
  mutable Eigen::VectorXf gatheredSingle_[2], solvedSingle_[2];
  mutable Eigen::VectorXcd complexIn_, complexOut_;
  mutable Eigen::MatrixXd w_, wNext_, f_;  // apply()'s element coordinates and forces
};

}  // namespace cyclone::hbm
