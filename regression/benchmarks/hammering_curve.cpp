// Benchmark (a program, not a test): the default disc's frequency curve in the hammering
// regime (every shroud pair opens each period) at a given H traced whole over a band by
// the predictor-corrector: points, Newton steps, GMRES iterations and the time split.
//   build/regression/hammering_curve [H (5)] [preload N (20)] [force N (20)] [from Hz (1380)]
//                                    [to Hz (1520)] [max points (3000)] [samples (0: the rule)]
//                                    [cache dir (disc_benchmark_models)] [points file ("")]
//                                    [Newton tolerance (0: the disc's default)]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cyclone/core/Timer.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"
#include "cyclone/response/ForcedResponseTrace.hpp"
#include "cyclone/fe/Environment.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "DemoDisc.hpp"

using namespace cyclone;

int main(int argc, char** argv) {
  Environment env(argc, argv);
  const int H = argc > 1 ? std::atoi(argv[1]) : 5;
  const double preload = argc > 2 ? std::atof(argv[2]) : 20.0;
  const double force = argc > 3 ? std::atof(argv[3]) : 20.0;
  const double fromHz = argc > 4 ? std::atof(argv[4]) : 1380.0;
  const double toHz = argc > 5 ? std::atof(argv[5]) : 1520.0;
  const int maxPoints = argc > 6 ? std::atoi(argv[6]) : 3000;
  const int samples = argc > 7 ? std::atoi(argv[7]) : 0;
  const std::string cache = argc > 8 ? argv[8] : "disc_benchmark_models";
  const std::string pointsFile = argc > 9 ? argv[9] : "";
  const double tolerance = argc > 10 ? std::atof(argv[10]) : 0.0;

  mesh::ShroudedSectorParameters p;
  const auto mesh = mesh::generateShroudedSector(p);
  const auto reduced = demo_disc::demoDiscReducedModels(mesh, p, H, cache, env.comm());
  disc::DiscResponseSpec spec = demo_disc::demoDiscResponse(H, preload);
  spec.excitation.amplitude = force;
  if (samples > 0) spec.samples = samples;
  auto setup = disc::makeDiscForcedResponse(mesh, reduced, spec, fromHz);
  setup.continuation = disc::discContinuationOptions();
  setup.continuation.from = 1.0, setup.continuation.to = toHz / fromHz;
  setup.continuation.maxSteps = maxPoints;
  if (tolerance > 0) setup.continuation.tolerance = tolerance;
  Timer timer;
  const auto start = response::findStartingPoint(setup);
  const auto problem = response::continuationProblem(setup);
  const auto branch = continuation::traceBranch(problem, start.x, setup.continuation);
  const auto& s = branch.statistics;
  const auto& set = setup.system->aft().harmonics();
  std::vector<double> hz, amp;
  double peak = 0, peakHz = 0;
  for (const auto& pt : branch.points) {
    hz.push_back(setup.apply(pt.parameter).first / (2 * M_PI));
    const int nc = setup.system->numCoefficients(), dof = setup.outputDofs.front();
    amp.push_back(hbm::peakMagnitude(set, Eigen::VectorXd(pt.x.segment(dof * nc, nc))));
    if (amp.back() > peak) peak = amp.back(), peakHz = hz.back();
  }
  std::printf("H %d (%d samples), preload %g N, force %g N, %g..%g Hz: %zu points in %.1f s (%s); largest %.6f mm at "
              "%.3f Hz\n", H, setup.system->aft().numSamples(), preload, force, fromHz, toHz, branch.points.size(),
              timer.seconds(), branch.stopReason.c_str(), peak, peakHz);
  std::printf("  Newton %d, rejected %d, spherical %d, GMRES %ld in %ld solves; residual %.1f s, Jacobian %.1f s, "
              "preconditioner %.1f s, solve %.1f s\n",
              s.newtonIterations, s.rejectedSteps, s.sphericalSteps, s.krylovIterations, s.krylovSolves,
              s.residualSeconds, s.jacobianSeconds, s.preconditionerSeconds, s.solveSeconds);
  if (!pointsFile.empty()) {
    FILE* f = std::fopen(pointsFile.c_str(), "w");
    for (std::size_t i = 0; i < hz.size(); ++i) std::fprintf(f, "%.6f %.8f\n", hz[i], amp[i]);
    std::fclose(f);
  }
  return 0;
}
