#include "cyclone/cyclic/CyclicSector.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "cyclone/core/Error.hpp"

namespace cyclone::cyclic {

double CyclicSector::sectorAngle() const { return 2 * M_PI / sectors; }

Eigen::Matrix3d CyclicSector::rotation() const {
  Eigen::Vector3d a(axis.direction[0], axis.direction[1], axis.direction[2]);
  return Eigen::AngleAxisd(sectorAngle(), a.normalized()).toRotationMatrix();
}

void checkNodalDiameter(int sectors, int k) {
  if (k < 0 || k > sectors / 2)
    throw InputError("nodal diameter " + std::to_string(k),
                     "must lie in 0.." + std::to_string(sectors / 2) + " for " + std::to_string(sectors) +
                         " sectors (a nodal diameter d > N/2 is the same as N - d)");
}

CyclicSector makeCyclicSector(const mesh::Mesh& mesh, int sectors, const mesh::RotationAxis& axis,
                              const std::vector<std::string>& leftSets, const std::vector<std::string>& rightSets,
                              double tolerance) {
  if (sectors < 2) throw InputError(mesh.source, "cyclic symmetry needs at least 2 sectors, got " + std::to_string(sectors));
  const double dirNorm = std::sqrt(axis.direction[0] * axis.direction[0] + axis.direction[1] * axis.direction[1] +
                                   axis.direction[2] * axis.direction[2]);
  if (!(dirNorm > 0)) throw InputError(mesh.source, "cyclic symmetry axis direction is zero");
  if (leftSets.empty() || leftSets.size() != rightSets.size())
    throw InputError(mesh.source, "cyclic symmetry needs as many left as right side-face sets (at least one)");
  auto merged = [&](const std::vector<std::string>& names) {
    std::set<Index> nodes;
    for (const auto& name : names)
      for (auto n : mesh.nodeSet(name)) nodes.insert(n);
    return std::vector<Index>(nodes.begin(), nodes.end());
  };
  std::vector<Index> left = merged(leftSets), right = merged(rightSets);
  if (tolerance <= 0) {
    double size = 0;
    for (const auto& x : mesh.coords) size = std::max({size, std::abs(x[0]), std::abs(x[1]), std::abs(x[2])});
    tolerance = 1e-6 * size;
  }
  // A node on both faces must sit on the axis (it maps onto itself): pair it with itself.
  std::vector<Index> onBoth;
  std::set_intersection(left.begin(), left.end(), right.begin(), right.end(), std::back_inserter(onBoth));
  std::vector<Index> l, r;
  std::set_difference(left.begin(), left.end(), onBoth.begin(), onBoth.end(), std::back_inserter(l));
  std::set_difference(right.begin(), right.end(), onBoth.begin(), onBoth.end(), std::back_inserter(r));
  CyclicSector sector;
  sector.sectors = sectors;
  sector.axis = axis;
  std::string what = "cyclic side faces (";
  for (std::size_t i = 0; i < leftSets.size(); ++i) what += (i ? ", " : "") + leftSets[i] + "/" + rightSets[i];
  what += ")";
  if (!l.empty() || !r.empty()) {
    const auto pairing = mesh::pairRotatedNodes(mesh, l, r, 2 * M_PI / sectors, axis, tolerance, what);
    sector.left = pairing.left;
    sector.right = pairing.right;
    sector.maxMismatch = pairing.maxDistance;
  }
  for (Index n : onBoth) {
    const auto x = mesh::rotate(mesh.coords[n], 2 * M_PI / sectors, axis);
    const double d = std::sqrt(std::pow(x[0] - mesh.coords[n][0], 2) + std::pow(x[1] - mesh.coords[n][1], 2) +
                               std::pow(x[2] - mesh.coords[n][2], 2));
    if (d > tolerance)
      throw InputError(mesh.source + ", " + what,
                       "node " + std::to_string(mesh.nodeIds[n]) + " is on both side faces but not on the axis");
    sector.left.push_back(n);
    sector.right.push_back(n);
  }
  return sector;
}

}  // namespace cyclone::cyclic
