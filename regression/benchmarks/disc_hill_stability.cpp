// Benchmark (a program, not a test): the cost of the stability of one point of the
// default disc's friction harmonic balance against the number of harmonics H (issue 47,
// item 5). At each H, Newton at one frequency (from the linearised solution at the first
// level, from the level before's solution at the others), then Hill's method on the
// point, timed, with the leading Floquet exponent and the verdict: its whole eigenproblem
// (LAPACK; up to a given H) and only the eigenvalues nearest zero (ARPACK, HillOptions:
// the default above 400 unknowns), the two sets of exponents compared; the scaling
// exponent of the nearest ones' cost in H from the first and last levels.
//   build/regression/disc_hill_stability [frequency Hz (1564)] [preload N a pair (500)]
//                                        [force N (20)] [H list (1,3,5,7)]
//                                        [whole problem up to H (7)] [mesh size (6)]
//                                        [cache dir (disc_benchmark_models)]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/fe/Environment.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/hbm/HarmonicSet.hpp"
#include "cyclone/hbm/HillStability.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "DemoDisc.hpp"

using namespace cyclone;

int main(int argc, char** argv) {
  Environment env(argc, argv);
  const double hz = argc > 1 ? std::atof(argv[1]) : 1564.0;
  const double preload = argc > 2 ? std::atof(argv[2]) : 500.0;
  const double force = argc > 3 ? std::atof(argv[3]) : 20.0;
  std::vector<int> levels{1, 3, 5, 7};
  if (argc > 4) levels = demo_disc::harmonicLevels(argv[4]);
  const int wholeUpTo = argc > 5 ? std::atoi(argv[5]) : 7;
  const double meshSize = argc > 6 ? std::atof(argv[6]) : 6.0;
  const std::string cache = argc > 7 ? argv[7] : "disc_benchmark_models";

  mesh::ShroudedSectorParameters p;
  p.meshSize = meshSize;
  const auto mesh = mesh::generateShroudedSector(p);
  const auto reduced = demo_disc::demoDiscReducedModels(mesh, p, levels.back(), cache, env.comm());
  std::printf("default disc, EO 3, preload %g N, force %g N, stability at %g Hz\n", preload, force, hz);
  std::printf("%4s %8s | %8s %10s | %-7s %5s %9s | %-32s %9s %6s\n", "H", "unknowns", "Newton", "||R||", "Hill",
              "eigs", "covered/w", "leading exponent (1/s) (strip count)", "time", "stable");
  double firstCost = 0, lastCost = 0;
  int firstH = 0, lastH = 0;
  Eigen::VectorXd carried;
  hbm::HarmonicSet carriedSet = hbm::HarmonicSet::upTo(1);
  for (int H : levels) {
    disc::DiscResponseSpec spec = demo_disc::demoDiscResponse(H, preload);
    spec.excitation.amplitude = force;
    auto setup = disc::makeDiscForcedResponse(mesh, reduced, spec, hz);
    const auto problem = response::continuationProblem(setup);
    const double pHz = 2 * M_PI * hz / setup.omegaUnit;
    const auto& set = setup.system->aft().harmonics();
    Eigen::VectorXd x = carried.size() ? hbm::transferCoefficients(carried, setup.system->numDofs(), carriedSet, set)
                                       : Eigen::VectorXd(setup.system->linearizedSolution(2 * M_PI * hz));
    Timer t;
    const auto nr = continuation::solveNewton(problem, x, pHz, 1e-10, 60);
    const double newtonSeconds = t.seconds();
    carried = x, carriedSet = set;
    // Untimed: the system's one-time work (each phase's modal realization), as at the
    // first point of a curve.
    (void)hbm::hillStability(*setup.system, x, 2 * M_PI * hz);
    Eigen::VectorXcd wholeExponents;
    for (const bool whole : {true, false}) {
      if (whole && H > wholeUpTo) continue;
      hbm::HillOptions o;
      if (whole) o.denseUpTo = 1 << 30;
      t.restart();
      const auto fl = hbm::hillStability(*setup.system, x, 2 * M_PI * hz, o);
      const double hillSeconds = t.seconds();
      const std::complex<double> lead = fl.exponents.size() ? fl.exponents(0) : std::complex<double>(NAN, NAN);
      // The nearest ones against the whole problem's: each exponent's distance to the other set.
      double apart = 0;
      if (whole)
        wholeExponents = fl.exponents;
      else if (wholeExponents.size() > 0)
        for (int i = 0; i < fl.exponents.size(); ++i)
          apart = std::max(apart, (wholeExponents.array() - fl.exponents(i)).abs().minCoeff());
      std::printf("%4d %8d | %7.3fs %10.2e | %-7s %5d %9.4g | %12.6g %+12.6gi (%3d) %8.3fs %6s", H, problem.size,
                  newtonSeconds, nr.residualNorm, whole ? "whole" : "nearest", int(fl.all.size()),
                  fl.covered / (2 * M_PI * hz), lead.real(), lead.imag(), int(fl.exponents.size()), hillSeconds,
                  fl.stable ? "yes" : "no");
      if (whole || wholeExponents.size() == 0)
        std::printf("\n");
      else
        std::printf("  (exponents %s the whole problem's: %.1e /s)\n",
                    fl.exponents.size() == wholeExponents.size() ? "as many as" : "NOT as many as", apart);
      if (!whole) {
        if (firstH == 0) firstH = H, firstCost = hillSeconds;
        lastH = H, lastCost = hillSeconds;
      }
    }
    std::fflush(stdout);
  }
  if (lastH > firstH && firstCost > 0)
    std::printf("Hill's method (nearest eigenvalues) from H = %d to %d: %.2fx, scaling exponent %.2f (cost ~ H^e)\n",
                firstH, lastH, lastCost / firstCost, std::log(lastCost / firstCost) / std::log(double(lastH) / firstH));
  return 0;
}
