#include "cyclone/rom/ReducedModes.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "cyclone/core/Error.hpp"

namespace cyclone::rom {

RetainedModes reducedModes(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, Eigen::Index retained, int copies) {
  // Eigen's generalised solver factors M without checking the factor (an indefinite M
  // came back as Success with meaningless eigenvalues): M's own LLT decides.
  if (Eigen::LLT<Eigen::MatrixXd>(M).info() != Eigen::Success)
    throw InputError("reduced model", "its mass matrix is not positive definite");
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(K, M, Eigen::ComputeEigenvectors | Eigen::Ax_lBx);
  if (eig.info() != Eigen::Success) throw InputError("reduced model", "its eigen-solution failed");
  RetainedModes out;
  out.copies = copies;
  out.eigenvalues.assign(eig.eigenvalues().data(), eig.eigenvalues().data() + eig.eigenvalues().size());
  out.shapes = eig.eigenvectors().topRows(retained);  // x^T M x = 1 from the Cholesky form
  return out;
}

void requireNonsingularStiffness(const Eigen::MatrixXd& stiffness, const char* kind) {
  const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(stiffness, Eigen::EigenvaluesOnly)
                                     .eigenvalues();
  const auto rigid = (lambda.array() <= 1e-10 * lambda.maxCoeff()).count();
  if (rigid > 0)
    throw InputError("reduced model", std::string(kind) + " model has " + std::to_string(rigid) +
                                          " rigid-body mode(s): no compliance at zero frequency (hold the sector)");
}

}  // namespace cyclone::rom
