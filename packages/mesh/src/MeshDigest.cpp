#include "cyclone/mesh/MeshDigest.hpp"

namespace cyclone::mesh {

void addToHash(ContentHash& hash, const Mesh& mesh) {
  for (const auto& p : mesh.coords) hash.add(p.data(), sizeof(double) * 3);
  for (const auto& b : mesh.blocks) {
    hash.add(int(b.type));
    hash.addAll(std::vector<long long>(b.connectivity.begin(), b.connectivity.end()));
  }
}

void addNodeSetsToHash(ContentHash& hash, const Mesh& mesh, const std::vector<std::string>& names) {
  hash.addAll(names);
  for (const auto& name : names) {
    const auto& nodes = mesh.nodeSet(name);
    hash.addAll(std::vector<long long>(nodes.begin(), nodes.end()));
  }
}

}  // namespace cyclone::mesh
