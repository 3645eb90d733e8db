#pragma once
// Gmsh element type codes and node order, converted to Cyclone's (Exodus) order.
// Gmsh reference manual, "Node ordering": corners agree with Exodus; mid-edge
// nodes are numbered differently:
//   tet10  gmsh edges 01,12,20,03,23,13   Exodus 01,12,20,03,13,23
//   hex20  gmsh edges 01,03,04,12,15,23,26,37,45,47,56,67
//          Exodus     01,12,23,30,45,56,67,74,04,15,26,37
// (unit test GmshNodeOrderTest checks this against gmsh's getElementProperties).
#include <optional>
#include <vector>

#include "cyclone/mesh/ElementType.hpp"

namespace cyclone::mesh {

/// Gmsh type code of a Cyclone element type: tet4 4, tet10 11, hex8 5, hex20 17.
int gmshElementType(ElementType type);
/// Cyclone element type of a gmsh type code; nothing for types Cyclone does not support.
std::optional<ElementType> elementTypeFromGmsh(int gmshType);
/// For each node position i in Exodus order, the gmsh local node that goes there:
/// exodusNodes[i] = gmshNodes[gmshNodeForExodusNode(type)[i]].
const std::vector<int>& gmshNodeForExodusNode(ElementType type);

}  // namespace cyclone::mesh
