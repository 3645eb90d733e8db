#pragma once
// The demo's default disc as the disc programs under regression/ build it (the built-in
// sector at 10 000 rpm, EO 3, 20 N of excitation, the shroud preload the demo's 500 N):
// one definition for the verification that checks the demo's converged peak and the
// benchmark that times its curve, so both measure the same disc.
#include <vector>

#include "cyclone/disc/DiscHarmonicBalance.hpp"
#include "cyclone/disc/DiscReducedModels.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

namespace cyclone::demo_disc {

inline disc::DiscModelSpec demoDiscModels(const mesh::ShroudedSectorParameters& p) {
  disc::DiscModelSpec models;
  models.sectors = p.sectors;
  models.rpm = 10000;
  return models;
}

/// Harmonics 0..maxHarmonic.
inline disc::DiscResponseSpec demoDiscResponse(int maxHarmonic, double preload = 500.0) {
  disc::DiscResponseSpec spec;
  spec.engineOrder = 3;
  spec.harmonics.clear();
  for (int h = 0; h <= maxHarmonic; ++h) spec.harmonics.push_back(h);
  spec.contact.preload = preload;
  spec.excitation.amplitude = 20.0;
  return spec;
}

}  // namespace cyclone::demo_disc
