#include "cyclone/rom/CraigBamptonModel.hpp"

#include <complex>

#include "cyclone/core/Error.hpp"
#include "cyclone/rom/ReducedModes.hpp"

namespace cyclone::rom {

CraigBamptonModel::CraigBamptonModel(const BoundaryReduction& reduction, int fixedInterfaceModes, double lossFactor)
    : stiffness_(reduction.stiffness), mass_(reduction.mass), copies_(reduction.copies), eta_(lossFactor) {
  if (!(lossFactor >= 0)) throw InputError("loss_factor", "must be >= 0");
  if (stiffness_.rows() == 0 || stiffness_.rows() != mass_.rows())
    throw InputError("reduced model", "Craig-Bampton: empty or inconsistent boundary reduction");
  const int m = fixedInterfaceModes * reduction.copies;
  if (fixedInterfaceModes < 1 || m > reduction.numInterfaceModes())
    throw InputError("fixed_interface_modes", std::to_string(fixedInterfaceModes) + " asked for, the reduction has " +
                                                  std::to_string(reduction.numInterfaceModes() / reduction.copies) +
                                                  " (at least 1; with none it is Guyan's model)");
  interface_ = Eigen::Map<const Eigen::VectorXd>(reduction.interfaceEigenvalues.data(), m);
  coupling_ = reduction.massCoupling.leftCols(m);
}

Eigen::MatrixXcd CraigBamptonModel::compliance(double omega) const {
  using C = std::complex<double>;
  const C damped(1.0, eta_);
  const double w2 = omega * omega;
  Eigen::VectorXcd modal(interface_.size());  // w^4 / ((1 + i eta) lambda_j - w^2): the modal block eliminated
  for (Eigen::Index j = 0; j < interface_.size(); ++j) modal(j) = w2 * w2 / (damped * interface_(j) - w2);
  const Eigen::MatrixXcd Mbm = coupling_.cast<C>();
  const Eigen::MatrixXcd S = damped * stiffness_.cast<C>() - w2 * mass_.cast<C>() -
                             Mbm * modal.asDiagonal() * Mbm.transpose();
  return S.partialPivLu().inverse();
}

Eigen::MatrixXd CraigBamptonModel::zeroFrequencyCompliance() const {
  requireNonsingularStiffness(stiffness_, "Craig-Bampton");
  return stiffness_.llt().solve(Eigen::MatrixXd::Identity(size(), size()));
}

Eigen::MatrixXd CraigBamptonModel::reducedStiffness() const {
  const Eigen::Index nb = size(), m = interface_.size();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(nb + m, nb + m);
  K.topLeftCorner(nb, nb) = stiffness_;
  K.bottomRightCorner(m, m) = interface_.asDiagonal();
  return K;
}

Eigen::MatrixXd CraigBamptonModel::reducedMass() const {
  const Eigen::Index nb = size(), m = interface_.size();
  Eigen::MatrixXd M(nb + m, nb + m);
  M.topLeftCorner(nb, nb) = mass_;
  M.topRightCorner(nb, m) = coupling_;
  M.bottomLeftCorner(m, nb) = coupling_.transpose();
  M.bottomRightCorner(m, m).setIdentity();
  return M;
}

RetainedModes CraigBamptonModel::modes() const {
  return reducedModes(reducedStiffness(), reducedMass(), size(), copies_);
}

}  // namespace cyclone::rom
