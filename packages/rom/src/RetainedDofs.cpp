#include "cyclone/rom/RetainedDofs.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cyclone/core/Error.hpp"

namespace cyclone::rom {
namespace {

void check(const std::string& set, const RetainedDirections& d) {
  const std::string where = "retained/" + set;
  if (d.directions.empty()) throw InputError(where + "/directions", "no directions chosen (0, 1, 2 of the frame)");
  for (std::size_t i = 0; i < d.directions.size(); ++i) {
    if (d.directions[i] < 0 || d.directions[i] > 2)
      throw InputError(where + "/directions", std::to_string(d.directions[i]) + " is not a direction (0, 1 or 2)");
    if (std::count(d.directions.begin(), d.directions.end(), d.directions[i]) > 1)
      throw InputError(where + "/directions", "direction " + std::to_string(d.directions[i]) + " is repeated");
  }
  if (!d.frame.allFinite()) throw InputError(where + "/frame", "has entries that are not finite numbers");
  // Orthonormal rows: a frame that is not would make T^T A T a different quantity.
  const double defect = (d.frame * d.frame.transpose() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (defect > 1e-9) {
    std::ostringstream s;
    s.precision(3);
    s << "the 3 vectors must be orthonormal (unit length, mutually perpendicular); |R R^T - I| = " << defect;
    throw InputError(where + "/frame", s.str());
  }
}

}  // namespace

RetainedDofSet retainedDofs(const mesh::Mesh& mesh, const std::vector<std::string>& sets,
                            const std::map<std::string, RetainedDirections>& directions,
                            std::vector<RetainedMean> means) {
  if (sets.empty() && means.empty()) throw InputError("retained", "no retained node sets or means given");
  for (const auto& [name, d] : directions) {
    if (std::find(sets.begin(), sets.end(), name) == sets.end())
      throw InputError("retained/" + name, "directions given for a node set that is not retained");
    check(name, d);
  }
  RetainedDofSet out;
  std::vector<const RetainedDirections*> chosen;  // per node: the set's choice that retained it
  const RetainedDirections all;
  for (const auto& name : sets) {
    const auto it = directions.find(name);
    const RetainedDirections& d = it == directions.end() ? all : it->second;
    for (mesh::Index n : mesh.nodeSet(name)) {  // InputError naming a missing or empty set
      const auto at = std::find(out.nodes.begin(), out.nodes.end(), n);
      if (at != out.nodes.end()) {
        const auto& first = *chosen[std::size_t(at - out.nodes.begin())];
        if (first.directions != d.directions || first.frame != d.frame)
          throw InputError("retained/" + name, "node " + std::to_string(mesh.nodeIds.at(std::size_t(n))) +
                                                   " is also in an earlier retained set with other directions or "
                                                   "another frame");
        continue;
      }
      out.nodes.push_back(n);
      out.frames.push_back(d.frame);
      out.rotated.push_back(d.frame != Eigen::Matrix3d::Identity());
      chosen.push_back(&d);
    }
  }
  for (std::size_t i = 0; i < out.nodes.size(); ++i)
    for (int dir : chosen[i]->directions) out.dofs.emplace_back(int(i), dir);
  for (std::size_t m = 0; m < means.size(); ++m) {
    const RetainedMean& mean = means[m];
    const std::string where = "retained/means/" + (mean.name.empty() ? std::to_string(m) : mean.name);
    if (mean.nodes.empty()) throw InputError(where, "has no nodes");
    if (mean.weights.size() != mean.nodes.size())
      throw InputError(where, std::to_string(mean.weights.size()) + " weights for " + std::to_string(mean.nodes.size()) +
                                  " nodes");
    for (std::size_t i = 0; i < mean.nodes.size(); ++i) {
      if (mean.nodes[i] < 0 || mean.nodes[i] >= mesh.numNodes())
        throw InputError(where, "node index " + std::to_string(mean.nodes[i]) + " is not in the mesh");
      if (std::count(mean.nodes.begin(), mean.nodes.end(), mean.nodes[i]) > 1)
        throw InputError(where, "node " + std::to_string(mesh.nodeIds.at(std::size_t(mean.nodes[i]))) + " appears twice");
      if (!(std::isfinite(mean.weights[i]) && mean.weights[i] > 0))
        throw InputError(where, "every weight must be positive and finite (node " +
                                    std::to_string(mesh.nodeIds.at(std::size_t(mean.nodes[i]))) + ")");
    }
    const int point = int(out.nodes.size() + m);
    for (int dir = 0; dir < 3; ++dir) out.dofs.emplace_back(point, dir);
  }
  out.means = std::move(means);
  return out;
}

}  // namespace cyclone::rom
