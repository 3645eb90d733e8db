// The disc scene's keys read into the disc library's specs and checked before any FE
// work (docs/scenes.md): reduced_model here, with the plan of the whole disc chain;
// disc_response's own keys in DiscResponseReaders.cpp.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <optional>
#include <sstream>

#include "DiscStages.hpp"
#include "cyclone/response/ForcedResponseChecks.hpp"
#include "cyclone/hbm/HarmonicSet.hpp"

#include <Teuchos_Comm.hpp>
#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/NumberText.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"
#include "cyclone/mesh/Mesh.hpp"
#include "cyclone/post/SvgPlot.hpp"
#include "cyclone/rom/HybridFrfModel.hpp"
#include "cyclone/disc/DiscHarmonicBalance.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/hbm/ElementStates.hpp"
#include "cyclone/disc/DiscParameterStudy.hpp"
#include "cyclone/disc/DiscReducedModels.hpp"
#include "cyclone/disc/ShroudContactLaw.hpp"
#include "cyclone/scenes/SceneSection.hpp"

namespace cyclone::scenes {

namespace {

DiscModelSpec readModelSpec(SceneSection& scene, SceneSection& r, const mesh::Mesh& mesh, int builtInSectors,
                            std::string& cache) {
  DiscModelSpec spec;
  spec.material = readMaterial(scene.section("material"));
  {
    auto c = scene.section("constraints");
    spec.fixedNodeSets = c.getStringList("fixed_node_sets", {});
    c.rejectUnknownKeys();
    if (spec.fixedNodeSets.empty())
      throw InputError(scene.where("constraints/fixed_node_sets"), "a disc response needs the disc held (e.g. [bore])");
  }
  {
    auto cy = scene.section("cyclic");
    spec.sectors = cy.getInt("sectors", builtInSectors);
    if (spec.sectors < 2) throw InputError(cy.where("sectors"), "is required (>= 2) for a mesh read from a file");
    spec.axis = readRotationAxis(cy);
    // The reduced models are cantilevered: the disc's faces cyclic, the shroud's free
    // (configuration and the shroud's faces are the modal analysis's).
    const auto faces = readCyclicFaces(cy);
    spec.leftSets = faces.discLeft, spec.rightSets = faces.discRight;
    const auto analyses = scene.getStringList("analysis", {});
    if (std::find(analyses.begin(), analyses.end(), "modal") == analyses.end())
      for (const char* key : {"configuration", "shroud_left_node_sets", "shroud_right_node_sets"})
        if (cy.has(key))
          log::warn(cy.where(key) + " is the modal analysis's (the reduced models are cantilevered: the disc's "
                                    "faces cyclic, the shroud's free for the contacts); this scene has none, so it is "
                                    "not used");
    cy.rejectUnknownKeys();
  }
  // The speed from loads (the static analysis's section, read whole so that its keys are
  // checked here too).
  analysis::StaticProblem loads;
  readStaticLoads(scene.section("loads"), mesh, loads);
  const double loadsRpm = loads.speedRpm;
  // The models' prestress spins the sector about the cyclic axis: a speed's axis given
  // elsewhere in loads changed nothing without a word (issue 49's fourth probe).
  if (!mesh::sameRotationLine(spec.axis, loads.axis))
    throw InputError(scene.where("loads/axis_direction"),
                     "the speed's axis differs from the cyclic symmetry's (cyclic/axis_point, cyclic/axis_direction): "
                     "the disc's reduced models spin about the cyclic axis; give the same axis in both, or leave "
                       "loads' out");
  spec.kind = disc::reducedModelKindFromName(r.getString("kind", "hybrid"), r.where("kind"));
  spec.retainedNodeSets = r.getStringList("retained_node_sets", spec.retainedNodeSets);
  if (spec.retainedNodeSets.empty())
    throw InputError(r.where("retained_node_sets"), "is empty: a reduced model needs the node sets it keeps "
                                                    "(the contact faces and the excited node; leave it out for them)");
  for (const auto& name : spec.retainedNodeSets) r.underKey("retained_node_sets", [&] { mesh.nodeSet(name); });
  spec.modes = r.getInt("modes", spec.modes);
  // The eigen-solver's space, about 3 modes vectors, must fit in the sector's DOFs: 10000
  // reached Anasazi and came back as its "Num Blocks must be strictly positive" (issue 49).
  if (spec.modes < 1) throw InputError(r.where("modes"), "must be at least 1, got " + std::to_string(spec.modes));
  if (const long nodes = long(mesh.numNodes()); spec.modes > nodes / 2)
    throw InputError(r.where("modes"), std::to_string(spec.modes) + " is more than half the sector's " +
                                           std::to_string(nodes) + " nodes: the eigen-solver's space of about 3 x "
                                           "modes vectors must fit in its 3 x nodes DOFs");
  spec.omega0 = r.getDouble("omega0", spec.omega0);
  // Before the prestress and the models (-1 was refused after them; issue 49 probe).
  if (!(spec.omega0 >= 0 && std::isfinite(spec.omega0)))
    throw InputError(r.where("omega0"), "must be >= 0 (rad/s; 0 for a held sector: the static correction's "
                                        "expansion point)");
  spec.lossFactor = r.getDouble("loss_factor", spec.lossFactor);
  if (!(spec.lossFactor >= 0)) throw InputError(r.where("loss_factor"), "must be >= 0");
  // eta is the energy lost per radian over the energy stored: 1 already loses 2 pi times
  // the stored energy a cycle, no structure's damping. 1e6 failed later as a frequency
  // range's fault (issue 49's fourth probe).
  if (spec.lossFactor > 1)
    throw InputError(r.where("loss_factor"), numberText(spec.lossFactor) + " is above 1: a structure's loss factor "
                                             "(2 x its damping ratio at resonance) is a few thousandths to a few "
                                             "hundredths");
  spec.rpm = r.getDouble("speed_rpm", loadsRpm);
  if (!(spec.rpm >= 0)) throw InputError(r.where("speed_rpm"), "must be >= 0");
  checkCentrifugalStrain(spec.material, spec.rpm, mesh, spec.axis,
                         r.has("speed_rpm") ? r.where("speed_rpm") : scene.where("loads/speed_rpm"),
                         scene.where("mesh"));
  spec.prestress = readPrestressKind(r, "nonlinear");
  cache = r.getString("cache", "reuse");
  if (cache != "reuse" && cache != "rebuild" && cache != "off")
    throw InputError(r.where("cache"), "use reuse (read a model whose inputs match), rebuild or off");
  return spec;
}

}  // namespace

DiscPlan readDiscPlan(SceneSection& scene, SceneSection& r, SceneSection& d, const mesh::Mesh& mesh,
                      int builtInSectors, bool forcedResponse, const std::string& outDir, bool requireNodalDiameters) {
  DiscPlan plan;
  std::string cache;
  plan.modelSpec = readModelSpec(scene, r, mesh, builtInSectors, cache);
  const int sectors = plan.modelSpec.sectors;
  auto& spec = plan.spec;
  if (forcedResponse) {
    spec = readDiscResponseSpec(d);
    plan.peakStudies = readPeakStudies(d.section("peak_studies"), spec, plan.modelSpec.lossFactor, plan.modelSpec.rpm);
    plan.peakStress = readPeakStressSpec(d, scene.section("material"), plan.modelSpec.material);
    const int maxHarmonic = *std::max_element(spec.harmonics.begin(), spec.harmonics.end());
    const HarmonicsTargetKeys target = readHarmonicsTarget(d, 48);
    plan.harmonicsCheckTo = readHarmonicsCheckTo(d, maxHarmonic, target);
    plan.harmonicsTolerance = target.tolerance;
    if (spec.engineOrder >= 1 && spec.engineOrder < sectors) {
      plan.nds = disc::nodalDiametersForCheckedCurve(sectors, spec.engineOrder, spec.harmonics, plan.harmonicsCheckTo);
      // And the time domain's: it integrates every sector the engine order tells apart
      // (DiscPeakInTime.hpp), whose phases harmonics 0..N / gcd(EO, N) - 1 reach (without
      // them the check failed after the curve: "no model for nodal diameter 12" with H = 3);
      // so does the sweep in time.
      if (d.has("time_domain_check") || d.has("time_domain_sweep")) {
        if (plan.modelSpec.kind == disc::ReducedModelKind::FullFe)
          throw InputError(d.where(d.has("time_domain_check") ? "time_domain_check" : "time_domain_sweep"),
                           "needs reduced models with modes (reduced_model/kind hybrid, truncation, guyan or "
                           "craig_bampton): the time domain integrates their modes, and a full FE model has none");
        std::vector<int> everyPhase;
        for (int h = 0; h < sectors / std::gcd(spec.engineOrder, sectors); ++h) everyPhase.push_back(h);
        plan.nds = disc::nodalDiametersFor(sectors, spec.engineOrder, everyPhase);
      }
      plan.modelSpec.checkNodalDiameter = disc::nodalDiametersFor(sectors, spec.engineOrder, {1}).front();
    } else {  // engine-order errors before any FE work
      DiscReducedModels none;
      none.sectors = sectors;
      disc::makeDiscForcedResponse(mesh, none, spec);  // throws the explained InputError
    }
    if (r.has("nodal_diameters"))
      throw InputError(r.where("nodal_diameters"), "is chosen by disc_response (engine order and harmonics)");
    // The contact (faces that do not pair under the sector rotation, a law per area whose
    // faces carry no area, the friction and gap values), the excitation and the node sets
    // named are refused before any FE work, under the scene's key.
    try {
      disc::checkDiscResponse(mesh, sectors, plan.modelSpec.axis, spec, plan.modelSpec.material.E);
    } catch (const InputError& e) {
      for (const char* section : {"contact", "gap", "excitation"})
        if (e.where().rfind(section, 0) == 0) throw InputError(d.where(e.where()), e.problem());
      throw;
    }
    // The contact faces' DOFs in the models: every face node, or each patch's mean motion
    // (a static correction of one load case per patch direction, not per face node DOF).
    const std::string contactDofs = r.getString("contact_dofs", "nodes");
    if (contactDofs == "patch_means") {
      try {
        plan.modelSpec = disc::retainingPatchMeans(plan.modelSpec, mesh, spec.contact);
      } catch (const InputError& e) {
        throw InputError(r.where(e.where()), e.problem());
      }
    } else if (contactDofs != "nodes") {
      throw InputError(r.where("contact_dofs"), "use nodes (every contact face node, the default) or patch_means "
                                                "(each contact patch's mean motion)");
    }
    r.underKey("retained_node_sets", [&] {
      disc::checkRetainedNodeSets(mesh, plan.modelSpec.retainedNodeSets, spec, !plan.modelSpec.retainedMeans.empty());
    });
    // The friction solve's cost at the highest harmonic the curve or its check reaches,
    // known from the contact pairs before any FE work (harmonics 500 on the demo's disc
    // was refused only after its reduced models were built): a 3D contact per pair, or
    // per patch.
    {
      const int top = std::max(maxHarmonic, plan.harmonicsCheckTo);
      const hbm::HarmonicSet set = hbm::HarmonicSet::upTo(top);
      const int pairs = spec.contact.patches > 0 ? spec.contact.patches : int(mesh.nodeSet(spec.contact.rightSet).size());
      const int samples = spec.samples > 0 ? spec.samples : disc::discAutomaticSamples(set);
      std::ostringstream what;
      what << "harmonics up to " << top << " on " << pairs << (spec.contact.patches > 0 ? " shroud contact patches" : " shroud contact pairs");
      // Named by the key that asks for the top level: the check's (harmonics_check_to 1000 was
      // refused as 'harmonics' of H = 1, issue 49's sixth probe) or the curve's.
      const char* costKey = plan.harmonicsCheckTo <= maxHarmonic ? "harmonics"
                            : target.tolerance > 0                ? "harmonics_max"
                                                                  : "harmonics_check_to";
      response::checkElementJacobianCost(samples, set.numCoefficients(), std::vector<int>(std::size_t(pairs), 3),
                                         what.str(), d.where(costKey));
      // A sample count far above the automatic one: said with its cost on the curve's harmonics.
      if (spec.samples > 0) {
        const hbm::HarmonicSet curve(spec.harmonics);
        response::checkSamplesCost(spec.samples, disc::discAutomaticSamples(curve),
                                   "that harmonics up to " + std::to_string(maxHarmonic) +
                                       " and the friction contacts need (the automatic count)",
                                   curve, std::vector<int>(std::size_t(pairs), 3), d.where("samples"));
      }
    }
  } else {
    plan.nds = r.getIntList("nodal_diameters", {});
    if (plan.nds.empty() && requireNodalDiameters)
      throw InputError(r.where("nodal_diameters"), "is required when the scene builds reduced models alone");
  }
  plan.cacheDir = cache == "off" ? std::string() : outDir + "/reduced_models";
  plan.modelSpec.checkFrequencies = r.getInt("check_frequencies", 12);
  r.underKey("check_frequencies", [&] { disc::checkModelCheckFrequencies(plan.modelSpec.checkFrequencies); });
  plan.rebuildCache = cache == "rebuild" && !plan.cacheDir.empty();
  r.rejectUnknownKeys();
  disc::checkReducedModelCache(mesh, plan.modelSpec, plan.nds, plan.cacheDir);  // before the modes' and static work
  return plan;
}

}  // namespace cyclone::scenes
