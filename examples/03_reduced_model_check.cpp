// Example 3: reduced models of the built-in sector at its shroud contact and mid-blade
// nodes, one per nodal diameter, the one of ND 3 checked against the full FE compliance.
//   example_reduced_model_check   (the models cached in ./reduced_models)
#include <cstdio>

#include "cyclone/disc/DiscReducedModels.hpp"
#include "cyclone/fe/Environment.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

using namespace cyclone;

int main(int argc, char** argv) {
  Environment env(argc, argv);

  // 1. The sector: the built-in shrouded sector of a 24-sector disc, coarse.
  mesh::ShroudedSectorParameters p;
  p.meshSize = 12.0;
  const auto mesh = mesh::generateShroudedSector(p);

  // 2. What the models are: Petrov's hybrid model (20 modes and the exact static
  //    correction) on the nonlinear prestress at 10 000 rpm, cantilevered (the shroud
  //    free, its contacts to be added by the harmonic balance), titanium, bore held.
  disc::DiscModelSpec spec;
  spec.sectors = p.sectors;
  spec.rpm = 10000;
  spec.kind = disc::ReducedModelKind::Hybrid;
  spec.modes = 20;
  spec.checkNodalDiameter = 3;  // compared with the complex FE solve at 12 frequencies
  const auto models = disc::buildDiscReducedModels(mesh, spec, {1, 2, 3}, "reduced_models", env.comm());

  // 3. The check: |A| at the mid-blade node, reduced against full, and the relative
  //    error of the whole compliance matrix at each frequency.
  const auto& c = models.check;
  for (std::size_t i = 0; i < c.hz.size(); ++i)
    std::printf("%9.2f Hz  reduced %.6e  full %.6e  error %.2e\n", c.hz[i], c.reduced[i], c.full[i], c.error[i]);
  std::printf("%zu retained nodes, models for %zu nodal diameters (%d built, %d reused) in %.1f s\n",
              models.retainedNodes.size(), models.models.size(), models.built, models.reused, models.seconds);

  // 4. The hybrid model's error is that of the modes left out beyond the static
  //    correction: small across the first five families.
  const bool ok = c.nodalDiameter == 3 && !c.hz.empty() && c.maxError() < 1e-3;
  std::printf("largest error %.2e: %s\n", c.maxError(), ok ? "reduced model check: ok" : "reduced model check: FAILED");
  return ok ? 0 : 1;
}
