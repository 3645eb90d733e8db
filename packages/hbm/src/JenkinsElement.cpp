#include "cyclone/hbm/JenkinsElement.hpp"

#include <memory>

#include "cyclone/core/Error.hpp"

#include <cmath>
#include <string>

namespace cyclone::hbm {

JenkinsElement::JenkinsElement(double kt, double slipForce) : kt_(kt), slipForce_(slipForce) {
  if (!(std::isfinite(kt) && kt > 0))
    throw InputError("JenkinsElement", "tangential stiffness must be positive, got " + std::to_string(kt));
  if (!(std::isfinite(slipForce) && slipForce > 0))
    throw InputError("JenkinsElement", "slip force must be positive, got " + std::to_string(slipForce));
}

void JenkinsElement::evaluate(const Eigen::VectorXd& w, const Eigen::VectorXd&, Eigen::VectorXd& f,
                              Eigen::MatrixXd* dfdw, Eigen::MatrixXd* dfdwdot) const {
  const Eigen::Index n = w.size();
  f.resize(n);
  // z: slider position; dz[m] = dz/dw[m], carried along the march.
  double z = 0.0;
  Eigen::VectorXd dz;
  if (dfdw) {
    dz.setZero(n);
    dfdw->setZero(n, n);
  }
  for (int loop = 0; loop < 2; ++loop) {
    const bool record = loop == 1;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double trial = kt_ * (w[i] - z);
      if (std::abs(trial) <= slipForce_) {  // stick: the slider stays, the spring takes the motion
        if (record) f[i] = trial;
        if (dfdw && record) {
          dfdw->row(i) = -kt_ * dz.transpose();
          (*dfdw)(i, i) += kt_;
        }
      } else {  // slip: force saturates, the slider follows w at a fixed spring stretch
        const double s = trial > 0 ? 1.0 : -1.0;
        if (record) f[i] = s * slipForce_;  // Jacobian row stays 0
        z = w[i] - s * slipForce_ / kt_;
        if (dfdw) {
          dz.setZero();
          dz[i] = 1.0;
        }
      }
    }
  }
  if (dfdwdot) dfdwdot->setZero(n, n);
}

void JenkinsElement::forceSensitivity(const Eigen::VectorXd& w, const Eigen::VectorXd&, const Eigen::MatrixXd& dw,
                                      const Eigen::MatrixXd&, Eigen::VectorXd& f, Eigen::MatrixXd& df) const {
  // The march of evaluate() with the slider's sensitivity carried as a row: after a
  // slip at sample j it is dw.row(j), and a stick sample's force row is kt (dw_i - dz).
  const Eigen::Index n = w.size();
  f.resize(n);
  df.setZero(n, dw.cols());
  double z = 0.0;
  Eigen::Index lastSlip = -1;  // dz = 0 until the first slip
  for (int loop = 0; loop < 2; ++loop) {
    const bool record = loop == 1;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double trial = kt_ * (w[i] - z);
      if (std::abs(trial) <= slipForce_) {
        if (!record) continue;
        f[i] = trial;
        df.row(i) = kt_ * dw.row(i);
        if (lastSlip >= 0) df.row(i) -= kt_ * dw.row(lastSlip);
      } else {
        const double s = trial > 0 ? 1.0 : -1.0;
        if (record) f[i] = s * slipForce_;  // its sensitivity row stays 0
        z = w[i] - s * slipForce_ / kt_;
        lastSlip = i;
      }
    }
  }
}

}  // namespace cyclone::hbm

namespace cyclone::hbm {

double JenkinsElement::incremental(double w, double, double& z, double& dfdw, double& dfdwdot) const {
  // The same return mapping as the periodic marching: stick keeps z, slip drags it.
  dfdwdot = 0;
  const double trial = kt_ * (w - z);
  if (std::abs(trial) <= slipForce_) {
    dfdw = kt_;
    return trial;
  }
  const double sign = trial > 0 ? 1.0 : -1.0;
  z = w - sign * slipForce_ / kt_;
  dfdw = 0;
  return sign * slipForce_;
}

std::shared_ptr<const ScalarElement> JenkinsElement::withParameter(const std::string& name, double value) const {
  if (name == "kt") return std::make_shared<JenkinsElement>(value, slipForce_);
  if (name == "slip_force") return std::make_shared<JenkinsElement>(kt_, value);
  throw InputError("nonlinear element", "unknown parameter '" + name + "' (kt, slip_force)");
}

}  // namespace cyclone::hbm
