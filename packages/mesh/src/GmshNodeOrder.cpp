#include "cyclone/mesh/GmshNodeOrder.hpp"

#include "cyclone/core/Error.hpp"

namespace cyclone::mesh {

int gmshElementType(ElementType type) {
  switch (type) {
    case ElementType::Tet4: return 4;
    case ElementType::Tet10: return 11;
    case ElementType::Hex8: return 5;
    case ElementType::Hex20: return 17;
  }
  throw Error("gmshElementType: invalid element type");
}

std::optional<ElementType> elementTypeFromGmsh(int gmshType) {
  switch (gmshType) {
    case 4: return ElementType::Tet4;
    case 11: return ElementType::Tet10;
    case 5: return ElementType::Hex8;
    case 17: return ElementType::Hex20;
    default: return std::nullopt;
  }
}

const std::vector<int>& gmshNodeForExodusNode(ElementType type) {
  static const std::vector<int> tet4 = {0, 1, 2, 3};
  // Exodus mid-edges 13, 23 are gmsh's 9, 8.
  static const std::vector<int> tet10 = {0, 1, 2, 3, 4, 5, 6, 7, 9, 8};
  static const std::vector<int> hex8 = {0, 1, 2, 3, 4, 5, 6, 7};
  // Exodus edge (gmsh node): 01(8) 12(11) 23(13) 30(9) 45(16) 56(18) 67(19) 74(17) 04(10) 15(12) 26(14) 37(15).
  static const std::vector<int> hex20 = {0, 1, 2, 3, 4, 5, 6, 7, 8, 11, 13, 9, 16, 18, 19, 17, 10, 12, 14, 15};
  switch (type) {
    case ElementType::Tet4: return tet4;
    case ElementType::Tet10: return tet10;
    case ElementType::Hex8: return hex8;
    case ElementType::Hex20: return hex20;
  }
  throw Error("gmshNodeForExodusNode: invalid element type");
}

}  // namespace cyclone::mesh
