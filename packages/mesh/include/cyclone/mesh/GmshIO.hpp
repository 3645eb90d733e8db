#pragma once
// Gmsh meshes: .msh files (read through libgmsh) and the current in-memory gmsh
// model (the built-in generators mesh with gmsh and convert here).
//
// Conversion rules:
//   - 3D elements tet4, tet10, hex8, hex20 (gmsh types 4, 11, 5, 17) become element
//     blocks, one per volume physical group (named by its physical name, or
//     "volume_<tag>" if unnamed; a group holding two element types gives two blocks
//     "<name>_<EXODUS TYPE>"). Without volume physical groups: one block per element
//     type over all volumes, named by the Exodus type ("TETRA10"). With volume physical
//     groups, volumes in none of them are left out (as gmsh itself does when saving).
//   - Other 3D types (prisms, pyramids, hex27, ...) are an InputError.
//   - Physical groups of dimension 0-2 become node sets: all nodes of their entities,
//     boundaries and high-order nodes included, named by their physical names (or
//     "point_<tag>", "curve_<tag>", "surface_<tag>"). Groups of different dimension with
//     the same name are merged.
//   - Only nodes used by 3D elements are kept, renumbered compactly in increasing tag
//     order; nodeIds and elementIds keep gmsh's tags.
//   - Node order is converted to Exodus order (GmshNodeOrder.hpp).
#include <string>

#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::mesh {

/// Reads a gmsh .msh file (format 4; 2.2 also works as gmsh reads it). Runs a private
/// gmsh session (initialize .. finalize), so it must not be called while another gmsh
/// session of this process is open. Runs checkConsistency and checkElementGeometry.
/// Throws InputError naming the file.
Mesh readGmsh(const std::string& path);

/// Converts the current gmsh model (after gmsh::model::mesh::generate). Does not
/// initialize or finalize gmsh and does not run the mesh checks (the caller adds its
/// own node sets first). `source` names the mesh in messages. gmsh's own exceptions
/// pass through; unsupported elements or an empty model give InputError.
Mesh meshFromGmshModel(const std::string& source);

}  // namespace cyclone::mesh
