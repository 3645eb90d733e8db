// The disc chain's last stage: the whole sector's vibration at the friction-damped
// peak (fatigue::recoverSectorVibration driven by the harmonic balance solution's
// loads), its stresses and the Goodman-Haigh margin, written as Exodus files a
// person opens in ParaView, a CSV of every node worst first, and the diagram.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <sstream>

#include <Teuchos_Comm.hpp>

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/NumberText.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/fatigue/SectorVibration.hpp"
#include "cyclone/hbm/HarmonicLoads.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/hbm/ProjectedReceptance.hpp"
#include "cyclone/mesh/ExodusIO.hpp"
#include "cyclone/post/PeakStressFiles.hpp"
#include "cyclone/scenes/SceneSection.hpp"
#include "DiscStages.hpp"
#include "cyclone/disc/DiscPeakVibration.hpp"
#include "cyclone/disc/DiscPointStates.hpp"
#include "cyclone/post/DiscPointFiles.hpp"

namespace cyclone::scenes {

namespace {

// disc_response/peak_stress's own keys.
void readPeakStressKeys(SceneSection s, PeakStressSpec& spec) {
  spec.margin = s.getChoice<bool>("margin", "true", {{"true", true}, {"false", false}}, [](const std::string& word) {
    return "must be true or false, got '" + word + "'";
  });
  spec.animationSteps = s.getInt("animation_steps", spec.animationSteps);
  spec.atHz = s.getDouble("at_hz", 0.0);
  if (s.has("at_hz") && !(spec.atHz > 0 && std::isfinite(spec.atHz)))
    throw InputError(s.where("at_hz"), "must be a positive frequency in Hz (leave it out for the peak)");
  if (spec.animationSteps < 4 || spec.animationSteps > 1000)
    throw InputError(s.where("animation_steps"), std::to_string(spec.animationSteps) +
                                                     ": one period needs 4..1000 time steps (about 32 play smoothly)");
  s.rejectUnknownKeys();
}

}  // namespace

PeakStressSpec readPeakStressSpec(SceneSection& discResponse, SceneSection materialSection,
                                  const fe::IsotropicElastic& material) {
  PeakStressSpec spec;
  // material/fatigue is read and checked whether or not a margin is asked for (a wrong
  // data name passed silently without peak_stress; issue 49).
  spec.run = discResponse.has("peak_stress");
  if (spec.run) readPeakStressKeys(discResponse.section("peak_stress"), spec);
  // The stress unit from the material's unit set (material/units).
  const double unitInMpa = fe::stressUnitInMpa(material.units);
  spec.stressUnit = fe::stressUnitName(material.units);
  auto f = materialSection.section("fatigue");
  const bool given = materialSection.has("fatigue");
  if (spec.run && spec.margin && !given)
    throw InputError(materialSection.where("fatigue"),
                     "disc_response/peak_stress asks for the Goodman margin (margin: true), which needs the "
                     "material's fatigue data: `data: Ti-6Al-4V` (ASM data sheet values), or ultimate_strength and "
                     "endurance_limit (and optionally yield_strength); or set peak_stress/margin: false");
  if (!given) return spec;
  const std::string data = f.getString("data", "");
  if (!data.empty()) {
    if (data != "Ti-6Al-4V")
      throw InputError(f.where("data"), "'" + data + "' is not known (Ti-6Al-4V is; or give the strengths)");
    if (unitInMpa == 0)
      throw InputError(f.where("data"), "Ti-6Al-4V's strengths need the scene's stress unit, which material/units: "
                                        "other does not tell: give ultimate_strength and endurance_limit in its units, "
                                        "or units: mm-N-s-t or SI");
    spec.material = fatigue::ti6al4vAnnealed(unitInMpa);
  } else {
    spec.material.name = material.name;
    spec.material.source = "the scene's material/fatigue";
  }
  spec.material.ultimateStrength = f.getDouble("ultimate_strength", spec.material.ultimateStrength);
  spec.material.enduranceLimit = f.getDouble("endurance_limit", spec.material.enduranceLimit);
  spec.material.yieldStrength = f.getDouble("yield_strength", spec.material.yieldStrength);
  spec.material.designCycles = f.getDouble("design_cycles", spec.material.designCycles);
  f.rejectUnknownKeys();
  spec.material.validate("material/fatigue");
  return spec;
}

namespace {

std::string number(double v, int digits = 4) { return numberText(v, digits); }

}  // namespace

void writePeakStress(const PeakStressSpec& spec, const mesh::Mesh& mesh, const DiscReducedModels& models,
                     const DiscModelSpec& modelSpec, const PeakPoint& point, double excitationScale,
                     bool afterHeadline, const std::string& outDir, linalg::CommPtr comm, SceneSummary& summary) {
  if (!spec.run) return;
  Timer timer;
  const auto peak = disc::solveDiscPeakVibration(mesh, models, modelSpec, point, excitationScale,
                                                 spec.margin ? &spec.material : nullptr, comm);
  const auto& vibration = peak.vibration;
  const auto& map = peak.fatigue;
  const double modelError = peak.modelError;
  const double hz = point.omega / (2 * M_PI);

  if (comm->getRank() == 0) {
    post::writePeakResponseExodus(outDir + "/disc_peak_response.exo", mesh, vibration, map ? &*map : nullptr, hz);
    post::writeVibrationAnimationExodus(outDir + "/disc_peak_vibration.exo", mesh, vibration, spec.animationSteps, hz);
  }
  summary.written.push_back(outDir + "/disc_peak_response.exo");
  summary.written.push_back(outDir + "/disc_peak_vibration.exo");
  std::ostringstream check;
  check << "the whole field at the retained DOFs differs from the harmonic balance solution by " << number(modelError, 3)
        << " of its largest motion (the reduced model's error at this point)";
  summary.computed.push_back("sector vibration at " + point.what + " (full FE solve per harmonic): " + check.str());
  log::info("sector vibration: " + check.str());
  if (map) {
    const auto& c = map->cycle[map->critical];
    const auto& p = mesh.coords[map->critical];
    const auto order = map->nodesWorstFirst();
    std::ostringstream line;
    const auto& m = spec.material;
    line << "fatigue margin at " << point.what << ": critical node " << mesh.nodeIds[map->critical] << " at ("
         << number(p[0]) << ", " << number(p[1]) << ", " << number(p[2]) << "), r = "
         << number(std::hypot(p[0], p[1])) << ": mean " << number(c.meanVonMises) << " " << spec.stressUnit
         << " (signed von Mises), alternating " << number(c.alternatingVonMises) << " " << spec.stressUnit
         << " (von Mises; largest principal " << number(c.alternatingPrincipal) << "); Goodman-Haigh safety factor "
         << number(map->safetyFactor[map->critical], 4) << " (" << m.name << ": S_u " << number(m.ultimateStrength)
         << ", S_e " << number(m.enduranceLimit);
    if (m.designCycles > 0) line << " at " << number(m.designCycles, 2) << " cycles";
    if (m.yieldStrength > 0) line << ", S_y " << number(m.yieldStrength);
    line << " " << spec.stressUnit << "; " << m.source << ")";
    if (!point.caveat.empty()) line << "; " << point.caveat;
    summary.computed.insert(summary.computed.begin() + (afterHeadline ? 1 : 0), line.str());
    log::info(line.str());
    if (comm->getRank() == 0) {
      post::writeFatigueNodeTable(outDir + "/disc_peak_stress.csv", mesh, *map, order);
      post::writeGoodmanDiagram(outDir + "/disc_goodman.svg", *map, m, spec.stressUnit,
                       "Goodman-Haigh diagram at " + point.what);
    }
    summary.written.push_back(outDir + "/disc_peak_stress.csv");
    summary.written.push_back(outDir + "/disc_goodman.svg");
  }
  summary.stages.push_back({"sector vibration and stress at the peak (" + std::to_string(peak.harmonics) +
                                " harmonics, full FE solves)",
                            timer.seconds(), check.str()});
}

// Contacts, loops, the period and the sector's stresses at one point: the converged
// peak (or peak_stress/at_hz for the stresses).
void peakOutputsStage(const mesh::Mesh& mesh, const DiscReducedModels& models, const DiscPlan& plan,
                      disc::DiscForcedResponse& solved, const std::vector<int>& hysteresisContacts,
                      const std::string& outDir, linalg::CommPtr comm, SceneSummary& summary) {
  auto& setup = solved.setup;
  const PeakPoint point = disc::referencePeakPoint(setup, solved.curve);
  if (comm->getRank() == 0) {
    // The contacts' table; the loops of the contacts asked for (by default the one that
    // dissipates most) and the output DOFs over the period.
    const auto states = disc::discPointStates(setup, point, hysteresisContacts);
    post::writeContactsCsv(outDir + "/disc_frc_contacts.csv", states);
    post::writeHysteresisFiles(outDir + "/disc_hysteresis.csv", outDir + "/disc_hysteresis.svg",
                               "Contact hysteresis at " + point.what, states);
    std::vector<std::string> names;
    for (int dof : setup.outputDofs) names.push_back(setup.dofNames[std::size_t(dof)]);
    post::writePeriodResponseFiles(outDir + "/disc_time_response.csv", outDir + "/disc_time_response.svg",
                                   "Response over one period at " + point.what, names, states);
  }
  for (const char* f : {"disc_frc_contacts.csv", "disc_hysteresis.csv", "disc_hysteresis.svg",
                        "disc_time_response.csv", "disc_time_response.svg"})
    summary.written.push_back(outDir + "/" + f);
  const auto& ps = plan.peakStress;
  // The reference stage put the headline first in the summary when it found a peak.
  const bool afterHeadline = solved.headline.found();
  if (ps.atHz > 0)
    writePeakStress(ps, mesh, models, plan.modelSpec, disc::referencePointAt(setup, solved.curve, ps.atHz),
                    setup.excitationScale, afterHeadline, outDir, comm, summary);
  else
    writePeakStress(ps, mesh, models, plan.modelSpec, point, setup.excitationScale, afterHeadline, outDir, comm,
                    summary);
}

}  // namespace cyclone::scenes
