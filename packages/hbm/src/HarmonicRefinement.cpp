#include "cyclone/hbm/HarmonicRefinement.hpp"

#include <string>

#include "cyclone/core/Error.hpp"

namespace cyclone::hbm {

Eigen::VectorXd transferCoefficients(const Eigen::VectorXd& X, int n, const HarmonicSet& from, const HarmonicSet& to) {
  const int ncf = from.numCoefficients(), nct = to.numCoefficients();
  if (X.size() != n * ncf) throw InputError("transferCoefficients", "coefficient vector of the wrong size");
  Eigen::VectorXd Y = Eigen::VectorXd::Zero(n * nct);
  for (int h : from.harmonics()) {
    if (!to.contains(h)) continue;
    const int slots = h == 0 ? 1 : 2;
    for (int a = 0; a < n; ++a)
      Y.segment(a * nct + to.cosIndex(h), slots) = X.segment(a * ncf + from.cosIndex(h), slots);
  }
  return Y;
}

std::vector<int> addedCoefficients(int numDofs, const HarmonicSet& from, const HarmonicSet& to) {
  std::vector<int> added;
  const int nc = to.numCoefficients();
  for (int d = 0; d < numDofs; ++d)
    for (int h : to.harmonics()) {
      if (from.contains(h)) continue;
      added.push_back(d * nc + to.cosIndex(h));
      if (h > 0) added.push_back(d * nc + to.sinIndex(h));
    }
  return added;
}

std::unique_ptr<HarmonicBalanceSystem> withHarmonics(const HarmonicBalanceSystem& s, HarmonicSet harmonics,
                                                     int samples) {
  const HarmonicSet& from = s.aft().harmonics();
  const int n = s.numDofs(), nc = s.numCoefficients();
  for (int h : from.harmonics()) {
    if (harmonics.contains(h)) continue;
    for (int a = 0; a < n; ++a) {
      const int slots = h == 0 ? 1 : 2;
      if (s.excitation().segment(a * nc + from.cosIndex(h), slots).squaredNorm() > 0 ||
          s.staticLoad().segment(a * nc + from.cosIndex(h), slots).squaredNorm() > 0)
        throw InputError("harmonics", "the excitation acts on harmonic " + std::to_string(h) +
                                          ", which the new harmonic set lacks");
    }
  }
  auto out = s.isReceptance() ? std::make_unique<HarmonicBalanceSystem>(s.receptance(), harmonics, samples)
                              : std::make_unique<HarmonicBalanceSystem>(s.M(), s.C(), s.K(), harmonics, samples);
  if (s.isCyclic()) out->setCyclic(s.cyclic());
  if (s.isReceptance()) out->useDynamicStiffness(s.usesDynamicStiffness());
  for (const auto& c : s.elements()) out->addElement(c.element, c.W, c.Wnext);
  const HarmonicSet& to = out->aft().harmonics();
  out->addExcitationCoefficients(transferCoefficients(s.excitation(), n, from, to));
  out->addStaticLoadCoefficients(transferCoefficients(s.staticLoad(), n, from, to));
  return out;
}

std::unique_ptr<HarmonicBalanceSystem> withReceptance(const HarmonicBalanceSystem& s,
                                                      std::shared_ptr<const ReceptanceModel> model) {
  if (!s.isReceptance()) throw InputError("receptance", "the system is not in receptance form");
  if (!model || model->numDofs() != s.numDofs() || model->sectors() != s.receptance()->sectors())
    throw InputError("receptance", "the new model must have the system's DOFs and sectors");
  auto out = std::make_unique<HarmonicBalanceSystem>(std::move(model), s.aft().harmonics(), s.aft().numSamples());
  if (s.isCyclic()) out->setCyclic(s.cyclic());
  for (const auto& c : s.elements()) out->addElement(c.element, c.W, c.Wnext);
  out->addExcitationCoefficients(s.excitation());
  out->addStaticLoadCoefficients(s.staticLoad());
  return out;
}

}  // namespace cyclone::hbm
