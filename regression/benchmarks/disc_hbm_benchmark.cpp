// Benchmark (a program, not a test): the default disc's friction forced response
// (the demo's sector, reduced models and contacts: EO 3, 43 shroud pairs, 500 N
// preload as the demo since session 31, 20 N at mid-blade) by harmonic balance with harmonics 0..H. Prints the
// unknowns, the time of one residual, one residual + Jacobian and one dense LU of
// the bordered Jacobian at the band's start, then the band traced with the disc's
// continuation defaults and again with an LU at every Newton step (no kept factors):
// points, Newton iterations, and the time split into residuals, Jacobians,
// factorisations and solves.
//   build/regression/disc_hbm_benchmark [H (5)] [from Hz (1300)] [to Hz (1330)]
//                                       [mesh size (6)] [cache dir (disc_benchmark_models)] [preload N (500)]
//                                       [variants: all | krylov | krylov-vs-dense6 (all)]
// The demo's whole curve at its converged H: disc_hbm_benchmark 6 349.443 1727.63
// krylov-vs-dense6: the Krylov curve with H, then the dense solve with kept factors (the
// default before the Krylov solve) on the same band with H = 6, and the ratio of their
// costs per curve point (issue 47's target: H = 30 at no more than 3x H = 6's).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cyclone/continuation/DenseLu.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/fe/Environment.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "DemoDisc.hpp"

using namespace cyclone;

int main(int argc, char** argv) {
  Environment env(argc, argv);
  const int H = argc > 1 ? std::atoi(argv[1]) : 5;
  const double fromHz = argc > 2 ? std::atof(argv[2]) : 1300.0, toHz = argc > 3 ? std::atof(argv[3]) : 1330.0;
  const double meshSize = argc > 4 ? std::atof(argv[4]) : 6.0;
  const std::string cache = argc > 5 ? argv[5] : "disc_benchmark_models";
  const double preload = argc > 6 ? std::atof(argv[6]) : 500.0;
  const std::string variants = argc > 7 ? argv[7] : "all";  // all | krylov (no dense LU: large H) | krylov-vs-dense6
  const bool krylovOnly = variants == "krylov" || variants == "krylov-vs-dense6";
  if (!krylovOnly && variants != "all") {
    std::fprintf(stderr, "disc_hbm_benchmark: variants '%s': all, krylov or krylov-vs-dense6\n", variants.c_str());
    return 2;
  }

  mesh::ShroudedSectorParameters p;
  p.meshSize = meshSize;
  const auto mesh = mesh::generateShroudedSector(p);
  const disc::DiscModelSpec models = demo_disc::demoDiscModels(p);
  const disc::DiscResponseSpec spec = demo_disc::demoDiscResponse(H, preload);
  std::vector<int> levels(spec.harmonics);
  const auto reduced = disc::buildDiscReducedModels(mesh, models, disc::nodalDiametersFor(p.sectors, 3, levels),
                                                    cache, env.comm());
  auto setup = disc::makeDiscForcedResponse(mesh, reduced, spec, fromHz);
  const auto problem = response::continuationProblem(setup);
  const int n = problem.size;

  // One evaluation of each kind at the band's start, from the linear solution (the
  // linearised one is a dense LU of every unknown: about 25 s at H = 30).
  const Eigen::VectorXd x = setup.system->linearSolution(2 * M_PI * fromHz) / setup.unknownScale;
  Eigen::VectorXd R;
  Eigen::MatrixXd J;
  const int reps = 5;
  Timer t;
  for (int r = 0; r < reps; ++r) problem.residual(x, 1.0 + 1e-9 * r, R);
  const double residual = t.seconds() / reps;
  t.restart();
  if (!krylovOnly)
    for (int r = 0; r < reps; ++r) problem.jacobian(x, 1.0 + 1e-9 * r, J);
  const double jacobian = t.seconds() / reps;
  double factor = 0;
  if (variants == "all") {
    Eigen::MatrixXd A = Eigen::MatrixXd::Identity(n + 1, n + 1);
    A.topLeftCorner(n, n) = J;
    t.restart();
    const continuation::DenseLu lu(A);
    factor = t.seconds();
  }
  if (variants == "all")
    std::printf("default disc, EO 3, harmonics 0..%d: %d unknowns; residual %.4f s, Jacobian %.4f s, LU %.4f s\n", H,
                n, residual, jacobian, factor);
  else  // the dense Jacobian is neither formed nor factored (krylov, krylov-vs-dense6)
    std::printf("default disc, EO 3, harmonics 0..%d: %d unknowns; residual %.4f s\n", H, n, residual);

  // GMRES on the Jacobian's blocks (Krylov), the dense LU with its factors kept (GMRES
  // preconditioned by the last LU), then an LU at every Newton step.
  using LinearSolver = continuation::ContinuationOptions::LinearSolver;
  const char* names[] = {"Krylov (GMRES on the Jacobian's blocks)", "dense, kept factors", "an LU at every Newton step"};
  auto trace = [&](response::ForcedResponseSetup& on, int variant, int harmonics) {
    const bool keep = variant == 1;
    disc::DiscSweepOptions sweep;
    sweep.harmonicsCheckTo = -1;
    sweep.stability = response::ForcedResponseSetup::Stability::Never;
    sweep.fallback.reset();
    sweep.continuation.reuseFactorizations = keep;
    sweep.continuation.linearSolver = variant == 0 ? LinearSolver::Krylov : LinearSolver::Dense;
    std::vector<std::string> warnings;
    t.restart();
    const auto curve = disc::sweepDisc(on, fromHz, toHz, sweep, warnings);
    const double secs = t.seconds();
    const auto& b = curve.branch;
    const auto& s = b.statistics;
    std::printf("%s, H = %d\n%.1f..%.1f Hz: %zu points in %.2f s (%.4f s per point), %d Newton iterations, %d steps cut; "
                "residuals %.2f s (%ld), Jacobians %.2f s (%ld), factorisations %.2f s (%ld), preconditioners %.2f s, "
                "solves %.2f s (%ld steps with kept factors, %ld Krylov solves, %ld GMRES iterations); peak %.6g mm at "
                "%.3f Hz; %s\n",
                names[variant], harmonics, fromHz, toHz, b.points.size(), secs,
                secs / std::max<std::size_t>(1, b.points.size()), s.newtonIterations, s.rejectedSteps,
                s.residualSeconds, s.residuals, s.jacobianSeconds, s.jacobians, s.factorSeconds, s.factorizations,
                s.preconditionerSeconds, s.solveSeconds, s.reusedFactorizations, s.krylovSolves, s.krylovIterations,
                curve.peak,
                curve.peakOmega / (2 * M_PI), b.stopReason.c_str());
    return secs / double(std::max<std::size_t>(1, b.points.size()));
  };
  const double perPoint = trace(setup, 0, H);
  if (variants == "all")
    for (int variant = 1; variant < 3; ++variant) trace(setup, variant, H);
  if (variants == "krylov-vs-dense6") {
    auto six = disc::makeDiscForcedResponse(mesh, reduced, demo_disc::demoDiscResponse(6, preload), fromHz);
    const double sixPerPoint = trace(six, 1, 6);
    std::printf("cost per curve point, Krylov with H = %d against the dense solve with H = 6: %.2fx\n", H,
                perPoint / sixPerPoint);
  }
  return 0;
}
