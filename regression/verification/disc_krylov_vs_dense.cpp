// Verification (issue 47): the Newton steps by GMRES on the Jacobian's blocks (the
// default from 1000 unknowns, ContinuationOptions::LinearSolver::Krylov) against an LU
// of the dense Jacobian at every Newton step, on the default disc (mesh size 6, EO 3,
// the shroud's law per pair, 20 N at mid-blade): the same frequency curve traced both
// ways, at the demo's former preload (500 N a pair, the shroud sliding; H = 5, 1452
// unknowns) and where every pair opens each period (20 N a pair; H = 4, 1188 unknowns,
// the resonance's lower branch). Both solve the same residual to the same Newton
// tolerance; what differs is each step's linear solve, so the curves must coincide:
// every point of one curve on the other's path (its distance to the other's polyline in
// frequency and amplitude, each relative to the curve's span, within the chord error of
// the steps), and each curve's largest point the solution Newton by the other solver
// reaches at its frequency from the other curve's nearest point, to the Newton
// tolerance. (The largest points themselves can differ by where the steps fall: 1.3e-5
// at H = 6 over 1530..1600 Hz.) Times printed.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "DemoDisc.hpp"

using namespace cyclone;

namespace {

using LinearSolver = continuation::ContinuationOptions::LinearSolver;

struct Traced {
  response::ForcedResponseResult curve;
  double seconds = 0;
};

Traced trace(const mesh::Mesh& mesh, const disc::DiscReducedModels& models, int H, double preload, double fromHz,
             double toHz, LinearSolver solver) {
  const auto spec = demo_disc::demoDiscResponse(H, preload);
  auto setup = disc::makeDiscForcedResponse(mesh, models, spec, fromHz);
  disc::DiscSweepOptions sweep;
  sweep.harmonicsCheckTo = -1;
  sweep.stability = response::ForcedResponseSetup::Stability::Never;
  sweep.fallback.reset();
  sweep.continuation.reuseFactorizations = false;  // an LU at every Newton step: exact Newton
  sweep.continuation.linearSolver = solver;
  std::vector<std::string> warnings;
  Timer timer;
  Traced t;
  t.curve = disc::sweepDisc(setup, fromHz, toHz, sweep, warnings);
  t.seconds = timer.seconds();
  return t;
}

// The largest distance of a's points to b's polyline, frequency and amplitude each over
// b's span.
double largestDistance(const response::ForcedResponseResult& a, const response::ForcedResponseResult& b) {
  const auto [wlo, whi] = std::minmax_element(b.omega.begin(), b.omega.end());
  const auto [mlo, mhi] = std::minmax_element(b.measure.begin(), b.measure.end());
  const double ws = *whi - *wlo, ms = *mhi - *mlo;
  double worst = 0;
  for (std::size_t i = 0; i < a.omega.size(); ++i) {
    const double px = a.omega[i] / ws, py = a.measure[i] / ms;
    double best = HUGE_VAL;
    for (std::size_t j = 0; j + 1 < b.omega.size(); ++j) {
      const double ax = b.omega[j] / ws, ay = b.measure[j] / ms;
      const double dx = b.omega[j + 1] / ws - ax, dy = b.measure[j + 1] / ms - ay;
      const double len2 = dx * dx + dy * dy;
      const double s = len2 > 0 ? std::clamp(((px - ax) * dx + (py - ay) * dy) / len2, 0.0, 1.0) : 0.0;
      best = std::min(best, std::hypot(px - ax - s * dx, py - ay - s * dy));
    }
    worst = std::max(worst, best);
  }
  return worst;
}

// Newton by `solver` at the largest point's parameter of `a`, from b's point nearest it
// (frequency and amplitude over b's span): its distance to a's point, relative.
double resolvedLargestPoint(const mesh::Mesh& mesh, const disc::DiscReducedModels& models, int H, double preload,
                            double fromHz, const response::ForcedResponseResult& a,
                            const response::ForcedResponseResult& b, LinearSolver solver) {
  auto setup = disc::makeDiscForcedResponse(mesh, models, demo_disc::demoDiscResponse(H, preload), fromHz);
  const auto problem = response::continuationProblem(setup);
  const auto& target = a.branch.points[a.peakIndex];
  const double ws = b.omega.back() - b.omega.front(), ms = b.peak;
  std::size_t near = 0;
  for (std::size_t j = 0; j < b.omega.size(); ++j)
    if (std::hypot((b.omega[j] - a.peakOmega) / ws, (b.measure[j] - a.peak) / ms) <
        std::hypot((b.omega[near] - a.peakOmega) / ws, (b.measure[near] - a.peak) / ms))
      near = j;
  Eigen::VectorXd x = b.branch.points[near].x;
  const auto r = continuation::solveNewton(problem, x, target.parameter, 1e-10, 50, nullptr, solver);
  if (!r.converged) return HUGE_VAL;
  return (x - target.x).norm() / target.x.norm();
}

void compare(const char* what, const mesh::Mesh& mesh, const disc::DiscReducedModels& models, int H, double preload,
             double fromHz, double toHz) {
  const auto krylov = trace(mesh, models, H, preload, fromHz, toHz, LinearSolver::Krylov);
  const auto dense = trace(mesh, models, H, preload, fromHz, toHz, LinearSolver::Dense);
  const auto& k = krylov.curve;
  const auto& d = dense.curve;
  ASSERT_TRUE(k.branch.finished) << what << ": " << k.branch.stopReason;
  ASSERT_TRUE(d.branch.finished) << what << ": " << d.branch.stopReason;
  const double kByDense = resolvedLargestPoint(mesh, models, H, preload, fromHz, k, d, LinearSolver::Dense);
  const double dByKrylov = resolvedLargestPoint(mesh, models, H, preload, fromHz, d, k, LinearSolver::Krylov);
  const double kOnD = largestDistance(k, d), dOnK = largestDistance(d, k);
  std::printf("%s, H = %d, %.0f..%.0f Hz:\n"
              "  GMRES on the blocks: %zu points, %.2f s (%ld GMRES iterations); peak %.9f mm at %.4f Hz\n"
              "  an LU a step:        %zu points, %.2f s; peak %.9f mm at %.4f Hz\n"
              "  largest distance to the other curve %.1e and %.1e of its span; each largest point solved again by "
              "the other solver from the other curve's nearest point: %.1e and %.1e apart\n",
              what, H, fromHz, toHz, k.branch.points.size(), krylov.seconds, k.branch.statistics.krylovIterations,
              k.peak, k.peakOmega / (2 * M_PI), d.branch.points.size(), dense.seconds, d.peak,
              d.peakOmega / (2 * M_PI), kOnD, dOnK, kByDense, dByKrylov);
  EXPECT_GT(k.branch.statistics.krylovSolves, 0) << what;  // the GMRES path was the one taken
  EXPECT_EQ(d.branch.statistics.krylovSolves, 0) << what;
  // The same solution to the Newton tolerance (1e-10 of the forces here; the
  // unknowns' conditioning at a resonance leaves about 1e-7 of them).
  EXPECT_LT(kByDense, 1e-6) << what;
  EXPECT_LT(dByKrylov, 1e-6) << what;
  // Point sets differ where a step's Newton count differs; a point off the other's path
  // by more than the chord error of a turn-angle step (0.1 rad, a few 1e-3 of the span
  // at most) would be another curve.
  EXPECT_LT(kOnD, 5e-3) << what;
  EXPECT_LT(dOnK, 5e-3) << what;
}

class DiscKrylovVsDense : public ::testing::Test {
protected:
  bool quiet = (log::setQuiet(true), true);
  mesh::ShroudedSectorParameters p;
  mesh::Mesh mesh = mesh::generateShroudedSector(p);
  disc::DiscReducedModels models =
      demo_disc::demoDiscReducedModels(mesh, p, 6, "disc_krylov_vs_dense_models", Tpetra::getDefaultComm());
};

}  // namespace

TEST_F(DiscKrylovVsDense, SlidingShroudSameCurve) { compare("500 N a pair", mesh, models, 5, 500.0, 1555.0, 1575.0); }

TEST_F(DiscKrylovVsDense, HammeringShroudSameCurve) { compare("20 N a pair", mesh, models, 4, 20.0, 1380.0, 1450.0); }
