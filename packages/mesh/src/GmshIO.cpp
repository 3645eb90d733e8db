#include "cyclone/mesh/GmshIO.hpp"

#include <gmsh.h>

#include <algorithm>
#include <filesystem>
#include <unordered_map>
#include <utility>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/mesh/GmshNodeOrder.hpp"
#include "cyclone/mesh/MeshGeometryCheck.hpp"
#include "GmshCountsCheck.hpp"
#include "IsolatedRead.hpp"

namespace cyclone::mesh {
namespace {

using Tag = std::size_t;

std::string physicalGroupName(int dim, int tag) {
  std::string name;
  gmsh::model::getPhysicalName(dim, tag, name);
  if (!name.empty()) return name;
  static const char* kind[] = {"point", "curve", "surface", "volume"};
  return std::string(kind[dim]) + "_" + std::to_string(tag);
}

std::string gmshTypeName(int gmshType) {
  std::string name;
  int dim, order, numNodes, numPrimary;
  std::vector<double> local;
  gmsh::model::mesh::getElementProperties(gmshType, name, dim, order, numNodes, local, numPrimary);
  return name;
}

// A block under construction: connectivity still in gmsh node tags (Exodus order).
struct PendingBlock {
  std::string group;  // physical group name, empty if the model has no volume groups
  ElementType type;
  std::vector<Tag> nodeTags;
  std::vector<Index> elementIds;
};

// Volumes to convert, each with the name of its physical group ("" if none are defined).
std::vector<std::pair<int, std::string>> volumesToConvert(const std::string& source) {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 3);
  std::vector<std::pair<int, std::string>> volumes;
  if (groups.empty()) {
    gmsh::vectorpair all;
    gmsh::model::getEntities(all, 3);
    for (const auto& [dim, tag] : all) volumes.emplace_back(tag, "");
    return volumes;
  }
  std::unordered_map<int, std::string> groupOf;
  for (const auto& [dim, groupTag] : groups) {
    const std::string name = physicalGroupName(dim, groupTag);
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, groupTag, entities);
    for (int volume : entities) {
      const auto [it, inserted] = groupOf.emplace(volume, name);
      if (!inserted)
        throw InputError(source, "volume " + std::to_string(volume) + " belongs to the physical groups '" +
                                     it->second + "' and '" + name +
                                     "'; an element can belong to one element block only");
      volumes.emplace_back(volume, name);
    }
  }
  gmsh::vectorpair all;
  gmsh::model::getEntities(all, 3);
  std::size_t left = 0;
  for (const auto& [dim, tag] : all) left += groupOf.count(tag) == 0;
  if (left > 0)
    log::warn(source + ": " + std::to_string(left) +
              " volume(s) belong to no volume physical group and are left out of the mesh");
  return volumes;
}

}  // namespace

namespace {

// The 3D elements, grouped by (physical group, type) in the order they are met, their
// nodes in Exodus order (gmsh tags).
std::vector<PendingBlock> readVolumeElements(const std::string& source) {
  std::vector<PendingBlock> pending;
  for (const auto& [volume, group] : volumesToConvert(source)) {
    std::vector<int> types;
    std::vector<std::vector<Tag>> elementTags, nodeTags;
    gmsh::model::mesh::getElements(types, elementTags, nodeTags, 3, volume);
    for (std::size_t t = 0; t < types.size(); ++t) {
      if (elementTags[t].empty()) continue;
      const auto type = elementTypeFromGmsh(types[t]);
      if (!type) {
        std::string hint = types[t] == 12 ? " (for 20-node hexahedra set Mesh.SecondOrderIncomplete = 1)" : "";
        throw InputError(source, "volume " + std::to_string(volume) + " has " +
                                     std::to_string(elementTags[t].size()) + " elements of gmsh type '" +
                                     gmshTypeName(types[t]) + "' (" + std::to_string(types[t]) +
                                     "); Cyclone supports 4- and 10-node tetrahedra and 8- and 20-node hexahedra" +
                                     hint);
      }
      auto it = std::find_if(pending.begin(), pending.end(),
                             [&](const PendingBlock& b) { return b.group == group && b.type == *type; });
      if (it == pending.end()) it = pending.insert(pending.end(), PendingBlock{group, *type, {}, {}});
      const auto& order = gmshNodeForExodusNode(*type);
      const std::size_t n = order.size();
      for (std::size_t e = 0; e < elementTags[t].size(); ++e) {
        it->elementIds.push_back(static_cast<Index>(elementTags[t][e]));
        for (std::size_t a = 0; a < n; ++a) it->nodeTags.push_back(nodeTags[t][e * n + order[a]]);
      }
    }
  }
  return pending;
}

// The nodes the 3D elements use, in increasing tag order, into `mesh`; their indices by tag.
std::unordered_map<Tag, Index> readUsedNodes(const std::vector<PendingBlock>& pending, const std::string& source,
                                             Mesh& mesh) {
  std::vector<Tag> used;
  for (const auto& block : pending) used.insert(used.end(), block.nodeTags.begin(), block.nodeTags.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::unordered_map<Tag, Index> indexOf;
  indexOf.reserve(used.size());
  for (std::size_t i = 0; i < used.size(); ++i) indexOf.emplace(used[i], static_cast<Index>(i));

  mesh.coords.resize(used.size());
  mesh.nodeIds.resize(used.size());
  {
    std::vector<Tag> tags;
    std::vector<double> xyz, parametric;
    gmsh::model::mesh::getNodes(tags, xyz, parametric, -1, -1, false, false);
    std::vector<bool> found(used.size(), false);
    for (std::size_t i = 0; i < tags.size(); ++i) {
      const auto it = indexOf.find(tags[i]);
      if (it == indexOf.end()) continue;
      mesh.coords[it->second] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
      found[it->second] = true;
    }
    for (std::size_t i = 0; i < used.size(); ++i) {
      if (!found[i])
        throw InputError(source, "elements refer to gmsh node " + std::to_string(used[i]) + ", which does not exist");
      mesh.nodeIds[i] = static_cast<Index>(used[i]);
    }
  }

  return indexOf;
}

// Node sets from lower-dimensional physical groups (the nodes on the 3D mesh).
void readNodeSets(const std::unordered_map<Tag, Index>& indexOf, const std::string& source, Mesh& mesh) {
  // Node sets from lower-dimensional physical groups.
  for (int dim = 0; dim <= 2; ++dim) {
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups, dim);
    for (const auto& [groupDim, groupTag] : groups) {
      const std::string name = physicalGroupName(groupDim, groupTag);
      std::vector<int> entities;
      gmsh::model::getEntitiesForPhysicalGroup(groupDim, groupTag, entities);
      std::vector<Index> nodes;
      for (int entity : entities) {
        std::vector<Tag> tags;
        std::vector<double> xyz, parametric;
        gmsh::model::mesh::getNodes(tags, xyz, parametric, groupDim, entity, true, false);
        for (Tag tag : tags)
          if (const auto it = indexOf.find(tag); it != indexOf.end()) nodes.push_back(it->second);
      }
      if (nodes.empty()) {
        log::warn(source + ": physical group '" + name + "' has no nodes on the 3D mesh; no node set made");
        continue;
      }
      auto& set = mesh.nodeSets[name];
      set.insert(set.end(), nodes.begin(), nodes.end());
      std::sort(set.begin(), set.end());
      set.erase(std::unique(set.begin(), set.end()), set.end());
    }
  }
}

}  // namespace

Mesh meshFromGmshModel(const std::string& source) {
  Mesh mesh;
  mesh.source = source;
  auto pending = readVolumeElements(source);
  if (pending.empty())
    throw InputError(source, "the gmsh model has no 3D elements (tetrahedra or hexahedra) to analyse");
  const auto indexOf = readUsedNodes(pending, source, mesh);
  int id = 1;
  for (auto& p : pending) {
    const bool mixed = std::count_if(pending.begin(), pending.end(),
                                     [&](const PendingBlock& b) { return b.group == p.group; }) > 1;
    ElementBlock block;
    block.id = id++;
    block.type = p.type;
    block.name = p.group.empty() ? exodusName(p.type) : mixed ? p.group + "_" + exodusName(p.type) : p.group;
    block.connectivity.reserve(p.nodeTags.size());
    for (Tag tag : p.nodeTags) block.connectivity.push_back(indexOf.at(tag));
    block.elementIds = std::move(p.elementIds);
    mesh.blocks.push_back(std::move(block));
  }

  readNodeSets(indexOf, source, mesh);
  return mesh;
}

namespace {

// A private gmsh session; gmsh keeps global state, so it is finalized on every exit path.
struct GmshSession {
  GmshSession() {
    gmsh::initialize(0, nullptr, false);  // no user configuration files: reading must not depend on them
    gmsh::option::setNumber("General.Terminal", 0);
  }
  ~GmshSession() {
    try {
      gmsh::finalize();
    } catch (...) {
    }
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

}  // namespace

Mesh readGmsh(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path, "file does not exist");
  // gmsh runs in a child process: some damaged files make gmsh 4.8 crash (IsolatedRead.hpp).
  Mesh mesh = detail::readInChildProcess(path, [&] {
    GmshSession session;
    detail::checkMshCounts(path, [](int type) {
      std::string name;
      int dim, order, numNodes, numPrimary;
      std::vector<double> local;
      gmsh::model::mesh::getElementProperties(type, name, dim, order, numNodes, local, numPrimary);
      return numNodes;
    });
    // gmsh 4.8 (General.AbortOnError = 2 under the API) throws std::string or std::exception.
    try {
      gmsh::open(path);
      std::string error;
      gmsh::logger::getLastError(error);
      if (!error.empty()) throw InputError(path, "gmsh could not read the file: " + error);
      return meshFromGmshModel(path);
    } catch (const cyclone::Error&) {
      throw;
    } catch (const std::string& e) {
      throw InputError(path, "gmsh could not read the file: " + e);
    } catch (const std::exception& e) {
      throw InputError(path, std::string("gmsh could not read the file: ") + e.what());
    }
  });
  checkConsistency(mesh);
  checkElementGeometry(mesh);
  return mesh;
}

}  // namespace cyclone::mesh
