#pragma once
// One nodal diameter's operators projected from the sector's physical matrices
// (SectorMatrices) by its cyclic transform T: T^H A T, and the factorization of
// K - sigma M for its shift-invert eigen-solution.
//
// For a travelling-wave pair (0 < k < N/2, cyclicTransform's paired unknowns) the
// operators are kept in complex Hermitian form on the n/2 unknowns
// z_m = x_2m + i x_2m+1: the real 2-copy form is [[P, -Q], [Q, P]] on the pairs and
// P + iQ holds the same information at a quarter of the storage; CHOLMOD factors it
// (complex LL^H) in about half the flops of the real form. Everything outside acts on
// real-form vectors (the unknowns of the transform), read in place as complex ones
// (a pair (x_2m, x_2m+1) is the memory layout of a complex number).
// Otherwise (k = 0, N/2, or a transform that does not pair) the real form
// sum over copies of T_c^T A T_c. Both forms keep only their lower triangles.
// Only K is projected (what the factor needs; M too where a shift needs K - sigma M);
// M, and K once the projections are released after the factor, are applied through
// the sector's matrices as T^H (A (T x)): the factorization's memory peak holds one
// projection (K at sigma = 0 is handed to the factor, which releases it once it has
// its permuted copy), the eigen-solution none.
#include <complex>
#include <memory>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "cyclone/cyclic/SectorMatrices.hpp"
#include "cyclone/fe/DofTransform.hpp"

namespace cyclone::cyclic {

/// Factorizations carried from one nodal diameter to the next. Every travelling-wave
/// nodal diameter projects onto the same pattern (and so does every real one), so
/// CHOLMOD's symbolic analysis (ordering, elimination tree, supernodes) is done once
/// per pattern and each further nodal diameter only factors numerically.
class FactorCache {
public:
  FactorCache();
  ~FactorCache();
  FactorCache(const FactorCache&) = delete;
  FactorCache& operator=(const FactorCache&) = delete;

private:
  friend class NodalDiameterForm;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

class NodalDiameterForm {
public:
  NodalDiameterForm(const SectorMatrices& sector, const fe::DofTransform& transform);
  ~NodalDiameterForm();
  NodalDiameterForm(NodalDiameterForm&&) noexcept;
  NodalDiameterForm& operator=(NodalDiameterForm&&) noexcept;

  bool complexForm() const;
  long long size() const;  ///< real-form unknowns (the transform's equations)

  /// y = K x and y = M x on real-form column blocks.
  void applyK(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const;
  void applyM(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const;
  /// y = i x on the real form (complex form only): (x_2m, x_2m+1) -> (-x_2m+1, x_2m).
  void timesI(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const;
  /// Frobenius norms of the real forms.
  double normK() const;
  double normM() const;

  /// Factors K - sigma M; throws SolverError when it is not positive definite.
  void factor(double sigma);
  /// The same, keeping the factor in `cache` (reusing its symbolic analysis when the
  /// pattern matches): solveShifted then holds until the cache factors another form.
  void factor(double sigma, FactorCache& cache);
  /// Frees the projected K (and M, formed only for a shift) after factor, which no
  /// longer needs them; K and M are applied from then on through the sector's
  /// matrices, T^H (A (T x)): the same products to rounding at about the same cost.
  /// `sector` must outlive the form.
  void releaseProjections();
  bool factored() const;
  /// y = (K - sigma M)^{-1} x after factor().
  void solveShifted(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const;
  /// Its halves (SparseCholesky::solveLower, solveUpper) on real-form blocks.
  void solveLower(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const;
  void solveUpper(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const;
  double factorNonzeros() const;  ///< nnz(L) (complex entries in complex form)

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cyclone::cyclic
