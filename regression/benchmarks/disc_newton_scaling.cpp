// Benchmark (a program, not a test): the cost of one Newton step of the default disc's
// friction harmonic balance against the number of harmonics H, by the two linear
// solvers the continuation has: the dense LU of the formed Jacobian and GMRES on the
// Jacobian's blocks preconditioned harmonic by harmonic (issue 47). At each H, Newton
// at one frequency from the linearised solution at the first level, from the level
// before's last iterate at the others; per step the time split into the residual (the AFT), the
// Jacobian (formed, or its blocks), the preconditioner's factorisation and the solve,
// with GMRES's iterations; the scaling exponent of the Krylov step's cost in H from the
// first and last levels. The dense path is run up to a size (its LU's memory and time).
//   build/regression/disc_newton_scaling [frequency Hz (1500)] [preload N (20)] [force N (20)]
//                                        [H list (6,12,24,48)] [dense up to unknowns (9000)]
//                                        [mesh size (6)] [cache dir (disc_benchmark_models)] [Newton steps (12)]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "cyclone/continuation/DenseLu.hpp"
#include "cyclone/continuation/KrylovSolve.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/fe/Environment.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/hbm/HarmonicSet.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "DemoDisc.hpp"

using namespace cyclone;

namespace {

struct StepCost {
  int steps = 0;
  long gmres = 0;
  double residual = 0, jacobian = 0, preconditioner = 0, solve = 0, residualNorm = 0;
  double perStep() const { return steps ? (residual + jacobian + preconditioner + solve) / steps : 0.0; }
};

// Newton with full steps (backtracking where ||F|| grows), timing each part.
StepCost newton(const continuation::ContinuationProblem& problem, Eigen::VectorXd& x, double p, bool krylov,
                int maxSteps) {
  StepCost c;
  Eigen::VectorXd F, Ft, dx;
  Timer t;
  problem.residual(x, p, F);
  c.residual += t.seconds();
  for (; c.steps < maxSteps && F.norm() > 1e-10; ++c.steps) {
    if (krylov) {
      t.restart();
      auto op = problem.jacobianOperator(x, p);
      c.jacobian += t.seconds();
      t.restart();
      op->preparePreconditioner();
      c.preconditioner += t.seconds();
      t.restart();
      const Eigen::VectorXd minusF = -F;
      const auto r = continuation::solveKrylov([&](const Eigen::VectorXd& v, Eigen::VectorXd& y) { op->apply(v, y); },
                                               [&](const Eigen::VectorXd& v, Eigen::VectorXd& y) { op->precondition(v, y); },
                                               minusF, dx);
      c.solve += t.seconds();
      c.gmres += r.iterations;
      if (!r.converged) break;
    } else {
      Eigen::MatrixXd J;
      t.restart();
      problem.jacobian(x, p, J);
      c.jacobian += t.seconds();
      t.restart();
      continuation::DenseLu lu;
      lu.computeTaking(J);
      c.preconditioner += t.seconds();  // the LU
      t.restart();
      dx = lu.solve(-F);
      c.solve += t.seconds();
    }
    double a = 1;
    for (; a > 1e-3; a *= 0.5) {
      t.restart();
      problem.residual(x + a * dx, p, Ft);
      c.residual += t.seconds();
      if (Ft.norm() < F.norm()) break;
    }
    x += a * dx;
    F = Ft;
  }
  c.residualNorm = F.norm();
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  Environment env(argc, argv);
  const double hz = argc > 1 ? std::atof(argv[1]) : 1500.0;
  const double preload = argc > 2 ? std::atof(argv[2]) : 20.0;
  const double force = argc > 3 ? std::atof(argv[3]) : 20.0;
  std::vector<int> levels{6, 12, 24, 48};
  if (argc > 4) levels = demo_disc::harmonicLevels(argv[4]);
  const int denseUpTo = argc > 5 ? std::atoi(argv[5]) : 9000;
  const double meshSize = argc > 6 ? std::atof(argv[6]) : 6.0;
  const std::string cache = argc > 7 ? argv[7] : "disc_benchmark_models";
  const int steps = argc > 8 ? std::atoi(argv[8]) : 12;

  mesh::ShroudedSectorParameters p;
  p.meshSize = meshSize;
  const auto mesh = mesh::generateShroudedSector(p);
  const auto reduced = demo_disc::demoDiscReducedModels(mesh, p, levels.back(), cache, env.comm());
  std::printf("default disc, EO 3, preload %g N, force %g N, Newton at %g Hz from the linearised solution\n", preload,
              force, hz);
  std::printf("%4s %8s %8s | %-8s %5s %6s %9s %9s %9s %9s %9s %10s\n", "H", "unknowns", "samples", "solver", "steps",
              "GMRES", "residual", "Jacobian", "precond/LU", "solve", "per step", "||R||");
  double firstCost = 0, lastCost = 0;
  int firstH = 0, lastH = 0;
  Eigen::VectorXd carried;  // the last level's Newton iterate
  hbm::HarmonicSet carriedSet = hbm::HarmonicSet::upTo(1);
  for (int H : levels) {
    disc::DiscResponseSpec spec = demo_disc::demoDiscResponse(H, preload);
    spec.excitation.amplitude = force;
    auto setup = disc::makeDiscForcedResponse(mesh, reduced, spec, hz);
    const auto problem = response::continuationProblem(setup);
    const double pHz = 2 * M_PI * hz / setup.omegaUnit;
    const auto& set = setup.system->aft().harmonics();
    const Eigen::VectorXd start =
        carried.size() ? hbm::transferCoefficients(carried, setup.system->numDofs(), carriedSet, set)
                       : Eigen::VectorXd(setup.system->linearizedSolution(2 * M_PI * hz));
    {  // the system's one-time work at its first residual (the receptance's per-phase set-up) is not a step's
      Eigen::VectorXd R;
      problem.residual(start, pHz, R);
    }
    for (const bool krylov : {true, false}) {
      if (!krylov && problem.size > denseUpTo) continue;
      Eigen::VectorXd x = start;
      const StepCost c = newton(problem, x, pHz, krylov, steps);
      if (krylov) carried = x, carriedSet = set;
      std::printf("%4d %8d %8d | %-8s %5d %6ld %8.3fs %8.3fs %9.3fs %8.3fs %8.3fs %10.2e\n", H, problem.size,
                  setup.system->aft().numSamples(), krylov ? "Krylov" : "dense LU", c.steps, c.gmres, c.residual,
                  c.jacobian, c.preconditioner, c.solve, c.perStep(), c.residualNorm);
      std::fflush(stdout);
      if (krylov) {
        if (firstH == 0) firstH = H, firstCost = c.perStep();
        lastH = H, lastCost = c.perStep();
      }
    }
  }
  if (lastH > firstH && firstCost > 0)
    std::printf("Krylov step cost from H = %d to %d: %.2fx, scaling exponent %.2f (cost ~ H^e)\n", firstH, lastH,
                lastCost / firstCost, std::log(lastCost / firstCost) / std::log(double(lastH) / firstH));
  return 0;
}
