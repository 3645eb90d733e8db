#pragma once
// The demo's default disc as the disc programs under regression/ build it (the built-in
// sector at 10 000 rpm, EO 3, 20 N of excitation), its shroud contact law per node pair
// (kn = kt = 1e4 N/mm and 500 N a pair: at mesh size 6 the same interface as the demo
// scene's law per unit area within 7 %): one definition for the verifications and the
// benchmarks that time its curves, so all of them measure the same disc at any mesh.
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/disc/DiscHarmonicBalance.hpp"
#include "cyclone/disc/DiscReducedModels.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

namespace cyclone::demo_disc {

/// A program argument's comma-separated list of harmonic counts ("6,12,24").
inline std::vector<int> harmonicLevels(const char* argument) {
  std::vector<int> levels;
  std::stringstream list(argument);
  for (std::string item; std::getline(list, item, ',');) levels.push_back(std::atoi(item.c_str()));
  return levels;
}

inline disc::DiscModelSpec demoDiscModels(const mesh::ShroudedSectorParameters& p) {
  disc::DiscModelSpec models;
  models.sectors = p.sectors;
  models.rpm = 10000;
  return models;
}

/// The reduced models of the nodal diameters engine order 3 reaches with harmonics
/// 0..maxHarmonic, built into (or read from) `cache`.
inline disc::DiscReducedModels demoDiscReducedModels(const mesh::Mesh& mesh, const mesh::ShroudedSectorParameters& p,
                                                     int maxHarmonic, const std::string& cache, linalg::CommPtr comm) {
  std::vector<int> all;
  for (int h = 0; h <= maxHarmonic; ++h) all.push_back(h);
  return disc::buildDiscReducedModels(mesh, demoDiscModels(p), disc::nodalDiametersFor(p.sectors, 3, all), cache,
                                      comm);
}

/// Harmonics 0..maxHarmonic.
inline disc::DiscResponseSpec demoDiscResponse(int maxHarmonic, double preload = 500.0) {
  disc::DiscResponseSpec spec;
  spec.engineOrder = 3;
  spec.harmonics.clear();
  for (int h = 0; h <= maxHarmonic; ++h) spec.harmonics.push_back(h);
  spec.contact.law = disc::ShroudContactSpec::Law::PerPair;
  spec.contact.kn = spec.contact.kt = 1e4;
  spec.contact.preload = preload;
  spec.excitation.amplitude = 20.0;
  return spec;
}

/// Harmonics 0..maxHarmonic with the demo scene's contact law: per unit area of the shroud
/// face, kn = kt = 5000 N/mm^3, `preload` N over the face (20 kN: mostly closed, sliding).
inline disc::DiscResponseSpec demoSceneResponse(int maxHarmonic, double preload = 20000.0) {
  disc::DiscResponseSpec spec = demoDiscResponse(maxHarmonic);
  spec.contact.law = disc::ShroudContactSpec::Law::PerArea;
  spec.contact.kn = spec.contact.kt = 5000.0;
  spec.contact.preload = preload;
  return spec;
}

/// The frequency curve of `spec` at another preload over 2 % about `omega` (rad/s): what a
/// continued peak at that preload is checked against (a friction-damped peak is 0.1 % wide
/// at most; the whole range took up to 19 s a curve).
inline disc::DiscForcedResponse curveAboutPeak(const mesh::Mesh& mesh, const disc::DiscReducedModels& models,
                                               disc::DiscResponseSpec spec, double preload, double omega,
                                               disc::DiscSweepOptions sweep) {
  spec.contact.preload = preload;
  sweep.fromHz = 0.99 * omega / (2 * M_PI), sweep.toHz = 1.01 * omega / (2 * M_PI);
  return disc::solveDiscForcedResponse(mesh, models, spec, sweep);
}

}  // namespace cyclone::demo_disc
