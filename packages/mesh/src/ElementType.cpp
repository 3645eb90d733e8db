#include "cyclone/mesh/ElementType.hpp"

#include <algorithm>
#include <cctype>

#include "cyclone/core/Error.hpp"

namespace cyclone::mesh {

int nodesPerElement(ElementType type) {
  switch (type) {
    case ElementType::Tet4: return 4;
    case ElementType::Tet10: return 10;
    case ElementType::Hex8: return 8;
    case ElementType::Hex20: return 20;
  }
  throw Error("nodesPerElement: invalid element type");
}

std::string exodusName(ElementType type) {
  switch (type) {
    case ElementType::Tet4: return "TETRA4";
    case ElementType::Tet10: return "TETRA10";
    case ElementType::Hex8: return "HEX8";
    case ElementType::Hex20: return "HEX20";
  }
  throw Error("exodusName: invalid element type");
}

ElementType elementTypeFromExodusName(const std::string& name, const std::string& where) {
  std::string upper = name;
  std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return std::toupper(c); });
  // Exodus writers pad names with blanks.
  while (!upper.empty() && std::isspace(static_cast<unsigned char>(upper.back()))) upper.pop_back();
  if (upper == "TETRA" || upper == "TETRA4" || upper == "TET" || upper == "TET4") return ElementType::Tet4;
  if (upper == "TETRA10" || upper == "TET10") return ElementType::Tet10;
  if (upper == "HEX" || upper == "HEX8" || upper == "HEXAHEDRON" || upper == "HEXAHEDRON8") return ElementType::Hex8;
  if (upper == "HEX20" || upper == "HEXAHEDRON20") return ElementType::Hex20;
  throw InputError(where, "unsupported element type '" + name +
                              "' (Cyclone supports TETRA4, TETRA10, HEX8 and HEX20)");
}

int facesPerElement(ElementType type) {
  switch (type) {
    case ElementType::Tet4:
    case ElementType::Tet10: return 4;
    case ElementType::Hex8:
    case ElementType::Hex20: return 6;
  }
  throw Error("facesPerElement: invalid element type");
}

std::vector<int> faceCornerNodes(ElementType type, int face) {
  // Exodus II side numbering (manual, "side set node ordering"), shifted to 0-based.
  static const int tet[4][3] = {{0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 2, 1}};
  static const int hex[6][4] = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  if (face < 0 || face >= facesPerElement(type))
    throw Error("faceCornerNodes: face " + std::to_string(face) + " out of range for " + exodusName(type));
  if (type == ElementType::Tet4 || type == ElementType::Tet10) return {tet[face], tet[face] + 3};
  return {hex[face], hex[face] + 4};
}

}  // namespace cyclone::mesh
