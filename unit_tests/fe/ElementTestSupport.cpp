#include "ElementTestSupport.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>

#include "cyclone/mesh/ReferenceElement.hpp"

namespace cyclone::fe::test {

namespace {

// Mid-edge nodes as corner pairs, Exodus order (ElementType.hpp).
const int kTet10Edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
const int kHex20Edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

int cornerCount(ElementType t) { return isTet(t) ? 4 : 8; }

std::vector<std::array<int, 2>> midEdges(ElementType t) {
  std::vector<std::array<int, 2>> edges;
  if (t == ElementType::Tet10)
    for (const auto& e : kTet10Edges) edges.push_back({e[0], e[1]});
  if (t == ElementType::Hex20)
    for (const auto& e : kHex20Edges) edges.push_back({e[0], e[1]});
  return edges;
}

bool valid(ElementType t, const ElementCoords& X) { return mesh::minJacobianDeterminant(t, X) > 0; }

}  // namespace

std::string nameOf(ElementType t) {
  switch (t) {
    case ElementType::Tet4: return "Tet4";
    case ElementType::Tet10: return "Tet10";
    case ElementType::Hex8: return "Hex8";
    case ElementType::Hex20: return "Hex20";
  }
  return "unknown";
}

bool isTet(ElementType t) { return t == ElementType::Tet4 || t == ElementType::Tet10; }

int nodeCount(ElementType t) {
  switch (t) {
    case ElementType::Tet4: return 4;
    case ElementType::Tet10: return 10;
    case ElementType::Hex8: return 8;
    case ElementType::Hex20: return 20;
  }
  return 0;
}

double referenceVolume(ElementType t) { return isTet(t) ? 1.0 / 6.0 : 8.0; }

Eigen::Vector3d referenceCentroid(ElementType t) {
  return isTet(t) ? Eigen::Vector3d::Constant(0.25) : Eigen::Vector3d::Zero();
}

ElementCoords affineElement(ElementType t, const Eigen::Matrix3d& A, const Eigen::Vector3d& c) {
  const auto ref = mesh::referenceNodes(t);
  ElementCoords X(ref.rows(), 3);
  for (int a = 0; a < ref.rows(); ++a) X.row(a) = (A * ref.row(a).transpose() + c).transpose();
  return X;
}

Eigen::Matrix3d randomAffineMatrix(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  Eigen::Matrix3d A;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) A(i, j) = (i == j ? 1.0 : 0.0) + u(rng);
  return A;
}

void straightenMidEdges(ElementType t, ElementCoords& X) {
  const int corners = cornerCount(t);
  const auto edges = midEdges(t);
  for (std::size_t e = 0; e < edges.size(); ++e)
    X.row(corners + e) = 0.5 * (X.row(edges[e][0]) + X.row(edges[e][1]));
}

ElementCoords distortedElement(ElementType t, std::mt19937& rng, double amount) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), shift(-10.0, 10.0);
  const double size = isTet(t) ? 1.0 : 2.0;
  for (int attempt = 0; attempt < 100; ++attempt) {
    const Eigen::Vector3d c(shift(rng), shift(rng), shift(rng));
    ElementCoords X = affineElement(t, randomAffineMatrix(rng), c);
    for (int a = 0; a < X.rows(); ++a)
      for (int d = 0; d < 3; ++d) X(a, d) += amount * size * u(rng);
    if (valid(t, X)) return X;
  }
  throw std::runtime_error("distortedElement: no valid element found");
}

Eigen::Matrix<double, 6, 6> lameElasticity(double E, double nu) {
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  Eigen::Matrix<double, 6, 6> D = Eigen::Matrix<double, 6, 6>::Zero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) D(i, j) = lambda;
    D(i, i) = lambda + 2 * mu;
    D(i + 3, i + 3) = mu;
  }
  return D;
}

Eigen::Vector3d distanceFromAxis(const Eigen::Vector3d& x, const Eigen::Vector3d& p, const Eigen::Vector3d& a) {
  const Eigen::Vector3d r = x - p;
  return r - (r.dot(a) / a.squaredNorm()) * a;
}

ElementCoords PatchMesh::coords(int e) const {
  const auto& el = elements[e];
  ElementCoords X(el.size(), 3);
  for (std::size_t a = 0; a < el.size(); ++a) X.row(a) = nodes[el[a]].transpose();
  return X;
}

Eigen::VectorXd PatchMesh::gather(int e, const Eigen::VectorXd& u) const {
  const auto& el = elements[e];
  Eigen::VectorXd ue(3 * el.size());
  for (std::size_t a = 0; a < el.size(); ++a) ue.segment<3>(3 * a) = u.segment<3>(3 * el[a]);
  return ue;
}

PatchMesh distortedBlock(ElementType t, std::mt19937& rng, double amount) {
  // Grid of corner nodes at integer positions in [0,kCells]^3, then all moved at random.
  constexpr int kCells = 3, g = kCells + 1;
  auto gridId = [](int i, int j, int k) { return i + g * j + g * g * k; };
  std::vector<Eigen::Vector3d> reference;
  for (int k = 0; k < g; ++k)
    for (int j = 0; j < g; ++j)
      for (int i = 0; i < g; ++i) reference.emplace_back(i, j, k);

  // Cells: hexes with Exodus corner order, or the 6 Kuhn tets of each cube (all sharing
  // the cube's main diagonal, hence conforming between translated cubes).
  const int hexOffsets[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int permutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  std::vector<std::vector<int>> cornerLists;
  for (int ck = 0; ck < kCells; ++ck)
    for (int cj = 0; cj < kCells; ++cj)
      for (int ci = 0; ci < kCells; ++ci) {
        if (!isTet(t)) {
          std::vector<int> hex;
          for (const auto& o : hexOffsets) hex.push_back(gridId(ci + o[0], cj + o[1], ck + o[2]));
          cornerLists.push_back(hex);
          continue;
        }
        for (const auto& p : permutations) {
          std::array<int, 3> at = {ci, cj, ck};
          std::vector<int> tet = {gridId(at[0], at[1], at[2])};
          for (int s = 0; s < 3; ++s) {
            ++at[p[s]];
            tet.push_back(gridId(at[0], at[1], at[2]));
          }
          const Eigen::Vector3d& x0 = reference[tet[0]];
          Eigen::Matrix3d edges;
          for (int s = 0; s < 3; ++s) edges.col(s) = reference[tet[s + 1]] - x0;
          if (edges.determinant() < 0) std::swap(tet[1], tet[2]);
          cornerLists.push_back(tet);
        }
      }

  std::uniform_real_distribution<double> u(-amount, amount);
  for (int attempt = 0; attempt < 100; ++attempt) {
    PatchMesh m;
    m.type = t;
    m.elements = cornerLists;
    std::vector<Eigen::Vector3d> ref = reference;
    for (const auto& x : reference) m.nodes.push_back(x + Eigen::Vector3d(u(rng), u(rng), u(rng)));
    // Mid-edge nodes, shared between elements, at the midpoints of the moved corners.
    std::map<std::pair<int, int>, int> midNode;
    for (auto& el : m.elements) {
      const std::vector<int> corners = el;
      for (const auto& e : midEdges(t)) {
        const int p = corners[e[0]], q = corners[e[1]];
        auto [it, inserted] = midNode.try_emplace({std::min(p, q), std::max(p, q)}, int(m.nodes.size()));
        if (inserted) {
          m.nodes.push_back(0.5 * (m.nodes[p] + m.nodes[q]));
          ref.push_back(0.5 * (ref[p] + ref[q]));
        }
        el.push_back(it->second);
      }
    }
    for (const auto& x : ref) m.onBoundary.push_back(x.minCoeff() == 0.0 || x.maxCoeff() == double(kCells));
    bool allValid = true;
    for (int e = 0; e < static_cast<int>(m.elements.size()); ++e) allValid = allValid && valid(t, m.coords(e));
    if (allValid) return m;
  }
  throw std::runtime_error("distortedBlock: no valid mesh found");
}

}  // namespace cyclone::fe::test
