#pragma once
// The linear part of a harmonic balance system given by its dynamic compliance
// (receptance) at the DOFs the nonlinear elements and the excitation use,
// instead of by M, C and K: what a reduced model of a large FE sector hands to
// the harmonic balance (Scalvini 2021, ch. 7: x_h = A(h w) (f_h - f_nl,h)). Whatever
// kind of model it is (full FE compliance, hybrid FRF, modal truncation,
// Guyan, Craig-Bampton), the harmonic balance sees only this.
//
// Complex convention: harmonic h of a DOF, c cos(h w t) + s sin(h w t), is
// Re(X e^{i h w t}) with X = c - i s, and X = A F for forces in the same form.
// A cyclic sector (N sectors) under an engine-order excitation has its
// neighbour j+1 moving as X_{j+1} = e^{-i 2 pi p / N} X_j, p the phase index
// h EO mod N (HarmonicBalanceSystem's convention): the model answers for that p.
#include <Eigen/Dense>
#include <optional>

namespace cyclone::hbm {

class ModalStiffness;

/// The compliance of one phase index as modes plus a constant part, what Hill's
/// method needs of a receptance (it has no M, C, K):
///   A(w) = R / (1 + i eta) + U diag(1 / ((1 + i eta) l_j + i c_j w - w^2)) V^T   for w > 0,
///   A(0) = R + U diag(1 / l_j) V^T   (the undamped mean compliance, phase 0),
/// eta the structural loss factor, c_j modal viscous damping. A time-domain
/// realization needs causal damping: Hill's method gives mode j at harmonic h
/// the viscous damping c_j + eta l_j / (h w) (eta w_j at h = 0), equal to the
/// structural one at the harmonic's frequency, so that its matrix at lambda = 0
/// is the harmonic balance Jacobian and folds fall where the curve turns.
struct ModalRealization {
  Eigen::MatrixXcd R;           ///< n x n constant part (the modes not kept), undamped
  Eigen::MatrixXcd U, V;        ///< n x m
  Eigen::VectorXd eigenvalues;  ///< l_j = w_j^2, (rad/s)^2
  Eigen::VectorXd viscous;      ///< c_j in rad/s (size m)
  double lossFactor = 0;
  int numModes() const { return int(eigenvalues.size()); }
};

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
  /// The undamped static compliance of phase p (complex Hermitian; phase 0's is
  /// meanCompliance()): what harmonic 0 of a ring assembled from the sector's phases needs
  /// (mistuning::RingReceptance). By default meanCompliance() for phase 0 and, for another
  /// phase, R + U diag(1 / l) V^T of its modal realization; InputError naming
  /// "receptance" where there is none.
  virtual Eigen::MatrixXcd staticCompliance(long phaseIndex) const;
  /// The modal realization of phase p (see ModalRealization), or none when the model
  /// has no modal form (then Hill's method cannot be applied to it).
  virtual std::optional<ModalRealization> modalRealization(long phaseIndex) const;
  /// The dynamic stiffness of phase p in Woodbury's parts (ModalStiffness: a constant plus
  /// a low-rank modal part) where the model has them and they hold, else nullptr; owned by
  /// the model. dynamicStiffness(w, p) is then that ModalStiffness's Z(w).
  virtual const ModalStiffness* modalStiffness(long phaseIndex) const;
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
  /// K_p^{-1} (InputError where K_p is singular).
  Eigen::MatrixXcd staticCompliance(long phaseIndex) const override;
  /// Modes of (K_p, M_p) with U = Phi, V = conj(Phi); none unless Phi^H C_p Phi is
  /// diagonal (modal damping) and M_p positive definite.
  std::optional<ModalRealization> modalRealization(long phaseIndex) const override;

private:
  Eigen::MatrixXcd phased(const Eigen::MatrixXd& A, const Eigen::MatrixXd& Anext, long phaseIndex) const;
  Eigen::MatrixXd M_, C_, K_, Mnext_, Cnext_, Knext_;
  int sectors_ = 1;
};

}  // namespace cyclone::hbm
