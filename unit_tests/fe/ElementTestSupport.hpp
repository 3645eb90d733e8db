#pragma once
// Test geometry for the element kernels: affine and randomly distorted single
// elements, small distorted patch meshes, dense assembly, and closed-form
// reference quantities computed independently of the library.
#include <Eigen/Dense>
#include <random>
#include <string>
#include <vector>

#include "cyclone/fe/ElementKernels.hpp"

namespace cyclone::fe::test {

inline const ElementType kAllTypes[] = {ElementType::Tet4, ElementType::Tet10, ElementType::Hex8,
                                        ElementType::Hex20};

std::string nameOf(ElementType t);
bool isTet(ElementType t);
int nodeCount(ElementType t);
/// Volume of the reference domain: 1/6 (tet) or 8 (cube).
double referenceVolume(ElementType t);
/// Reference coordinates of the centroid.
Eigen::Vector3d referenceCentroid(ElementType t);

/// The reference element mapped by x = A xi + c.
ElementCoords affineElement(ElementType t, const Eigen::Matrix3d& A, const Eigen::Vector3d& c);
/// A random affine map with det A in about [0.3, 3].
Eigen::Matrix3d randomAffineMatrix(std::mt19937& rng);
/// An affinely mapped element with every node moved by up to `amount` times its size
/// (mid-edge nodes too: curved edges), checked valid.
ElementCoords distortedElement(ElementType t, std::mt19937& rng, double amount = 0.08);
/// Places every mid-edge node at the midpoint of its corners (no-op for linear types).
void straightenMidEdges(ElementType t, ElementCoords& X);

/// Closed-form isotropic elasticity (Lame form), Voigt xx yy zz yz xz xy, engineering shear.
Eigen::Matrix<double, 6, 6> lameElasticity(double E, double nu);
/// Distance vector from the axis through p with direction a (any length).
Eigen::Vector3d distanceFromAxis(const Eigen::Vector3d& x, const Eigen::Vector3d& p, const Eigen::Vector3d& a);

/// A mesh of several elements filling a distorted 3x3x3 block of unit cells (hexes, or each
/// cell split into 6 tets), every node moved at random by up to `amount`, mid-edge nodes on
/// straight edges.
struct PatchMesh {
  ElementType type;
  std::vector<Eigen::Vector3d> nodes;
  std::vector<std::vector<int>> elements;
  std::vector<bool> onBoundary;  ///< node on the block's outer surface
  ElementCoords coords(int e) const;
  Eigen::VectorXd gather(int e, const Eigen::VectorXd& u) const;  ///< element DOFs of a node-major field
};
PatchMesh distortedBlock(ElementType t, std::mt19937& rng, double amount = 0.12);
/// Dense global matrix (3 DOFs per node, node-major) from an element matrix kernel.
template <class Kernel>
Eigen::MatrixXd assembleDense(const PatchMesh& m, Kernel&& elementMatrix) {
  const int n = 3 * static_cast<int>(m.nodes.size());
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  for (int e = 0; e < static_cast<int>(m.elements.size()); ++e) {
    const Eigen::MatrixXd Ke = elementMatrix(m.coords(e));
    const auto& nodes = m.elements[e];
    for (std::size_t a = 0; a < nodes.size(); ++a)
      for (std::size_t b = 0; b < nodes.size(); ++b)
        K.block<3, 3>(3 * nodes[a], 3 * nodes[b]) += Ke.block<3, 3>(3 * a, 3 * b);
  }
  return K;
}

}  // namespace cyclone::fe::test
