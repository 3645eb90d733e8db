#include "cyclone/continuation/BranchTurn.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cyclone::continuation {

namespace {

double distance(const BranchPoint& a, const BranchPoint& b) {
  return std::sqrt((b.x - a.x).squaredNorm() + (b.parameter - a.parameter) * (b.parameter - a.parameter));
}

// Distance from c to the segment a-b in (x, p).
double distanceToSegment(const BranchPoint& a, const BranchPoint& b, const BranchPoint& c) {
  const double L2 = (b.x - a.x).squaredNorm() + (b.parameter - a.parameter) * (b.parameter - a.parameter);
  double t = 0;
  if (L2 > 0) t = ((c.x - a.x).dot(b.x - a.x) + (c.parameter - a.parameter) * (b.parameter - a.parameter)) / L2;
  t = std::clamp(t, 0.0, 1.0);
  const BranchPoint q{a.parameter + t * (b.parameter - a.parameter), a.x + t * (b.x - a.x)};
  return distance(q, c);
}

}  // namespace

double turnStep(const BranchPoint& a, const BranchPoint& b) { return distance(a, b); }

double turnCosine(const BranchPoint& a, const BranchPoint& b, const BranchPoint& c) {
  const double n1 = distance(a, b), n2 = distance(b, c);
  if (n1 == 0 || n2 == 0) return 1.0;
  return ((b.x - a.x).dot(c.x - b.x) + (b.parameter - a.parameter) * (c.parameter - b.parameter)) / (n1 * n2);
}

bool branchJump(const BranchPoint& a, const BranchPoint& b, const BranchPoint& c) {
  const double before = distance(a, b);
  return before > 0 && distance(b, c) > kJumpRatio * before;
}

int retracedFrom(const std::vector<const BranchPoint*>& path, const BranchPoint& c) {
  const int n = int(path.size());
  if (n < 2) return -1;
  const BranchPoint& b = *path[std::size_t(n - 1)];
  const double step = distance(b, c);
  if (step == 0) return -1;
  for (int i = std::max(0, n - 51); i + 1 < n; ++i) {
    const BranchPoint &s0 = *path[std::size_t(i)], &s1 = *path[std::size_t(i + 1)];
    const double length = distance(s0, s1);
    if (length == 0 || distanceToSegment(s0, s1, c) >= 0.1 * std::max(step, length)) continue;
    const double against = ((c.x - b.x).dot(s1.x - s0.x) + (c.parameter - b.parameter) * (s1.parameter - s0.parameter)) /
                           (step * length);
    if (against >= -0.5) continue;
    // The kink: walking back from b, the last point whose step still went along s0 -> s1.
    int k = n - 1;
    while (k > i + 1) {
      const BranchPoint &p0 = *path[std::size_t(k - 1)], &p1 = *path[std::size_t(k)];
      const double along = (p1.x - p0.x).dot(s1.x - s0.x) + (p1.parameter - p0.parameter) * (s1.parameter - s0.parameter);
      if (along > 0) break;
      --k;
    }
    return k;
  }
  return -1;
}

bool landsOnTracedPath(const std::vector<const BranchPoint*>& path, const BranchPoint& c) {
  const int n = int(path.size());
  if (n < 3) return false;
  const BranchPoint& b = *path[std::size_t(n - 1)];
  const double step = distance(b, c);
  // The regular step: creeping steps at a kink cluster points, and a step back
  // inside the cluster is the retrace check's business.
  double regular = step;
  for (int i = std::max(1, n - 10); i < n; ++i)
    regular = std::max(regular, distance(*path[std::size_t(i - 1)], *path[std::size_t(i)]));
  double behind = distance(*path[std::size_t(n - 2)], b);  // arclength from path[i + 1] to b
  for (int i = n - 3; i >= std::max(0, n - 51); --i) {
    const BranchPoint &s0 = *path[std::size_t(i)], &s1 = *path[std::size_t(i + 1)];
    const double length = distance(s0, s1);
    if (length > 0 && distanceToSegment(s0, s1, c) < 0.1 * std::max(step, length)) {
      const double t =
          std::clamp(((c.x - s0.x).dot(s1.x - s0.x) + (c.parameter - s0.parameter) * (s1.parameter - s0.parameter)) /
                         (length * length),
                     0.0, 1.0);
      if (behind + (1 - t) * length > kLandingArclengthRatio * regular) return true;
    }
    behind += length;
  }
  return false;
}

}  // namespace cyclone::continuation
