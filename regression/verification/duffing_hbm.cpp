// Verification: the Duffing oscillator x'' + 0.05 x' + x + 0.1 x^3 = 0.18 cos(W t)
// by AFT harmonic balance and the library's default arclength continuation, H = 1..7.
//   H = 1: the single-term closed form, peak 2.84162 at W = 1.26663 (s = c^2/2m).
//   H = 7: peak first-harmonic amplitude 2.8302 at W = 1.2688, folds near W = 1.2696
//          and 1.1157 (the reference values).
// Prints, per H, the peak, the folds, the change from the previous H and the run time.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/response/ForcedResponseTrace.hpp"
#include "cyclone/scenes/ForcedResponseScene.hpp"

using namespace cyclone;

namespace {

struct CurveFeatures {
  double peakAmplitude = 0, peakOmega = 0;
  std::vector<double> folds;
  std::size_t points = 0;
  double seconds = 0;
};

CurveFeatures traceDuffing(int H, int samples) {
  Timer timer;
  Eigen::MatrixXd M(1, 1), C(1, 1), K(1, 1);
  M << 1.0;
  C << 0.05;
  K << 1.0;
  hbm::HarmonicBalanceSystem sys(M, C, K, hbm::HarmonicSet::upTo(H), samples);
  sys.addElement(std::make_shared<hbm::CubicSpring>(0.1), Eigen::VectorXd::Ones(1));
  sys.addExcitation(0, 1, 0.18);
  auto problem = response::continuationProblem(sys, response::ForcedResponseSetup::Parameter::Omega);
  // The first-harmonic amplitude as the response measure: the engine locates its
  // maximum on the path and inserts it as a point.
  problem.measure = [&sys](const Eigen::VectorXd& x) { return sys.amplitude(x, 0, 1); };
  continuation::ContinuationOptions o;
  o.from = 0.5;
  o.to = 2.0;  // the library's default engine and steps
  const auto branch = continuation::traceBranch(problem, sys.linearSolution(0.5), o);
  EXPECT_TRUE(branch.finished) << "H = " << H << ": " << branch.stopReason;
  CurveFeatures out;
  out.points = branch.points.size();
  // Peak of the first-harmonic amplitude: the engine located its maximum on the path
  // (the measure above) and inserted it as a point, a solution; a parabola through
  // neighbouring points in omega would not improve it and is wrong next to the fold,
  // where the amplitude is not a function of omega.
  std::size_t top = 0;
  std::vector<double> A(branch.points.size());
  for (std::size_t i = 0; i < A.size(); ++i) {
    A[i] = sys.amplitude(branch.points[i].x, 0, 1);
    if (A[i] > A[top]) top = i;
  }
  out.peakAmplitude = A[top];
  out.peakOmega = branch.points[top].parameter;
  // Folds: where the parameter turns back (parabola through the three points in arclength order).
  for (std::size_t i = 1; i + 2 < branch.points.size(); ++i) {
    const double d1 = branch.points[i].parameter - branch.points[i - 1].parameter;
    const double d2 = branch.points[i + 1].parameter - branch.points[i].parameter;
    if (std::abs(d1) > 1e-12 && std::abs(d2) > 1e-12 && (d1 > 0) != (d2 > 0)) {
      const double a = branch.points[i - 1].parameter, b = branch.points[i].parameter,
                   c = branch.points[i + 1].parameter;
      // Extreme of the parabola through (-1, a), (0, b), (1, c) in a local index variable.
      const double curvature = a - 2 * b + c;
      out.folds.push_back(curvature != 0 ? b - (c - a) * (c - a) / (8 * curvature) : b);
    }
  }
  out.seconds = timer.seconds();
  return out;
}

}  // namespace

TEST(DuffingHarmonicBalance, PeakAndFoldsAgainstReferencesForH1To7) {
  std::printf("\nDuffing by AFT harmonic balance + default arclength continuation, N = 64 samples\n");
  std::printf("%3s %7s %10s %10s %22s %12s %8s\n", "H", "points", "peak |x1|", "at W", "folds (W)", "peak change",
              "time(s)");
  CurveFeatures previous, h1, h7;
  std::vector<double> changes;
  for (int H : {1, 3, 5, 7}) {
    const auto c = traceDuffing(H, 64);
    std::printf("%3d %7zu %10.5f %10.5f %10.5f %10.5f %12.2e %8.2f\n", H, c.points, c.peakAmplitude, c.peakOmega,
                c.folds.size() > 0 ? c.folds[0] : NAN, c.folds.size() > 1 ? c.folds[1] : NAN,
                H > 1 ? c.peakAmplitude - previous.peakAmplitude : NAN, c.seconds);
    EXPECT_EQ(c.folds.size(), 2u) << "H = " << H;
    if (H > 1) changes.push_back(std::abs(c.peakAmplitude - previous.peakAmplitude));
    if (H == 1) h1 = c;
    if (H == 7) h7 = c;
    previous = c;
  }
  // The solution is analytic in time: spectral (geometric) convergence in H.
  for (std::size_t i = 1; i < changes.size(); ++i) EXPECT_LT(changes[i], 0.01 * changes[i - 1]);
  // H = 1 against the closed-form single-term peak.
  const double c = 0.05, P = 0.18, sPeak = c * c / 2;
  double Wpeak = 1.2, Apeak = 0;
  for (int i = 0; i < 500; ++i) {
    Apeak = P / std::sqrt(sPeak * sPeak + c * c * Wpeak * Wpeak);
    Wpeak = std::sqrt(1 + 0.075 * Apeak * Apeak - sPeak);
  }
  EXPECT_NEAR(h1.peakAmplitude, Apeak, 1e-4);
  EXPECT_NEAR(h1.peakOmega, Wpeak, 1e-3);
  // H = 7 against the reference values (4 digits).
  EXPECT_NEAR(h7.peakAmplitude, 2.8302, 1e-4);
  EXPECT_NEAR(h7.peakOmega, 1.2688, 1e-3);
  ASSERT_EQ(h7.folds.size(), 2u);
  EXPECT_NEAR(h7.folds[0], 1.2696, 1e-3);
  EXPECT_NEAR(h7.folds[1], 1.1157, 1e-3);
}
