#include "cyclone/mistuning/DiscMistunedRing.hpp"

#include <cmath>
#include <complex>
#include <map>
#include <string>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/CyclicModalAnalysis.hpp"
#include "cyclone/fe/ElementKernels.hpp"
#include "cyclone/mistuning/ReducedSectorRing.hpp"
#include "cyclone/rom/SectorReceptance.hpp"

namespace cyclone::mistuning {

using cd = std::complex<double>;

namespace {

/// Mode i's shape as one complex column: real + sign i imag, node-major.
Eigen::VectorXcd travellingWave(const cyclic::ModeShape& s, int sign) {
  const std::size_t n = s.real.size();
  Eigen::VectorXcd c(3 * Eigen::Index(n));
  for (std::size_t a = 0; a < n; ++a)
    for (int d = 0; d < 3; ++d) c(3 * Eigen::Index(a) + d) = cd(s.real[a][d], sign * s.imag[a][d]);
  return c;
}

}  // namespace

DiscNominalModes discNominalModes(const mesh::Mesh& mesh, const disc::DiscReducedModels& models,
                                  const disc::DiscModelSpec& spec, linalg::CommPtr comm) {
  Timer timer;
  checkRingModels(models);
  if (!models.retainedMeans.empty())
    throw InputError("reduced_model/retained_means",
                     "the mistuned ring (subset of nominal modes) takes retained nodes only, not weighted means");
  const int N = models.sectors;
  auto receptance = std::make_shared<rom::SectorReceptance>(N, models.models);

  cyclic::CyclicModalProblem problem;
  problem.material = spec.material;
  problem.fixedNodeSets = spec.fixedNodeSets;
  problem.modesPerNodalDiameter = spec.modes;
  problem.shapeStorage = cyclic::CyclicModalProblem::ShapeStorage::Memory;
  for (int k = 0; k <= N / 2; ++k) problem.nodalDiameters.push_back(k);
  if (auto prestress = disc::discPrestress(mesh, models.sector, spec, comm))
    problem.prestress = std::make_shared<const cyclic::PrestressState>(std::move(*prestress));
  const auto byNd = cyclic::solveCyclicModes(mesh, models.sector, problem, comm);
  std::map<int, const cyclic::NodalDiameterModes*> nd;
  for (const auto& m : byNd) nd[m.nodalDiameter] = &m;

  DiscNominalModes out;
  out.sectors = N;
  std::map<long, hbm::ModalRealization> phases;
  for (int p = 0; p < N; ++p) {
    const auto [k, sign] = rom::SectorReceptance::nodalDiameter(N, p);
    const auto it = nd.find(k);
    if (it == nd.end()) throw Error("discNominalModes: nodal diameter " + std::to_string(k) + " was not solved");
    const auto& modes = *it->second;
    const auto tuned = receptance->modalRealization(p);
    if (!tuned)
      throw InputError("reduced_model/kind", "the nodal diameter " + std::to_string(k) +
                                                 " model has no modal form (the mistuned ring needs hybrid models)");
    // One travelling wave per natural frequency: a pair's two real-form modes span one
    // complex shape (the second is +-i times the first's), so its first stands for both.
    std::vector<Eigen::VectorXcd> cols;
    std::vector<double> ls;
    const auto& hz = modes.frequenciesHz;
    for (std::size_t i = 0; i < hz.size();) {
      std::size_t e = i + 1;
      if (modes.copies == 2)
        while (e < hz.size() && std::abs(hz[e] - hz[i]) <= 1e-6 * std::abs(hz[i])) ++e;
      if (modes.copies == 2 && e - i != 2)
        throw Error("discNominalModes: nodal diameter " + std::to_string(k) + " has " + std::to_string(e - i) +
                    " real-form modes at " + std::to_string(hz[i]) + " Hz (a pair is 2)");
      cols.push_back(travellingWave(modes.shapes[i], sign));
      const double w = 2 * M_PI * 0.5 * (hz[i] + hz[e - 1]);
      ls.push_back(w * w);
      i = e;
    }
    const int m = int(cols.size());
    Eigen::MatrixXcd Phi(cols[0].size(), m);
    for (int a = 0; a < m; ++a) Phi.col(a) = cols[a];
    hbm::ModalRealization r;
    r.R = tuned->R;
    r.lossFactor = tuned->lossFactor;
    r.eigenvalues = Eigen::Map<const Eigen::VectorXd>(ls.data(), m);
    r.viscous = Eigen::VectorXd::Zero(m);
    const int n = receptance->numDofs();
    r.U.resize(n, m);
    for (std::size_t i = 0; i < models.retainedNodes.size(); ++i)
      for (int d = 0; d < 3; ++d) r.U.row(3 * Eigen::Index(i) + d) = Phi.row(3 * Eigen::Index(models.retainedNodes[i]) + d);
    if (3 * int(models.retainedNodes.size()) != n)
      throw Error("discNominalModes: the models' retained DOFs are not 3 per retained node");
    r.V = r.U.conjugate();
    phases.emplace(p, std::move(r));
    out.shapes.push_back(std::move(Phi));
    out.modesPerPhase.push_back(m);
  }
  out.sectorModel = std::make_shared<hbm::ModalReceptance>(N, std::move(phases));
  out.seconds = timer.seconds();
  return out;
}

Eigen::MatrixXcd bladeModalProjection(const mesh::Mesh& mesh, const std::vector<mesh::Index>& bladeElements,
                                      const fe::IsotropicElastic& material, const std::vector<Eigen::MatrixXcd>& shapes) {
  Eigen::Index m = 0;
  for (const auto& s : shapes) m += s.cols();
  Eigen::MatrixXcd S(shapes.empty() ? 0 : shapes[0].rows(), m);
  Eigen::Index c = 0;
  for (const auto& s : shapes) S.middleCols(c, s.cols()) = s, c += s.cols();
  Eigen::MatrixXcd B = Eigen::MatrixXcd::Zero(m, m), Se;  // Se: one element's rows of the shapes, reused
  for (const auto g : bladeElements) {
    const auto [b, e] = mesh.locateElement(g);
    const auto& block = mesh.blocks[b];
    const int nn = mesh::nodesPerElement(block.type);
    const mesh::Index* nodes = block.element(e);
    fe::ElementCoords X(nn, 3);
    for (int a = 0; a < nn; ++a)
      for (int d = 0; d < 3; ++d) X(a, d) = mesh.coords[nodes[a]][d];
    const Eigen::MatrixXd Ke = fe::elementStiffness(block.type, X, material);
    Se.resize(3 * nn, m);  // no reallocation while the element type stays the same
    for (int a = 0; a < nn; ++a) Se.middleRows(3 * a, 3) = S.middleRows(3 * Eigen::Index(nodes[a]), 3);
    B.noalias() += Se.adjoint() * (Ke * Se);
  }
  return 0.5 * (B + B.adjoint());
}

DiscMistunedRing makeDiscMistunedRing(const mesh::Mesh& mesh, const DiscNominalModes& nominal,
                                      const fe::IsotropicElastic& material,
                                      const std::vector<mesh::Index>& bladeElements, const BladeMistuning& pattern) {
  pattern.validate(nominal.sectors);
  DiscMistunedRing out;
  out.tuned = std::make_shared<RingReceptance>(nominal.sectorModel);
  out.modesPerPhase = nominal.modesPerPhase;
  out.bladeProjection = bladeModalProjection(mesh, bladeElements, material, nominal.shapes);
  const auto tuned = out.tuned->modalRealization(0);
  if (!tuned) throw Error("makeDiscMistunedRing: the tuned ring has no modal realization");
  out.mistuned = std::make_shared<MistunedRingReceptance>(
      *tuned, subsetOfNominalModesStiffness(out.modesPerPhase, out.bladeProjection, pattern.deviations()));
  return out;
}

}  // namespace cyclone::mistuning
