#include "cyclone/mesh/MeshGeometryCheck.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cyclone/core/Error.hpp"
#include "cyclone/mesh/ReferenceElement.hpp"

namespace cyclone::mesh {

void checkElementGeometry(const Mesh& mesh) {
  checkElementGeometry(mesh, [&](int, Index) { return mesh.source; });
}

void checkElementGeometry(const Mesh& mesh, const std::function<std::string(int block, Index element)>& where) {
  // A coordinate that is not a number (NaN, inf in the file) is named as such, not as
  // the Jacobian determinant it makes (issue 49: "minimum Jacobian determinant inf").
  for (Index node = 0; node < Index(mesh.coords.size()); ++node)
    for (int d = 0; d < 3; ++d)
      if (!std::isfinite(mesh.coords[node][d])) {
        std::ostringstream msg;
        msg << "node " << (mesh.nodeIds.empty() ? node + 1 : mesh.nodeIds[node]) << " has the coordinate "
            << "xyz"[d] << " = " << mesh.coords[node][d] << ": every coordinate must be a finite number";
        throw InputError(mesh.source, msg.str());
      }
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const auto& block = mesh.blocks[b];
    const int n = nodesPerElement(block.type);
    // det(dx/dxi) of an undistorted element scales with size^3 (times 1 for tets, 1/8 for
    // hexes on [-1,1]^3); anything below 1e-10 of that is a collapsed element, not round-off.
    const double referenceScale = (block.type == ElementType::Hex8 || block.type == ElementType::Hex20) ? 0.125 : 1.0;
    Eigen::Matrix<double, Eigen::Dynamic, 3> x(n, 3);
    for (Index e = 0; e < block.numElements(); ++e) {
      const Index* nodes = block.element(e);
      for (int a = 0; a < n; ++a)
        for (int d = 0; d < 3; ++d) x(a, d) = mesh.coords[nodes[a]][d];
      const double size = (x.colwise().maxCoeff() - x.colwise().minCoeff()).norm();
      const double detJ = minJacobianDeterminant(block.type, x);
      if (detJ > 1e-10 * referenceScale * size * size * size) continue;
      std::ostringstream msg;
      msg.precision(6);
      msg << block.describeElement(e) << " is inverted or degenerate: minimum Jacobian determinant " << detJ
          << (detJ <= 0 ? " is not positive" : " is negligible for its size")
          << " (check its node order and coordinates; nodes";
      for (int a = 0; a < n; ++a)
        msg << ' ' << (mesh.nodeIds.empty() ? nodes[a] + 1 : mesh.nodeIds[nodes[a]]);
      msg << ")";
      throw InputError(where(static_cast<int>(b), e), msg.str());
    }
  }
}

}  // namespace cyclone::mesh
