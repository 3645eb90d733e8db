#pragma once
// A mesh's part of a cache or checkpoint key: node coordinates, element types and
// connectivity, and the nodes of the named sets a result depends on.
#include <string>
#include <vector>

#include "cyclone/core/ContentHash.hpp"
#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::mesh {

void addToHash(ContentHash& hash, const Mesh& mesh);
/// The set names and each set's nodes (InputError for a missing set, as Mesh::nodeSet).
void addNodeSetsToHash(ContentHash& hash, const Mesh& mesh, const std::vector<std::string>& names);

}  // namespace cyclone::mesh
