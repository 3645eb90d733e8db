#include "cyclone/disc/ShroudContactPatches.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "cyclone/core/Error.hpp"

namespace cyclone::disc {

namespace {

double weightOf(const std::vector<int>& group, const std::vector<double>& weights) {
  double w = 0;
  for (int i : group) w += weights[std::size_t(i)];
  return w;
}

// The group's two halves of about equal weight across its principal axis of largest
// weighted spread (a shroud face is a thin plane: that axis lies in it).
std::pair<std::vector<int>, std::vector<int>> bisect(std::vector<int> group, const std::vector<Eigen::Vector3d>& points,
                                                     const std::vector<double>& weights) {
  const double total = weightOf(group, weights);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int i : group) mean += weights[std::size_t(i)] * points[std::size_t(i)];
  mean /= total;
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for (int i : group) {
    const Eigen::Vector3d d = points[std::size_t(i)] - mean;
    spread += weights[std::size_t(i)] * d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(spread);
  const Eigen::Vector3d axis = eig.eigenvectors().col(2);  // the largest eigenvalue's
  // Ties broken by index: the same mesh gives the same patches.
  std::sort(group.begin(), group.end(), [&](int a, int b) {
    const double pa = axis.dot(points[std::size_t(a)] - mean), pb = axis.dot(points[std::size_t(b)] - mean);
    return pa != pb ? pa < pb : a < b;
  });
  // The weighted median: the first cut where the lower part reaches half the weight,
  // leaving at least one point on each side.
  std::size_t cut = 1;
  double below = weights[std::size_t(group[0])];
  while (cut + 1 < group.size() && below + 0.5 * weights[std::size_t(group[cut])] < 0.5 * total)
    below += weights[std::size_t(group[cut++])];
  return {std::vector<int>(group.begin(), group.begin() + long(cut)), std::vector<int>(group.begin() + long(cut), group.end())};
}

}  // namespace

std::vector<std::vector<int>> splitIntoPatches(const std::vector<Eigen::Vector3d>& points,
                                               const std::vector<double>& weights, int count) {
  const int n = int(points.size());
  if (weights.size() != points.size())
    throw InputError("contact/patches", "one weight per contact point is needed");
  if (count < 1 || count > n)
    throw InputError("contact/patches", "must lie in 1.." + std::to_string(n) + " (the face's contact node pairs), got " +
                                            std::to_string(count));
  for (double w : weights)
    if (!(std::isfinite(w) && w > 0))
      throw InputError("contact/patches", "every contact point needs a positive finite weight (its tributary area)");
  std::vector<std::vector<int>> groups(1, std::vector<int>(std::size_t(n)));
  std::iota(groups[0].begin(), groups[0].end(), 0);
  while (int(groups.size()) < count) {
    // The heaviest group with two points or more (one always exists while count <= n).
    std::size_t heaviest = groups.size();
    for (std::size_t g = 0; g < groups.size(); ++g)
      if (groups[g].size() >= 2 &&
          (heaviest == groups.size() || weightOf(groups[g], weights) > weightOf(groups[heaviest], weights)))
        heaviest = g;
    auto [lower, upper] = bisect(std::move(groups[heaviest]), points, weights);
    groups[heaviest] = std::move(lower);
    groups.push_back(std::move(upper));
  }
  for (auto& g : groups) std::sort(g.begin(), g.end());
  return groups;
}

}  // namespace cyclone::disc
