#include "cyclone/disc/ShroudContactLaw.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/NumberText.hpp"
#include "cyclone/disc/ShroudContactPatches.hpp"
#include "cyclone/mesh/TributaryArea.hpp"

namespace cyclone::disc {

ShroudContactValues shroudContactValues(const mesh::Mesh& mesh, const mesh::NodePairing& pairs,
                                        const ShroudContactSpec& contact) {
  const bool perArea = contact.law == ShroudContactSpec::Law::PerArea;
  const char* stiffnessUnit = perArea ? " N/mm^3" : " N/mm";
  // (Per pair the friction law itself refuses bad values, naming the contact.)
  if (perArea)
    for (const auto& [name, value] : {std::pair<const char*, double>{"kn", contact.kn}, {"kt", contact.kt},
                                      {"preload", contact.preload}})
      if (!(std::isfinite(value) && value >= 0))
        throw InputError(std::string("contact/") + name, "must be finite and >= 0, got " + numberText(value));
  const std::size_t n = pairs.right.size();
  if (contact.patches < 0 || std::size_t(contact.patches) > n)
    throw InputError("contact/patches", "must lie in 0.." + std::to_string(n) + " (0: every node pair a contact; " +
                                            std::to_string(n) + " pairs on this face), got " +
                                            std::to_string(contact.patches));
  ShroudContactValues out;
  out.pairs = int(n);
  // Each pair's own share: its tributary area (PerArea) or one (PerPair); patches weigh
  // their pairs' motions by it.
  std::vector<double> pairArea(n, 1.0);
  double totalArea = double(n);
  if (perArea || contact.patches > 0) {
    const auto t = mesh::tributaryAreas(mesh, pairs.right, "contact/right_node_set '" + contact.rightSet + "' (" +
                                                               (perArea ? "contact law per area" : "contact patches") +
                                                               ")");
    if (perArea) pairArea = t.area, totalArea = t.total;
    if (contact.patches > 0) {
      std::vector<Eigen::Vector3d> points;
      for (auto node : pairs.right) points.emplace_back(mesh.coords[node][0], mesh.coords[node][1], mesh.coords[node][2]);
      out.members = splitIntoPatches(points, t.area, contact.patches);
    }
  }
  if (out.members.empty())
    for (std::size_t i = 0; i < n; ++i) out.members.push_back({int(i)});
  for (const auto& m : out.members) {
    double share = 0;
    for (int i : m) share += pairArea[std::size_t(i)];
    std::vector<double> w;
    for (int i : m) w.push_back(pairArea[std::size_t(i)] / share);
    out.memberWeights.push_back(std::move(w));
    if (perArea) out.area.push_back(share);
    // Per area the contact's stiffness is the law's times its area and its preload the
    // total's share; per pair both are the pair's times the pairs it holds.
    out.stiffnessFactor.push_back(share);
    out.preloadFactor.push_back(perArea ? share / totalArea : share);
    out.kn.push_back(contact.kn * out.stiffnessFactor.back());
    out.kt.push_back(contact.kt * out.stiffnessFactor.back());
    out.preload.push_back(contact.preload * out.preloadFactor.back());
    out.totalKn += out.kn.back(), out.totalKt += out.kt.back(), out.totalPreload += out.preload.back();
  }
  if (perArea) out.totalArea = totalArea;
  std::ostringstream text;
  text.precision(4);
  text << "shroud contact: " << n << " node pairs, ";
  if (contact.patches > 0) text << "in " << out.members.size() << " patches (each one contact on its mean motion), ";
  if (perArea)
    text << "law per unit area over " << out.totalArea << " mm^2 (kn " << contact.kn << ", kt " << contact.kt
         << stiffnessUnit << ", normal load " << contact.preload << " N in all)";
  else
    text << "law per node pair (kn " << contact.kn << ", kt " << contact.kt << stiffnessUnit << ", preload "
         << contact.preload << " N each)";
  text << "; the interface: kn " << out.totalKn << ", kt " << out.totalKt << " N/mm, normal load " << out.totalPreload
       << " N, mu " << contact.mu;
  out.text = text.str();
  return out;
}

std::vector<rom::RetainedMean> shroudPatchMeans(const mesh::NodePairing& pairs, const ShroudContactValues& values,
                                                const ShroudContactSpec& contact) {
  if (contact.patches < 1)
    throw InputError("contact/patches", "the patches' mean motions are retained only where the face is split into "
                                        "patches (patches >= 1)");
  std::vector<rom::RetainedMean> out;
  for (std::size_t c = 0; c < values.members.size(); ++c)
    for (const bool right : {true, false}) {
      rom::RetainedMean mean;
      mean.name = "patch " + std::to_string(c) + (right ? " right" : " left");
      for (std::size_t m = 0; m < values.members[c].size(); ++m) {
        const auto i = std::size_t(values.members[c][m]);
        mean.nodes.push_back(right ? pairs.right[i] : pairs.left[i]);
        mean.weights.push_back(values.memberWeights[c][m]);
      }
      out.push_back(std::move(mean));
    }
  return out;
}

DiscModelSpec retainingPatchMeans(DiscModelSpec models, const mesh::Mesh& mesh, const ShroudContactSpec& contact) {
  if (contact.patches < 1)
    throw InputError("contact_dofs", "patch_means needs disc_response/contact/patches >= 1 (the face split into "
                                     "patches whose mean motions the models retain)");
  const auto pairs = shroudContactPairs(mesh, models.sectors, models.axis, contact);
  models.retainedMeans = shroudPatchMeans(pairs, shroudContactValues(mesh, pairs, contact), contact);
  auto& sets = models.retainedNodeSets;
  for (const auto& face : {contact.leftSet, contact.rightSet}) sets.erase(std::remove(sets.begin(), sets.end(), face), sets.end());
  if (sets.empty())
    throw InputError("retained_node_sets", "retains only the contact faces, whose patch means contact_dofs: "
                                           "patch_means retains instead: add the excitation's node set");
  return models;
}

}  // namespace cyclone::disc
