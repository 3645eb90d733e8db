#include "cyclone/hbm/HarmonicBalanceSystem.hpp"

#include <cmath>

#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/HarmonicForce.hpp"

namespace cyclone::hbm {

HarmonicBalanceSystem::HarmonicBalanceSystem(Eigen::MatrixXd M, Eigen::MatrixXd C, Eigen::MatrixXd K,
                                             HarmonicSet harmonics, int samples)
    : M_(std::move(M)), C_(std::move(C)), K_(std::move(K)) {
  const auto n = K_.rows();
  if (K_.cols() != n || M_.rows() != n || M_.cols() != n || C_.rows() != n || C_.cols() != n)
    throw InputError("system", "M, C and K must be square and of the same size");
  aft_ = std::make_unique<Aft>(std::move(harmonics), samples);
  excitation_ = Eigen::VectorXd::Zero(numUnknowns());
}

void HarmonicBalanceSystem::addElement(std::shared_ptr<const ScalarElement> element, Eigen::VectorXd direction) {
  if (direction.size() != numDofs())
    throw InputError("nonlinear element", "direction has " + std::to_string(direction.size()) + " entries for " +
                                              std::to_string(numDofs()) + " DOFs");
  elements_.push_back({std::move(element), std::move(direction)});
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

Eigen::MatrixXd HarmonicBalanceSystem::linearOperator(double omega) const {
  // Per harmonic h on (cos, sin): [K - (h w)^2 M,  h w C; -h w C,  K - (h w)^2 M].
  const int n = numDofs(), nc = numCoefficients();
  Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(n * nc, n * nc);
  for (int h : aft_->harmonics().harmonics()) {
    const double hw = h * omega;
    const Eigen::MatrixXd D = K_ - hw * hw * M_;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        if (h == 0) {
          const int i = aft_->harmonics().cosIndex(0);
          Z(a * nc + i, b * nc + i) = K_(a, b);
          continue;
        }
        const int ic = aft_->harmonics().cosIndex(h), is = aft_->harmonics().sinIndex(h);
        Z(a * nc + ic, b * nc + ic) = D(a, b);
        Z(a * nc + is, b * nc + is) = D(a, b);
        Z(a * nc + ic, b * nc + is) = hw * C_(a, b);
        Z(a * nc + is, b * nc + ic) = -hw * C_(a, b);
      }
  }
  return Z;
}

void HarmonicBalanceSystem::residual(const Eigen::VectorXd& X, double omega, Eigen::VectorXd& R,
                                     Eigen::MatrixXd* jacobian, double excitationScale) const {
  const int n = numDofs(), nc = numCoefficients();
  if (X.size() != n * nc) throw Error("harmonic balance: unknown vector of the wrong size");
  const Eigen::MatrixXd Z = linearOperator(omega);
  R = Z * X - excitationScale * excitation_;
  if (jacobian) *jacobian = Z;
  Eigen::MatrixXd Jw;
  for (const auto& c : elements_) {
    Eigen::VectorXd w = Eigen::VectorXd::Zero(nc);
    for (int a = 0; a < n; ++a)
      if (c.direction(a) != 0) w += c.direction(a) * X.segment(a * nc, nc);
    const Eigen::VectorXd F = harmonicForce(*c.element, *aft_, w, jacobian ? &Jw : nullptr, omega);
    for (int a = 0; a < n; ++a) {
      if (c.direction(a) == 0) continue;
      R.segment(a * nc, nc) += c.direction(a) * F;
      if (jacobian)
        for (int b = 0; b < n; ++b)
          if (c.direction(b) != 0) jacobian->block(a * nc, b * nc, nc, nc) += c.direction(a) * c.direction(b) * Jw;
    }
  }
}

Eigen::VectorXd HarmonicBalanceSystem::linearSolution(double omega) const {
  return linearOperator(omega).partialPivLu().solve(excitation_);
}

double HarmonicBalanceSystem::amplitude(const Eigen::VectorXd& X, int dof, int harmonic) const {
  const int nc = numCoefficients();
  const auto& H = aft_->harmonics();
  if (harmonic == 0) return std::abs(X(dof * nc + H.cosIndex(0)));
  return std::hypot(X(dof * nc + H.cosIndex(harmonic)), X(dof * nc + H.sinIndex(harmonic)));
}

}  // namespace cyclone::hbm
