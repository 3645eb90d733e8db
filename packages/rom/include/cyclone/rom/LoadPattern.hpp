#pragma once
// A load on the sector that need not act at the retained DOFs (a distributed
// load, a force at a node that is not retained): nodal forces in x, y, z per
// real-form copy of the nodal diameter. A reduced model carries the response
// at its retained DOFs to such loads, x_r(w) = A_rf(w) f, as the excitation
// part of Scalvini 2021, eqs. 5.27-5.35.
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::rom {

struct NodalForce {
  mesh::Index node = 0;  ///< 0-based mesh node
  int copy = 0;          ///< real-form copy: 0 real part, 1 imaginary part (0 < k < N/2 only)
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  ///< N, global x, y, z
};

struct LoadPattern {
  std::string name;
  std::vector<NodalForce> forces;
};

}  // namespace cyclone::rom
