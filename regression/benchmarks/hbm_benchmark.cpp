// Benchmark (a program, not a test): harmonic balance of a reduced cyclic
// sector with 3D friction contacts, the size the project's issue names: 84 DOFs
// (27 contact nodes and one excitation node, 3 directions each), 27 friction3d
// elements joining each contact node to its partner on the next sector, an
// engine-order 3 travelling wave on 24 sectors. Prints, against H and the
// number of time samples N: the time of one residual + Jacobian and its
// shares (element AFT and marching, linear operator, assembly of the element
// blocks), the dense LU of the Jacobian, and then a whole resonance curve
// traced with default settings (only the range given) by each continuation
// engine, with its points, Newton iterations and the time split into residuals,
// Jacobians and factorisations; the predictor-corrector with its defaults (kept factors
// and GMRES, single-precision LU refined in double), with an LU at every Newton step,
// and with that LU in double, in the same run.
//   build/regression/hbm_benchmark [max H (default 7)]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>

#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/continuation/DenseLu.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "FrictionSector.hpp"

using namespace cyclone;

namespace {

constexpr int kNodes = 28, kDofs = 3 * kNodes, kContacts = 27;

// The sector: FrictionSector.hpp (28 nodes, 27 contacts).
std::unique_ptr<hbm::HarmonicBalanceSystem> sector(int H, int samples) {
  return test_support::frictionSector(kNodes, H, samples, 2024);
}

}  // namespace

int main(int argc, char** argv) {
  const int maxH = argc > 1 ? std::atoi(argv[1]) : 7;
  std::printf("reduced cyclic sector: %d DOFs, %d friction3d elements across the sector boundary, EO 3 of 24\n\n",
              kDofs, kContacts);
  // LU: Eigen's PartialPivLU, LAPACK's dgetrf, and sgetrf with one solve refined in double
  // (DenseLu's two precisions; the predictor-corrector's default is the mixed one).
  std::printf("%3s %5s %9s | %10s %8s %8s %8s | %9s %9s %11s\n", "H", "N", "unknowns", "R+J [s]", "elements",
              "linear", "assembly", "Eigen LU", "LAPACK LU", "mixed+solve");
  for (int H = 1; H <= maxH; H += 2)
    for (int N : {64, 128, 256, 512}) {
      if (N < 2 * H + 1) continue;
      const auto s = sector(H, N);
      const double w = 1.0;
      const Eigen::VectorXd X = s->linearizedSolution(w);
      Eigen::VectorXd R;
      Eigen::MatrixXd J;
      const int reps = 3;
      Timer t;
      for (int r = 0; r < reps; ++r) s->residual(X, w, R, &J);
      const double total = t.seconds() / reps;
      t.restart();
      for (int r = 0; r < reps; ++r) s->linearOperator(w);
      const double linear = t.seconds() / reps;
      // The elements alone: their AFT, march and coefficient Jacobians.
      const int nc = s->numCoefficients();
      const Eigen::Map<const Eigen::MatrixXd> Xm(X.data(), nc, kDofs);
      Eigen::MatrixXd F, Jf;
      t.restart();
      for (int r = 0; r < reps; ++r)
        for (const auto& c : s->elements()) {
          const Eigen::MatrixXd Wc = Xm * c.W + s->nextSectorMap() * (Xm * c.Wnext);
          c.element->harmonicForce(s->aft(), Wc, w, F, &Jf);
        }
      const double elements = t.seconds() / reps;
      t.restart();
      const auto lu = J.partialPivLu();
      const double luTime = t.seconds();
      t.restart();
      const continuation::DenseLu lapackLu(J, continuation::DenseLu::Precision::Double);
      const double lapackTime = t.seconds();
      t.restart();
      const continuation::DenseLu mixedLu(J, continuation::DenseLu::Precision::Mixed);
      const Eigen::VectorXd dx = mixedLu.solve(R);
      const double mixedTime = t.seconds();
      std::printf("%3d %5d %9d | %10.4f %7.0f%% %7.0f%% %7.0f%% | %9.4f %9.4f %11.4f%s\n", H, N, s->numUnknowns(),
                  total, 100 * elements / total, 100 * linear / total, 100 * (total - elements - linear) / total,
                  luTime, lapackTime, mixedTime, mixedLu.doubleFallbacks() > 0 ? " (fell back to double)" : "");
      (void)lu;
      (void)lapackLu;
      (void)dx;
    }

  std::printf("\nresonance curve, EO 3 (nodal diameter 3), omega 0.9 -> 1.6:\n");
  for (int H : {1, 3, maxH}) {
    const int N = 128;
    const auto s = sector(H, N);
    continuation::ContinuationProblem problem;
    problem.size = s->numUnknowns();
    problem.residual = [&](const Eigen::VectorXd& X, double p, Eigen::VectorXd& R) { s->residual(X, p, R, nullptr); };
    problem.jacobian = [&](const Eigen::VectorXd& X, double p, Eigen::MatrixXd& J) {
      Eigen::VectorXd R;
      s->residual(X, p, R, &J);
    };
    using Engine = continuation::ContinuationOptions::Engine;
    for (const int run : {0, 1, 2, 3}) {
      const Engine engine = run == 3 ? Engine::Loca : Engine::PredictorCorrector;
      // Each engine with its own default steps (their units differ).
      continuation::ContinuationOptions o =
          engine == Engine::Loca ? continuation::locaOptions() : continuation::ContinuationOptions{};
      o.from = 0.9, o.to = 1.6;
      o.mixedPrecisionLu = run <= 1;
      o.reuseFactorizations = run == 0;
      const char* name = run == 0   ? "predictor-corrector"
                         : run == 1 ? "the same, an LU per step"
                         : run == 2 ? "LU per step, in double"
                                    : "LOCA";
      Timer t;
      const auto branch = continuation::traceBranch(problem, s->linearizedSolution(o.from), o);
      const double secs = t.seconds();
      double peak = 0, peakW = 0;
      for (const auto& pt : branch.points)
        if (s->amplitude(pt.x, 0, 1) > peak) peak = s->amplitude(pt.x, 0, 1), peakW = pt.parameter;
      const auto& st = branch.statistics;
      std::printf("  H = %d, N = %d, %-24s: %4zu points in %6.2f s (%.4f s per point), peak |x1| of DOF 0 %.5f at "
                  "%.4f; %s\n",
                  H, N, name, branch.points.size(), secs,
                  secs / std::max<std::size_t>(1, branch.points.size()), peak, peakW, branch.stopReason.c_str());
      if (engine == Engine::PredictorCorrector)
        std::printf("      %d Newton iterations (%.2f per point), %d steps cut; residuals %.2f s, Jacobians %.2f s, "
                    "factorisations %.2f s (%ld, %ld again in double), solves %.2f s (%ld steps with kept factors, "
                    "%ld GMRES iterations)\n",
                    st.newtonIterations, double(st.newtonIterations) / std::max<std::size_t>(1, branch.points.size()),
                    st.rejectedSteps, st.residualSeconds, st.jacobianSeconds, st.factorSeconds, st.factorizations,
                    st.doubleFallbacks, st.solveSeconds, st.reusedFactorizations, st.krylovIterations);
    }
  }
  return 0;
}
