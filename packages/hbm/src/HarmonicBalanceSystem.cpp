#include "cyclone/hbm/HarmonicBalanceSystem.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/ScalarElementAdapter.hpp"

namespace cyclone::hbm {

HarmonicBalanceSystem::HarmonicBalanceSystem(Eigen::MatrixXd M, Eigen::MatrixXd C, Eigen::MatrixXd K,
                                             HarmonicSet harmonics, int samples)
    : M_(std::move(M)), C_(std::move(C)), K_(std::move(K)) {
  const auto n = K_.rows();
  if (K_.cols() != n || M_.rows() != n || M_.cols() != n || C_.rows() != n || C_.cols() != n)
    throw InputError("system", "M, C and K must be square and of the same size");
  aft_ = std::make_unique<Aft>(std::move(harmonics), samples);
  excitation_ = Eigen::VectorXd::Zero(numUnknowns());
  static_ = Eigen::VectorXd::Zero(numUnknowns());
  next_ = Eigen::MatrixXd::Identity(numCoefficients(), numCoefficients());
  C0_ = C_;
}

HarmonicBalanceSystem::HarmonicBalanceSystem(std::shared_ptr<const ReceptanceModel> receptance,
                                             HarmonicSet harmonics, int samples)
    : receptance_(std::move(receptance)) {
  if (!receptance_) throw InputError("system", "no receptance model given");
  if (receptance_->numDofs() < 1) throw InputError("system", "the receptance model has no DOFs");
  aft_ = std::make_unique<Aft>(std::move(harmonics), samples);
  excitation_ = Eigen::VectorXd::Zero(numUnknowns());
  static_ = Eigen::VectorXd::Zero(numUnknowns());
  next_ = Eigen::MatrixXd::Identity(numCoefficients(), numCoefficients());
  if (aft_->harmonics().contains(0)) {
    mean_ = receptance_->meanCompliance();
    if (mean_.rows() != numDofs() || mean_.cols() != numDofs() || !mean_.allFinite())
      throw InputError("system", "the receptance model's mean compliance is not a finite " +
                                     std::to_string(numDofs()) + " square matrix");
  }
  kappa_ = 0;  // set on first use (the phases of a cyclic system come later)
}

double HarmonicBalanceSystem::receptanceStiffness() const {
  if (kappa_ > 0) return kappa_;
  if (!receptance_) return 1.0;
  // 1 / the largest static compliance on the diagonal: the mean's, or the lowest harmonic's at rest.
  const auto& H = aft_->harmonics();
  double largest = 0;
  if (mean_.size() != 0) largest = mean_.diagonal().cwiseAbs().maxCoeff();
  else largest = receptance_->compliance(0.0, phaseIndex(H.harmonics().front())).diagonal().cwiseAbs().maxCoeff();
  if (!(largest > 0) || !std::isfinite(largest))
    throw InputError("system", "the receptance model's static compliance is zero or not finite");
  kappa_ = 1.0 / largest;
  return kappa_;
}

const Eigen::MatrixXd& HarmonicBalanceSystem::M() const { return requireMatrixForm("M"), M_; }
const Eigen::MatrixXd& HarmonicBalanceSystem::C() const { return requireMatrixForm("C"), C_; }
const Eigen::MatrixXd& HarmonicBalanceSystem::K() const { return requireMatrixForm("K"), K_; }

void HarmonicBalanceSystem::requireMatrixForm(const char* what) const {
  if (receptance_)
    throw InputError("system", std::string(what) + " needs the matrix form (M, C, K); this system is given by a "
                                                   "receptance (reduced) model");
}

void HarmonicBalanceSystem::setCyclic(CyclicCoupling coupling) {
  const int n = numDofs();
  if (coupling.sectors < 2)
    throw InputError("system", "a cyclic system needs at least 2 sectors, got " + std::to_string(coupling.sectors));
  if (receptance_) {
    if (coupling.sectors != receptance_->sectors())
      throw InputError("system", "the receptance model is a sector of " + std::to_string(receptance_->sectors()) +
                                     ", the cyclic coupling says " + std::to_string(coupling.sectors) + " sectors");
    for (auto* A : {&coupling.Mnext, &coupling.Cnext, &coupling.Knext})
      if (A->size() != 0 && A->norm() != 0)
        throw InputError("system", "a receptance model holds its coupling to the next sector itself: no M/C/K_next");
  }
  for (auto* A : {&coupling.Mnext, &coupling.Cnext, &coupling.Knext}) {
    if (A->size() == 0) *A = Eigen::MatrixXd::Zero(n, n);
    if (A->rows() != n || A->cols() != n)
      throw InputError("system", "the coupling matrices to the next sector must be " + std::to_string(n) + " x " +
                                     std::to_string(n));
  }
  cyclic_ = std::move(coupling);
  blocks_ = HarmonicBlocks{}, woodbury_.reset(), woodburyOmega_ = -1, woodburyHeld_ = -1;  // the phases changed
  if (receptance_ && mean_.size() == 0) kappa_ = 0;
  Cnext0_ = cyclic_.Cnext;
  cyclic_.Cnext *= dampingScale_;
  // Sector j+1 is sector j delayed by phi = 2 pi EO / N: harmonic h rotates by h phi.
  const auto& H = aft_->harmonics();
  next_.setIdentity(numCoefficients(), numCoefficients());
  const long N = cyclic_.sectors;
  for (int h : H.harmonics()) {
    if (h == 0) continue;
    const long k = phaseIndex(h);  // exact integer phase before the trig
    const double a = 2 * M_PI * double(k) / double(N), c = std::cos(a), s = std::sin(a);
    const int i = H.cosIndex(h);
    next_(i, i) = c, next_(i, i + 1) = -s;
    next_(i + 1, i) = s, next_(i + 1, i + 1) = c;
  }
}

long HarmonicBalanceSystem::phaseIndex(int harmonic) const {
  const long N = cyclic_.sectors;
  return ((long(harmonic) * cyclic_.engineOrder) % N + N) % N;
}

int HarmonicBalanceSystem::nodalDiameter(int harmonic) const {
  if (!isCyclic()) return 0;
  const long N = cyclic_.sectors, k = phaseIndex(harmonic);
  return int(k > N / 2 ? N - k : k);
}

void HarmonicBalanceSystem::addElement(std::shared_ptr<const NonlinearElement> element, Eigen::MatrixXd W,
                                       Eigen::MatrixXd Wnext) {
  if (!element) throw InputError("nonlinear element", "no element given");
  const int d = element->dimension();
  auto check = [&](const Eigen::MatrixXd& A, const char* name) {
    if (A.rows() != numDofs() || A.cols() != d)
      throw InputError("nonlinear element", std::string(name) + " must be " + std::to_string(numDofs()) + " x " +
                                                std::to_string(d) + " (DOFs x element coordinates), got " +
                                                std::to_string(A.rows()) + " x " + std::to_string(A.cols()));
    if (!A.allFinite()) throw InputError("nonlinear element", std::string(name) + " has entries that are not finite");
  };
  check(W, "W");
  if (Wnext.size() != 0) {
    check(Wnext, "W_next");
    if (!isCyclic())
      throw InputError("nonlinear element", "W_next joins a sector to the next one: the system must be cyclic");
  }
  elements_.push_back({std::move(element), std::move(W), std::move(Wnext)});
}

void HarmonicBalanceSystem::replaceElement(std::size_t i, std::shared_ptr<const NonlinearElement> element) {
  if (i >= elements_.size()) throw InputError("nonlinear element", "no element " + std::to_string(i));
  if (!element || element->dimension() != elements_[i].element->dimension())
    throw InputError("nonlinear element", "a replacement must have the same number of coordinates");
  elements_[i].element = std::move(element);
}

void HarmonicBalanceSystem::setDampingScale(double s) {
  if (receptance_)
    throw InputError("damping scale", "the damping of a receptance (reduced) model is inside the model: rebuild it "
                                      "with another loss factor");
  if (!(std::isfinite(s) && s >= 0)) throw InputError("damping scale", "must be >= 0, got " + std::to_string(s));
  dampingScale_ = s;
  C_ = s * C0_;
  if (isCyclic()) cyclic_.Cnext = s * Cnext0_;
}

void HarmonicBalanceSystem::addElement(std::shared_ptr<const ScalarElement> element, Eigen::VectorXd direction) {
  if (direction.size() != numDofs())
    throw InputError("nonlinear element", "direction has " + std::to_string(direction.size()) + " entries for " +
                                              std::to_string(numDofs()) + " DOFs");
  addElement(std::make_shared<ScalarElementAdapter>(std::move(element)), Eigen::MatrixXd(direction));
}

void HarmonicBalanceSystem::addExcitation(int dof, int harmonic, double cosAmplitude, double sinAmplitude) {
  if (dof < 0 || dof >= numDofs()) throw InputError("excitation", "DOF " + std::to_string(dof) + " out of range");
  const auto& H = aft_->harmonics();
  if (!H.contains(harmonic))
    throw InputError("excitation", "harmonic " + std::to_string(harmonic) + " is not in the harmonic set");
  const int nc = numCoefficients();
  if (harmonic == 0) {
    excitation_(dof * nc + H.cosIndex(0)) += cosAmplitude;
    return;
  }
  excitation_(dof * nc + H.cosIndex(harmonic)) += cosAmplitude;
  excitation_(dof * nc + H.sinIndex(harmonic)) += sinAmplitude;
}

void HarmonicBalanceSystem::addStaticLoad(int dof, double value) {
  if (dof < 0 || dof >= numDofs()) throw InputError("static load", "DOF " + std::to_string(dof) + " out of range");
  if (!aft_->harmonics().contains(0))
    throw InputError("static load", "needs harmonic 0 in the harmonic set (the mean of the response)");
  static_(dof * numCoefficients() + aft_->harmonics().cosIndex(0)) += value;
}

void HarmonicBalanceSystem::addExcitationCoefficients(const Eigen::VectorXd& F) {
  if (F.size() != numUnknowns()) throw InputError("excitation", "coefficient vector of the wrong size");
  excitation_ += F;
}

void HarmonicBalanceSystem::addStaticLoadCoefficients(const Eigen::VectorXd& L) {
  if (L.size() != numUnknowns()) throw InputError("static load", "coefficient vector of the wrong size");
  for (int a = 0; a < numDofs(); ++a)
    for (int k = 0; k < numCoefficients(); ++k) {
      const double v = L(a * numCoefficients() + k);
      if (v == 0) continue;
      if (!aft_->harmonics().contains(0) || k != aft_->harmonics().cosIndex(0))
        throw InputError("static load", "a static load has only a harmonic-0 part");
      static_(a * numCoefficients() + k) += v;
    }
}

Eigen::MatrixXd HarmonicBalanceSystem::coefficientOperator(const Eigen::MatrixXd& A, const Eigen::MatrixXd& Anext) const {
  const int n = numDofs(), nc = numCoefficients();
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(nc, nc);
  const bool coupled = isCyclic() && Anext.size() != 0;
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(n * nc, n * nc);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      auto block = L.block(a * nc, b * nc, nc, nc);
      if (A(a, b) != 0) block += A(a, b) * I;
      if (coupled && Anext(a, b) != 0) block += Anext(a, b) * next_;
      if (coupled && Anext(b, a) != 0) block += Anext(b, a) * next_.transpose();
    }
  return L;
}

Eigen::MatrixXd HarmonicBalanceSystem::complianceOperator(double omega) const {
  if (!receptance_) throw InputError("system", "complianceOperator needs the receptance form");
  return harmonicOperator(omega, false);
}

Eigen::MatrixXd HarmonicBalanceSystem::dynamicStiffnessOperator(double omega) const {
  if (!receptance_) throw InputError("system", "dynamicStiffnessOperator needs the receptance form");
  return harmonicOperator(omega, true);
}

void HarmonicBalanceSystem::useDynamicStiffness(bool on) {
  if (!receptance_) throw InputError("system", "the dynamic-stiffness statement is for receptance models");
  if (on && meanStiffness_.size() == 0) {
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(mean_);
    if (!lu.isInvertible()) throw InputError("system", "the mean compliance is singular: keep the compliance form");
    meanStiffness_ = lu.inverse();
  }
  stiffnessForm_ = on;
  blocks_ = HarmonicBlocks{}, woodbury_.reset(), woodburyOmega_ = -1, woodburyHeld_ = -1;
}

const HarmonicBalanceSystem::HarmonicBlocks& HarmonicBalanceSystem::harmonicBlocks(double omega, bool inverse) const {
  if (omega == blocks_.omega && inverse == blocks_.inverse) return blocks_;
  const int n = numDofs();
  const auto& H = aft_->harmonics();
  HarmonicBlocks b;
  for (int h : H.harmonics()) {
    if (h == 0) {
      b.re.push_back(inverse ? meanStiffness_ : mean_);
      b.im.emplace_back();
      continue;
    }
    const Eigen::MatrixXcd A = inverse ? receptance_->dynamicStiffness(h * omega, phaseIndex(h))
                                       : receptance_->compliance(h * omega, phaseIndex(h));
    if (A.rows() != n || A.cols() != n || !A.allFinite())
      throw Error(std::string("receptance model: ") + (inverse ? "dynamic stiffness" : "compliance") +
                  " at harmonic " + std::to_string(h) + " is not a finite " + std::to_string(n) + " square matrix");
    b.re.push_back(A.real());
    b.im.push_back(A.imag());
  }
  b.omega = omega, b.inverse = inverse;
  blocks_ = std::move(b);
  return blocks_;
}

std::shared_ptr<const ModalStiffnessBlocks> HarmonicBalanceSystem::modalStiffnessBlocks(double omega) const {
  if (!receptance_ || !stiffnessForm_ || !(omega > 0) || woodburyHeld_ == 0) return nullptr;
  if (woodbury_ && omega == woodburyOmega_) return woodbury_;
  const auto& H = aft_->harmonics();
  std::vector<const ModalStiffness*> parts;
  std::vector<double> frequencies;
  for (int h : H.harmonics()) {
    const ModalStiffness* p = h == 0 ? nullptr : receptance_->modalStiffness(phaseIndex(h));
    if (h != 0 && !p) {
      woodburyHeld_ = 0;
      return nullptr;
    }
    parts.push_back(p), frequencies.push_back(h * omega);
  }
  woodburyHeld_ = 1;
  woodbury_ = std::make_shared<const ModalStiffnessBlocks>(std::move(parts), frequencies);
  woodburyOmega_ = omega;
  return woodbury_;
}

// X = c - i s, U = A X: c_U = Re A c + Im A s, s_U = -Im A c + Re A s (the same for Z = A^-1).
void HarmonicBalanceSystem::applyHarmonicOperator(double omega, bool inverse, const Eigen::VectorXd& X,
                                                  Eigen::VectorXd& Y) const {
  const int n = numDofs(), nc = numCoefficients();
  const auto& H = aft_->harmonics();
  // The residual forms the blocks (harmonicBlocks): applying it in Woodbury's parts, as the
  // Jacobian's products are, changes its rounding, and with it where a friction curve's
  // steps fall; two equivalent systems then traced different paths over the sampled
  // law's stair of kinks at the top, and their largest points were 1.4e-4 apart
  // (disc_contact_patches) where the same path gives 1e-9.
  const HarmonicBlocks& b = harmonicBlocks(omega, inverse);
  Y.setZero(n * nc);
  using Strided = Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<>>;
  using StridedOut = Eigen::Map<Eigen::VectorXd, 0, Eigen::InnerStride<>>;
  for (std::size_t i = 0; i < H.harmonics().size(); ++i) {
    const int h = H.harmonics()[i];
    const int c = H.cosIndex(h);
    const Strided xc(X.data() + c, n, Eigen::InnerStride<>(nc));
    StridedOut yc(Y.data() + c, n, Eigen::InnerStride<>(nc));
    if (h == 0) {
      yc.noalias() = b.re[i] * xc;
      continue;
    }
    const int s = H.sinIndex(h);
    const Strided xs(X.data() + s, n, Eigen::InnerStride<>(nc));
    StridedOut ys(Y.data() + s, n, Eigen::InnerStride<>(nc));
    const Eigen::VectorXd vc = xc, vs = xs;  // contiguous copies for the products
    Eigen::VectorXd uc = b.re[i] * vc, us = b.re[i] * vs;
    uc.noalias() += b.im[i] * vs;
    us.noalias() -= b.im[i] * vc;
    yc = uc, ys = us;
  }
}

Eigen::MatrixXd HarmonicBalanceSystem::harmonicOperator(double omega, bool inverse) const {
  Eigen::MatrixXd B;
  harmonicOperatorInto(omega, inverse, B);
  return B;
}

void HarmonicBalanceSystem::harmonicOperatorInto(double omega, bool inverse, Eigen::MatrixXd& B) const {
  const int n = numDofs(), nc = numCoefficients();
  const auto& H = aft_->harmonics();
  const HarmonicBlocks& bl = harmonicBlocks(omega, inverse);
  // A Jacobian's storage is reused: a fresh matrix of this size (23 MB for the default
  // disc at H = 6) costs its page faults at every Newton step.
  B.setZero(Eigen::Index(n) * nc, Eigen::Index(n) * nc);
  for (std::size_t i = 0; i < H.harmonics().size(); ++i) {
    const int h = H.harmonics()[i];
    const int c = H.cosIndex(h);
    if (h == 0) {
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) B(a * nc + c, b * nc + c) = bl.re[i](a, b);
      continue;
    }
    const int s = H.sinIndex(h);
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a) {
        const double re = bl.re[i](a, b), im = bl.im[i](a, b);
        B(a * nc + c, b * nc + c) = re, B(a * nc + c, b * nc + s) = im;
        B(a * nc + s, b * nc + c) = -im, B(a * nc + s, b * nc + s) = re;
      }
  }
}

namespace {

// The nonzeros of a coefficient-space operator: the derivative, its square, the
// next-sector rotation and their products are block diagonal per harmonic (at most two
// entries a row), so a DOF pair's block of the dynamic stiffness is written entry by
// entry instead of as nc x nc dense additions.
struct CoefficientEntries {
  std::vector<int> row, col;
  std::vector<double> value;
  explicit CoefficientEntries(const Eigen::MatrixXd& A) {
    for (Eigen::Index j = 0; j < A.cols(); ++j)
      for (Eigen::Index i = 0; i < A.rows(); ++i)
        if (A(i, j) != 0) row.push_back(int(i)), col.push_back(int(j)), value.push_back(A(i, j));
  }
  void addTo(double factor, Eigen::MatrixXd& Z, Eigen::Index r0, Eigen::Index c0) const {
    for (std::size_t k = 0; k < value.size(); ++k) Z(r0 + row[k], c0 + col[k]) += factor * value[k];
  }
};

}  // namespace

Eigen::MatrixXd HarmonicBalanceSystem::linearOperator(double omega) const {
  Eigen::MatrixXd Z;
  linearOperatorInto(omega, Z);
  return Z;
}

void HarmonicBalanceSystem::linearOperatorInto(double omega, Eigen::MatrixXd& Z) const {
  requireMatrixForm("the dynamic stiffness");
  // Z = L(K) + omega L(C) D + omega^2 L(M) D^2, D the per-DOF derivative in
  // coefficient space (it commutes with the next-sector rotation). Per harmonic
  // h on (cos, sin): [K - (h w)^2 M,  h w C; -h w C,  K - (h w)^2 M] for a lone sector.
  const int n = numDofs(), nc = numCoefficients();
  const Eigen::MatrixXd D = omega * aft_->derivativeMatrix(), D2 = D * D;
  const CoefficientEntries I(Eigen::MatrixXd::Identity(nc, nc)), d(D), d2(D2);
  // The next sector's couplings through the rotation S (and its products with D).
  const bool cyclic = isCyclic();
  const Eigen::MatrixXd S = cyclic ? next_ : Eigen::MatrixXd::Zero(nc, nc), ST = S.transpose();
  const CoefficientEntries s(S), st(ST), sd(S * D), std_(ST * D), sd2(S * D2), std2(ST * D2);
  const Eigen::MatrixXd none;
  const auto &Kn = cyclic ? cyclic_.Knext : none, &Cn = cyclic ? cyclic_.Cnext : none,
             &Mn = cyclic ? cyclic_.Mnext : none;
  Z.setZero(Eigen::Index(n) * nc, Eigen::Index(n) * nc);
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a) {
      const Eigen::Index r0 = Eigen::Index(a) * nc, c0 = Eigen::Index(b) * nc;
      if (K_(a, b) != 0) I.addTo(K_(a, b), Z, r0, c0);
      if (C_(a, b) != 0) d.addTo(C_(a, b), Z, r0, c0);
      if (M_(a, b) != 0) d2.addTo(M_(a, b), Z, r0, c0);
      if (!cyclic) continue;
      if (Kn(a, b) != 0) s.addTo(Kn(a, b), Z, r0, c0);
      if (Kn(b, a) != 0) st.addTo(Kn(b, a), Z, r0, c0);
      if (Cn(a, b) != 0) sd.addTo(Cn(a, b), Z, r0, c0);
      if (Cn(b, a) != 0) std_.addTo(Cn(b, a), Z, r0, c0);
      if (Mn(a, b) != 0) sd2.addTo(Mn(a, b), Z, r0, c0);
      if (Mn(b, a) != 0) std2.addTo(Mn(b, a), Z, r0, c0);
    }
}

// Z X without Z: with X as the nc x n matrix Xm of the DOFs' coefficients, block (a, b)
// of linearOperator summed over b is, term by term,
//   Xm K^T + D Xm C^T + D^2 Xm M^T + S Xm Kn^T + S^T Xm Kn + S D Xm Cn^T + S^T D Xm Cn
//   + S D^2 Xm Mn^T + S^T D^2 Xm Mn:
// products of nc x n by n x n, where forming Z costs (n nc)^2.
void HarmonicBalanceSystem::applyLinearOperator(double omega, const Eigen::VectorXd& X, Eigen::VectorXd& R) const {
  const int n = numDofs(), nc = numCoefficients();
  const Eigen::MatrixXd D = omega * aft_->derivativeMatrix(), D2 = D * D;
  const Eigen::Map<const Eigen::MatrixXd> Xm(X.data(), nc, n);
  R.resize(n * nc);
  Eigen::Map<Eigen::MatrixXd> Rm(R.data(), nc, n);
  Rm.noalias() = Xm * K_.transpose();
  Rm.noalias() += D * (Xm * C_.transpose());
  Rm.noalias() += D2 * (Xm * M_.transpose());
  if (!isCyclic()) return;
  const Eigen::MatrixXd& S = next_;
  const auto& c = cyclic_;
  Eigen::MatrixXd toNext = Xm * c.Knext.transpose(), toPrevious = Xm * c.Knext;  // S and S^T terms
  toNext.noalias() += D * (Xm * c.Cnext.transpose());
  toPrevious.noalias() += D * (Xm * c.Cnext);
  toNext.noalias() += D2 * (Xm * c.Mnext.transpose());
  toPrevious.noalias() += D2 * (Xm * c.Mnext);
  Rm.noalias() += S * toNext;
  Rm.noalias() += S.transpose() * toPrevious;
}

void HarmonicBalanceSystem::residual(const Eigen::VectorXd& X, double omega, Eigen::VectorXd& R,
                                     Eigen::MatrixXd* jacobian, double excitationScale) const {
  const int n = numDofs(), nc = numCoefficients();
  if (X.size() != n * nc) throw Error("harmonic balance: unknown vector of the wrong size");
  if (receptance_ && stiffnessForm_) {
    if (jacobian) harmonicOperatorInto(omega, true, *jacobian);
    applyHarmonicOperator(omega, true, X, R);
    R -= excitationScale * excitation_ + static_;
    addElementForces(X, omega, R, jacobian);
    return;
  }
  if (receptance_) {
    // kappa (X - B (s F + F_static - F_nl)), J = kappa (I + B dF_nl/dX).
    R = Eigen::VectorXd::Zero(n * nc);
    if (jacobian) jacobian->setZero(n * nc, n * nc);
    addElementForces(X, omega, R, jacobian);
    const Eigen::VectorXd load = excitationScale * excitation_ + static_ - R;
    const double kappa = receptanceStiffness();
    Eigen::VectorXd Bload;
    applyHarmonicOperator(omega, false, load, Bload);
    R.noalias() = kappa * (X - Bload);
    if (jacobian) {
      Eigen::MatrixXd BJ = complianceOperator(omega) * *jacobian;
      *jacobian = kappa * BJ;
      jacobian->diagonal().array() += kappa;
    }
    return;
  }
  if (jacobian) linearOperatorInto(omega, *jacobian);
  applyLinearOperator(omega, X, R);
  R -= excitationScale * excitation_ + static_;
  addElementForces(X, omega, R, jacobian);
}

void HarmonicBalanceSystem::nonlinearForces(const Eigen::VectorXd& X, double omega, Eigen::VectorXd& F,
                                            Eigen::MatrixXd* jacobian) const {
  if (X.size() != numUnknowns()) throw Error("harmonic balance: unknown vector of the wrong size");
  F = Eigen::VectorXd::Zero(numUnknowns());
  if (jacobian) jacobian->setZero(numUnknowns(), numUnknowns());
  addElementForces(X, omega, F, jacobian);
}

void HarmonicBalanceSystem::addElementForces(const Eigen::VectorXd& X, double omega, Eigen::VectorXd& R,
                                             Eigen::MatrixXd* jacobian) const {
  const int n = numDofs(), nc = numCoefficients();
  const Eigen::Map<const Eigen::MatrixXd> Xm(X.data(), nc, n);  // column a: coefficients of DOF a
  Eigen::Map<Eigen::MatrixXd> Rm(R.data(), nc, n);
  const Eigen::MatrixXd& S = next_;
  Eigen::MatrixXd F, Jf;
  for (const auto& c : elements_) {
    const int d = c.element->dimension();
    const bool across = c.Wnext.size() != 0;
    Eigen::MatrixXd Wc = Xm * c.W;
    if (across) Wc.noalias() += S * (Xm * c.Wnext);
    c.element->harmonicForce(*aft_, Wc, omega, F, jacobian ? &Jf : nullptr);
    Rm.noalias() += F * c.W.transpose();
    if (across) Rm.noalias() += S.transpose() * (F * c.Wnext.transpose());
    if (!jacobian) continue;
    // dR_a/dX_b = B_a Jf A_b with A_b = [W(b,k) I + Wnext(b,k) S]_k stacked and
    // B_a = [W(a,c) I + Wnext(a,c) S^T]_c side by side: formed block by block
    // with the S products made once per element (and per column DOF), never
    // by multiplying with the identity blocks.
    std::vector<int> support;
    for (int a = 0; a < n; ++a)
      if (c.W.row(a).squaredNorm() > 0 || (across && c.Wnext.row(a).squaredNorm() > 0)) support.push_back(a);
    Eigen::MatrixXd JfS;  // Jf (I_d (x) S)
    if (across) {
      JfS.resize(nc * d, nc * d);
      for (int k = 0; k < d; ++k) JfS.middleCols(k * nc, nc).noalias() = Jf.middleCols(k * nc, nc) * S;
    }
    Eigen::MatrixXd JA(nc * d, nc), STJA;
    for (int b : support) {
      JA.setZero();
      for (int k = 0; k < d; ++k) {
        if (c.W(b, k) != 0) JA += c.W(b, k) * Jf.middleCols(k * nc, nc);
        if (across && c.Wnext(b, k) != 0) JA += c.Wnext(b, k) * JfS.middleCols(k * nc, nc);
      }
      if (across) {
        STJA.resize(nc * d, nc);
        for (int k = 0; k < d; ++k) STJA.middleRows(k * nc, nc).noalias() = S.transpose() * JA.middleRows(k * nc, nc);
      }
      for (int a : support) {
        auto block = jacobian->block(a * nc, b * nc, nc, nc);
        for (int k = 0; k < d; ++k) {
          if (c.W(a, k) != 0) block += c.W(a, k) * JA.middleRows(k * nc, nc);
          if (across && c.Wnext(a, k) != 0) block += c.Wnext(a, k) * STJA.middleRows(k * nc, nc);
        }
      }
    }
  }
}

Eigen::MatrixXd HarmonicBalanceSystem::linearHarmonicBlock(double omega, std::size_t i) const {
  if (!hasJacobianBlocks())
    throw InputError("harmonic balance", "the linear part as a dynamic stiffness needs the matrix form or useDynamicStiffness");
  const int n = numDofs();
  const auto& H = aft_->harmonics();
  const int h = H.harmonics().at(i);
  const std::vector<int> slots = h == 0 ? std::vector<int>{H.cosIndex(0)} : std::vector<int>{H.cosIndex(h), H.sinIndex(h)};
  const int m = int(slots.size());
  Eigen::MatrixXd P(n * m, n * m);
  if (receptance_) {
    const HarmonicBlocks& bl = harmonicBlocks(omega, true);
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a) {
        if (m == 1) {
          P(a, b) = bl.re[i](a, b);
          continue;
        }
        const double re = bl.re[i](a, b), im = bl.im[i](a, b);  // as harmonicOperatorInto
        P(2 * a, 2 * b) = re, P(2 * a, 2 * b + 1) = im, P(2 * a + 1, 2 * b) = -im, P(2 * a + 1, 2 * b + 1) = re;
      }
    return P;
  }
  // The matrix form's operators are block diagonal per harmonic (linearOperatorInto), so
  // their harmonic-h blocks are products of the m x m blocks of D and S.
  auto sub = [&](const Eigen::MatrixXd& A) {
    Eigen::MatrixXd B(m, m);
    for (int r = 0; r < m; ++r)
      for (int q = 0; q < m; ++q) B(r, q) = A(slots[r], slots[q]);
    return B;
  };
  const Eigen::MatrixXd D = omega * sub(aft_->derivativeMatrix()), D2 = D * D, I = Eigen::MatrixXd::Identity(m, m);
  const bool cyclic = isCyclic();
  const Eigen::MatrixXd S = cyclic ? sub(next_) : Eigen::MatrixXd::Zero(m, m), ST = S.transpose();
  const Eigen::MatrixXd SD = S * D, STD = ST * D, SD2 = S * D2, STD2 = ST * D2;
  P.setZero();
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a) {
      auto block = P.block(a * m, b * m, m, m);
      block += K_(a, b) * I + C_(a, b) * D + M_(a, b) * D2;
      if (!cyclic) continue;
      const auto &Kn = cyclic_.Knext, &Cn = cyclic_.Cnext, &Mn = cyclic_.Mnext;
      if (Kn.size()) block += Kn(a, b) * S + Kn(b, a) * ST;
      if (Cn.size()) block += Cn(a, b) * SD + Cn(b, a) * STD;
      if (Mn.size()) block += Mn(a, b) * SD2 + Mn(b, a) * STD2;
    }
  return P;
}

std::unique_ptr<JacobianBlocks> HarmonicBalanceSystem::jacobianBlocks(const Eigen::VectorXd& X, double omega,
                                                                     ElementJacobians elementJacobians) const {
  if (!hasJacobianBlocks())
    throw InputError("harmonic balance", "a Jacobian kept as blocks needs the matrix form or useDynamicStiffness");
  const int n = numDofs(), nc = numCoefficients();
  if (X.size() != n * nc) throw Error("harmonic balance: unknown vector of the wrong size");
  const Eigen::Map<const Eigen::MatrixXd> Xm(X.data(), nc, n);
  const Eigen::MatrixXd& S = next_;
  std::vector<JacobianBlocks::ElementBlock> blocks;
  blocks.reserve(elements_.size());
  Eigen::MatrixXd F;
  for (std::size_t i = 0; i < elements_.size(); ++i) {
    const auto& c = elements_[i];
    const bool across = c.Wnext.size() != 0;
    Eigen::MatrixXd Wc = Xm * c.W;
    if (across) Wc.noalias() += S * (Xm * c.Wnext);
    JacobianBlocks::ElementBlock b;
    b.element = i;
    // Decided before either is made: a linearization made and then dropped would march
    // the period once more for nothing (at low H, where the formed one is kept).
    const long formedNumbers = long(c.element->dimension()) * nc * c.element->dimension() * nc;
    const long tangentNumbers = c.element->linearizationNumbers(*aft_);
    if (elementJacobians == ElementJacobians::Tangents ||
        (elementJacobians == ElementJacobians::Automatic && tangentNumbers > 0 && tangentNumbers < formedNumbers))
      b.linearization = c.element->linearization(*aft_, Wc, omega);
    if (!b.linearization) c.element->harmonicForce(*aft_, Wc, omega, F, &b.jacobian);
    for (int a = 0; a < n; ++a)
      if (c.W.row(a).squaredNorm() > 0 || (across && c.Wnext.row(a).squaredNorm() > 0)) b.support.push_back(a);
    blocks.push_back(std::move(b));
  }
  return std::make_unique<JacobianBlocks>(*this, omega, std::move(blocks));
}

Eigen::VectorXd HarmonicBalanceSystem::linearSolution(double omega, double excitationScale) const {
  if (receptance_) {
    Eigen::VectorXd X;
    applyHarmonicOperator(omega, false, Eigen::VectorXd(excitationScale * excitation_ + static_), X);
    return X;
  }
  return linearOperator(omega).partialPivLu().solve(Eigen::VectorXd(excitationScale * excitation_ + static_));
}

Eigen::VectorXd HarmonicBalanceSystem::linearizedSolution(double omega, double excitationScale) const {
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(numUnknowns());
  Eigen::VectorXd R;
  Eigen::MatrixXd J;
  residual(zero, omega, R, &J, excitationScale);
  return J.partialPivLu().solve(Eigen::VectorXd(-R));
}

double HarmonicBalanceSystem::amplitude(const Eigen::VectorXd& X, int dof, int harmonic) const {
  const int nc = numCoefficients();
  const auto& H = aft_->harmonics();
  if (harmonic == 0) return std::abs(X(dof * nc + H.cosIndex(0)));
  return std::hypot(X(dof * nc + H.cosIndex(harmonic)), X(dof * nc + H.sinIndex(harmonic)));
}

}  // namespace cyclone::hbm
