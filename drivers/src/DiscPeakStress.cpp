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
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/fatigue/SectorVibration.hpp"
#include "cyclone/hbm/HarmonicLoads.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/hbm/ProjectedReceptance.hpp"
#include "cyclone/mesh/ExodusIO.hpp"
#include "cyclone/post/SvgPlot.hpp"
#include "cyclone/scenes/SceneSection.hpp"
#include "SceneStages.hpp"
#include "cyclone/disc/DiscPeakVibration.hpp"

namespace cyclone::scenes {

namespace {

// disc_response/peak_stress's own keys.
void readPeakStressKeys(SceneSection s, PeakStressSpec& spec) {
  const std::string margin = s.getString("margin", "true");
  if (margin != "true" && margin != "false") throw InputError(s.where("margin"), "must be true or false, got '" + margin + "'");
  spec.margin = margin == "true";
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
  // The stress unit from E: titanium-like moduli in MPa (mm-N-s-t) or Pa (SI).
  const double ratio = material.E / 113.8e3;
  double unitInMpa = 0;
  if (ratio > 0.3 && ratio < 3) unitInMpa = 1, spec.stressUnit = "MPa";
  else if (ratio > 0.3e6 && ratio < 3e6) unitInMpa = 1e-6, spec.stressUnit = "Pa";
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
      throw InputError(f.where("data"), "Ti-6Al-4V's strengths need the scene's stress unit, which E = " +
                                            std::to_string(material.E) +
                                            " does not tell (not titanium's 113.8 GPa in MPa or Pa): give "
                                            "ultimate_strength and endurance_limit");
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

std::string number(double v, int digits = 4) {
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

void writeFields(const std::string& path, const mesh::Mesh& mesh, const fatigue::SectorVibration& v,
                 const fatigue::FatigueMap* map, double hz) {
  mesh::ExodusResults r;
  mesh::ExodusResults::Step step;
  step.time = hz;
  const std::size_t nn = std::size_t(mesh.numNodes());
  auto add = [&](const std::string& name, std::vector<double> values) {
    r.nodalNames.push_back(name);
    step.nodal.push_back(std::move(values));
  };
  const char* xyz[] = {"x", "y", "z"};
  for (std::size_t k = 0; k < v.harmonics.size(); ++k) {
    const std::string h = "u_h" + std::to_string(v.harmonics[k]);
    for (int part = 0; part < (v.harmonics[k] == 0 ? 1 : 2); ++part)
      for (int d = 0; d < 3; ++d) {
        std::vector<double> values(nn);
        for (std::size_t n = 0; n < nn; ++n)
          values[n] = part == 0 ? v.displacement[k][n](d).real() : v.displacement[k][n](d).imag();
        add(h + (v.harmonics[k] == 0 ? "" : part == 0 ? "_re" : "_im") + "_" + xyz[d], std::move(values));
      }
  }
  if (map) {
    std::vector<double> mean(nn), alt(nn), principal(nn), top(nn), sf(nn);
    for (std::size_t n = 0; n < nn; ++n) {
      mean[n] = map->cycle[n].meanVonMises, alt[n] = map->cycle[n].alternatingVonMises;
      principal[n] = map->cycle[n].alternatingPrincipal, top[n] = map->cycle[n].maxVonMises;
      sf[n] = std::min(map->safetyFactor[n], 1e3);  // capped: an unloaded node's infinity spoils a colour map
    }
    add("sigma_mean_vm_signed", mean), add("sigma_alt_vm", alt), add("sigma_alt_principal", principal);
    add("sigma_max_vm", top), add("safety_factor", sf);
  }
  r.steps.push_back(std::move(step));
  mesh::writeExodus(path, mesh, r);
}

void writeAnimation(const std::string& path, const mesh::Mesh& mesh, const fatigue::SectorVibration& v, int steps,
                    double hz) {
  mesh::ExodusResults r;
  r.nodalNames = {"u_x", "u_y", "u_z", "sigma_vm"};
  const std::size_t nn = std::size_t(mesh.numNodes());
  for (int s = 0; s < steps; ++s) {
    const double theta = 2 * M_PI * s / steps;
    mesh::ExodusResults::Step step;
    step.time = s / (steps * hz);
    const auto u = v.displacementAt(theta);
    step.nodal.assign(4, std::vector<double>(nn));
    for (std::size_t n = 0; n < nn; ++n) {
      for (int d = 0; d < 3; ++d) step.nodal[std::size_t(d)][n] = u[n](d);
      step.nodal[3][n] = fatigue::vonMises(fatigue::stressAt(v.meanStress(n), v.alternatingStress(n), theta));
    }
    r.steps.push_back(std::move(step));
  }
  mesh::writeExodus(path, mesh, r);
}

void writeNodeTable(const std::string& path, const mesh::Mesh& mesh, const fatigue::FatigueMap& map,
                    const std::vector<std::size_t>& order) {
  AtomicFile file(path);
  std::ofstream csv(file.tempPath());
  csv.precision(8);
  csv << "node,x,y,z,mean_vm_signed,alternating_vm,alternating_principal,max_vm,safety_factor\n";
  for (auto n : order) {
    const auto& c = map.cycle[n];
    const auto& p = mesh.coords[n];
    csv << mesh.nodeIds[n] << "," << p[0] << "," << p[1] << "," << p[2] << "," << c.meanVonMises << ","
        << c.alternatingVonMises << "," << c.alternatingPrincipal << "," << c.maxVonMises << ","
        << map.safetyFactor[n] << "\n";
  }
  file.check(csv);
  file.commit();
}

void writeGoodmanPlot(const std::string& path, const fatigue::FatigueMap& map, const fatigue::FatigueMaterial& m,
                      const std::string& unit, const std::string& title) {
  post::SvgPlot plot(title, "mean stress, signed von Mises (" + unit + ")",
                     "alternating stress, von Mises (" + unit + ")");
  std::vector<double> lx, ly;
  const double lo = -0.2 * m.ultimateStrength;
  for (int i = 0; i <= 200; ++i) {
    const double s = lo + (m.ultimateStrength - lo) * i / 200.0;
    lx.push_back(s), ly.push_back(fatigue::allowableAlternating(s, m));
  }
  plot.addLine(lx, ly, "#c00", m.yieldStrength > 0 ? "modified Goodman" : "Goodman");
  std::vector<double> px, py;
  for (std::size_t n = 0; n < map.cycle.size(); ++n)
    px.push_back(map.cycle[n].meanVonMises), py.push_back(map.cycle[n].alternatingVonMises);
  plot.addMarkers(px, py, post::SvgPlot::palette(0), "nodes of the sector", 1.5);
  const auto& c = map.cycle[map.critical];
  plot.addMarkers({c.meanVonMises}, {c.alternatingVonMises}, "#000", "critical node", 4.0);
  plot.addText(c.meanVonMises, c.alternatingVonMises, "  n = " + number(map.safetyFactor[map.critical], 3));
  plot.write(path);
}

}  // namespace

void writePeakStress(const PeakStressSpec& spec, const mesh::Mesh& mesh, const DiscReducedModels& models,
                     const DiscModelSpec& modelSpec, const PeakPoint& point, double excitationScale,
                     const std::string& outDir, linalg::CommPtr comm, SceneSummary& summary) {
  if (!spec.run) return;
  Timer timer;
  const auto peak = disc::solveDiscPeakVibration(mesh, models, modelSpec, point, excitationScale,
                                                 spec.margin ? &spec.material : nullptr, comm);
  const auto& vibration = peak.vibration;
  const auto& map = peak.fatigue;
  const double modelError = peak.modelError;
  const double hz = point.omega / (2 * M_PI);

  if (comm->getRank() == 0) {
    writeFields(outDir + "/disc_peak_response.exo", mesh, vibration, map ? &*map : nullptr, hz);
    writeAnimation(outDir + "/disc_peak_vibration.exo", mesh, vibration, spec.animationSteps, hz);
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
    std::vector<std::size_t> order(map->cycle.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](auto a, auto b) { return map->safetyFactor[a] < map->safetyFactor[b]; });
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
    // After the headline peak, when there is one.
    const bool headline = !summary.computed.empty() && summary.computed.front().rfind("friction-damped peak", 0) == 0;
    summary.computed.insert(summary.computed.begin() + (headline ? 1 : 0), line.str());
    log::info(line.str());
    if (comm->getRank() == 0) {
      writeNodeTable(outDir + "/disc_peak_stress.csv", mesh, *map, order);
      writeGoodmanPlot(outDir + "/disc_goodman.svg", *map, m, spec.stressUnit,
                       "Goodman-Haigh diagram at " + point.what);
    }
    summary.written.push_back(outDir + "/disc_peak_stress.csv");
    summary.written.push_back(outDir + "/disc_goodman.svg");
  }
  summary.stages.push_back({"sector vibration and stress at the peak (" + std::to_string(peak.harmonics) +
                                " harmonics, full FE solves)",
                            timer.seconds(), check.str()});
}

}  // namespace cyclone::scenes
