#include "BoxMesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace cyclone::test_support {

using cyclone::mesh::ElementType;
using cyclone::mesh::Index;

namespace {

double signedVolume(const cyclone::mesh::Mesh& m, const std::array<Index, 4>& t) {
  const auto &a = m.coords[t[0]], &b = m.coords[t[1]], &c = m.coords[t[2]], &d = m.coords[t[3]];
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

}  // namespace

cyclone::mesh::Mesh makeBoxMesh(double lx, double ly, double lz, int nx, int ny, int nz, ElementType type) {
  cyclone::mesh::Mesh m;
  m.source = "structured box";
  auto corner = [&](int i, int j, int k) { return Index(i + (nx + 1) * (j + (ny + 1) * k)); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) m.coords.push_back({lx * i / nx, ly * j / ny, lz * k / nz});

  std::map<std::pair<Index, Index>, Index> midNodes;
  auto mid = [&](Index a, Index b) {
    const auto key = std::minmax(a, b);
    auto it = midNodes.find(key);
    if (it != midNodes.end()) return it->second;
    const auto &pa = m.coords[a], &pb = m.coords[b];
    m.coords.push_back({0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]), 0.5 * (pa[2] + pb[2])});
    const Index n = Index(m.coords.size()) - 1;
    midNodes[key] = n;
    return n;
  };

  cyclone::mesh::ElementBlock block;
  block.name = "box";
  block.id = 1;
  block.type = type;
  const bool tet = type == ElementType::Tet4 || type == ElementType::Tet10;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        // Cell corners in Exodus hex order.
        const std::array<Index, 8> c = {corner(i, j, k),         corner(i + 1, j, k),     corner(i + 1, j + 1, k),
                                        corner(i, j + 1, k),     corner(i, j, k + 1),     corner(i + 1, j, k + 1),
                                        corner(i + 1, j + 1, k + 1), corner(i, j + 1, k + 1)};
        if (!tet) {
          for (Index n : c) block.connectivity.push_back(n);
          if (type == ElementType::Hex20) {
            const int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                      {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
            for (auto& e : edges) block.connectivity.push_back(mid(c[e[0]], c[e[1]]));
          }
          continue;
        }
        // Kuhn split along the diagonal from corner (0,0,0) to (1,1,1): one tet per axis order.
        auto byBits = [&](int bits) {  // bit 0: +x, bit 1: +y, bit 2: +z
          return corner(i + (bits & 1), j + ((bits >> 1) & 1), k + ((bits >> 2) & 1));
        };
        const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
        for (auto& o : orders) {
          const int b1 = 1 << o[0], b2 = b1 | (1 << o[1]);
          std::array<Index, 4> t = {byBits(0), byBits(b1), byBits(b2), byBits(7)};
          if (signedVolume(m, t) < 0) std::swap(t[1], t[2]);
          for (Index n : t) block.connectivity.push_back(n);
          if (type == ElementType::Tet10) {
            const int edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
            for (auto& e : edges) block.connectivity.push_back(mid(t[e[0]], t[e[1]]));
          }
        }
      }
  m.blocks.push_back(block);
  m.assignDefaultIds();

  const double tol = 1e-9 * std::max({lx, ly, lz});
  const double L[3] = {lx, ly, lz};
  const char* names[3][2] = {{"x0", "x1"}, {"y0", "y1"}, {"z0", "z1"}};
  for (Index n = 0; n < m.numNodes(); ++n) {
    m.nodeSets["all"].push_back(n);
    for (int d = 0; d < 3; ++d) {
      if (std::abs(m.coords[n][d]) < tol) m.nodeSets[names[d][0]].push_back(n);
      if (std::abs(m.coords[n][d] - L[d]) < tol) m.nodeSets[names[d][1]].push_back(n);
    }
  }
  return m;
}

}  // namespace cyclone::test_support
