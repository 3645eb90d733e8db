#include "cyclone/hbm/ElementStates.hpp"

#include <cmath>

#include "cyclone/core/Error.hpp"

namespace cyclone::hbm {

std::vector<ElementState> elementStates(const HarmonicBalanceSystem& system, const Eigen::VectorXd& x, double omega) {
  const int nc = system.numCoefficients();
  if (x.size() != Eigen::Index(nc) * system.numDofs())
    throw InputError("element states", "the solution has " + std::to_string(x.size()) + " coefficients, the system " +
                                           std::to_string(nc * system.numDofs()));
  const Eigen::Map<const Eigen::MatrixXd> X(x.data(), nc, system.numDofs());
  std::vector<ElementState> out;
  for (const auto& c : system.elements()) {
    ElementState s;
    s.W = X * c.W;
    if (c.Wnext.size() != 0) s.W += system.nextSectorMap() * (X * c.Wnext);
    c.element->harmonicForce(system.aft(), s.W, omega, s.F, nullptr);
    out.push_back(std::move(s));
  }
  return out;
}

double dissipatedEnergyPerCycle(const HarmonicSet& harmonics, const ElementState& state) {
  double energy = 0;
  for (int h : harmonics.harmonics()) {
    if (h == 0) continue;
    const int ic = harmonics.cosIndex(h), is = harmonics.sinIndex(h);
    for (Eigen::Index k = 0; k < state.W.cols(); ++k)
      energy += M_PI * h * (state.F(ic, k) * state.W(is, k) - state.F(is, k) * state.W(ic, k));
  }
  return energy;
}

ElementPeriod elementPeriod(const HarmonicBalanceSystem& system, std::size_t element, const ElementState& state,
                            double omega) {
  const auto& aft = system.aft();
  ElementPeriod out;
  out.w.resize(aft.numSamples(), state.W.cols());
  for (Eigen::Index c = 0; c < state.W.cols(); ++c) aft.toTime(state.W.col(c).data(), out.w.col(c).data());
  out.f = system.elements().at(element).element->forceSamples(aft, state.W, omega);
  return out;
}

}  // namespace cyclone::hbm
