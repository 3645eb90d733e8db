#pragma once
// The full 360-degree model from one sector: N rotated copies, the right face
// of copy j merged with the left face of copy j+1. The independent reference
// for everything cyclic (full ring against sector), and the model for
// mistuned or full-assembly checks later.
#include "cyclone/cyclic/CyclicSector.hpp"

namespace cyclone::cyclic {

struct FullRing {
  mesh::Mesh mesh;
  /// ringNode[j][n]: the ring node of sector node n in sector copy j.
  std::vector<std::vector<Index>> ringNode;
};

/// Node sets are the unions of the sector's sets over all copies (names kept).
FullRing replicateSector(const mesh::Mesh& sectorMesh, const CyclicSector& sector);

}  // namespace cyclone::cyclic
