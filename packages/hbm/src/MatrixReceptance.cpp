#include <algorithm>
#include <cmath>
#include <complex>
#include <string>

#include <Eigen/Eigenvalues>

#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/ReceptanceModel.hpp"

namespace cyclone::hbm {

Eigen::MatrixXcd ReceptanceModel::dynamicStiffness(double frequency, long phaseIndex) const {
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(compliance(frequency, phaseIndex));
  Eigen::MatrixXcd Z = lu.inverse();
  if (!Z.allFinite() || lu.rcond() < 1e-14)
    throw Error("receptance model: the compliance at " + std::to_string(frequency) +
                " rad/s is singular (a modal truncation with fewer modes than DOFs?): use the compliance form");
  return Z;
}

std::optional<ModalRealization> ReceptanceModel::modalRealization(long) const { return std::nullopt; }

const ModalStiffness* ReceptanceModel::modalStiffness(long) const { return nullptr; }

Eigen::MatrixXcd ReceptanceModel::staticCompliance(long phaseIndex) const {
  const int N = std::max(sectors(), 1);
  const long p = ((phaseIndex % N) + N) % N;
  if (p == 0) return meanCompliance().cast<std::complex<double>>();
  const auto r = modalRealization(p);
  if (!r)
    throw InputError("receptance", "no static compliance for phase index " + std::to_string(p) +
                                       ": the model has no modal realization of it");
  if ((r->eigenvalues.array() <= 0).any())
    throw InputError("receptance", "no static compliance for phase index " + std::to_string(p) +
                                       ": its modal realization has a rigid-body mode");
  return r->R + r->U * r->eigenvalues.cwiseInverse().cast<std::complex<double>>().asDiagonal() * r->V.transpose();
}

MatrixReceptance::MatrixReceptance(Eigen::MatrixXd M, Eigen::MatrixXd C, Eigen::MatrixXd K, int sectors,
                                   Eigen::MatrixXd Mnext, Eigen::MatrixXd Cnext, Eigen::MatrixXd Knext)
    : M_(std::move(M)), C_(std::move(C)), K_(std::move(K)), sectors_(sectors) {
  const auto n = K_.rows();
  if (sectors < 1) throw InputError("receptance", "sectors must be >= 1, got " + std::to_string(sectors));
  for (auto* A : {&M_, &C_, &K_, &Mnext, &Cnext, &Knext}) {
    if (A->size() == 0) *A = Eigen::MatrixXd::Zero(n, n);
    if (A->rows() != n || A->cols() != n) throw InputError("receptance", "all matrices must be " + std::to_string(n) + " square");
  }
  if (sectors == 1 && (Mnext.norm() > 0 || Cnext.norm() > 0 || Knext.norm() > 0))
    throw InputError("receptance", "coupling to the next sector needs sectors >= 2");
  Mnext_ = std::move(Mnext), Cnext_ = std::move(Cnext), Knext_ = std::move(Knext);
}

Eigen::MatrixXcd MatrixReceptance::phased(const Eigen::MatrixXd& A, const Eigen::MatrixXd& Anext,
                                          long phaseIndex) const {
  // Sector j's equation holds A x_j + A_next x_{j+1} + A_next^T x_{j-1}, x_{j+1} = e^{-i a} x_j.
  const double a = 2 * M_PI * double(phaseIndex % sectors_) / double(sectors_);
  const std::complex<double> e(std::cos(a), -std::sin(a));
  return A.cast<std::complex<double>>() + e * Anext.cast<std::complex<double>>() +
         std::conj(e) * Anext.transpose().cast<std::complex<double>>();
}

Eigen::MatrixXcd MatrixReceptance::compliance(double f, long p) const {
  const Eigen::MatrixXcd Z = phased(K_, Knext_, p) + std::complex<double>(0, f) * phased(C_, Cnext_, p) -
                             f * f * phased(M_, Mnext_, p);
  return Z.partialPivLu().inverse();
}

Eigen::MatrixXd MatrixReceptance::meanCompliance() const {
  const Eigen::MatrixXd K0 = K_ + Knext_ + Knext_.transpose();
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(K0);
  if (!lu.isInvertible()) throw InputError("receptance", "K is singular: no static compliance for the mean");
  return lu.inverse();
}

Eigen::MatrixXcd MatrixReceptance::staticCompliance(long p) const {
  const Eigen::MatrixXcd Kp = phased(K_, Knext_, p);
  const Eigen::FullPivLU<Eigen::MatrixXcd> lu(Kp);
  if (!lu.isInvertible())
    throw InputError("receptance", "K of phase index " + std::to_string(p) + " is singular: no static compliance");
  return lu.inverse();
}

std::optional<ModalRealization> MatrixReceptance::modalRealization(long p) const {
  const Eigen::MatrixXcd Kp = phased(K_, Knext_, p), Mp = phased(M_, Mnext_, p), Cp = phased(C_, Cnext_, p);
  if (Eigen::LLT<Eigen::MatrixXcd>(Mp).info() != Eigen::Success) return std::nullopt;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXcd> es(Kp, Mp);
  if (es.info() != Eigen::Success) return std::nullopt;
  const Eigen::MatrixXcd& Phi = es.eigenvectors();  // Phi^H M_p Phi = I
  const Eigen::MatrixXcd Cm = Phi.adjoint() * Cp * Phi;
  const Eigen::MatrixXcd off = Cm - Eigen::MatrixXcd(Cm.diagonal().asDiagonal());
  if (off.norm() > 1e-9 * Cm.norm()) return std::nullopt;  // not modal damping
  ModalRealization r;
  const auto n = K_.rows();
  r.R = Eigen::MatrixXcd::Zero(n, n);
  r.U = Phi;
  r.V = Phi.conjugate();
  r.eigenvalues = es.eigenvalues();
  r.viscous = Cm.diagonal().real();
  return r;
}

}  // namespace cyclone::hbm
