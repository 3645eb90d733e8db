#include "cyclone/mistuning/ReducedSectorRing.hpp"

#include <string>

#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/FullRingSystem.hpp"
#include "cyclone/mistuning/RingReceptance.hpp"

namespace cyclone::mistuning {

std::vector<int> everyNodalDiameter(int sectors) {
  if (sectors < 2) throw InputError("sectors", "a ring needs at least 2 sectors, got " + std::to_string(sectors));
  std::vector<int> out;
  for (int k = 0; 2 * k <= sectors; ++k) out.push_back(k);
  return out;
}

namespace {

void checkRingSector(const hbm::HarmonicBalanceSystem& s) {
  if (!s.isCyclic()) throw InputError("ring", "the sector's system is not cyclic");
  if (!s.isReceptance())
    throw InputError("ring", "the sector's system is in the matrix form (hbm::expandToFullRing expands it)");
  if (s.receptance()->sectors() != s.cyclic().sectors)
    throw InputError("ring", "the sector's model has " + std::to_string(s.receptance()->sectors()) +
                                 " sectors, its system " + std::to_string(s.cyclic().sectors));
}

}  // namespace

std::unique_ptr<hbm::HarmonicBalanceSystem> ringOfSectors(const hbm::HarmonicBalanceSystem& s) {
  checkRingSector(s);
  return ringOfSectors(s, std::make_shared<RingReceptance>(s.receptance()));
}

std::unique_ptr<hbm::HarmonicBalanceSystem> ringOfSectors(const hbm::HarmonicBalanceSystem& s,
                                                          std::shared_ptr<const hbm::ReceptanceModel> model) {
  checkRingSector(s);
  const int N = s.cyclic().sectors, n = s.numDofs();
  if (!model || model->sectors() != 1 || model->numDofs() != N * n)
    throw InputError("ring", "the ring's model must be one non-cyclic model of " + std::to_string(N * n) +
                                 " DOFs (N sectors' " + std::to_string(n) + ")");
  auto ring = std::make_unique<hbm::HarmonicBalanceSystem>(model, s.aft().harmonics(), s.aft().numSamples());
  ring->useDynamicStiffness(s.usesDynamicStiffness());
  for (const auto& c : s.elements())
    for (int j = 0; j < N; ++j) {
      Eigen::MatrixXd W = Eigen::MatrixXd::Zero(long(N) * n, c.W.cols());
      W.middleRows(long(j) * n, n) += c.W;
      if (c.Wnext.size()) W.middleRows(long((j + 1) % N) * n, n) += c.Wnext;
      ring->addElement(c.element, W);
    }
  ring->addExcitationCoefficients(hbm::ringCoefficients(s, s.excitation()));
  ring->addStaticLoadCoefficients(hbm::ringCoefficients(s, s.staticLoad()));
  return ring;
}

void checkRingModels(const disc::DiscReducedModels& models) {
  const int N = models.sectors;
  if (N < 2) throw InputError("reduced_model/nodal_diameters", "the models are not of a ring (N = " + std::to_string(N) + ")");
  std::string missing;
  for (int k : everyNodalDiameter(N))
    if (!models.models.count(k) || !models.models.at(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
  if (!missing.empty())
    throw InputError("reduced_model/nodal_diameters",
                     "the ring of reduced sectors needs a model of every nodal diameter 0.." + std::to_string(N / 2) +
                         "; missing: " + missing);
}

DiscRing makeDiscRing(const mesh::Mesh& mesh, const disc::DiscReducedModels& models, const disc::DiscResponseSpec& spec,
                      double referenceHz) {
  checkRingModels(models);
  auto sectorSpec = spec;
  sectorSpec.condensed = false;
  DiscRing out;
  out.sector = disc::makeDiscForcedResponse(mesh, models, sectorSpec, referenceHz);
  const auto& s = out.sector;
  out.sectors = models.sectors, out.sectorDofs = s.system->numDofs();
  const int N = out.sectors, n = out.sectorDofs;
  auto& r = out.ring;
  r.system = ringOfSectors(*s.system);
  r.parameter = s.parameter, r.omegaUnit = s.omegaUnit, r.unknownScale = s.unknownScale;
  r.excitationScale = s.excitationScale, r.stability = s.stability;
  r.continuation = s.continuation, r.fallback = s.fallback;
  for (int j = 0; j < N; ++j) {
    for (const auto& e : s.elementNames) r.elementNames.push_back(e);
    for (const auto& d : s.dofNames) r.dofNames.push_back("blade" + std::to_string(j) + "_" + d);
    std::vector<int> dofs;
    for (int d : s.outputDofs) dofs.push_back(j * n + d);
    out.bladeOutputDofs.push_back(dofs);
  }
  r.outputDofs = out.bladeOutputDofs.front();
  return out;
}

}  // namespace cyclone::mistuning
