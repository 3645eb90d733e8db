// disc_response's own keys (engine order, harmonics, samples, contact, gap, excitation,
// response node sets, hysteresis contacts) read onto disc::DiscResponseSpec.
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "DiscStages.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/mesh/Mesh.hpp"
#include "cyclone/scenes/SceneSection.hpp"

namespace cyclone::scenes {

namespace {

Eigen::Vector3d toEigen(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

}  // namespace

DiscResponseSpec readDiscResponseSpec(SceneSection& d) {
  DiscResponseSpec spec;
  spec.engineOrder = d.getInt("engine_order", 0);
  if (!d.has("engine_order"))
    throw InputError(d.where("engine_order"), d.requiredText("engine_order") + " (the excitation's engine order)");
  spec.harmonics = readHarmonicList(d, 3);
  // The engine-order excitation acts on harmonic 1: [0, 2] was refused only after the
  // reduced models, as "excitation: harmonic 1 is not in the harmonic set" (a fifth probe).
  if (std::find(spec.harmonics.begin(), spec.harmonics.end(), 1) == spec.harmonics.end())
    throw InputError(d.where("harmonics"), "must contain harmonic 1: the engine-order excitation acts on it");
  spec.samples = d.getInt("samples", 0);
  {
    // Enough for the highest harmonic given (a harmonics check or target raises it, and
    // its samples with it where the count is automatic), and for the friction law: the
    // 3D contact's sampled law is first order in the spacing (4e-3 of the force at 256
    // samples), so below 32 its error passes a few percent (3 samples traced a curve of
    // nonsense, exit 0; issue 49).
    int top = 0;
    for (int h : spec.harmonics) top = std::max(top, h);
    constexpr int kFrictionSamples = 32;
    const int least = std::max(2 * top + 1, kFrictionSamples);
    if (spec.samples != 0 && (spec.samples < least || spec.samples > kMaxSamples))
      throw InputError(d.where("samples"), std::to_string(spec.samples) + ": must lie in " + std::to_string(least) +
                                               ".." + std::to_string(kMaxSamples) + " time samples per period (2 H + 1 "
                                               "resolve harmonic H = " + std::to_string(top) + ", and the friction "
                                               "contacts need at least 32; 0 or left out: the automatic count)");
  }
  auto c = d.section("contact");
  auto& ct = spec.contact;
  ct.leftSet = c.getString("left_node_set", ct.leftSet);
  ct.rightSet = c.getString("right_node_set", ct.rightSet);
  // kn, kt and preload per node pair, or per unit area of the interface (kn, kt in N/mm^3,
  // preload the interface's total load): ShroudContactSpec::Law.
  const std::string law = c.getString("law", "per_area");
  if (law == "per_area") ct.law = disc::ShroudContactSpec::Law::PerArea;
  else if (law == "per_pair") {
    // The thesis' stiffness per contact element (Scalvini 2021, Table 8.4), the per-area
    // default's source, where kn or kt is not given.
    ct.law = disc::ShroudContactSpec::Law::PerPair;
    ct.kn = ct.kt = 1e4;
  } else
    throw InputError(c.where("law"), "'" + law + "': per_pair (kn, kt in N/mm and the preload per node pair) or "
                                     "per_area (kn, kt in N/mm^3 and the interface's total preload in N, spread by "
                                     "each node's tributary area)");
  ct.kn = c.getDouble("kn", ct.kn);
  ct.kt = c.getDouble("kt", ct.kt);
  ct.mu = c.getDouble("mu", ct.mu);
  ct.preload = c.getDouble("preload", ct.preload);
  ct.patches = c.getInt("patches", 0);  // its range against the face's pairs: disc::shroudContactValues
  if (c.has("normal") != c.has("tangent"))
    throw InputError(c.location(), "give both normal and tangent (the contact frame), or neither");
  if (c.has("normal")) ct.normal = toEigen(c.getVector3("normal", {0, 0, 0}));
  if (c.has("tangent")) ct.tangent = toEigen(c.getVector3("tangent", {0, 0, 0}));
  c.rejectUnknownKeys();
  if (d.has("gap")) {
    auto g = d.section("gap");
    spec.gap.pairs = g.getIntList("pairs", {});
    if (spec.gap.pairs.empty()) throw InputError(g.where("pairs"), "needs the contact pairs that are gap elements");
    spec.gap.kn = g.getDouble("kn", spec.gap.kn);
    spec.gap.clearance = g.getDouble("clearance", spec.gap.clearance);
    g.rejectUnknownKeys();
  }
  // The force is physics a forced response needs: not a silent 1 N (issue 49).
  if (!d.has("excitation"))
    throw InputError(d.where("excitation"), d.requiredText("excitation") +
                                                ": the force on each blade (node_set, direction, amplitude in the "
                                                "scene's force unit)");
  auto e = d.section("excitation");
  spec.excitation.nodeSet = e.getString("node_set", spec.excitation.nodeSet);
  spec.excitation.direction = toEigen(e.getVector3("direction", {0, 0, 1}));
  spec.excitation.amplitude = e.getDouble("amplitude", spec.excitation.amplitude);
  e.rejectUnknownKeys();
  spec.responseNodeSets = d.getStringList("response_node_sets", spec.responseNodeSets);
  return spec;
}

// disc_response/hysteresis_contacts, checked against the contact pairs (one element per pair).
std::vector<int> readHysteresisContacts(SceneSection& d, const mesh::Mesh& mesh, const DiscResponseSpec& spec) {
  const std::vector<int> contacts = d.getIntList("hysteresis_contacts", {});
  const int count = int(mesh.nodeSet(spec.contact.rightSet).size());
  for (int e : contacts)
    if (e < 0 || e >= count)
      throw InputError(d.where("hysteresis_contacts"), "contact " + std::to_string(e) + " is not one of the " +
                                                           std::to_string(count) +
                                                           " shroud contact pairs (0-based, as in disc_frc_contacts.csv)");
  return contacts;
}

}  // namespace cyclone::scenes
