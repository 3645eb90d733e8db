#include "cyclone/rom/HybridFrfModel.hpp"

#include <algorithm>
#include <complex>

#include "cyclone/core/Error.hpp"

namespace cyclone::rom {

RetainedModes RetainedModes::first(int distinct) const {
  const int m = distinct * copies;
  if (distinct < 1 || m > numModes())
    throw InputError("modes", "asked for " + std::to_string(distinct) + " natural frequencies, " +
                                  std::to_string(numModes() / copies) + " computed");
  RetainedModes out;
  out.copies = copies;
  out.eigenvalues.assign(eigenvalues.begin(), eigenvalues.begin() + m);
  out.shapes = shapes.leftCols(m);
  if (loads.size()) out.loads = loads.topRows(m);
  out.seconds = seconds;
  return out;
}

int RetainedModes::numRigidBodyModes() const {
  if (eigenvalues.empty()) return 0;
  const double largest = *std::max_element(eigenvalues.begin(), eigenvalues.end());
  return int(std::count_if(eigenvalues.begin(), eigenvalues.end(),
                           [&](double l) { return std::abs(l) < 1e-6 * largest; }));
}

HybridFrfModel::HybridFrfModel(RetainedModes modes, double lossFactor) : modes_(std::move(modes)), eta_(lossFactor) {
  if (modes_.numModes() == 0) throw InputError("modes", "a reduced model needs at least one mode");
  if (modes_.shapes.cols() != modes_.numModes())
    throw InputError("modes", "mode shapes and eigenvalues differ in number");
  if (!(lossFactor >= 0)) throw InputError("loss_factor", "must be >= 0");
  if (modes_.loads.size() && modes_.loads.rows() != modes_.numModes())
    throw InputError("loads", "modal loads for " + std::to_string(modes_.loads.rows()) + " modes, the model has " +
                                  std::to_string(modes_.numModes()));
}

HybridFrfModel::HybridFrfModel(RetainedModes modes, StaticCompliance staticCompliance, double lossFactor)
    : HybridFrfModel(std::move(modes), lossFactor) {
  if (staticCompliance.matrix.rows() != size() || staticCompliance.matrix.cols() != size())
    throw InputError("static compliance", "is " + std::to_string(staticCompliance.matrix.rows()) + " x " +
                                              std::to_string(staticCompliance.matrix.cols()) + ", the modes have " +
                                              std::to_string(size()) + " retained DOFs");
  if (staticCompliance.loadResponse.cols() != numLoads() ||
      (numLoads() > 0 && staticCompliance.loadResponse.rows() != size()))
    throw InputError("loads", "the static load response (" + std::to_string(staticCompliance.loadResponse.cols()) +
                                  " patterns) and the modal loads (" + std::to_string(numLoads()) +
                                  ") must come from the same load patterns");
  static_ = std::move(staticCompliance);
  hasStatic_ = true;
}

HybridFrfModel HybridFrfModel::modalTruncation(RetainedModes modes, double lossFactor) {
  return HybridFrfModel(std::move(modes), lossFactor);
}

Eigen::VectorXcd HybridFrfModel::modalWeights(double omega) const {
  const std::complex<double> damped(1.0, eta_);
  Eigen::VectorXcd d(modes_.numModes());
  for (int j = 0; j < modes_.numModes(); ++j) d(j) = 1.0 / (damped * modes_.eigenvalues[j] - omega * omega);
  return d;
}

Eigen::MatrixXcd HybridFrfModel::residualCompliance() const {
  const auto n = size();
  if (!hasStatic_) return Eigen::MatrixXcd::Zero(n, n);
  const std::complex<double> damped(1.0, eta_);
  Eigen::VectorXcd w(modes_.numModes());
  for (int j = 0; j < modes_.numModes(); ++j) w(j) = -1.0 / (damped * (modes_.eigenvalues[j] - static_.shift));
  const Eigen::MatrixXcd phi = modes_.shapes.cast<std::complex<double>>();
  return static_.matrix.cast<std::complex<double>>() / damped + phi * w.asDiagonal() * phi.transpose();
}

Eigen::VectorXcd HybridFrfModel::expansionWeights(double omega) const {
  const std::complex<double> damped(1.0, eta_);
  const double w2 = omega * omega;
  Eigen::VectorXcd weight(modes_.numModes());
  for (int j = 0; j < modes_.numModes(); ++j) {
    const double l = modes_.eigenvalues[j];
    weight(j) = 1.0 / (damped * l - w2);
    if (hasStatic_) weight(j) -= 1.0 / (damped * (l - static_.shift));
  }
  return weight;
}

Eigen::MatrixXcd HybridFrfModel::compliance(double omega) const {
  const Eigen::VectorXcd weight = expansionWeights(omega);
  // Real shapes, complex weights: two real products (half the work of one complex product).
  const auto& phi = modes_.shapes;
  Eigen::MatrixXcd A(size(), size());
  A.real() = phi * weight.real().asDiagonal() * phi.transpose();
  A.imag() = phi * weight.imag().asDiagonal() * phi.transpose();
  if (hasStatic_) A += static_.matrix.cast<std::complex<double>>() / std::complex<double>(1.0, eta_);
  return A;
}

Eigen::MatrixXcd HybridFrfModel::loadResponse(double omega) const {
  if (numLoads() == 0) return ComplianceModel::loadResponse(omega);  // the InputError
  const Eigen::VectorXcd weight = expansionWeights(omega);
  const auto& phi = modes_.shapes;
  Eigen::MatrixXcd X(size(), numLoads());
  X.real() = phi * weight.real().asDiagonal() * modes_.loads;
  X.imag() = phi * weight.imag().asDiagonal() * modes_.loads;
  if (hasStatic_) X += static_.loadResponse.cast<std::complex<double>>() / std::complex<double>(1.0, eta_);
  return X;
}

Eigen::MatrixXd HybridFrfModel::zeroFrequencyCompliance() const {
  if (modes_.numRigidBodyModes() > 0)
    throw InputError("reduced model", "has rigid-body modes: no compliance at zero frequency (hold the sector)");
  Eigen::VectorXd weight(modes_.numModes());
  for (int j = 0; j < modes_.numModes(); ++j) {
    const double l = modes_.eigenvalues[j];
    weight(j) = 1.0 / l - (hasStatic_ ? 1.0 / (l - static_.shift) : 0.0);
  }
  Eigen::MatrixXd A = modes_.shapes * weight.asDiagonal() * modes_.shapes.transpose();
  if (hasStatic_) A += static_.matrix;
  return A;
}

}  // namespace cyclone::rom
