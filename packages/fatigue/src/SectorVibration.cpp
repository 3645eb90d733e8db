#include "cyclone/fatigue/SectorVibration.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/CyclicModalAnalysis.hpp"
#include "cyclone/fe/StressRecovery.hpp"
#include "cyclone/rom/SectorReceptance.hpp"

namespace cyclone::fatigue {

namespace {

std::vector<std::array<double, 3>> part(const std::vector<Eigen::Vector3cd>& u, bool imaginary) {
  std::vector<std::array<double, 3>> out(u.size());
  for (std::size_t n = 0; n < u.size(); ++n)
    for (int d = 0; d < 3; ++d) out[n][std::size_t(d)] = imaginary ? u[n](d).imag() : u[n](d).real();
  return out;
}

}  // namespace

std::vector<Eigen::Vector3d> SectorVibration::displacementAt(double theta) const {
  std::vector<Eigen::Vector3d> out(displacement.empty() ? 0 : displacement.front().size(), Eigen::Vector3d::Zero());
  for (std::size_t k = 0; k < harmonics.size(); ++k) {
    const std::complex<double> e(std::cos(harmonics[k] * theta), std::sin(harmonics[k] * theta));
    for (std::size_t n = 0; n < out.size(); ++n) out[n] += (displacement[k][n] * e).real();
  }
  return out;
}

Voigt SectorVibration::meanStress(std::size_t node) const {
  Voigt s = prestress.empty() ? Voigt::Zero() : prestress[node];
  for (std::size_t k = 0; k < harmonics.size(); ++k)
    if (harmonics[k] == 0) s += stress[k][node].real();
  return s;
}

std::vector<HarmonicStress> SectorVibration::alternatingStress(std::size_t node) const {
  std::vector<HarmonicStress> out;
  for (std::size_t k = 0; k < harmonics.size(); ++k)
    if (harmonics[k] > 0) out.push_back({harmonics[k], stress[k][node]});
  return out;
}

SectorVibration recoverSectorVibration(const mesh::Mesh& mesh, const cyclic::CyclicSector& sector,
                                       rom::NodalDiameterModelProblem problem, const std::vector<hbm::HarmonicLoad>& loads,
                                       double omega, linalg::CommPtr comm) {
  Timer timer;
  SectorVibration out;
  out.omega = omega;
  std::map<int, std::unique_ptr<rom::NodalDiameterModel>> models;  // one per nodal diameter
  for (const auto& load : loads) {
    const auto [k, sign] = rom::SectorReceptance::nodalDiameter(sector.sectors, load.phaseIndex);
    auto& model = models[k];
    if (!model) {
      problem.nodalDiameter = k;
      model = std::make_unique<rom::NodalDiameterModel>(mesh, sector, problem, comm);
    }
    const auto u = model->fieldResponse(load.harmonic * omega, load.force, sign);
    // The field at the retained DOFs, in the loads' order (copy a's DOFs).
    const auto& dofs = model->retainedDofs();
    Eigen::VectorXcd x(dofs.size());
    for (Eigen::Index i = 0; i < dofs.size(); ++i)
      x(i) = dofs.read(i, u);
    const auto& assembler = *model->operators().assembler;
    const auto re = fe::recoverStresses(assembler, problem.material, part(u, false));
    const auto im = fe::recoverStresses(assembler, problem.material, part(u, true));
    std::vector<ComplexVoigt> s(u.size());
    for (std::size_t n = 0; n < u.size(); ++n)
      for (int c = 0; c < 6; ++c) s[n](c) = {re.nodalStress[n][std::size_t(c)], im.nodalStress[n][std::size_t(c)]};
    out.harmonics.push_back(load.harmonic);
    out.nodalDiameters.push_back(k);
    out.displacement.push_back(u);
    out.stress.push_back(std::move(s));
    out.retainedResponse.push_back(std::move(x));
  }
  if (problem.prestress) {
    const auto& state = problem.prestress->stress;
    if (std::ptrdiff_t(state.size()) != std::ptrdiff_t(mesh.numElements()))
      throw InputError("prestress", "its stresses are not per element of this mesh");
    std::vector<std::array<double, 6>> element(state.size());
    for (std::size_t e = 0; e < state.size(); ++e) {
      const Eigen::Matrix<double, 1, 6> m = state[e].colwise().mean();
      for (int c = 0; c < 6; ++c) element[e][std::size_t(c)] = m(c);
    }
    for (const auto& a : fe::averageToNodes(mesh, element)) out.prestress.push_back(Eigen::Map<const Voigt>(a.data()));
  }
  out.seconds = timer.seconds();
  std::ostringstream msg;
  msg << "sector vibration: " << loads.size() << " harmonics on " << models.size() << " nodal diameters, "
      << mesh.numNodes() << " nodes, " << out.seconds << " s";
  log::info(msg.str());
  return out;
}

FatigueMap assessFatigue(const SectorVibration& v, const FatigueMaterial& material, int samples) {
  material.validate("fatigue");
  FatigueMap out;
  const std::size_t nn = v.displacement.empty() ? 0 : v.displacement.front().size();
  out.cycle.resize(nn);
  out.safetyFactor.resize(nn);
  for (std::size_t n = 0; n < nn; ++n) {
    out.cycle[n] = measureCycle(v.meanStress(n), v.alternatingStress(n), samples);
    out.safetyFactor[n] = goodmanSafetyFactor(out.cycle[n].meanVonMises, out.cycle[n].alternatingVonMises, material);
  }
  if (nn > 0) out.critical = std::size_t(std::min_element(out.safetyFactor.begin(), out.safetyFactor.end()) - out.safetyFactor.begin());
  return out;
}

std::vector<std::size_t> FatigueMap::nodesWorstFirst() const {
  std::vector<std::size_t> order(safetyFactor.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [this](auto a, auto b) { return safetyFactor[a] < safetyFactor[b]; });
  return order;
}

}  // namespace cyclone::fatigue
