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

/// A retained point that is no node: the weighted sum of some nodes' displacements (a
/// weighted mean when the weights sum to 1), kept in x, y and z. A unit load there is
/// spread over the nodes by the same weights (the virtual work of the averaged motion:
/// an RBE3-like multipoint constraint). A contact patch's mean motion is one: a reduced
/// model then solves one static load case per patch direction, not one per face node.
struct RetainedMean {
  std::string name;                  ///< for messages (e.g. "patch 3 right")
  std::vector<mesh::Index> nodes;    ///< distinct
  std::vector<double> weights;       ///< per node, positive
};

/// The retained DOFs of one real-form copy, in order: the nodes of the sets merged in
/// order (a node in several sets counts once), each node's directions in its set's order;
/// then the means' x, y, z, in their order.
struct RetainedDofSet {
  std::vector<mesh::Index> nodes;             ///< distinct retained nodes
  std::vector<Eigen::Matrix3d> frames;        ///< per node: rows e1, e2, e3 (identity: global)
  std::vector<bool> rotated;                  ///< per node: its frame is not x, y, z
  std::vector<RetainedMean> means;            ///< retained points after the nodes
  /// (point, direction in its frame): point i < nodes.size() is node i, else mean
  /// i - nodes.size() (global x, y, z).
  std::vector<std::pair<int, int>> dofs;

  Eigen::Index size() const { return Eigen::Index(dofs.size()); }
  /// The unit vector (global coordinates) of retained DOF k.
  Eigen::Vector3d axis(Eigen::Index k) const {
    const auto& [point, direction] = dofs[std::size_t(k)];
    if (std::size_t(point) >= nodes.size()) return Eigen::Vector3d::Unit(direction);
    return frames[std::size_t(point)].row(direction).transpose();
  }
  /// The mean retained DOF k belongs to, or null for a node's DOF.
  const RetainedMean* mean(Eigen::Index k) const {
    const auto point = std::size_t(dofs[std::size_t(k)].first);
    return point < nodes.size() ? nullptr : &means[point - nodes.size()];
  }
  /// f(node, weight) for every node retained DOF k reads (a node's own DOF: weight 1).
  template <class F>
  void forEachNode(Eigen::Index k, F&& f) const {
    if (const RetainedMean* m = mean(k)) {
      for (std::size_t i = 0; i < m->nodes.size(); ++i) f(m->nodes[i], m->weights[i]);
      return;
    }
    f(nodes[std::size_t(dofs[std::size_t(k)].first)], 1.0);
  }
  /// The DOF's displacement from per-node displacements u (indexed by mesh node).
  template <class Vector3>
  auto read(Eigen::Index k, const std::vector<Vector3>& u) const {
    using Scalar = typename Vector3::Scalar;
    const Eigen::Matrix<Scalar, 3, 1> a = axis(k).template cast<Scalar>();
    Scalar sum(0);
    forEachNode(k, [&](mesh::Index node, double w) { sum += w * a.dot(u[std::size_t(node)]); });
    return sum;
  }
};

/// InputError naming the set ("retained/<set>/frame", ".../directions") for a frame
/// that is not orthonormal (|R R^T - I| > 1e-9) or directions that are empty, repeated
/// or outside 0..2; naming "retained" for no sets, a direction entry for a set not
/// retained, or a node that two sets would retain differently. Missing or empty sets:
/// the mesh's InputError. Means (after the sets' nodes; `sets` may then be empty): InputError
/// naming "retained/means/<name>" for no nodes, a node twice or outside the mesh, weights
/// of another count or not positive and finite.
RetainedDofSet retainedDofs(const mesh::Mesh& mesh, const std::vector<std::string>& sets,
                            const std::map<std::string, RetainedDirections>& directions,
                            std::vector<RetainedMean> means = {});

}  // namespace cyclone::rom
