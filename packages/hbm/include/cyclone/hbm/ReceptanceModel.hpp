#pragma once
// The linear part of a harmonic balance system given by its dynamic compliance
// (receptance) at the DOFs the nonlinear elements and the excitation use,
// instead of by M, C and K: what a reduced model of a large FE sector hands to
// the harmonic balance (seed ch. 7: x_h = A(h w) (f_h - f_nl,h)). Whatever
// kind of model it is (full FE compliance, hybrid FRF, modal truncation,
// Guyan, Craig-Bampton), the harmonic balance sees only this.
//
// Complex convention: harmonic h of a DOF, c cos(h w t) + s sin(h w t), is
// Re(X e^{i h w t}) with X = c - i s, and X = A F for forces in the same form.
// A cyclic sector (N sectors) under an engine-order excitation has its
// neighbour j+1 moving as X_{j+1} = e^{-i 2 pi p / N} X_j, p the phase index
// h EO mod N (HarmonicBalanceSystem's convention): the model answers for that p.
#include <Eigen/Dense>

namespace cyclone::hbm {

class ReceptanceModel {
public:
  virtual ~ReceptanceModel() = default;
  virtual int numDofs() const = 0;
  /// N of the ring the model is a sector of (1: not cyclic).
  virtual int sectors() const = 0;
  /// A at frequency `frequency` > 0 (rad/s) for the inter-sector phase index p in 0..N-1.
  virtual Eigen::MatrixXcd compliance(double frequency, long phaseIndex) const = 0;
  /// Its inverse, the dynamic stiffness; models with structure (a constant plus a
  /// low-rank modal part) override this with something cheaper than an LU inverse.
  virtual Eigen::MatrixXcd dynamicStiffness(double frequency, long phaseIndex) const;
  /// The undamped static compliance of the phase-0 (nodal diameter 0) motion: harmonic 0.
  virtual Eigen::MatrixXd meanCompliance() const = 0;
};

/// The receptance of a matrix system (and its cyclic coupling, as in
/// HarmonicBalanceSystem): A = (K_p + i f C_p - f^2 M_p)^{-1} with
/// K_p = K + K_next e^{-i 2 pi p / N} + K_next^T e^{+i 2 pi p / N}. For tests
/// (the receptance form against the matrix form) and for codes that have a
/// small reduced model as matrices.
class MatrixReceptance final : public ReceptanceModel {
public:
  MatrixReceptance(Eigen::MatrixXd M, Eigen::MatrixXd C, Eigen::MatrixXd K, int sectors = 1,
                   Eigen::MatrixXd Mnext = {}, Eigen::MatrixXd Cnext = {}, Eigen::MatrixXd Knext = {});
  int numDofs() const override { return int(K_.rows()); }
  int sectors() const override { return sectors_; }
  Eigen::MatrixXcd compliance(double frequency, long phaseIndex) const override;
  Eigen::MatrixXd meanCompliance() const override;

private:
  Eigen::MatrixXcd phased(const Eigen::MatrixXd& A, const Eigen::MatrixXd& Anext, long phaseIndex) const;
  Eigen::MatrixXd M_, C_, K_, Mnext_, Cnext_, Knext_;
  int sectors_ = 1;
};

}  // namespace cyclone::hbm
