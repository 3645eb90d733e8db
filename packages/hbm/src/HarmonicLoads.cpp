#include "cyclone/hbm/HarmonicLoads.hpp"

#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/ProjectedReceptance.hpp"

namespace cyclone::hbm {

std::vector<HarmonicLoad> harmonicLoads(const HarmonicBalanceSystem& system, const Eigen::VectorXd& X, double omega,
                                        double excitationScale) {
  if (!system.isReceptance()) throw InputError("harmonic loads", "needs a receptance-form system");
  if (X.size() != system.numUnknowns())
    throw InputError("harmonic loads", "the solution has " + std::to_string(X.size()) + " coefficients, the system " +
                                           std::to_string(system.numUnknowns()));
  Eigen::VectorXd Fnl;
  system.nonlinearForces(X, omega, Fnl, nullptr);
  const Eigen::VectorXd f = excitationScale * system.excitation() + system.staticLoad() - Fnl;
  const auto projected = std::dynamic_pointer_cast<const ProjectedReceptance>(system.receptance());
  const auto& H = system.aft().harmonics();
  const int n = system.numDofs(), nc = system.numCoefficients();
  std::vector<HarmonicLoad> out;
  for (int h : H.harmonics()) {
    HarmonicLoad load;
    load.harmonic = h;
    load.phaseIndex = system.isCyclic() ? system.phaseIndex(h) : 0;
    Eigen::VectorXcd fq(n);
    for (int i = 0; i < n; ++i)
      fq(i) = h == 0 ? std::complex<double>(f(i * nc + H.cosIndex(0)), 0.0)
                     : std::complex<double>(f(i * nc + H.cosIndex(h)), -f(i * nc + H.sinIndex(h)));
    // Harmonic 0 is the same in every sector: T_0 = T + T_next (the transform of phase 0).
    load.force = projected ? Eigen::VectorXcd(projected->transform(load.phaseIndex).adjoint() * fq) : fq;
    out.push_back(std::move(load));
  }
  return out;
}

std::vector<Eigen::VectorXcd> harmonicResponse(const ReceptanceModel& model, const std::vector<HarmonicLoad>& loads,
                                               double omega) {
  std::vector<Eigen::VectorXcd> out;
  for (const auto& load : loads) {
    if (load.force.size() != model.numDofs())
      throw InputError("harmonic response", "a load on " + std::to_string(load.force.size()) + " DOFs for a model of " +
                                                std::to_string(model.numDofs()));
    if (load.harmonic == 0) out.push_back(model.meanCompliance().cast<std::complex<double>>() * load.force);
    else out.push_back(model.compliance(load.harmonic * omega, load.phaseIndex) * load.force);
  }
  return out;
}

}  // namespace cyclone::hbm
