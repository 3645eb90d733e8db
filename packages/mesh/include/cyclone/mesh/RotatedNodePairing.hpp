#pragma once
// Pairs the nodes of two faces related by a rotation about an axis (the left
// and right side faces of a cyclic sector): right[i] sits at R(angle) left[i].
#include <string>

#include <Eigen/Core>
#include <vector>

#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::mesh {

/// A rotation axis: a point on it and its direction (normalised where it is used). The
/// one axis type of the library: cyclic symmetry's and the centrifugal load's.
struct RotationAxis {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
};

/// Rotates p by `angle` (radians, right-handed) about the axis.
Point rotate(const Point& p, double angle, const RotationAxis& axis);

/// The largest distance of a mesh node from the axis (0 for no nodes): the radius a
/// centrifugal load's scale and a plausibility check of the length unit are taken at.
double outermostRadius(const Mesh& mesh, const RotationAxis& axis);

/// Whether two axes are one line: directions parallel (either sense) and each point on
/// the other's line, within 1e-9 (the points' offset relative to max(1, its length)).
bool sameRotationLine(const RotationAxis& a, const RotationAxis& b);

struct NodePairing {
  std::vector<Index> left, right;  ///< right[i] = partner of left[i]
  double maxDistance = 0;          ///< largest |R x_left - x_right| over the pairs
};

/// Every node of `left` must find exactly one node of `right` within `tolerance`
/// of its rotated position, and the counts must agree; otherwise InputError naming
/// `what` (e.g. "shroud faces"), how many nodes failed, the first few with their
/// ids and distances.
NodePairing pairRotatedNodes(const Mesh& mesh, const std::vector<Index>& left, const std::vector<Index>& right,
                             double angle, const RotationAxis& axis, double tolerance, const std::string& what);

}  // namespace cyclone::mesh
