#include "cyclone/response/StiffContacts.hpp"

#include <algorithm>
#include <cmath>

#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/ScalarElementAdapter.hpp"

namespace cyclone::response {

std::vector<StiffContact> stiffContacts(const ForcedResponseSetup& setup, double ratio) {
  std::vector<StiffContact> out;
  if (!setup.system) return out;
  const auto& hb = *setup.system;
  const Eigen::MatrixXd& K = hb.K();
  const auto& elements = hb.elements();
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const auto* contact = dynamic_cast<const hbm::FrictionContact*>(elements[i].element.get());
    if (!contact) continue;
    const auto& p = contact->parameters();
    const int d = contact->dimension();  // [t (, t2), n]
    for (int j = 0; j < d; ++j) {
      const Eigen::VectorXd w = elements[i].W.col(j);
      const double ww = w.squaredNorm();
      if (!(ww > 0)) continue;  // a coordinate across the sector boundary alone: W_next's
      const double along = w.dot(K * w) / ww;
      if (!(along > 0)) continue;
      const bool normal = j == d - 1;
      StiffContact s{int(i), normal ? "kn" : "kt", normal ? p.kn : p.kt, along, normal ? p.kn : p.kt, 0};
      if (!(s.ratio() > ratio)) continue;
      // Both tangential coordinates have the one kt: the larger ratio stands for it.
      auto same = std::find_if(out.begin(), out.end(),
                               [&](const StiffContact& o) { return o.element == s.element && o.parameter == s.parameter; });
      if (same == out.end())
        out.push_back(s);
      else if (s.ratio() > same->ratio())
        *same = s;
    }
  }
  std::sort(out.begin(), out.end(), [](const StiffContact& a, const StiffContact& b) { return a.ratio() > b.ratio(); });
  return out;
}

std::vector<StiffContact> stiffCubicSprings(const ForcedResponseSetup& setup, double omega, double ratio) {
  std::vector<StiffContact> out;
  if (!setup.system || setup.system->isReceptance()) return out;
  const auto& hb = *setup.system;
  const Eigen::MatrixXd& K = hb.K();
  const int nc = hb.numCoefficients();
  Eigen::VectorXd linear;
  for (std::size_t i = 0; i < hb.elements().size(); ++i) {
    const auto* adapter = dynamic_cast<const hbm::ScalarElementAdapter*>(hb.elements()[i].element.get());
    const auto* cubic = adapter ? dynamic_cast<const hbm::CubicSpring*>(&adapter->scalar()) : nullptr;
    if (!cubic) continue;
    const Eigen::VectorXd w = hb.elements()[i].W.col(0);
    const double ww = w.squaredNorm();
    if (!(ww > 0)) continue;
    const double along = w.dot(K * w) / ww;
    if (!(along > 0)) continue;
    if (linear.size() == 0) linear = hb.linearSolution(omega);
    // The coordinate's coefficients, w^T x per coefficient: their norm stands for its amplitude.
    const Eigen::Map<const Eigen::MatrixXd> X(linear.data(), nc, hb.numDofs());
    const double amplitude = (X * w).norm();
    const double stiffness = 3 * std::abs(cubic->k3()) * amplitude * amplitude;
    StiffContact s{int(i), "k3", stiffness, along, cubic->k3(), amplitude};
    if (std::isfinite(amplitude) && !(s.ratio() <= ratio)) out.push_back(s);
  }
  std::sort(out.begin(), out.end(), [](const StiffContact& a, const StiffContact& b) { return a.ratio() > b.ratio(); });
  return out;
}

}  // namespace cyclone::response
