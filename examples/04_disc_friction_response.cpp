// Example 4: the friction-damped forced response of the built-in disc under engine
// order 3, its headline peak, and a study of the shroud contacts' preload.
//   example_disc_friction_response
#include <cmath>
#include <cstdio>

#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/disc/DiscParameterStudy.hpp"
#include "cyclone/fe/Environment.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

using namespace cyclone;

int main(int argc, char** argv) {
  Environment env(argc, argv);

  // 1. The sector and its reduced models (hybrid, 20 modes, 10 000 rpm) for the nodal
  //    diameters engine order 3's harmonics 0..2 live on (the check adds harmonic 2).
  mesh::ShroudedSectorParameters p;
  p.meshSize = 12.0;
  const auto mesh = mesh::generateShroudedSector(p);
  disc::DiscModelSpec models;
  models.sectors = p.sectors;
  models.rpm = 10000;
  // 3D friction at the shroud: kn = kt = 4167 N/mm^3 per unit area of the interface, mu = 0.4
  // (the defaults); the preload is the interface's total, spread by each node's area.
  disc::DiscResponseSpec spec;
  spec.engineOrder = 3;
  spec.harmonics = {0, 1};
  spec.contact.preload = 100.0;       // N
  spec.excitation.amplitude = 20.0;   // N at the mid-blade node, axial
  const auto nds = disc::nodalDiametersFor(p.sectors, spec.engineOrder, {0, 1, 2});
  const auto reduced = disc::buildDiscReducedModels(mesh, models, nds, "reduced_models", env.comm());

  // 2. The frequency curve over the range the resonance estimate gives, its peak found
  //    again with harmonics 0..2: the headline, converged or labelled an estimate.
  disc::DiscSweepOptions sweep;
  sweep.harmonicsCheckTo = 2;
  const auto response = disc::solveDiscForcedResponse(mesh, reduced, spec, sweep);
  // How the curve ended and whether its peak converged are types to branch on; the
  // sentences are for a person.
  const bool wholeRange = response.curve.branch.end == continuation::BranchEnd::RangeEnd;
  std::printf("%zu points, ended: %s (%s)\nheadline: %s; %s\n", response.curve.branch.points.size(),
              continuation::branchEndName(response.curve.branch.end), response.curve.branch.stopReason.c_str(),
              disc::convergenceName(response.headline.convergence), response.headline.text.c_str());
  if (response.headline.convergence == disc::DiscHeadline::Convergence::Estimate)
    std::printf("the peak is an estimate: raise harmonicsCheckTo for a converged one\n");

  // 3. The preload study: one curve per preload over the same range (100 N is the
  //    reference: its curve, not traced again).
  const auto study = disc::studyDisc(mesh, reduced, spec, response, disc::DiscStudyParameter::Preload,
                                     {25.0, 100.0, 400.0}, sweep);

  // 4. What friction must give: the peak between the linear limits (shroud free and
  //    contacts stuck), rising in frequency as more preload holds the contacts.
  const double hz = response.curve.peakOmega / (2 * M_PI);
  bool ok = wholeRange && response.headline.found() && response.estimate &&
            hz >= response.estimate->freeHz && hz <= response.estimate->stuckHz;
  double lastHz = 0;
  for (const auto& c : study) {
    const double f = c.curve.peakOmega / (2 * M_PI);
    std::printf("preload %6.1f N: peak %.5f mm at %.2f Hz (%zu points)\n", c.value, c.curve.peak, f,
                c.curve.branch.points.size());
    ok = ok && c.curve.branch.finished && f > lastHz;
    lastHz = f;
  }
  std::printf("free %.2f Hz, stuck %.2f Hz: %s\n", response.estimate ? response.estimate->freeHz : 0.0,
              response.estimate ? response.estimate->stuckHz : 0.0, ok ? "disc friction response: ok" : "FAILED");
  return ok ? 0 : 1;
}
