#include "cyclone/cyclic/CyclicTransform.hpp"

#include <algorithm>
#include <functional>
#include <cmath>
#include <map>

#include "cyclone/core/Error.hpp"

namespace cyclone::cyclic {

using Term = fe::DofTransform::Term;

int copiesFor(int sectors, int k) { return (k == 0 || 2 * k == sectors) ? 1 : 2; }

namespace {

// i times a real-form vector [a; b] of one node (3 + 3 components): [-b; a].
Eigen::VectorXd timesI(const Eigen::VectorXd& v) {
  Eigen::VectorXd w(6);
  w << -v.tail(3), v.head(3);
  return w;
}

// An orthonormal basis of the same (i-invariant) null space as v, w = i v, v', i v', ...:
// the unknowns then pair as (x_a, x_b) like every other node's copies, which the
// travelling-wave solve needs (travellingWavePaired).
std::vector<Eigen::VectorXd> travellingWavePairedBasis(std::vector<Eigen::VectorXd> rest) {
  std::vector<Eigen::VectorXd> out;
  while (!rest.empty()) {
    Eigen::VectorXd v = rest.front();
    rest.erase(rest.begin());
    for (const auto& u : out) v -= u.dot(v) * u;
    if (v.norm() < 1e-10) continue;
    v.normalize();
    out.push_back(v);
    out.push_back(timesI(v));  // orthogonal to v (i is antisymmetric) and to all before
  }
  return out;
}

}  // namespace

bool travellingWavePaired(const fe::DofTransform& T) {
  if (T.copies() != 2 || T.numEquations() % 2 != 0) return false;
  // T i = i T on every DOF: copy b of (i x) is copy a of x, copy a of (i x) is -copy b of x,
  // with i x = (-x_{2m+1}, x_{2m}) on the unknowns.
  for (Index n = 0; n < T.numNodes(); ++n)
    for (int d = 0; d < 3; ++d) {
      std::map<long long, double> a, b;
      for (const auto& t : T.terms(n, d, 0)) a[t.equation] += t.coefficient;
      for (const auto& t : T.terms(n, d, 1)) b[t.equation] += t.coefficient;
      const auto coefficient = [](const std::map<long long, double>& m, long long eq) {
        const auto it = m.find(eq);
        return it == m.end() ? 0.0 : it->second;
      };
      for (const auto* m : {&a, &b})
        for (const auto& [eq, unused] : *m) {
          const long long ea = eq - eq % 2, eb = ea + 1;
          const double scale = std::max({std::abs(coefficient(a, ea)), std::abs(coefficient(a, eb)),
                                         std::abs(coefficient(b, ea)), std::abs(coefficient(b, eb)), 1e-300});
          if (std::abs(coefficient(b, eb) - coefficient(a, ea)) > 1e-12 * scale ||
              std::abs(coefficient(a, eb) + coefficient(b, ea)) > 1e-12 * scale)
            return false;
        }
    }
  return true;
}

namespace {

// The unknowns of a node on the axis: v = [a; b] must satisfy v = (c + i s) Q v in real
// form, and its fixed components vanish; the unknowns are coordinates in that null space.
std::vector<Eigen::VectorXd> axisNodeBasis(const Eigen::Matrix3d& Q, double c, double s, int copies,
                                           const char* fixed) {
  const int m = 3 * copies;
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(2 * m, m);
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  C.block(0, 0, 3, 3) = I - c * Q;
  if (copies == 2) {
    C.block(0, 3, 3, 3) = s * Q;
    C.block(3, 0, 3, 3) = -s * Q;
    C.block(3, 3, 3, 3) = I - c * Q;
  }
  int row = m;
  for (int d = 0; d < 3; ++d)
    if (fixed[d])
      for (int copy = 0; copy < copies; ++copy) C(row++, 3 * copy + d) = 1.0;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(C, Eigen::ComputeFullV);
  const auto& sv = svd.singularValues();
  std::vector<Eigen::VectorXd> basis;
  for (int j = 0; j < m; ++j)
    if (!(j < sv.size() && sv(j) > 1e-10)) basis.push_back(svd.matrixV().col(j));
  return copies == 2 ? travellingWavePairedBasis(basis) : basis;
}

// A right-face component of copy `copy` (direction d): the rotated, phase-shifted
// combination of its left-face partner's terms (`left`: per copy, per direction),
// repeated unknowns merged and exact zeros dropped.
std::vector<Term> rightFaceTerms(const Eigen::Matrix3d& Q, double c, double s, int copies, int copy, int d,
                                 const std::function<const std::vector<Term>&(int, int)>& left) {
  std::vector<Term> out;
  for (int e = 0; e < 3; ++e) {
    if (Q(d, e) == 0.0) continue;
    // copy a: c * a_L - s * b_L ; copy b: s * a_L + c * b_L
    const double fromA = copy == 0 ? c : s, fromB = copy == 0 ? -s : c;
    for (const auto& t : left(e, 0)) out.push_back({t.equation, Q(d, e) * fromA * t.coefficient});
    if (copies == 2)
      for (const auto& t : left(e, 1)) out.push_back({t.equation, Q(d, e) * fromB * t.coefficient});
  }
  std::vector<Term> merged;
  for (const auto& t : out) {
    auto it = std::find_if(merged.begin(), merged.end(), [&](const Term& m) { return m.equation == t.equation; });
    if (it == merged.end()) merged.push_back(t);
    else it->coefficient += t.coefficient;
  }
  merged.erase(std::remove_if(merged.begin(), merged.end(), [](const Term& t) { return t.coefficient == 0.0; }),
               merged.end());
  return merged;
}

}  // namespace

fe::DofTransform cyclicTransform(Index numNodes, const CyclicSector& sector, int k, const std::vector<char>& fixed,
                                 const Eigen::Matrix3d& Q) {
  checkNodalDiameter(sector.sectors, k);
  const int copies = copiesFor(sector.sectors, k);
  const double phi = k * 2 * M_PI / sector.sectors;
  // Exact values where they are exact, so k = 0 and N/2 stay real and clean.
  const double c = (k == 0) ? 1.0 : (2 * k == sector.sectors ? -1.0 : std::cos(phi));
  const double s = (copies == 1) ? 0.0 : std::sin(phi);

  std::vector<Index> masterOf(numNodes, -1);
  std::vector<char> onAxis(numNodes, 0);
  for (std::size_t i = 0; i < sector.left.size(); ++i) {
    if (sector.left[i] == sector.right[i]) onAxis[sector.left[i]] = 1;
    else masterOf[sector.right[i]] = sector.left[i];
  }

  // Per (node, component, copy): the terms; masters first, slaves composed after.
  std::vector<std::vector<Term>> terms(std::size_t(numNodes) * 3 * copies);
  auto at = [&](Index n, int d, int copy) -> std::vector<Term>& { return terms[(std::size_t(copy) * numNodes + n) * 3 + d]; };
  long long next = 0;
  for (Index n = 0; n < numNodes; ++n) {
    if (masterOf[n] >= 0) continue;
    if (!onAxis[n]) {
      for (int d = 0; d < 3; ++d)
        if (!fixed[3 * n + d])
          for (int copy = 0; copy < copies; ++copy) at(n, d, copy) = {{next++, 1.0}};
      continue;
    }
    for (const auto& v : axisNodeBasis(Q, c, s, copies, &fixed[3 * n])) {
      const long long eq = next++;
      for (int copy = 0; copy < copies; ++copy)
        for (int d = 0; d < 3; ++d)
          if (std::abs(v(3 * copy + d)) > 1e-14) at(n, d, copy).push_back({eq, v(3 * copy + d)});
    }
  }
  // Right face: rotated, phase-shifted combinations of the left face.
  for (Index n = 0; n < numNodes; ++n) {
    const Index L = masterOf[n];
    if (L < 0) continue;
    const auto left = [&](int e, int copy) -> const std::vector<Term>& { return at(L, e, copy); };
    for (int copy = 0; copy < copies; ++copy)
      for (int d = 0; d < 3; ++d) {
        auto merged = rightFaceTerms(Q, c, s, copies, copy, d, left);
        // A fixed component of a right-face node must follow from its partner's fixity.
        if (fixed[3 * n + d] && !merged.empty())
          throw InputError("cyclic constraint",
                           "the fixed degrees of freedom are not cyclically symmetric: right-face node index " +
                               std::to_string(n) + " has component " + std::to_string(d) +
                               " fixed but its left-face partner " + std::to_string(L) +
                               " moves in that direction (fix both or neither)");
        at(n, d, copy) = std::move(merged);
      }
  }
  fe::DofTransform T(numNodes, copies);
  for (int copy = 0; copy < copies; ++copy)
    for (Index n = 0; n < numNodes; ++n)
      for (int d = 0; d < 3; ++d) T.set(n, d, copy, std::move(at(n, d, copy)));
  T.finalize(next);
  return T;
}

fe::DofTransform cyclicTransform(const mesh::Mesh& mesh, const CyclicSector& sector, int k,
                                 const std::vector<std::string>& fixedSets) {
  std::vector<char> fixed(3 * mesh.numNodes(), 0);
  for (const auto& name : fixedSets)
    for (auto n : mesh.nodeSet(name)) fixed[3 * n] = fixed[3 * n + 1] = fixed[3 * n + 2] = 1;
  return cyclicTransform(mesh.numNodes(), sector, k, fixed, sector.rotation());
}

}  // namespace cyclone::cyclic
