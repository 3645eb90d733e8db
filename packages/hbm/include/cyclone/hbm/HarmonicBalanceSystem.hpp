#pragma once
// The harmonic balance equations of a linear system with scalar nonlinear
// elements: M x'' + C x' + K x + sum_e d_e f_e(d_e^T x, d_e^T x') = f_ex(t),
// x periodic, unknowns the real Fourier coefficients of every DOF
// (X[dof * nc + coefficient], coefficient order of the HarmonicSet). The linear
// part is block diagonal per harmonic; the elements go through the AFT.
#include <memory>
#include <vector>

#include "cyclone/hbm/Aft.hpp"
#include "cyclone/hbm/ScalarElement.hpp"

namespace cyclone::hbm {

class HarmonicBalanceSystem {
public:
  HarmonicBalanceSystem(Eigen::MatrixXd M, Eigen::MatrixXd C, Eigen::MatrixXd K, HarmonicSet harmonics, int samples);

  /// An element acting on w = direction^T x (e.g. a unit vector for DOF-to-ground,
  /// e_i - e_j between two DOFs); its force goes back through the direction.
  void addElement(std::shared_ptr<const ScalarElement> element, Eigen::VectorXd direction);
  /// Harmonic excitation on one DOF: f = cosAmplitude cos(h w t) + sinAmplitude sin(h w t).
  void addExcitation(int dof, int harmonic, double cosAmplitude, double sinAmplitude = 0);

  int numDofs() const { return int(K_.rows()); }
  int numCoefficients() const { return aft_->numCoefficients(); }
  int numUnknowns() const { return numDofs() * numCoefficients(); }
  const Aft& aft() const { return *aft_; }

  /// R(X; omega) = Z(omega) X + F_nl(X) - s F_ex (s: excitation scale, a continuation
  /// parameter for force-level studies), and optionally dR/dX.
  void residual(const Eigen::VectorXd& X, double omega, Eigen::VectorXd& R, Eigen::MatrixXd* jacobian,
                double excitationScale = 1.0) const;
  /// The solution without the nonlinear elements: a start for continuation.
  Eigen::VectorXd linearSolution(double omega) const;
  const Eigen::MatrixXd& M() const { return M_; }
  const Eigen::MatrixXd& C() const { return C_; }
  const Eigen::MatrixXd& K() const { return K_; }
  struct Connection {
    std::shared_ptr<const ScalarElement> element;
    Eigen::VectorXd direction;
  };
  const std::vector<Connection>& elements() const { return elements_; }
  /// The excitation in coefficient form (same layout as X).
  const Eigen::VectorXd& excitation() const { return excitation_; }

  /// Amplitude sqrt(c_h^2 + s_h^2) of harmonic h >= 1 of a DOF.
  double amplitude(const Eigen::VectorXd& X, int dof, int harmonic) const;

private:
  Eigen::MatrixXd linearOperator(double omega) const;
  Eigen::MatrixXd M_, C_, K_;
  std::unique_ptr<Aft> aft_;
  std::vector<Connection> elements_;
  Eigen::VectorXd excitation_;
};

}  // namespace cyclone::hbm
