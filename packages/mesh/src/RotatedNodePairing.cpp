#include "cyclone/mesh/RotatedNodePairing.hpp"

#include <algorithm>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <sstream>
#include <unordered_map>

#include "cyclone/core/Error.hpp"

namespace cyclone::mesh {

double outermostRadius(const Mesh& mesh, const RotationAxis& axis) {
  const Eigen::Vector3d d = axis.direction.normalized();
  double radius = 0;
  for (const auto& x : mesh.coords) {
    const Eigen::Vector3d r = Eigen::Vector3d(x[0], x[1], x[2]) - axis.point;
    radius = std::max(radius, (r - r.dot(d) * d).norm());
  }
  return radius;
}

bool sameRotationLine(const RotationAxis& a, const RotationAxis& b) {
  const Eigen::Vector3d da = a.direction.normalized(), db = b.direction.normalized();
  const Eigen::Vector3d offset = b.point - a.point;
  const double size = std::max(1.0, offset.norm());
  return !(da.cross(db).norm() > 1e-9 || da.cross(offset).norm() > 1e-9 * size);
}

Point rotate(const Point& p, double angle, const RotationAxis& axis) {
  // Rodrigues' formula about a unit axis through axis.point.
  const double len = std::sqrt(axis.direction[0] * axis.direction[0] + axis.direction[1] * axis.direction[1] +
                               axis.direction[2] * axis.direction[2]);
  const double k[3] = {axis.direction[0] / len, axis.direction[1] / len, axis.direction[2] / len};
  const double v[3] = {p[0] - axis.point[0], p[1] - axis.point[1], p[2] - axis.point[2]};
  const double c = std::cos(angle), s = std::sin(angle);
  const double kv = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
  const double kxv[3] = {k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0]};
  Point r;
  for (int d = 0; d < 3; ++d) r[d] = axis.point[d] + v[d] * c + kxv[d] * s + k[d] * kv * (1 - c);
  return r;
}

namespace {
struct CellHash {
  std::size_t operator()(const std::array<long long, 3>& c) const {
    return std::size_t(c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL);
  }
};
double distance(const Point& a, const Point& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}
}  // namespace

NodePairing pairRotatedNodes(const Mesh& mesh, const std::vector<Index>& left, const std::vector<Index>& right,
                             double angle, const RotationAxis& axis, double tolerance, const std::string& what) {
  const std::string where = mesh.source + ", " + what;
  if (left.empty() || right.empty()) throw InputError(where, "a side face has no nodes");
  // Spatial hash of the right face: candidates lie in the 27 cells around a point.
  const double h = tolerance > 0 ? tolerance : 1e-12;
  auto cellOf = [&](const Point& p) {
    return std::array<long long, 3>{(long long)std::floor(p[0] / h), (long long)std::floor(p[1] / h),
                                    (long long)std::floor(p[2] / h)};
  };
  std::unordered_map<std::array<long long, 3>, std::vector<Index>, CellHash> grid;
  for (Index n : right) grid[cellOf(mesh.coords[n])].push_back(n);

  NodePairing out;
  std::vector<std::pair<Index, double>> failed;  // left node, nearest distance found (inf if none)
  std::vector<int> used(mesh.numNodes(), 0);
  for (Index n : left) {
    const Point target = rotate(mesh.coords[n], angle, axis);
    const auto c = cellOf(target);
    Index best = -1;
    double bestDist = std::numeric_limits<double>::infinity();
    for (long long i = -1; i <= 1; ++i)
      for (long long j = -1; j <= 1; ++j)
        for (long long k = -1; k <= 1; ++k) {
          auto it = grid.find({c[0] + i, c[1] + j, c[2] + k});
          if (it == grid.end()) continue;
          for (Index m : it->second) {
            const double d = distance(target, mesh.coords[m]);
            if (d < bestDist) bestDist = d, best = m;
          }
        }
    if (best < 0 || bestDist > tolerance) {
      if (best < 0) {  // report the true nearest distance, searched the slow way for the message only
        for (Index m : right) bestDist = std::min(bestDist, distance(target, mesh.coords[m]));
      }
      failed.emplace_back(n, bestDist);
      continue;
    }
    ++used[best];
    out.left.push_back(n);
    out.right.push_back(best);
    out.maxDistance = std::max(out.maxDistance, bestDist);
  }
  std::size_t doubled = 0;
  for (Index m : right) doubled += used[m] > 1;
  if (!failed.empty() || left.size() != right.size() || doubled) {
    std::ostringstream msg;
    msg << "side faces do not match under the rotation by " << angle * 180 / M_PI << " degrees (tolerance "
        << tolerance << "): " << left.size() << " left nodes, " << right.size() << " right nodes, "
        << failed.size() << " left nodes without a partner";
    if (doubled) msg << ", " << doubled << " right nodes claimed twice";
    for (std::size_t i = 0; i < failed.size() && i < 5; ++i)
      msg << (i ? "; " : ": ") << "node " << mesh.nodeIds[failed[i].first] << " nearest partner at "
          << failed[i].second;
    if (failed.size() > 5) msg << "; ...";
    throw InputError(where, msg.str());
  }
  return out;
}

}  // namespace cyclone::mesh
