#include "cyclone/cyclic/SectorMatrices.hpp"

#include <algorithm>
#include <vector>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/fe/ElementKernels.hpp"

namespace cyclone::cyclic {

namespace {

using Sparse = SectorMatrices::Sparse;

// The sorted neighbours of every node (itself included) through the elements.
std::vector<std::vector<mesh::Index>> nodeGraph(const mesh::Mesh& mesh) {
  std::vector<std::vector<mesh::Index>> adjacent(mesh.numNodes());
  for (const auto& block : mesh.blocks) {
    const int nn = mesh::nodesPerElement(block.type);
    for (mesh::Index e = 0; e < block.numElements(); ++e) {
      const mesh::Index* nodes = block.element(e);
      for (int a = 0; a < nn; ++a) adjacent[nodes[a]].insert(adjacent[nodes[a]].end(), nodes, nodes + nn);
    }
  }
  for (auto& list : adjacent) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return adjacent;
}

// A zero matrix with the 3 x 3 node blocks of the graph, compressed column storage.
Sparse blockPattern(const std::vector<std::vector<mesh::Index>>& adjacent) {
  const int n = int(3 * adjacent.size());
  long long nonzeros = 0;
  for (const auto& list : adjacent) nonzeros += 9 * (long long)list.size();
  Sparse A(n, n);
  A.makeCompressed();
  A.resizeNonZeros(Eigen::Index(nonzeros));
  int* outer = A.outerIndexPtr();
  int* inner = A.innerIndexPtr();
  int position = 0;
  for (std::size_t b = 0; b < adjacent.size(); ++b)
    for (int e = 0; e < 3; ++e) {
      outer[3 * b + e] = position;
      for (mesh::Index a : adjacent[b])
        for (int d = 0; d < 3; ++d) inner[position++] = int(3 * a + d);
    }
  outer[n] = position;
  std::fill(A.valuePtr(), A.valuePtr() + nonzeros, 0.0);
  return A;
}

fe::ElementCoords coordinates(const mesh::Mesh& mesh, const mesh::Index* nodes, int nn) {
  fe::ElementCoords X(nn, 3);
  for (int a = 0; a < nn; ++a)
    for (int d = 0; d < 3; ++d) X(a, d) = mesh.coords[nodes[a]][d];
  return X;
}

}  // namespace

SectorMatrices assembleSectorMatrices(const mesh::Mesh& mesh, const fe::IsotropicElastic& material,
                                      const PrestressState* prestress) {
  Timer timer;
  const auto adjacent = nodeGraph(mesh);
  SectorMatrices out;
  out.K = blockPattern(adjacent);
  out.M = out.K;
  const int* outer = out.K.outerIndexPtr();
  double* k = out.K.valuePtr();
  double* m = out.M.valuePtr();
  std::vector<int> slot;  // per element node pair: where node a's block sits in node b's columns
  mesh::Index global = 0;
  for (const auto& block : mesh.blocks) {
    const int nn = mesh::nodesPerElement(block.type);
    slot.resize(std::size_t(nn) * nn);
    for (mesh::Index e = 0; e < block.numElements(); ++e, ++global) {
      const mesh::Index* nodes = block.element(e);
      const auto X = coordinates(mesh, nodes, nn);
      Eigen::MatrixXd Ke, Me;
      try {
        Ke = tangentElementMatrix(mesh, global, block.type, X, material, prestress);
        Me = fe::elementMass(block.type, X, material.rho, material.massQuadrature);
      } catch (const fe::InvalidElementGeometry& err) {
        throw InputError(mesh.source, mesh.elementName(global) + ": inverted or degenerate element (det J = " +
                                          std::to_string(err.detJ) + " at integration point " +
                                          std::to_string(err.point) + ")");
      }
      for (int j = 0; j < nn; ++j) {
        const auto& list = adjacent[nodes[j]];
        for (int i = 0; i < nn; ++i)
          slot[std::size_t(j) * nn + i] = int(std::lower_bound(list.begin(), list.end(), nodes[i]) - list.begin());
      }
      for (int j = 0; j < nn; ++j)
        for (int c = 0; c < 3; ++c) {
          const int column = outer[3 * nodes[j] + c];
          for (int i = 0; i < nn; ++i) {
            const int at = column + 3 * slot[std::size_t(j) * nn + i];
            for (int r = 0; r < 3; ++r) {
              k[at + r] += Ke(3 * i + r, 3 * j + c);
              m[at + r] += Me(3 * i + r, 3 * j + c);
            }
          }
        }
    }
  }
  out.seconds = timer.seconds();
  return out;
}

}  // namespace cyclone::cyclic
