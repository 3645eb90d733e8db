#include "cyclone/cyclic/SectorMatrices.hpp"

#include <algorithm>
#include <vector>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/fe/ElementKernels.hpp"

namespace cyclone::cyclic {

namespace {

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

// The lower block pattern (neighbours a >= b of each node b) and its mirror.
void blockPattern(const std::vector<std::vector<mesh::Index>>& adjacent, SectorMatrices& out) {
  const std::size_t nodes = adjacent.size();
  out.blockStart.assign(1, 0);
  out.mirrorStart.assign(1, 0);
  for (std::size_t b = 0; b < nodes; ++b) {
    for (mesh::Index a : adjacent[b])
      if (std::size_t(a) >= b) out.blockRow.push_back(int(a));
    out.blockStart.push_back(int(out.blockRow.size()));
  }
  // Column a's block (b, a), b > a, mirrored into column b; columns are visited in
  // ascending a, so each mirror list comes out ascending.
  std::vector<int> count(nodes + 1, 0);
  for (std::size_t a = 0; a < nodes; ++a)
    for (int p = out.blockStart[a]; p < out.blockStart[a + 1]; ++p)
      if (std::size_t(out.blockRow[std::size_t(p)]) != a) ++count[std::size_t(out.blockRow[std::size_t(p)]) + 1];
  for (std::size_t b = 0; b < nodes; ++b) count[b + 1] += count[b];
  out.mirrorStart = count;
  out.mirrorNode.resize(std::size_t(count[nodes]));
  out.mirrorBlock.resize(std::size_t(count[nodes]));
  for (std::size_t a = 0; a < nodes; ++a)
    for (int p = out.blockStart[a]; p < out.blockStart[a + 1]; ++p) {
      const std::size_t b = std::size_t(out.blockRow[std::size_t(p)]);
      if (b == a) continue;
      const std::size_t q = std::size_t(count[b]++);
      out.mirrorNode[q] = int(a), out.mirrorBlock[q] = p;
    }
  out.k.assign(9 * out.blockRow.size(), 0.0);
  out.m.assign(9 * out.blockRow.size(), 0.0);
}

void coordinates(const mesh::Mesh& mesh, const mesh::Index* nodes, int nn, fe::ElementCoords& X) {
  X.resize(nn, 3);
  for (int a = 0; a < nn; ++a)
    for (int d = 0; d < 3; ++d) X(a, d) = mesh.coords[nodes[a]][d];
}

}  // namespace

long long SectorMatrices::nonzeros() const {
  const long long diagonal = blockStart.empty() ? 0 : (long long)blockStart.size() - 1;
  return 9 * (2 * (long long)blockRow.size() - diagonal);
}

double SectorMatrices::bytes() const {
  return double(sizeof(double)) * double(k.size() + m.size()) +
         double(sizeof(int)) * double(blockStart.size() + blockRow.size() + mirrorStart.size() + mirrorNode.size() +
                                      mirrorBlock.size());
}

SectorMatrices assembleSectorMatrices(const mesh::Mesh& mesh, const fe::IsotropicElastic& material,
                                      const PrestressState* prestress) {
  Timer timer;
  SectorMatrices out;
  blockPattern(nodeGraph(mesh), out);
  double* k = out.k.data();
  double* m = out.m.data();
  std::vector<int> slot;  // per element node pair (i, j), nodes[i] >= nodes[j]: block of nodes[i] in nodes[j]'s column
  mesh::Index global = 0;
  fe::ElementCoords X;
  fe::ElementMatrix Ke, Me;  // element-sized storage inside: nothing allocated per element
  for (const auto& block : mesh.blocks) {
    const int nn = mesh::nodesPerElement(block.type);
    slot.resize(std::size_t(nn) * nn);
    for (mesh::Index e = 0; e < block.numElements(); ++e, ++global) {
      const mesh::Index* nodes = block.element(e);
      coordinates(mesh, nodes, nn, X);
      try {
        modalElementMatrices(mesh, global, block.type, X, material, prestress, Ke, &Me);
      } catch (const fe::InvalidElementGeometry& err) {
        throw InputError(mesh.source, mesh.elementName(global) + ": inverted or degenerate element (det J = " +
                                          std::to_string(err.detJ) + " at integration point " +
                                          std::to_string(err.point) + ")");
      }
      for (int j = 0; j < nn; ++j) {
        const auto first = out.blockRow.begin() + out.blockStart[std::size_t(nodes[j])];
        const auto last = out.blockRow.begin() + out.blockStart[std::size_t(nodes[j]) + 1];
        for (int i = 0; i < nn; ++i)
          slot[std::size_t(j) * nn + i] =
              nodes[i] < nodes[j] ? -1 : int(std::lower_bound(first, last, int(nodes[i])) - out.blockRow.begin());
      }
      // The lower triangle only: the element matrices are symmetric.
      for (int j = 0; j < nn; ++j)
        for (int i = 0; i < nn; ++i) {
          const int p = slot[std::size_t(j) * nn + i];
          if (p < 0) continue;
          for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) {
              k[9 * p + 3 * c + r] += Ke(3 * i + r, 3 * j + c);
              m[9 * p + 3 * c + r] += Me(3 * i + r, 3 * j + c);
            }
        }
    }
  }
  out.seconds = timer.seconds();
  return out;
}

}  // namespace cyclone::cyclic
