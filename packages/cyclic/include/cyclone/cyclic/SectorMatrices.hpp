#pragma once
// The sector's modal tangent and mass on all its physical DOFs (3 per node,
// node-major, nothing eliminated, no cyclic constraint): everything of the
// cyclic eigenproblem that does not depend on the nodal diameter. Assembled once
// per speed; each nodal diameter then only projects it with its cyclic transform
// (NodalDiameterForm), instead of computing every element matrix again.
//
// Both matrices are symmetric and share the mesh's node graph, so they are held as
// the lower triangle in 3 x 3 node blocks on one pattern: a third of two general
// compressed matrices (28 against 74 MB on the built-in sector at 42k DOFs), which
// the sweep holds through every nodal diameter's factorization.
#include <vector>

#include "cyclone/cyclic/Prestress.hpp"
#include "cyclone/fe/Material.hpp"
#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::cyclic {

struct SectorMatrices {
  /// Node column b holds the blocks of its neighbours a >= b: blockRow[p] = a for p in
  /// [blockStart[b], blockStart[b + 1]), ascending. Block p of K is k[9p .. 9p + 8],
  /// column-major: entry (3a + r, 3b + c) at 9p + 3c + r; M alike in m. A diagonal
  /// block (a = b) is held whole.
  std::vector<int> blockStart, blockRow;
  std::vector<double> k, m;
  /// The upper blocks of node column b, read through the lower ones: for q in
  /// [mirrorStart[b], mirrorStart[b + 1]), neighbour mirrorNode[q] = a < b (ascending)
  /// whose column holds block (b, a) at mirrorBlock[q].
  std::vector<int> mirrorStart, mirrorNode, mirrorBlock;
  double seconds = 0;

  int dofs() const { return blockStart.empty() ? 0 : 3 * (int(blockStart.size()) - 1); }
  /// Stored entries of the whole symmetric matrix (what a general sparse format holds).
  long long nonzeros() const;
  /// Bytes held by both matrices and their pattern.
  double bytes() const;

  /// Every entry of column j of the whole matrix, rows ascending: visit(i, v) with v the
  /// entry's index into k and m.
  template <class Visit>
  void forEachInColumn(int j, Visit&& visit) const {
    const int b = j / 3, c = j % 3;
    for (int q = mirrorStart[b]; q < mirrorStart[b + 1]; ++q) {
      const int a = mirrorNode[q], at = 9 * mirrorBlock[q] + c;  // (3b + c, 3a + r) of block (b, a)
      for (int r = 0; r < 3; ++r) visit(3 * a + r, at + 3 * r);
    }
    for (int p = blockStart[b]; p < blockStart[b + 1]; ++p) {
      const int a = blockRow[p], at = 9 * p + 3 * c;
      for (int r = 0; r < 3; ++r) visit(3 * a + r, at + r);
    }
  }

  /// y = A x with A = K (values k) or M (values m); y is overwritten.
  template <class Scalar>
  void multiply(const std::vector<double>& values, const Scalar* x, Scalar* y) const {
    const int nodes = int(blockStart.size()) - 1;
    for (int i = 0; i < 3 * nodes; ++i) y[i] = Scalar(0);
    for (int b = 0; b < nodes; ++b)
      for (int p = blockStart[b]; p < blockStart[b + 1]; ++p) {
        const int a = blockRow[p];
        const double* A = values.data() + 9 * p;
        for (int c = 0; c < 3; ++c)
          for (int r = 0; r < 3; ++r) y[3 * a + r] += A[3 * c + r] * x[3 * b + c];
        if (a == b) continue;
        for (int c = 0; c < 3; ++c)
          for (int r = 0; r < 3; ++r) y[3 * b + c] += A[3 * c + r] * x[3 * a + r];
      }
  }
};

/// Sums every element's tangent (tangentElementMatrix) and mass into the node-graph
/// pattern of the mesh (one process). Throws InputError naming an inverted element.
SectorMatrices assembleSectorMatrices(const mesh::Mesh& mesh, const fe::IsotropicElastic& material,
                                      const PrestressState* prestress);

}  // namespace cyclone::cyclic
