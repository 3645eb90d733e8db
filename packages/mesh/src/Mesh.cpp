#include "cyclone/mesh/Mesh.hpp"

#include <cmath>

#include <algorithm>
#include <unordered_map>

#include "cyclone/core/Error.hpp"

namespace cyclone::mesh {

Index ElementBlock::numElements() const {
  return static_cast<Index>(connectivity.size()) / nodesPerElement(type);
}

const Index* ElementBlock::element(Index e) const {
  return connectivity.data() + e * nodesPerElement(type);
}

std::string ElementBlock::describeElement(Index e) const {
  const Index id = e < static_cast<Index>(elementIds.size()) ? elementIds[e] : e + 1;
  return "element " + std::to_string(id) + " (block '" + name + "')";
}

Index Mesh::numElements() const {
  Index n = 0;
  for (const auto& block : blocks) n += block.numElements();
  return n;
}

const std::vector<Index>& Mesh::nodeSet(const std::string& name) const {
  const auto it = nodeSets.find(name);
  if (it != nodeSets.end() && !it->second.empty()) return it->second;
  std::string known;
  for (const auto& [setName, nodes] : nodeSets)
    if (!nodes.empty()) known += (known.empty() ? "'" : ", '") + setName + "'";
  if (known.empty()) known = "none";
  throw InputError(source, "node set '" + name + "' " + (it == nodeSets.end() ? "does not exist" : "is empty") +
                               " (node sets of this mesh: " + known + "; names are case-sensitive)");
}

std::pair<int, Index> Mesh::locateElement(Index globalElement) const {
  Index first = 0;
  if (globalElement >= 0) {
    for (std::size_t b = 0; b < blocks.size(); ++b) {
      const Index n = blocks[b].numElements();
      if (globalElement < first + n) return {static_cast<int>(b), globalElement - first};
      first += n;
    }
  }
  throw InputError(source, "element index " + std::to_string(globalElement) + " out of range (the mesh has " +
                               std::to_string(first) + " elements)");
}

void Mesh::assignDefaultIds() {
  if (nodeIds.empty()) {
    nodeIds.resize(coords.size());
    for (std::size_t n = 0; n < coords.size(); ++n) nodeIds[n] = static_cast<Index>(n) + 1;
  }
  // Blocks without ids continue after the largest id in use, so they never collide
  // with blocks that have them; a mesh without any ids gets 1..numElements.
  Index next = 1;
  for (const auto& block : blocks)
    for (Index id : block.elementIds) next = std::max(next, id + 1);
  for (auto& block : blocks) {
    if (!block.elementIds.empty()) continue;
    block.elementIds.resize(block.numElements());
    for (auto& id : block.elementIds) id = next++;
  }
}

double boundingDiagonal(const Mesh& mesh) {
  if (mesh.coords.empty()) return 0.0;
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const auto& x : mesh.coords)
    for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], x[d]), hi[d] = std::max(hi[d], x[d]);
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

std::vector<Index> orphanNodes(const Mesh& mesh) {
  std::vector<char> used(std::size_t(mesh.numNodes()), 0);
  for (const auto& block : mesh.blocks)
    for (Index n : block.connectivity)
      if (n >= 0 && n < mesh.numNodes()) used[std::size_t(n)] = 1;
  std::vector<Index> out;
  for (Index n = 0; n < mesh.numNodes(); ++n)
    if (!used[std::size_t(n)]) out.push_back(n);
  return out;
}

void checkConsistency(const Mesh& mesh) {
  const std::string& where = mesh.source;
  const Index numNodes = mesh.numNodes();

  if (!mesh.nodeIds.empty() && static_cast<Index>(mesh.nodeIds.size()) != numNodes)
    throw InputError(where, std::to_string(mesh.nodeIds.size()) + " node ids for " + std::to_string(numNodes) +
                                " nodes");
  {
    std::unordered_map<Index, Index> firstIndex;
    firstIndex.reserve(mesh.nodeIds.size());
    for (Index n = 0; n < static_cast<Index>(mesh.nodeIds.size()); ++n) {
      const auto [it, inserted] = firstIndex.emplace(mesh.nodeIds[n], n);
      if (!inserted)
        throw InputError(where, "node id " + std::to_string(mesh.nodeIds[n]) + " is used twice (node indices " +
                                    std::to_string(it->second) + " and " + std::to_string(n) + ")");
    }
  }

  std::unordered_map<int, std::string> blockIds;
  std::unordered_map<Index, std::string> elementIds;
  for (const auto& block : mesh.blocks) {
    const int n = nodesPerElement(block.type);
    const std::string blockName = "block '" + block.name + "'";
    if (const auto [it, inserted] = blockIds.emplace(block.id, block.name); !inserted)
      throw InputError(where, blockName + " has the same block id " + std::to_string(block.id) + " as block '" +
                                  it->second + "'");
    if (block.connectivity.size() % n != 0)
      throw InputError(where, blockName + " has " + std::to_string(block.connectivity.size()) +
                                  " connectivity entries, not a multiple of " + std::to_string(n) + " (" +
                                  exodusName(block.type) + ")");
    const Index ne = block.numElements();
    if (!block.elementIds.empty() && static_cast<Index>(block.elementIds.size()) != ne)
      throw InputError(where, blockName + " has " + std::to_string(block.elementIds.size()) + " element ids for " +
                                  std::to_string(ne) + " elements");
    for (Index e = 0; e < static_cast<Index>(block.elementIds.size()); ++e) {
      const auto [it, inserted] = elementIds.emplace(block.elementIds[e], block.name);
      if (!inserted)
        throw InputError(where, block.describeElement(e) + " has the same id as an element of block '" +
                                    it->second + "'");
    }
    for (Index e = 0; e < ne; ++e) {
      const Index* nodes = block.element(e);
      for (int a = 0; a < n; ++a)
        if (nodes[a] < 0 || nodes[a] >= numNodes)
          throw InputError(where, block.describeElement(e) + " refers to node index " + std::to_string(nodes[a]) +
                                      " out of range (the mesh has " + std::to_string(numNodes) + " nodes)");
    }
  }

  const Index numElements = mesh.numElements();
  auto checkIndexSet = [&](const std::string& kind, const std::string& name, const std::vector<Index>& entries,
                           Index count, const std::string& entity) {
    if (entries.empty()) throw InputError(where, kind + " '" + name + "' is empty");
    for (Index i : entries)
      if (i < 0 || i >= count)
        throw InputError(where, kind + " '" + name + "' refers to " + entity + " index " + std::to_string(i) +
                                    " out of range (the mesh has " + std::to_string(count) + " " + entity + "s)");
  };
  for (const auto& [name, nodes] : mesh.nodeSets) checkIndexSet("node set", name, nodes, numNodes, "node");
  for (const auto& [name, elements] : mesh.elementSets)
    checkIndexSet("element set", name, elements, numElements, "element");
  for (const auto& [name, sides] : mesh.sideSets) {
    if (sides.empty()) throw InputError(where, "side set '" + name + "' is empty");
    for (const auto& side : sides) {
      if (side.element < 0 || side.element >= numElements)
        throw InputError(where, "side set '" + name + "' refers to element index " + std::to_string(side.element) +
                                    " out of range (the mesh has " + std::to_string(numElements) + " elements)");
      const auto [b, e] = mesh.locateElement(side.element);
      const int faces = facesPerElement(mesh.blocks[b].type);
      if (side.side < 0 || side.side >= faces)
        throw InputError(where, "side set '" + name + "' refers to face " + std::to_string(side.side + 1) + " of " +
                                    mesh.blocks[b].describeElement(e) + ", which has faces 1.." +
                                    std::to_string(faces));
    }
  }
}

std::string Mesh::elementName(Index globalElement) const {
  auto [b, e] = locateElement(globalElement);
  const auto& block = blocks[b];
  return "element " + std::to_string(block.elementIds.empty() ? e + 1 : block.elementIds[e]) + " (block '" +
         block.name + "')";
}

}  // namespace cyclone::mesh
