#include "cyclone/rom/GuyanModel.hpp"

#include <complex>

#include "cyclone/core/Error.hpp"
#include "cyclone/rom/ReducedModes.hpp"

namespace cyclone::rom {

GuyanModel::GuyanModel(const BoundaryReduction& reduction, double lossFactor)
    : stiffness_(reduction.stiffness), mass_(reduction.mass), copies_(reduction.copies), eta_(lossFactor) {
  if (!(lossFactor >= 0)) throw InputError("loss_factor", "must be >= 0");
  if (stiffness_.rows() == 0 || stiffness_.rows() != mass_.rows())
    throw InputError("reduced model", "Guyan: empty or inconsistent boundary reduction");
}

Eigen::MatrixXcd GuyanModel::compliance(double omega) const {
  const Eigen::MatrixXcd Z = std::complex<double>(1.0, eta_) * stiffness_.cast<std::complex<double>>() -
                             (omega * omega) * mass_.cast<std::complex<double>>();
  return Z.partialPivLu().inverse();  // complex symmetric, not Hermitian: LU
}

Eigen::MatrixXd GuyanModel::zeroFrequencyCompliance() const {
  requireNonsingularStiffness(stiffness_, "Guyan");
  return stiffness_.llt().solve(Eigen::MatrixXd::Identity(size(), size()));
}

RetainedModes GuyanModel::modes() const { return reducedModes(stiffness_, mass_, size(), copies_); }

}  // namespace cyclone::rom
