#pragma once
// Global FE operators of a mesh on MPI ranks: Tpetra FECrsGraph/FECrsMatrix
// and FEMultiVector assembly (owned + shared rows), elements distributed over
// the ranks, constrained DOFs eliminated by the DofMap.
//
// The mesh is replicated on every rank (each rank reads or generates it); each
// rank owns a contiguous range of equations and assembles the elements whose
// lowest equation it owns. A partitioned mesh would change only this class.
//
// The unknowns are given by a DofTransform (DofMap::transform() for plain
// constraints, cyclic transforms per nodal diameter): every operator is
// sum over copies of T_c^T A T_c; loads act on copy 0 (the real part).
#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "cyclone/fe/DofMap.hpp"
#include "cyclone/fe/ElementKernels.hpp"
#include "cyclone/fe/LinearAlgebra.hpp"
#include "cyclone/fe/Material.hpp"
#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::fe {

class Assembler {
public:
  struct Impl;  // Tpetra graph, maps and importer: defined in Assembler.cpp only
  Assembler(const mesh::Mesh& mesh, const DofMap& dofs, linalg::CommPtr comm);
  Assembler(const mesh::Mesh& mesh, DofTransform transform, linalg::CommPtr comm);
  ~Assembler();
  Assembler(const Assembler&) = delete;
  Assembler& operator=(const Assembler&) = delete;

  const mesh::Mesh& mesh() const { return mesh_; }
  const DofTransform& transform() const { return transform_; }
  linalg::CommPtr comm() const;
  /// Owned equations of this rank (row, domain and range map of every operator).
  Teuchos::RCP<const linalg::Map> map() const;

  /// Any element matrix (3n x 3n, node-major) summed into the global operator;
  /// the kernel gets the global element index, its type and coordinates.
  using ElementMatrixKernel = std::function<ElementMatrix(mesh::Index, ElementType, const ElementCoords&)>;
  Teuchos::RCP<linalg::Matrix> assemble(const ElementMatrixKernel& kernel) const;

  /// Any element vector (3n, node-major) summed into a global vector through the copy-0 transform.
  using ElementVectorKernel = std::function<ElementVector(mesh::Index, ElementType, const ElementCoords&)>;
  Teuchos::RCP<linalg::MultiVector> assembleVector(const ElementVectorKernel& kernel) const;

  Teuchos::RCP<linalg::Matrix> stiffness(const IsotropicElastic& material) const;
  Teuchos::RCP<linalg::Matrix> mass(const IsotropicElastic& material) const;
  /// Centrifugal body load at angular speed omega (rad/s) about the axis, undeformed geometry.
  Teuchos::RCP<linalg::MultiVector> centrifugalLoad(const IsotropicElastic& material, double omega,
                                                    const RotationAxis& axis) const;
  /// Uniform body force density b (force per volume), e.g. gravity rho*g.
  Teuchos::RCP<linalg::MultiVector> bodyLoad(const Eigen::Vector3d& b) const;
  /// Force on each listed node (components on constrained DOFs are dropped).
  Teuchos::RCP<linalg::MultiVector> nodalLoad(const std::vector<mesh::Index>& nodes,
                                              const Eigen::Vector3d& forcePerNode) const;

  /// The 6 rigid-body motions (3 translations, 3 rotations about the origin) on the free
  /// DOFs, per copy (6 x copies columns): MueLu's near null space for elasticity, and a
  /// check for free-body models.
  Teuchos::RCP<linalg::MultiVector> rigidBodyModes() const;

  /// Full nodal field (numNodes x 3, zeros on constrained components) of column `column`
  /// of a distributed solution, in copy `copy` (0: real part, 1: imaginary part), the
  /// same on every rank.
  std::vector<std::array<double, 3>> nodalField(const linalg::MultiVector& u, int column = 0, int copy = 0) const;

  /// Elements assembled on this rank (global element indices).
  const std::vector<mesh::Index>& localElements() const;
  /// Element coordinates (n x 3) of a global element.
  ElementCoords elementCoords(mesh::Index globalElement) const;

private:
  const mesh::Mesh& mesh_;
  DofTransform transform_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cyclone::fe
