#include "cyclone/post/PeakStressFiles.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/NumberText.hpp"
#include "cyclone/mesh/ExodusIO.hpp"
#include "cyclone/post/SvgPlot.hpp"

namespace cyclone::post {

namespace {

std::string number(double v, int digits = 4) { return numberText(v, digits); }

}  // namespace

void writePeakResponseExodus(const std::string& path, const mesh::Mesh& mesh, const fatigue::SectorVibration& v,
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

void writeVibrationAnimationExodus(const std::string& path, const mesh::Mesh& mesh, const fatigue::SectorVibration& v, int steps,
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

void writeFatigueNodeTable(const std::string& path, const mesh::Mesh& mesh, const fatigue::FatigueMap& map,
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

void writeGoodmanDiagram(const std::string& path, const fatigue::FatigueMap& map, const fatigue::FatigueMaterial& m,
                      const std::string& unit, const std::string& title) {
  SvgPlot plot(title, "mean stress, signed von Mises (" + unit + ")",
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
  plot.addMarkers(px, py, SvgPlot::palette(0), "nodes of the sector", 1.5);
  const auto& c = map.cycle[map.critical];
  plot.addMarkers({c.meanVonMises}, {c.alternatingVonMises}, "#000", "critical node", 4.0);
  plot.addText(c.meanVonMises, c.alternatingVonMises, "  n = " + number(map.safetyFactor[map.critical], 3));
  plot.write(path);
}

}  // namespace cyclone::post
