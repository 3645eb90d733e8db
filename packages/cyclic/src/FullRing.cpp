#include "cyclone/cyclic/FullRing.hpp"

#include <algorithm>
#include <cmath>

namespace cyclone::cyclic {

FullRing replicateSector(const mesh::Mesh& sm, const CyclicSector& sector) {
  const int N = sector.sectors;
  const Index nn = sm.numNodes();
  std::vector<Index> masterOf(nn, -1);
  std::vector<char> onAxis(nn, 0);
  for (std::size_t i = 0; i < sector.left.size(); ++i) {
    if (sector.left[i] == sector.right[i]) onAxis[sector.left[i]] = 1;
    else masterOf[sector.right[i]] = sector.left[i];
  }
  FullRing ring;
  ring.ringNode.assign(N, std::vector<Index>(nn, -1));
  auto& m = ring.mesh;
  m.source = sm.source + " (full ring of " + std::to_string(N) + ")";
  // New nodes: every non-right-face node of every copy (axis nodes once).
  for (int j = 0; j < N; ++j)
    for (Index n = 0; n < nn; ++n) {
      if (masterOf[n] >= 0) continue;
      if (onAxis[n] && j > 0) {
        ring.ringNode[j][n] = ring.ringNode[0][n];
        continue;
      }
      ring.ringNode[j][n] = m.numNodes();
      m.coords.push_back(mesh::rotate(sm.coords[n], j * sector.sectorAngle(), sector.axis));
    }
  // Right-face nodes of copy j are the left-face nodes of copy j+1.
  for (int j = 0; j < N; ++j)
    for (Index n = 0; n < nn; ++n)
      if (masterOf[n] >= 0) ring.ringNode[j][n] = ring.ringNode[(j + 1) % N][masterOf[n]];
  for (const auto& block : sm.blocks) {
    mesh::ElementBlock b;
    b.name = block.name;
    b.id = block.id;
    b.type = block.type;
    for (int j = 0; j < N; ++j)
      for (auto n : block.connectivity) b.connectivity.push_back(ring.ringNode[j][n]);
    m.blocks.push_back(std::move(b));
  }
  for (const auto& [name, nodes] : sm.nodeSets) {
    std::vector<Index> all;
    for (int j = 0; j < N; ++j)
      for (auto n : nodes) all.push_back(ring.ringNode[j][n]);
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    m.nodeSets[name] = std::move(all);
  }
  m.assignDefaultIds();
  return ring;
}

}  // namespace cyclone::cyclic
