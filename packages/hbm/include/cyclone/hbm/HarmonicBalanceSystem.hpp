#pragma once
// The harmonic balance equations of a linear system with nonlinear elements:
//   M x'' + C x' + K x + sum_e [W_e f_e(w_e) + ...] = f_ex(t),  w_e = W_e^T x (+ W_next,e^T x_next),
// x periodic, unknowns the real Fourier coefficients of every DOF
// (X[dof * nc + coefficient], coefficient order of the HarmonicSet). The linear
// part is block diagonal per harmonic; the elements go through the AFT.
//
// Cyclic systems: one sector of a ring of N identical sectors, coupled to its
// neighbours by M_next, C_next, K_next (sector j's equation holds
// A x_j + A_next x_{j+1} + A_next^T x_{j-1}), under a travelling-wave
// excitation of engine order EO: sector j+1 moves like sector j delayed by
// 2 pi EO / N, so harmonic h of every sector is harmonic h of sector 0 rotated
// by h 2 pi EO / N (it lives on nodal diameter h EO mod N; Petrov 2004; Scalvini 2021,
// eqs. 7.9-7.15). Only sector 0 is solved; an element joining sector j to
// j+1 (W_next) is evaluated exactly, and its reaction on sector j+1 comes back
// to sector 0 from the element joining sector N-1 to 0.
//
// Receptance form: the linear part may instead be a model's dynamic compliance
// A at the DOFs the elements and the excitation use (ReceptanceModel: a reduced
// model of an FE sector). The residual is then, per harmonic,
//   R = kappa (X - A(h w) (s F_ex + F_static - F_nl(X))),
// kappa a fixed stiffness (1 / the largest diagonal entry of the mean
// compliance) that keeps the rows in force units like the matrix form's.
#include <memory>
#include <vector>

#include "cyclone/hbm/Aft.hpp"
#include "cyclone/hbm/JacobianBlocks.hpp"
#include "cyclone/hbm/ModalStiffnessBlocks.hpp"
#include "cyclone/hbm/NonlinearElement.hpp"
#include "cyclone/hbm/ReceptanceModel.hpp"
#include "cyclone/hbm/ScalarElement.hpp"

namespace cyclone::hbm {

/// Coupling of a sector to its neighbours in a ring of identical sectors.
struct CyclicCoupling {
  int sectors = 1;      ///< N >= 2 for a cyclic system
  int engineOrder = 0;  ///< EO of the travelling-wave excitation (any integer; folded mod N)
  Eigen::MatrixXd Mnext, Cnext, Knext;  ///< coupling to sector j+1 (empty = zero)
};

class HarmonicBalanceSystem {
public:
  HarmonicBalanceSystem(Eigen::MatrixXd M, Eigen::MatrixXd C, Eigen::MatrixXd K, HarmonicSet harmonics, int samples);
  /// The receptance form (see the file comment). A cyclic model still needs setCyclic
  /// (N equal to the model's, EO, no coupling matrices). M, C and K do not exist in this
  /// form: time integration, Hill stability, the damping scale and the full-ring
  /// expansion need the matrix form and say so.
  HarmonicBalanceSystem(std::shared_ptr<const ReceptanceModel> receptance, HarmonicSet harmonics, int samples);
  bool isReceptance() const { return receptance_ != nullptr; }
  /// Receptance form only: state the equations with the dynamic stiffness Z_h = A_h^{-1}
  /// per harmonic instead (R = Z X + F_nl - s F_ex - F_static, as the matrix form). The
  /// Jacobian is then Z + dF_nl/dX, without the dense product A dF_nl/dX: several times
  /// cheaper per Newton step. Needs every A_h invertible (a hybrid or full model; not a
  /// modal truncation with fewer modes than DOFs: Error when a harmonic's A is singular).
  void useDynamicStiffness(bool on);
  bool usesDynamicStiffness() const { return stiffnessForm_; }
  const std::shared_ptr<const ReceptanceModel>& receptance() const { return receptance_; }
  /// The stiffness kappa of the receptance form's rows (1 in the matrix form).
  double receptanceStiffness() const;

  /// Makes the system one sector of a ring (see the file comment). Call before
  /// adding elements that use W_next.
  void setCyclic(CyclicCoupling coupling);
  bool isCyclic() const { return cyclic_.sectors > 1; }
  const CyclicCoupling& cyclic() const { return cyclic_; }
  /// Nodal diameter of harmonic h: h EO mod N folded to 0..N/2 (0 when not cyclic).
  int nodalDiameter(int harmonic) const;
  /// The inter-sector phase index of harmonic h: h EO mod N in 0..N-1 (0 when not cyclic).
  long phaseIndex(int harmonic) const;
  /// Coefficients of sector j+1 from those of sector j, per DOF (nc x nc):
  /// the rotation of each harmonic h by -h 2 pi EO / N (identity when not cyclic).
  const Eigen::MatrixXd& nextSectorMap() const { return next_; }

  /// An element acting on w = W^T x (+ Wnext^T x_next): W (and Wnext) are
  /// numDofs x element.dimension(); Wnext is for elements joining this sector
  /// to the next one of a cyclic system. Forces go back through the transposes.
  void addElement(std::shared_ptr<const NonlinearElement> element, Eigen::MatrixXd W,
                  Eigen::MatrixXd Wnext = Eigen::MatrixXd());
  /// A scalar element on w = direction^T x (e.g. a unit vector for DOF-to-ground,
  /// e_i - e_j between two DOFs).
  void addElement(std::shared_ptr<const ScalarElement> element, Eigen::VectorXd direction);
  /// Swaps element i for another of the same dimension (a parameter study:
  /// element.withParameter(...)); W and W_next stay.
  void replaceElement(std::size_t i, std::shared_ptr<const NonlinearElement> element);
  /// Damping = s times the damping given (C and C_next): a continuation parameter.
  void setDampingScale(double s);
  double dampingScale() const { return dampingScale_; }
  /// Harmonic excitation on one DOF: f = cosAmplitude cos(h w t) + sinAmplitude sin(h w t)
  /// (on sector 0 of a cyclic system; sector j gets it delayed by j 2 pi EO / N).
  void addExcitation(int dof, int harmonic, double cosAmplitude, double sinAmplitude = 0);
  /// A constant force on one DOF that the excitation scale does not multiply (a
  /// static preload pressing a contact shut); needs harmonic 0 in the set.
  void addStaticLoad(int dof, double value);
  /// The same in coefficient form (layout of X): added to excitation() and staticLoad().
  void addExcitationCoefficients(const Eigen::VectorXd& F);
  void addStaticLoadCoefficients(const Eigen::VectorXd& L);

  int numDofs() const { return receptance_ ? receptance_->numDofs() : int(K_.rows()); }
  int numCoefficients() const { return aft_->numCoefficients(); }
  int numUnknowns() const { return numDofs() * numCoefficients(); }
  const Aft& aft() const { return *aft_; }

  /// R(X; omega) = Z(omega) X + F_nl(X) - s F_ex - F_static (s: excitation scale, a continuation
  /// parameter for force-level studies), and optionally dR/dX.
  void residual(const Eigen::VectorXd& X, double omega, Eigen::VectorXd& R, Eigen::MatrixXd* jacobian,
                double excitationScale = 1.0) const;
  /// The Jacobian dR/dX at X kept as its blocks (JacobianBlocks: applied and
  /// preconditioned harmonic by harmonic, never formed), for the matrix form and the
  /// dynamic-stiffness receptance form (InputError in the compliance form, whose rows
  /// A dF_nl/dX couple every harmonic: see hasJacobianBlocks). The blocks refer to this
  /// system, which must outlive them. Elements with a linearization (a 3D friction
  /// contact: ElementLinearization) are applied by their tangent per time sample as
  /// `elementJacobians` says (by default where it holds fewer numbers than the formed
  /// Jacobian; the formed one's (h, h) blocks are exact in the preconditioner).
  std::unique_ptr<JacobianBlocks> jacobianBlocks(const Eigen::VectorXd& X, double omega,
                                                 ElementJacobians elementJacobians = ElementJacobians::Automatic) const;
  bool hasJacobianBlocks() const { return !receptance_ || stiffnessForm_; }
  /// The dynamic-stiffness form's Z(omega) for every harmonic h >= 1 in Woodbury's parts
  /// (ModalStiffnessBlocks), when the model has them for every phase those harmonics use;
  /// else nullptr (the blocks are then formed). Kept for the last frequency asked.
  std::shared_ptr<const ModalStiffnessBlocks> modalStiffnessBlocks(double omega) const;
  /// Harmonic index i's block of Z(omega) (the harmonic's 1 or 2 coefficients of every
  /// DOF; local index a m + j, m = 1 for the mean, 2 otherwise).
  Eigen::MatrixXd linearHarmonicBlock(double omega, std::size_t i) const;
  /// The elements' force coefficients F_nl(X) and dF_nl/dX alone (both forms).
  void nonlinearForces(const Eigen::VectorXd& X, double omega, Eigen::VectorXd& F, Eigen::MatrixXd* jacobian) const;
  /// The solution without the nonlinear elements.
  Eigen::VectorXd linearSolution(double omega, double excitationScale = 1.0) const;
  /// The response of the system linearised about rest (X = 0), i.e. one Newton
  /// step from zero: stuck friction contacts and closed preloaded gaps keep their
  /// stiffness. The start for continuation (the linear solution without the
  /// elements can be far from a stuck contact's response).
  Eigen::VectorXd linearizedSolution(double omega, double excitationScale = 1.0) const;
  /// The dynamic stiffness Z(omega) of the linear part (numUnknowns square); matrix form only.
  Eigen::MatrixXd linearOperator(double omega) const;
  /// The same into Z, whose storage is kept when it has the size (a Jacobian's).
  void linearOperatorInto(double omega, Eigen::MatrixXd& Z) const;
  /// The compliance A(omega) in coefficient space (numUnknowns square, 2 x 2 blocks
  /// [Re A, Im A; -Im A, Re A] per harmonic on (cos, sin)); receptance form only.
  Eigen::MatrixXd complianceOperator(double omega) const;
  /// Its inverse, harmonic by harmonic (receptance form only).
  Eigen::MatrixXd dynamicStiffnessOperator(double omega) const;
  /// A (x) I + A_next (x) S + A_next^T (x) S^T in coefficient space, S the next-sector
  /// map: how a sector matrix acts on the coefficients of a cyclic solution.
  Eigen::MatrixXd coefficientOperator(const Eigen::MatrixXd& A, const Eigen::MatrixXd& Anext) const;

  /// The matrices of the matrix form (InputError in the receptance form).
  const Eigen::MatrixXd& M() const;
  const Eigen::MatrixXd& C() const;
  const Eigen::MatrixXd& K() const;
  struct Connection {
    std::shared_ptr<const NonlinearElement> element;
    Eigen::MatrixXd W, Wnext;  ///< Wnext empty unless the element joins to the next sector
  };
  const std::vector<Connection>& elements() const { return elements_; }
  /// The (scaled) excitation in coefficient form (same layout as X).
  const Eigen::VectorXd& excitation() const { return excitation_; }
  /// The static loads in coefficient form (same layout as X).
  const Eigen::VectorXd& staticLoad() const { return static_; }

  /// Amplitude sqrt(c_h^2 + s_h^2) of harmonic h >= 1 of a DOF.
  double amplitude(const Eigen::VectorXd& X, int dof, int harmonic) const;

private:
  void requireMatrixForm(const char* what) const;
  /// Adds the elements' force coefficients to R and their Jacobian to *jacobian.
  void addElementForces(const Eigen::VectorXd& X, double omega, Eigen::VectorXd& R, Eigen::MatrixXd* jacobian) const;
  std::shared_ptr<const ReceptanceModel> receptance_;
  Eigen::MatrixXd mean_;  // receptance form: the mean compliance
  mutable double kappa_ = 1.0;
  bool stiffnessForm_ = false;
  Eigen::MatrixXd meanStiffness_;
  // The last frequency's per-harmonic blocks (residual and Jacobian come at the same
  // frequency): for harmonic index i of the harmonic set, the real and imaginary parts
  // of A(h w) or its inverse (the mean block real, imaginary part empty).
  struct HarmonicBlocks {
    double omega = -1;
    bool inverse = false;
    std::vector<Eigen::MatrixXd> re, im;
  };
  mutable HarmonicBlocks blocks_;
  mutable std::shared_ptr<const ModalStiffnessBlocks> woodbury_;  // modalStiffnessBlocks' last
  mutable double woodburyOmega_ = -1;
  mutable int woodburyHeld_ = -1;  // whether the model has the parts: -1 not yet asked
  const HarmonicBlocks& harmonicBlocks(double omega, bool inverse) const;
  /// Y = B X with B the per-harmonic operator, applied block by block (never formed).
  void applyHarmonicOperator(double omega, bool inverse, const Eigen::VectorXd& X, Eigen::VectorXd& Y) const;
  /// R = Z(omega) X of the matrix form, applied DOF block by DOF block (never formed).
  void applyLinearOperator(double omega, const Eigen::VectorXd& X, Eigen::VectorXd& R) const;
  /// The per-harmonic operator as a dense numUnknowns square matrix.
  Eigen::MatrixXd harmonicOperator(double omega, bool inverse) const;
  void harmonicOperatorInto(double omega, bool inverse, Eigen::MatrixXd& B) const;  // B's storage kept
  Eigen::MatrixXd M_, C_, K_;
  Eigen::MatrixXd C0_, Cnext0_;  // the damping given, before setDampingScale
  double dampingScale_ = 1.0;
  std::unique_ptr<Aft> aft_;
  CyclicCoupling cyclic_;
  Eigen::MatrixXd next_;
  std::vector<Connection> elements_;
  Eigen::VectorXd excitation_, static_;
};

}  // namespace cyclone::hbm
