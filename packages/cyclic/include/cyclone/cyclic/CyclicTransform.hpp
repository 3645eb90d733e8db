#pragma once
// The cyclic constraint at nodal diameter k in real form.
// With phase phi = k 2pi/N and Q the rotation of the left face onto the right:
//   right face, real part:      u_R^a = Q (cos phi u_L^a - sin phi u_L^b)
//   right face, imaginary part: u_R^b = Q (sin phi u_L^a + cos phi u_L^b)
// k = 0 and k = N/2 are real (one copy, u_R = +-Q u_L, single modes); for
// 0 < k < N/2 the two copies give each travelling-wave pair as two equal
// eigenvalues. Nodes on the axis keep only the motions the constraint allows
// (axial for k = 0, in-plane for k = 1, none otherwise).
#include <string>
#include <vector>

#include "cyclone/cyclic/CyclicSector.hpp"
#include "cyclone/fe/DofTransform.hpp"

namespace cyclone::cyclic {

/// 1 for k = 0 and k = N/2, else 2.
int copiesFor(int sectors, int k);

/// True when the unknowns come in pairs (2m, 2m+1) = (x_a, x_b) on which
/// multiplication by i (the travelling-wave phase, (a, b) -> (-b, a) on every
/// physical DOF) acts as (x_a, x_b) -> (-x_b, x_a). Then the real-form K_k, M_k
/// are [[A, -B], [B, A]] on the pairs and decouple into the forward travelling
/// wave's A + iB (and its transpose for the backward wave): half the size.
/// cyclicTransform numbers its unknowns so for 0 < k < N/2.
bool travellingWavePaired(const fe::DofTransform& T);

/// General form: `fixed[3 * node + component]` marks DOFs held at zero; Q maps a
/// left-face vector onto the right face (the identity for scalar DOFs such as
/// lumped models). Throws InputError if the fixed DOFs are not cyclically symmetric.
fe::DofTransform cyclicTransform(Index numNodes, const CyclicSector& sector, int k, const std::vector<char>& fixed,
                                 const Eigen::Matrix3d& Q);

/// FE form: all components of the nodes in `fixedSets` are fixed; Q = sector.rotation().
fe::DofTransform cyclicTransform(const mesh::Mesh& mesh, const CyclicSector& sector, int k,
                                 const std::vector<std::string>& fixedSets);

}  // namespace cyclone::cyclic
