#pragma once
// One sector of a cyclically symmetric structure with N sectors: the rotation
// axis and the paired side faces (right[i] = R(2 pi / N) left[i]).
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "cyclone/mesh/Mesh.hpp"
#include "cyclone/mesh/RotatedNodePairing.hpp"

namespace cyclone::cyclic {

using mesh::Index;

struct CyclicSector {
  int sectors = 0;
  mesh::RotationAxis axis;
  std::vector<Index> left, right;  ///< paired side-face nodes; a node on the axis is its own partner
  double maxMismatch = 0;          ///< largest |R x_left - x_right|

  double sectorAngle() const;        ///< 2 pi / N
  Eigen::Matrix3d rotation() const;  ///< R(2 pi / N) about the axis
  int maxNodalDiameter() const { return sectors / 2; }
};

/// Pairs the nodes of the named left and right face sets (each list's sets are
/// merged) under the rotation by 2 pi / N about the axis. Throws InputError for
/// N < 2, missing sets, or faces that do not match (how many nodes, which, how far).
/// Tolerance <= 0 picks 1e-6 of the model size.
CyclicSector makeCyclicSector(const mesh::Mesh& mesh, int sectors, const mesh::RotationAxis& axis,
                              const std::vector<std::string>& leftSets, const std::vector<std::string>& rightSets,
                              double tolerance = 0);

/// Checks 0 <= k <= N/2; InputError naming the nodal diameter otherwise.
void checkNodalDiameter(int sectors, int k);

}  // namespace cyclone::cyclic
