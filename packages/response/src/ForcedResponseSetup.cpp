#include "cyclone/response/ForcedResponseSetup.hpp"

#include <cmath>

#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"

namespace cyclone::response {

namespace {

// The harmonic balance Jacobian's blocks as the continuation's operator, its rows scaled
// as the residual's.
std::shared_ptr<continuation::JacobianOperator> jacobianOperator(std::unique_ptr<hbm::JacobianBlocks> blocks,
                                                                 const Eigen::VectorXd& f) {
  blocks->scaleRows(f.cwiseInverse());
  return std::make_shared<continuation::JacobianOperatorOf<hbm::JacobianBlocks>>(std::move(blocks));
}// Residual rows are divided by the size of the forces acting on them: the
// mean (harmonic 0) rows by the static loads and mean excitation, the others
// by the dynamic excitation. The continuation's tolerance is then relative,
// and a 1e9 N preload neither swamps a 10 N excitation nor is held to its
// absolute accuracy.
Eigen::VectorXd forceScale(const hbm::HarmonicBalanceSystem& hb, double excitationScale) {
  const auto& H = hb.aft().harmonics();
  const int n = hb.numDofs(), nc = hb.numCoefficients();
  const Eigen::VectorXd F = std::abs(excitationScale) * hb.excitation();
  Eigen::VectorXd mean = Eigen::VectorXd::Zero(n * nc), dynamic = mean;
  for (int a = 0; a < n; ++a)
    for (int k = 0; k < nc; ++k) {
      const bool isMean = H.contains(0) && k == H.cosIndex(0);
      (isMean ? mean : dynamic)(a * nc + k) = F(a * nc + k) + (isMean ? hb.staticLoad()(a * nc + k) : 0.0);
    }
  double f0 = mean.norm(), fd = dynamic.norm();
  if (f0 == 0) f0 = fd > 0 ? fd : 1.0;
  if (fd == 0) fd = f0;
  Eigen::VectorXd D = Eigen::VectorXd::Constant(n * nc, fd);
  if (H.contains(0))
    for (int a = 0; a < n; ++a) D(a * nc + H.cosIndex(0)) = f0;
  return D;
}

// The continuation's scale groups, split the same way: the mean coefficients (0) and the
// oscillating ones (1). A preload's static deformation is then not the yardstick of the
// vibration's change along the path (a stuck shroud's sharp resonance was stepped over).
std::vector<int> meanAndOscillation(const hbm::HarmonicBalanceSystem& hb) {
  const auto& H = hb.aft().harmonics();
  const int n = hb.numDofs(), nc = hb.numCoefficients();
  std::vector<int> groups(std::size_t(n * nc), 1);
  if (H.contains(0))
    for (int a = 0; a < n; ++a) groups[std::size_t(a * nc + H.cosIndex(0))] = 0;
  return groups;
}
}  // namespace

continuation::ContinuationProblem continuationProblem(const hbm::HarmonicBalanceSystem& hb,
                                                      ForcedResponseSetup::Parameter parameter, double omega,
                                                      double excitationScale) {
  if (parameter != ForcedResponseSetup::Parameter::Omega && parameter != ForcedResponseSetup::Parameter::ForceScale)
    throw InputError("continuation", "element and damping parameters need the scene's setup: continuationProblem(setup)");
  const bool byForce = parameter == ForcedResponseSetup::Parameter::ForceScale;
  continuation::ContinuationProblem problem;
  problem.size = hb.numUnknowns();
  problem.scaleGroups = meanAndOscillation(hb);
  const double s = excitationScale;
  const Eigen::VectorXd f = forceScale(hb, byForce ? 1.0 : s);
  problem.residual = [&hb, byForce, omega, s, f](const Eigen::VectorXd& X, double p, Eigen::VectorXd& R) {
    hb.residual(X, byForce ? omega : p, R, nullptr, byForce ? p : s);
    R.array() /= f.array();
  };
  problem.jacobian = [&hb, byForce, omega, s, f](const Eigen::VectorXd& X, double p, Eigen::MatrixXd& J) {
    Eigen::VectorXd R;
    hb.residual(X, byForce ? omega : p, R, &J, byForce ? p : s);
    J = f.cwiseInverse().asDiagonal() * J;
  };
  if (hb.hasJacobianBlocks())
    problem.jacobianOperator = [&hb, byForce, omega, f](const Eigen::VectorXd& X, double p) {
      return jacobianOperator(hb.jacobianBlocks(X, byForce ? omega : p), f);
    };
  return problem;
}

void selectElementParameter(ForcedResponseSetup& setup, const std::string& element, const std::string& parameter,
                            double probe, std::vector<double> weights) {
  setup.parameter = ForcedResponseSetup::Parameter::ElementParameter;
  setup.elementParameter = parameter;
  setup.parameterElements.clear();
  setup.baseElements.clear();
  for (std::size_t i = 0; i < setup.elementNames.size(); ++i)
    if (setup.elementNames[i] == element) {
      setup.parameterElements.push_back(int(i));
      setup.baseElements.push_back(setup.system->elements()[i].element);
      setup.baseElements.back()->withParameter(parameter, probe);  // InputError for an unknown parameter
    }
  if (setup.parameterElements.empty()) throw InputError("continuation", "no nonlinear element named '" + element + "'");
  if (!weights.empty() && weights.size() != setup.parameterElements.size())
    throw InputError("continuation", std::to_string(weights.size()) + " weights for the " +
                                         std::to_string(setup.parameterElements.size()) + " elements named '" +
                                         element + "'");
  setup.parameterWeights = std::move(weights);
}

std::string ForcedResponseSetup::parameterName() const {
  switch (parameter) {
    case Parameter::Omega: return "omega";
    case Parameter::ForceScale: return "force_scale";
    case Parameter::DampingScale: return "damping_scale";
    case Parameter::Rebuilt: return rebuiltParameter;
    case Parameter::ElementParameter: return elementNames.at(parameterElements.at(0)) + "/" + elementParameter;
  }
  return "";
}

std::pair<double, double> ForcedResponseSetup::apply(double p) {
  switch (parameter) {
    case Parameter::Omega: return {p * omegaUnit, excitationScale};
    case Parameter::ForceScale: return {omega, p};
    case Parameter::DampingScale: system->setDampingScale(p); break;
    case Parameter::Rebuilt:
      if (!rebuild) throw InputError("continuation", "a rebuilt parameter needs its rebuild function");
      if (!(p == rebuiltAt)) system = rebuild(p), rebuiltAt = p;
      break;
    case Parameter::ElementParameter:
      for (std::size_t i = 0; i < parameterElements.size(); ++i)
        system->replaceElement(parameterElements[i],
                               baseElements[i]->withParameter(
                                   elementParameter, parameterWeights.empty() ? p : parameterWeights[i] * p));
      break;
  }
  return {omega, excitationScale};
}

continuation::ContinuationProblem continuationProblem(ForcedResponseSetup& setup) {
  continuation::ContinuationProblem problem;
  problem.size = setup.system->numUnknowns();
  problem.scaleGroups = meanAndOscillation(*setup.system);
  const bool byForce = setup.parameter == ForcedResponseSetup::Parameter::ForceScale;
  const Eigen::VectorXd f = forceScale(*setup.system, byForce ? 1.0 : setup.excitationScale);
  problem.residual = [&setup, f](const Eigen::VectorXd& X, double p, Eigen::VectorXd& R) {
    const auto [w, s] = setup.apply(p);  // an invalid value (e.g. kt < 0) throws: the step is cut
    setup.system->residual(X, w, R, nullptr, s);
    R.array() /= f.array();
  };
  problem.jacobian = [&setup, f](const Eigen::VectorXd& X, double p, Eigen::MatrixXd& J) {
    const auto [w, s] = setup.apply(p);
    Eigen::VectorXd R;
    setup.system->residual(X, w, R, &J, s);
    J = f.cwiseInverse().asDiagonal() * J;
  };
  // A rebuilt system is replaced at every other parameter value, and the operator refers
  // to the system it came from (its elements' maps): that parameter keeps the formed Jacobian.
  if (setup.system->hasJacobianBlocks() && setup.parameter != ForcedResponseSetup::Parameter::Rebuilt)
    problem.jacobianOperator = [&setup, f](const Eigen::VectorXd& X, double p) {
      const double w = setup.apply(p).first;
      return jacobianOperator(setup.system->jacobianBlocks(X, w), f);
    };
  // A frequency curve's resonance peaks (of the first output DOF's max |x(t)|, the
  // summary's peak) are located exactly on the path, not left between two samples.
  if (setup.parameter == ForcedResponseSetup::Parameter::Omega && !setup.outputDofs.empty()) {
    const int dof = setup.outputDofs.front(), nc = setup.system->numCoefficients();
    const hbm::HarmonicSet harmonics = setup.system->aft().harmonics();
    problem.measure = [harmonics, dof, nc](const Eigen::VectorXd& X) {
      return hbm::peakMagnitude(harmonics, Eigen::VectorXd(X.segment(dof * nc, nc)));
    };
  }
  return problem;
}

continuation::PeakTrackingProblem peakFollowingProblem(ForcedResponseSetup& setup) {
  if (setup.parameter == ForcedResponseSetup::Parameter::Omega)
    throw InputError("peak following", "the parameter must be other than the frequency");
  if (setup.outputDofs.empty()) throw InputError("peak following", "needs an output DOF (its max |x(t)| is the peak)");
  continuation::PeakTrackingProblem problem;
  problem.size = setup.system->numUnknowns();
  problem.scaleGroups = meanAndOscillation(*setup.system);
  const bool byForce = setup.parameter == ForcedResponseSetup::Parameter::ForceScale;
  const Eigen::VectorXd f = forceScale(*setup.system, byForce ? 1.0 : setup.excitationScale);
  problem.residual = [&setup, f](const Eigen::VectorXd& X, double w, double p, Eigen::VectorXd& R) {
    const double s = setup.apply(p).second;
    setup.system->residual(X, w, R, nullptr, s);
    R.array() /= f.array();
  };
  problem.jacobian = [&setup, f](const Eigen::VectorXd& X, double w, double p, Eigen::MatrixXd& J) {
    const double s = setup.apply(p).second;
    Eigen::VectorXd R;
    setup.system->residual(X, w, R, &J, s);
    J = f.cwiseInverse().asDiagonal() * J;
  };
  const int dof = setup.outputDofs.front(), nc = setup.system->numCoefficients();
  const hbm::HarmonicSet harmonics = setup.system->aft().harmonics();
  problem.measure = [harmonics, dof, nc](const Eigen::VectorXd& X) {
    return hbm::peakMagnitude(harmonics, Eigen::VectorXd(X.segment(dof * nc, nc)));
  };
  if (harmonics.contains(1)) {  // the output DOF's fundamental: its phase turns through the resonance
    problem.phaseCosIndex = dof * nc + harmonics.cosIndex(1);
    problem.phaseSinIndex = dof * nc + harmonics.sinIndex(1);
  }
  return problem;
}

}  // namespace cyclone::response
