#include "StuckSliderState.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cyclone::hbm::detail {

namespace {

struct Candidate {
  Eigen::Vector2d z;
  std::vector<int> active;
};

// The two crossings of circles i and j (none when they do not meet).
std::vector<Eigen::Vector2d> crossings(const Eigen::Vector2d& ci, double ri, const Eigen::Vector2d& cj, double rj) {
  const Eigen::Vector2d d = cj - ci;
  const double L = d.norm();
  if (L == 0 || L > ri + rj || L < std::abs(ri - rj)) return {};
  const double a = (ri * ri - rj * rj + L * L) / (2 * L);
  const double h = std::sqrt(std::max(ri * ri - a * a, 0.0));
  const Eigen::Vector2d e = d / L, p = ci + a * e, n(-e.y(), e.x());
  return {p + h * n, p - h * n};
}

}  // namespace

StuckSliderState nearestStuckState(const Eigen::Matrix2Xd& centres, const Eigen::VectorXd& radii) {
  const int n = static_cast<int>(radii.size());
  double scale = radii.maxCoeff();
  for (int i = 0; i < n; ++i) scale = std::max(scale, centres.col(i).norm());
  const double tol = 1e-12 * scale;
  auto violation = [&](const Eigen::Vector2d& z, int i) { return (z - centres.col(i)).norm() - radii(i); };

  // The minimum-norm point of the intersection of the disks in `set`.
  auto solveSubset = [&](const std::vector<int>& set, Candidate& best) {
    std::vector<Candidate> candidates;
    candidates.push_back({Eigen::Vector2d::Zero(), {}});
    for (int i : set) {
      const double c = centres.col(i).norm();
      if (c > radii(i)) candidates.push_back({centres.col(i) * (1 - radii(i) / c), {i}});
    }
    for (std::size_t a = 0; a < set.size(); ++a)
      for (std::size_t b = a + 1; b < set.size(); ++b)
        for (const Eigen::Vector2d& z : crossings(centres.col(set[a]), radii(set[a]), centres.col(set[b]),
                                                  radii(set[b])))
          candidates.push_back({z, {set[a], set[b]}});
    bool found = false;
    double bestNorm = std::numeric_limits<double>::infinity();
    for (const Candidate& c : candidates) {
      bool ok = true;
      for (int i : set) ok = ok && violation(c.z, i) <= tol;
      if (ok && c.z.norm() < bestNorm) bestNorm = c.z.norm(), best = c, found = true;
    }
    return found;
  };

  // Add the most violated disk to the basis and re-solve: the optimum's norm
  // rises strictly each time, so the search ends (a handful of steps in practice).
  Candidate current{Eigen::Vector2d::Zero(), {}};
  for (int iteration = 0; iteration < 4 * n + 10; ++iteration) {
    int worst = -1;
    double worstViolation = tol;
    for (int i = 0; i < n; ++i)
      if (const double v = violation(current.z, i); v > worstViolation) worstViolation = v, worst = i;
    if (worst < 0) return {true, current.z, current.active};
    std::vector<int> set = current.active;
    set.push_back(worst);
    if (!solveSubset(set, current)) return {};  // these disks alone have no common point
  }
  return {};  // not reached for a valid input; treat as slipping
}

namespace {

struct Minimax {
  Eigen::Vector2d z;
  double value;  // max over the subset of |z - c_i| - r_i
};

// The minimiser of the largest violation over the disks in `set` (at most 4): the best
// of the candidates with 1 (a centre), 2 (on the segment of two centres, equal
// violations) and 3 (equal violations of three, by Newton) active disks.
Minimax minimaxOfSubset(const Eigen::Matrix2Xd& c, const Eigen::VectorXd& r, const std::vector<int>& set) {
  Minimax best{Eigen::Vector2d::Zero(), std::numeric_limits<double>::infinity()};
  auto consider = [&](const Eigen::Vector2d& z) {
    if (!z.allFinite()) return;
    double v = -std::numeric_limits<double>::infinity();
    for (int i : set) v = std::max(v, (z - c.col(i)).norm() - r(i));
    if (v < best.value) best = {z, v};
  };
  const std::size_t n = set.size();
  for (std::size_t a = 0; a < n; ++a) consider(c.col(set[a]));
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      const Eigen::Vector2d d = c.col(set[b]) - c.col(set[a]);
      const double L = d.norm();
      if (L == 0) continue;
      consider(c.col(set[a]) + std::clamp((L + r(set[a]) - r(set[b])) / 2, 0.0, L) * d / L);
    }
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      for (std::size_t e = b + 1; e < n; ++e) {
        const int k[3] = {set[a], set[b], set[e]};
        Eigen::Vector3d x;  // (z, t): |z - c_k| - r_k = t for the three
        x.head<2>() = (c.col(k[0]) + c.col(k[1]) + c.col(k[2])) / 3, x(2) = 0;
        for (int it = 0; it < 50; ++it) {
          Eigen::Matrix3d J;
          Eigen::Vector3d F;
          for (int q = 0; q < 3; ++q) {
            const Eigen::Vector2d g = x.head<2>() - c.col(k[q]);
            const double gn = std::max(g.norm(), 1e-300);
            F(q) = gn - r(k[q]) - x(2);
            J.row(q) << g(0) / gn, g(1) / gn, -1;
          }
          const Eigen::Vector3d dx = J.fullPivLu().solve(F);
          x -= dx;
          if (!(dx.norm() > 1e-15 * (1 + x.norm()))) break;
        }
        consider(x.head<2>());
      }
  return best;
}

}  // namespace

Eigen::Vector2d leastViolatingState(const Eigen::Matrix2Xd& centres, const Eigen::VectorXd& radii) {
  const int n = static_cast<int>(radii.size());
  double scale = radii.maxCoeff();
  for (int i = 0; i < n; ++i) scale = std::max(scale, centres.col(i).norm());
  const double tol = 1e-13 * scale;
  std::vector<int> basis{0};
  Minimax current{centres.col(0), -radii(0)};
  // As for the nearest stuck state: add the most violating disk and re-solve on the
  // basis and it; the minimax value rises each time.
  for (int iteration = 0; iteration < 4 * n + 10; ++iteration) {
    int worst = -1;
    double worstValue = current.value + tol;
    for (int i = 0; i < n; ++i)
      if (const double v = (current.z - centres.col(i)).norm() - radii(i); v > worstValue) worstValue = v, worst = i;
    if (worst < 0) break;
    std::vector<int> set = basis;
    set.push_back(worst);
    current = minimaxOfSubset(centres, radii, set);
    basis.clear();
    for (int i : set)
      if ((current.z - centres.col(i)).norm() - radii(i) >= current.value - tol) basis.push_back(i);
  }
  return current.z;
}

}  // namespace cyclone::hbm::detail
