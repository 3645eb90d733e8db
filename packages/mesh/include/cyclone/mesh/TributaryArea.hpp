#pragma once
// The area each node of a surface node set carries: the share of the surface a contact
// node stands for, so that a contact stiffness per unit area and a total normal load can
// be spread over a face's nodes independently of the mesh (a node-pair law's sum grows
// as the mesh is refined). The surface is every element face whose nodes (midside ones
// included) all lie in the set. Each face is split into straight triangles through its
// nodes (a 6-node triangle into 4, a 4-node quadrilateral into 2 both ways (the mean), an
// 8-node one into the 4 corner triangles and the 2 of its inner quadrilateral), and each
// triangle gives a third of its area to each of its corners: every weight is positive,
// and the sum is the area of the triangulated surface (the face's own where it is flat
// and its edges straight).
#include <string>
#include <vector>

#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::mesh {

struct TributaryAreas {
  std::vector<double> area;  ///< per node of the set, in the set's order
  double total = 0;          ///< their sum: the surface's area
  long faces = 0;            ///< element faces found on the surface
};

/// InputError naming `what` (the set, for messages) where a node of the set lies on no
/// such face (a line of nodes or isolated points carry no area).
TributaryAreas tributaryAreas(const Mesh& mesh, const std::vector<Index>& nodes, const std::string& what);

}  // namespace cyclone::mesh
