#pragma once
// The ring-of-sectors verifications' disc (disc_reduced_ring, disc_mistuned_ring): the
// built-in shrouded sector, coarse and with a thin disc (a small sector), and hybrid
// reduced models at rest (no prestress), cantilever, 10 modes per nodal diameter.
#include <string>
#include <vector>

#include "cyclone/disc/DiscReducedModels.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

namespace cyclone::regression {

inline mesh::ShroudedSectorParameters smallRingGeometry(int sectors) {
  mesh::ShroudedSectorParameters geometry;
  geometry.sectors = sectors;
  geometry.meshSize = 14.0;    // coarse
  geometry.boreRadius = 70.0;  // a thin disc ring: a small sector
  return geometry;
}

inline disc::DiscModelSpec smallRingModelSpec(int sectors, std::vector<std::string> retainedNodeSets) {
  disc::DiscModelSpec spec;
  spec.sectors = sectors;
  spec.modes = 10;
  spec.retainedNodeSets = std::move(retainedNodeSets);
  return spec;
}

}  // namespace cyclone::regression
