#include "cyclone/rom/GuyanModel.hpp"

#include "cyclone/core/Error.hpp"
#include "cyclone/rom/ReducedModes.hpp"

namespace cyclone::rom {
namespace {

const BoundaryReduction& checked(const BoundaryReduction& reduction) {
  if (reduction.stiffness.rows() == 0 || reduction.stiffness.rows() != reduction.mass.rows())
    throw InputError("reduced model", "Guyan: empty or inconsistent boundary reduction");
  return reduction;
}

}  // namespace

GuyanModel::GuyanModel(const BoundaryReduction& reduction, double lossFactor)
    : stiffness_(checked(reduction).stiffness),
      mass_(reduction.mass),
      modal_(HybridFrfModel::modalTruncation(
          reducedModes(reduction.stiffness, reduction.mass, reduction.stiffness.rows(), reduction.copies),
          lossFactor)) {}

Eigen::MatrixXcd GuyanModel::compliance(double omega) const { return modal_.compliance(omega); }

Eigen::MatrixXd GuyanModel::zeroFrequencyCompliance() const {
  requireNonsingularStiffness(stiffness_, "Guyan");
  return stiffness_.llt().solve(Eigen::MatrixXd::Identity(size(), size()));
}

}  // namespace cyclone::rom
