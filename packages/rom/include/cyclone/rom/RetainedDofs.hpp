#pragma once
// Which DOFs of a sector a reduced model keeps: the nodes of some node sets,
// each set with all 3 directions or chosen ones, in the global frame or in a
// given orthonormal local frame (e.g. normal and tangents of a contact face).
// A retained DOF is the displacement of its node along one unit vector (a row
// of the node's frame); a unit load there is a force along that vector, so
// the compliance at the retained DOFs is T^T A T for the compliance A in x, y, z.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::rom {

/// The directions one retained node set keeps.
struct RetainedDirections {
  std::vector<int> directions{0, 1, 2};  ///< of the frame: distinct, each 0, 1 or 2, kept in this order
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();  ///< rows: the frame's unit vectors in global coordinates (identity: x, y, z)
};

/// The retained DOFs of one real-form copy, in order: the nodes of the sets merged in
/// order (a node in several sets counts once), each node's directions in its set's order.
struct RetainedDofSet {
  std::vector<mesh::Index> nodes;             ///< distinct retained nodes
  std::vector<Eigen::Matrix3d> frames;        ///< per node: rows e1, e2, e3 (identity: global)
  std::vector<bool> rotated;                  ///< per node: its frame is not x, y, z
  std::vector<std::pair<int, int>> dofs;      ///< (index into nodes, direction in its frame)

  Eigen::Index size() const { return Eigen::Index(dofs.size()); }
  /// The unit vector (global coordinates) of retained DOF k.
  Eigen::Vector3d axis(Eigen::Index k) const {
    const auto& [node, direction] = dofs[std::size_t(k)];
    return frames[std::size_t(node)].row(direction).transpose();
  }
};

/// InputError naming the set ("retained/<set>/frame", ".../directions") for a frame
/// that is not orthonormal (|R R^T - I| > 1e-9) or directions that are empty, repeated
/// or outside 0..2; naming "retained" for no sets, a direction entry for a set not
/// retained, or a node that two sets would retain differently. Missing or empty sets:
/// the mesh's InputError.
RetainedDofSet retainedDofs(const mesh::Mesh& mesh, const std::vector<std::string>& sets,
                            const std::map<std::string, RetainedDirections>& directions);

}  // namespace cyclone::rom
