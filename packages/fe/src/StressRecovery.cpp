#include "cyclone/fe/StressRecovery.hpp"

#include <Teuchos_CommHelpers.hpp>

namespace cyclone::fe {

std::vector<std::array<double, 6>> averageToNodes(const mesh::Mesh& mesh,
                                                  const std::vector<std::array<double, 6>>& elementValues) {
  std::vector<std::array<double, 6>> out(std::size_t(mesh.numNodes()), {0, 0, 0, 0, 0, 0});
  std::vector<int> count(std::size_t(mesh.numNodes()), 0);
  mesh::Index e = 0;
  for (const auto& block : mesh.blocks) {
    const int n = mesh::nodesPerElement(block.type);
    for (mesh::Index le = 0; le < block.numElements(); ++le, ++e)
      for (int a = 0; a < n; ++a) {
        const auto node = std::size_t(block.element(le)[a]);
        for (int k = 0; k < 6; ++k) out[node][k] += elementValues[std::size_t(e)][k];
        ++count[node];
      }
  }
  for (std::size_t node = 0; node < out.size(); ++node)
    if (count[node] > 0)
      for (auto& v : out[node]) v /= count[node];
  return out;
}

StressField recoverStresses(const Assembler& assembler, const IsotropicElastic& material,
                            const std::vector<std::array<double, 3>>& u) {
  const auto& mesh = assembler.mesh();
  const mesh::Index ne = mesh.numElements(), nn = mesh.numNodes();
  // Element stresses computed locally, then summed over ranks: each element has one rank.
  std::vector<double> local(6 * ne, 0.0), global(6 * ne, 0.0);
  for (auto e : assembler.localElements()) {
    auto [b, le] = mesh.locateElement(e);
    const auto& block = mesh.blocks[b];
    const int n = mesh::nodesPerElement(block.type);
    const mesh::Index* nodes = block.element(le);
    Eigen::VectorXd ue(3 * n);
    for (int a = 0; a < n; ++a)
      for (int d = 0; d < 3; ++d) ue(3 * a + d) = u[nodes[a]][d];
    const auto s = elementStresses(block.type, assembler.elementCoords(e), material, ue);
    const Eigen::Matrix<double, 1, 6> mean = s.colwise().mean();
    for (int k = 0; k < 6; ++k) local[6 * e + k] = mean(k);
  }
  Teuchos::reduceAll(*assembler.comm(), Teuchos::REDUCE_SUM, int(6 * ne), local.data(), global.data());

  StressField out;
  out.elementStress.resize(ne);
  out.elementVonMises.resize(ne);
  for (mesh::Index e = 0; e < ne; ++e) {
    Eigen::Matrix<double, 6, 1> s;
    for (int k = 0; k < 6; ++k) out.elementStress[e][k] = s(k) = global[6 * e + k];
    out.elementVonMises[e] = vonMises(s);
  }
  out.nodalStress = averageToNodes(mesh, out.elementStress);
  out.nodalVonMises.assign(nn, 0.0);
  for (mesh::Index node = 0; node < nn; ++node)
    out.nodalVonMises[node] = vonMises(Eigen::Map<const Eigen::Matrix<double, 6, 1>>(out.nodalStress[node].data()));
  return out;
}

}  // namespace cyclone::fe
