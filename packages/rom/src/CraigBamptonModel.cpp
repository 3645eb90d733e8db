#include "cyclone/rom/CraigBamptonModel.hpp"

#include "cyclone/core/Error.hpp"
#include "cyclone/rom/ReducedModes.hpp"

namespace cyclone::rom {
namespace {

// The interface modes kept: the lowest `distinct` frequencies, both copies of a pair.
int keptModes(const BoundaryReduction& reduction, int distinct) {
  if (reduction.stiffness.rows() == 0 || reduction.stiffness.rows() != reduction.mass.rows())
    throw InputError("reduced model", "Craig-Bampton: empty or inconsistent boundary reduction");
  if (distinct < 1 || distinct * reduction.copies > reduction.numInterfaceModes())
    throw InputError("fixed_interface_modes", std::to_string(distinct) + " asked for, the reduction has " +
                                                  std::to_string(reduction.numInterfaceModes() / reduction.copies) +
                                                  " (at least 1; with none it is Guyan's model)");
  return distinct * reduction.copies;
}

}  // namespace

CraigBamptonModel::CraigBamptonModel(const BoundaryReduction& reduction, int fixedInterfaceModes, double lossFactor)
    : stiffness_(reduction.stiffness),
      mass_(reduction.mass),
      coupling_(reduction.massCoupling.leftCols(keptModes(reduction, fixedInterfaceModes))),
      interface_(Eigen::Map<const Eigen::VectorXd>(reduction.interfaceEigenvalues.data(), coupling_.cols())),
      modal_(HybridFrfModel::modalTruncation(
          reducedModes(reducedStiffness(), reducedMass(), stiffness_.rows(), reduction.copies), lossFactor)) {}

Eigen::MatrixXcd CraigBamptonModel::compliance(double omega) const { return modal_.compliance(omega); }

Eigen::MatrixXd CraigBamptonModel::zeroFrequencyCompliance() const {
  requireNonsingularStiffness(stiffness_, "Craig-Bampton");  // K_r = diag(K_g, Lambda): K_g^{-1} is its boundary block
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

}  // namespace cyclone::rom
