#include "cyclone/disc/ShroudContactLaw.hpp"

#include <cmath>
#include <sstream>

#include "cyclone/core/Error.hpp"
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
        throw InputError(std::string("contact/") + name, "must be finite and >= 0, got " + std::to_string(value));
  const std::size_t n = pairs.right.size();
  ShroudContactValues out;
  out.stiffnessFactor.assign(n, 1.0);
  out.preloadShare.assign(n, 1.0 / double(n));
  if (perArea) {
    const auto t = mesh::tributaryAreas(mesh, pairs.right, "contact/right_node_set '" + contact.rightSet +
                                                               "' (contact law per area)");
    out.area = t.area, out.totalArea = t.total;
    for (std::size_t i = 0; i < n; ++i) out.stiffnessFactor[i] = t.area[i], out.preloadShare[i] = t.area[i] / t.total;
  }
  for (std::size_t i = 0; i < n; ++i) {
    out.kn.push_back(contact.kn * out.stiffnessFactor[i]);
    out.kt.push_back(contact.kt * out.stiffnessFactor[i]);
    out.preload.push_back(perArea ? contact.preload * out.preloadShare[i] : contact.preload);
    out.totalKn += out.kn.back(), out.totalKt += out.kt.back(), out.totalPreload += out.preload.back();
  }
  std::ostringstream text;
  text.precision(4);
  text << "shroud contact: " << n << " node pairs, ";
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

}  // namespace cyclone::disc
