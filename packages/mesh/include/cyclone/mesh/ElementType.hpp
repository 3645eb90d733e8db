#pragma once
// Solid element types. Node order inside an element is always the Exodus II
// order (identical to CalculiX/Abaqus C3D4/C3D10/C3D8/C3D20); readers of
// other formats (Gmsh) convert on input.
//   tet10: corners 0-3, then mid-edges 01, 12, 20, 03, 13, 23
//   hex20: corners 0-7, then mid-edges 01,12,23,30, 45,56,67,74, 04,15,26,37
#include <string>
#include <vector>

namespace cyclone::mesh {

enum class ElementType { Tet4, Tet10, Hex8, Hex20 };

int nodesPerElement(ElementType type);
/// Exodus II name: "TETRA4", "TETRA10", "HEX8", "HEX20".
std::string exodusName(ElementType type);
/// Parses an Exodus element type name (case-insensitive; "TETRA"/"TET4"/"HEX"/"HEX27"...).
/// Throws InputError naming `where` for unsupported types.
ElementType elementTypeFromExodusName(const std::string& name, const std::string& where);
/// Number of faces and, for a local face f, its corner nodes (Exodus side numbering, 0-based).
int facesPerElement(ElementType type);
/// Corner nodes of local face f (0-based, Exodus side f+1), ordered so the normal points outwards.
std::vector<int> faceCornerNodes(ElementType type, int face);

}  // namespace cyclone::mesh
