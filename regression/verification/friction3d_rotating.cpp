// Verification of the 3D friction contact's circular limit in a whole forced
// response (scene friction3d_rotating.yaml): under a rotating force F the mass
// moves on a circle of radius R. Stuck (kt R <= mu N) the system is linear with
// k + kt. Slipping, the friction force has constant magnitude mu N and leads
// the displacement by beta, cos(beta) = mu N / (kt R), so
//   |(k - m w^2) R + mu N cos(beta) + i (c w R + mu N sin(beta))| = F,
// one equation for R at each frequency (solved here by bisection). The
// harmonic balance must match it along the whole curve; its error comes from
// the time discretisation of the slider's path and falls at first order in N.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>

#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/response/ForcedResponseTrace.hpp"
#include "cyclone/scenes/ForcedResponseScene.hpp"

using namespace cyclone;

namespace {

const double m = 1, k = 10, c = 0.2, kt = 5, muN = 0.3 * 50, F = 20;

// Radius of the circular orbit at frequency w (closed form above).
double orbitRadius(double w) {
  const double stuck = F / std::abs(std::complex<double>(k + kt - m * w * w, c * w));
  if (kt * stuck <= muN) return stuck;
  auto g = [&](double R) {
    const double cb = muN / (kt * R), sb = std::sqrt(1 - cb * cb);
    return std::hypot((k - m * w * w) * R + muN * cb, c * w * R + muN * sb) - F;
  };
  double lo = muN / kt, hi = 1e3;  // g(lo) < 0 when slipping; g grows with R for c > 0
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) > 0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST(Friction3DRotating, CircularOrbitMatchesClosedForm) {
  Timer timer;
  auto setup = scenes::loadForcedResponseScene(CYCLONE_SCENE_DIR "/friction3d_rotating.yaml");
  const auto& sys = *setup.system;
  const auto branch = response::traceForcedResponse(setup);
  ASSERT_TRUE(branch.finished) << branch.stopReason;
  double worst = 0, worstW = 0, peak = 0, peakW = 0;
  int slipping = 0;
  for (const auto& pt : branch.points) {
    const double R = orbitRadius(pt.parameter), hb = sys.amplitude(pt.x, 0, 1);
    slipping += kt * R > muN;
    const double err = std::abs(hb / R - 1);
    if (err > worst) worst = err, worstW = pt.parameter;
    if (hb > peak) peak = hb, peakW = pt.parameter;
    EXPECT_NEAR(sys.amplitude(pt.x, 1, 1) / hb, 1.0, 1e-9);  // a circle: |y1| = |x1|
  }
  std::printf("%zu points (%d slipping) in %.2f s; peak radius %.5f at W = %.4f (closed form %.5f); max relative "
              "difference to the closed form %.2e at W = %.3f (N = %d)\n",
              branch.points.size(), slipping, timer.seconds(), peak, peakW, orbitRadius(peakW), worst, worstW,
              sys.aft().numSamples());
  EXPECT_GT(slipping, 10);
  EXPECT_LT(worst, 5e-3);

  // At the peak: the error against N (first order: the return mapping
  // discretises the slider's path).
  double previous = 0;
  for (int N : {512, 2048, 8192}) {
    timer.restart();
    const auto refined = hbm::withHarmonics(sys, sys.aft().harmonics(), N);
    Eigen::VectorXd X = branch.points.front().x;
    for (const auto& pt : branch.points)
      if (std::abs(pt.parameter - peakW) < 1e-12) X = pt.x;
    const auto problem = response::continuationProblem(*refined, response::ForcedResponseSetup::Parameter::Omega);
    ASSERT_TRUE(continuation::solveNewton(problem, X, peakW, 1e-11).converged);
    const double err = std::abs(refined->amplitude(X, 0, 1) / orbitRadius(peakW) - 1);
    std::printf("  N = %5d: radius %.7f, relative error %.2e (%.3f s)%s\n", N, refined->amplitude(X, 0, 1), err,
                timer.seconds(),
                previous > 0 ? ("  order " + std::to_string(std::log2(previous / err) / 2)).c_str() : "");
    if (previous > 0) {
      EXPECT_GT(std::log2(previous / err) / 2, 0.8);
    }
    previous = err;
  }
}
