// Benchmark (a program, not a test): the disc chain's cost at a mesh size, stage by
// stage, on the demo's disc (issue 48: the seed's scale is mesh size 1.25, 334k DOF):
// the mesh, the centrifugal prestress, the reduced model of each nodal diameter engine
// order 3 reaches (hybrid, 20 modes, the contacts' DOFs as every face node or as the
// patches' mean motions), and the friction curve (the demo's contact law per area at
// its 20 kN preload, 20 N at mid-blade, harmonics 0..H, the contacts in patches). Per
// stage its time and its peak resident memory (VmHWM, reset after each stage), from
// the library's progress lines; then the friction-damped peak.
//   build/regression/disc_chain_benchmark [mesh size (3)] [patches (27)] [contact DOFs: patch_means | nodes
//                                         (patch_means)] [H (5)] [cache dir ("": none)]
// The seed's scale (about 40 minutes and 18 GB on one core): disc_chain_benchmark 1.25 27 patch_means 7
#include <Tpetra_Core.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "cyclone/core/LogSink.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/disc/ShroudContactLaw.hpp"
#include "cyclone/fe/Environment.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "DemoDisc.hpp"

using namespace cyclone;

namespace {

// The process's peak resident memory since the last reset, GB; writing 5 to clear_refs
// resets it (Linux), so each stage's peak is its own.
double peakGbSinceReset() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::atof(line.c_str() + 6) / (1024.0 * 1024.0);
  return 0;
}
void resetPeak() { std::ofstream("/proc/self/clear_refs") << "5"; }

struct Stage {
  std::string name;
  double seconds = 0, peakGb = 0;
};

class StageClock {
public:
  void end(const std::string& name) {
    stages_.push_back({name, timer_.seconds(), peakGbSinceReset()});
    std::printf("  %-58s %9.1f s %7.2f GB\n", name.c_str(), stages_.back().seconds, stages_.back().peakGb);
    std::fflush(stdout);
    timer_.restart();
    resetPeak();
  }
  double total() const {
    double t = 0;
    for (const auto& s : stages_) t += s.seconds;
    return t;
  }
  double peak() const {
    double p = 0;
    for (const auto& s : stages_) p = std::max(p, s.peakGb);
    return p;
  }

private:
  Timer timer_;
  std::vector<Stage> stages_;
};

}  // namespace

int main(int argc, char** argv) {
  Environment env(argc, argv);
  const double meshSize = argc > 1 ? std::atof(argv[1]) : 3.0;
  const int patches = argc > 2 ? std::atoi(argv[2]) : 27;
  const std::string contactDofs = argc > 3 ? argv[3] : "patch_means";
  const int H = argc > 4 ? std::atoi(argv[4]) : 5;
  const std::string cache = argc > 5 ? argv[5] : "";
  std::setvbuf(stdout, nullptr, _IOLBF, 0);

  StageClock clock;
  resetPeak();
  // A stage ends where the library says it has: the prestress and each model's line.
  log::setSink([&](log::Level, const std::string& line) {
    if (line.rfind("nonlinear prestress at", 0) == 0 || line.rfind("linear prestress at", 0) == 0)
      clock.end("prestress");
    else if (line.rfind("reduced model ND", 0) == 0 && line.find(": built in") != std::string::npos)
      clock.end(line.substr(0, line.find(" (")));
  });

  mesh::ShroudedSectorParameters p;
  p.meshSize = meshSize;
  const auto mesh = mesh::generateShroudedSector(p);
  disc::DiscResponseSpec spec = demo_disc::demoDiscResponse(H);
  spec.contact.law = disc::ShroudContactSpec::Law::PerArea;
  spec.contact.kn = spec.contact.kt = 5000.0;
  spec.contact.preload = 20000.0;
  spec.contact.patches = patches;
  disc::DiscModelSpec models = demo_disc::demoDiscModels(p);
  models.checkFrequencies = 0;
  if (contactDofs == "patch_means") models = disc::retainingPatchMeans(models, mesh, spec.contact);
  std::printf("the demo's disc at mesh size %g: %zu nodes, %zu elements; %d patches, contacts' DOFs: %s; H = %d\n",
              meshSize, std::size_t(mesh.numNodes()), std::size_t(mesh.numElements()), patches, contactDofs.c_str(), H);
  std::printf("  %-58s %11s %10s\n", "stage", "time", "peak");
  clock.end("mesh");

  const auto reduced = disc::buildDiscReducedModels(mesh, models, disc::nodalDiametersFor(p.sectors, 3, spec.harmonics),
                                                    cache, Tpetra::getDefaultComm());
  if (reduced.reused > 0) clock.end("reduced models read from the cache");
  disc::DiscSweepOptions sweep;
  sweep.harmonicsCheckTo = -1;
  sweep.stability = response::ForcedResponseSetup::Stability::Never;
  const auto response = disc::solveDiscForcedResponse(mesh, reduced, spec, sweep);
  const auto& curve = response.curve;
  clock.end("friction curve, H = " + std::to_string(H) + " (" + std::to_string(curve.branch.points.size()) + " points)");
  log::setSink({});
  std::printf("whole chain: %.1f s, peak memory %.2f GB; friction-damped peak %.6f mm at %.2f Hz (%s)\n", clock.total(),
              clock.peak(), curve.peak, curve.peakOmega / (2 * M_PI),
              curve.branch.finished ? "the curve traced whole" : curve.branch.stopReason.c_str());
  return 0;
}
