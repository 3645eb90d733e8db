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

}  // namespace cyclone::hbm::detail
