#pragma once
// The sector's modal tangent and mass on all its physical DOFs (3 per node,
// node-major, nothing eliminated, no cyclic constraint): everything of the
// cyclic eigenproblem that does not depend on the nodal diameter. Assembled once
// per speed; each nodal diameter then only projects it with its cyclic transform
// (HarmonicForm), instead of computing every element matrix again.
#include <Eigen/SparseCore>

#include "cyclone/cyclic/Prestress.hpp"
#include "cyclone/fe/Material.hpp"
#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::cyclic {

struct SectorMatrices {
  using Sparse = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
  Sparse K;  ///< tangent K (+ K_sigma - K_Omega with a prestress), 3n x 3n, both triangles
  Sparse M;  ///< consistent mass, same pattern
  double seconds = 0;
};

/// Sums every element's tangent (tangentElementMatrix) and mass into the node-graph
/// pattern of the mesh (one process). Throws InputError naming an inverted element.
SectorMatrices assembleSectorMatrices(const mesh::Mesh& mesh, const fe::IsotropicElastic& material,
                                      const PrestressState* prestress);

}  // namespace cyclone::cyclic
