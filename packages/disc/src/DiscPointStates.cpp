#include "cyclone/disc/DiscPointStates.hpp"

#include <algorithm>
#include <cmath>

#include "cyclone/core/Error.hpp"

namespace cyclone::disc {

namespace {

ContactAtPoint contactAt(const hbm::HarmonicSet& H, const hbm::ElementState& state) {
  ContactAtPoint c;
  c.energyPerCycle = hbm::dissipatedEnergyPerCycle(H, state);
  const Eigen::MatrixXd &W = state.W, &F = state.F;
  const Eigen::Index d = W.cols();
  if (H.contains(0)) c.meanNormalForce = F(H.cosIndex(0), d - 1);
  if (H.contains(1))
    for (Eigen::Index t = 0; t + 1 < d; ++t)
      c.slipAmplitude += W(H.cosIndex(1), t) * W(H.cosIndex(1), t) + W(H.sinIndex(1), t) * W(H.sinIndex(1), t);
  c.slipAmplitude = std::sqrt(c.slipAmplitude);
  return c;
}

}  // namespace

DiscPointStates discPointStates(const response::ForcedResponseSetup& setup, const PeakPoint& point,
                                const std::vector<int>& loopContacts) {
  const auto& hb = *point.system;
  const auto& H = hb.aft().harmonics();
  DiscPointStates out;
  out.omega = point.omega;
  const auto states = hbm::elementStates(hb, point.x, point.omega);
  for (const auto& s : states) out.contacts.push_back(contactAt(H, s));
  if (!out.contacts.empty())
    out.mostDissipating = int(std::max_element(out.contacts.begin(), out.contacts.end(),
                                               [](const auto& a, const auto& b) {
                                                 return a.energyPerCycle < b.energyPerCycle;
                                               }) -
                              out.contacts.begin());
  std::vector<int> chosen = loopContacts;
  if (chosen.empty() && out.mostDissipating >= 0) chosen.push_back(out.mostDissipating);
  for (int e : chosen) {
    if (e < 0 || e >= int(states.size()))
      throw InputError("hysteresis_contacts", std::to_string(e) + " is not a contact of the system (0.." +
                                                  std::to_string(int(states.size()) - 1) + ")");
    out.loops.push_back({e, hbm::elementPeriod(hb, std::size_t(e), states[std::size_t(e)], point.omega)});
  }
  const auto& aft = hb.aft();
  const int N = aft.numSamples(), nc = hb.numCoefficients();
  for (int i = 0; i < N; ++i) out.phase.push_back(double(i) / N);
  out.response.resize(N, Eigen::Index(setup.outputDofs.size()));
  for (std::size_t k = 0; k < setup.outputDofs.size(); ++k)
    aft.toTime(point.x.data() + std::ptrdiff_t(setup.outputDofs[k]) * nc, out.response.col(Eigen::Index(k)).data());
  return out;
}

}  // namespace cyclone::disc
