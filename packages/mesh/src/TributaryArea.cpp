#include "cyclone/mesh/TributaryArea.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <unordered_map>

#include "cyclone/core/Error.hpp"

namespace cyclone::mesh {

namespace {

// The midside node (local index) of the edge between corners a and b of a quadratic
// element (Exodus order: ElementType.hpp).
int midsideNode(ElementType type, int a, int b) {
  static const int tet[6][3] = {{0, 1, 4}, {1, 2, 5}, {2, 0, 6}, {0, 3, 7}, {1, 3, 8}, {2, 3, 9}};
  static const int hex[12][3] = {{0, 1, 8},   {1, 2, 9},   {2, 3, 10},  {3, 0, 11}, {4, 5, 12}, {5, 6, 13},
                                 {6, 7, 14}, {7, 4, 15}, {0, 4, 16}, {1, 5, 17}, {2, 6, 18}, {3, 7, 19}};
  if (type == ElementType::Tet10) {
    for (const auto& e : tet)
      if ((e[0] == a && e[1] == b) || (e[0] == b && e[1] == a)) return e[2];
  } else {
    for (const auto& e : hex)
      if ((e[0] == a && e[1] == b) || (e[0] == b && e[1] == a)) return e[2];
  }
  throw Error("midsideNode: no edge between local nodes " + std::to_string(a) + " and " + std::to_string(b));
}

Eigen::Vector3d at(const Mesh& mesh, Index n) { return {mesh.coords[n][0], mesh.coords[n][1], mesh.coords[n][2]}; }

// A third of the triangle's area to each corner (slot = position in the set).
void addTriangle(const Mesh& mesh, const std::array<Index, 3>& nodes, const std::unordered_map<Index, std::size_t>& slot,
                 double weight, std::vector<double>& area) {
  const double a = 0.5 * (at(mesh, nodes[1]) - at(mesh, nodes[0])).cross(at(mesh, nodes[2]) - at(mesh, nodes[0])).norm();
  for (Index n : nodes) area[slot.at(n)] += weight * a / 3;
}

}  // namespace

TributaryAreas tributaryAreas(const Mesh& mesh, const std::vector<Index>& nodes, const std::string& what) {
  std::unordered_map<Index, std::size_t> slot;
  for (std::size_t i = 0; i < nodes.size(); ++i) slot.emplace(nodes[i], i);
  TributaryAreas out;
  out.area.assign(nodes.size(), 0.0);
  const auto in = [&slot](Index n) { return slot.count(n) > 0; };
  for (const auto& block : mesh.blocks) {
    const bool quadratic = block.type == ElementType::Tet10 || block.type == ElementType::Hex20;
    for (Index e = 0; e < block.numElements(); ++e) {
      const Index* element = block.element(e);
      for (int f = 0; f < facesPerElement(block.type); ++f) {
        const auto corners = faceCornerNodes(block.type, f);
        const int nc = int(corners.size());
        std::vector<Index> c(nc), m(nc);  // corner nodes and, if quadratic, the midside node after each
        bool onSurface = true;
        for (int k = 0; k < nc; ++k) {
          c[k] = element[corners[k]];
          if (quadratic) m[k] = element[midsideNode(block.type, corners[k], corners[(k + 1) % nc])];
          onSurface = onSurface && in(c[k]) && (!quadratic || in(m[k]));
        }
        if (!onSurface) continue;
        ++out.faces;
        if (nc == 3 && !quadratic) {
          addTriangle(mesh, {c[0], c[1], c[2]}, slot, 1.0, out.area);
        } else if (nc == 3) {  // 6-node triangle: the corner triangles and the middle one
          for (int k = 0; k < 3; ++k) addTriangle(mesh, {c[k], m[k], m[(k + 2) % 3]}, slot, 1.0, out.area);
          addTriangle(mesh, {m[0], m[1], m[2]}, slot, 1.0, out.area);
        } else if (!quadratic) {  // 4-node quadrilateral: both diagonals, the mean
          addTriangle(mesh, {c[0], c[1], c[2]}, slot, 0.5, out.area);
          addTriangle(mesh, {c[0], c[2], c[3]}, slot, 0.5, out.area);
          addTriangle(mesh, {c[1], c[2], c[3]}, slot, 0.5, out.area);
          addTriangle(mesh, {c[1], c[3], c[0]}, slot, 0.5, out.area);
        } else {  // 8-node quadrilateral: the corner triangles and the inner quadrilateral's two
          for (int k = 0; k < 4; ++k) addTriangle(mesh, {c[k], m[k], m[(k + 3) % 4]}, slot, 1.0, out.area);
          addTriangle(mesh, {m[0], m[1], m[2]}, slot, 0.5, out.area);
          addTriangle(mesh, {m[0], m[2], m[3]}, slot, 0.5, out.area);
          addTriangle(mesh, {m[1], m[2], m[3]}, slot, 0.5, out.area);
          addTriangle(mesh, {m[1], m[3], m[0]}, slot, 0.5, out.area);
        }
      }
    }
  }
  std::vector<Index> bare;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (!(out.area[i] > 0)) bare.push_back(nodes[i]);
    out.total += out.area[i];
  }
  if (!bare.empty()) {
    std::ostringstream why;
    why << bare.size() << " of its " << nodes.size() << " nodes lie on no element face whose nodes are all in the set "
        << "(node";
    for (std::size_t k = 0; k < std::min<std::size_t>(bare.size(), 5); ++k) why << " " << mesh.nodeIds[bare[k]];
    why << (bare.size() > 5 ? " ..." : "") << "), so they carry no area: a surface law needs the face's nodes, every one "
        << "of them";
    throw InputError(what, why.str());
  }
  return out;
}

}  // namespace cyclone::mesh
