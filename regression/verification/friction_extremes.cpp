// Stiff and extreme cases of the friction contact (the tmdsimpy 2-DOF system,
// s = 10): contact stiffness from 1e2 to 1e10 times the structure's, friction
// coefficient 0 and 1e-8, preload 0 and 1e9, zero viscous damping. Each curve
// must either reach the end of its range or stop with a stated reason, and
// every point it returns must solve the equations (recomputed here, each row
// relative to the forces acting on it). Where a
// limit has a closed form (stuck, free) the curve must equal it.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>

#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/response/ForcedResponseTrace.hpp"
#include "cyclone/scenes/ForcedResponseScene.hpp"

using namespace cyclone;

namespace {

struct Case {
  const char* name;
  double kt, kn, mu, staticLoad, dampingScale;
  double limitKt;  // closed form of the x response with this tangential spring; < 0: none
  double tolerance = 1e-10;  // the continuation's (relative) tolerance
  double excitation = 10;    // the excitation scale s
};

}  // namespace

TEST(FrictionExtremes, ConvergeOrStopWithAReason) {
  const Case cases[] = {
      {"kt = kn = 1e2 k", 1.2e3, 2.1e3, 0.85, 100, 1, -1},
      {"kt = kn = 1e6 k", 1.2e7, 2.1e7, 0.85, 100, 1, -1},
      {"kt = kn = 1e10 k (stuck: rigid)", 1.2e11, 2.1e11, 0.85, 100, 1, 1.2e11},
      {"mu = 0 (free)", 5, 21, 0.0, 100, 1, 0.0},
      {"mu = 1e-8", 5, 21, 1e-8, 100, 1, -1},
      {"no static load (contact opens)", 5, 21, 0.85, 0, 1, -1},
      // Round-off of the 1e9 mean force leaks ~1e-16 x 1e9 into the harmonics
      // of a 10 N excitation: 1e-10 is out of reach (the trace stops and says
      // so), 1e-6 is not.
      {"preload 1e9, tolerance 1e-10", 5, 21, 0.85, 1e9, 1, -1},
      {"preload 1e9 (stuck), tolerance 1e-6", 5, 21, 0.85, 1e9, 1, 5.0, 1e-6},
      {"zero damping", 5, 21, 0.85, 100, 0, -1},
      // Every force 1e-9 times smaller: amplitudes of 1e-8 converge like O(1) ones.
      {"tiny amplitudes (forces x 1e-9)", 5, 21, 0.85, 1e-7, 1, 5.0, 1e-10, 1e-8},
  };
  for (const Case& c : cases) {
    Timer timer;
    auto setup = scenes::loadForcedResponseScene(CYCLONE_SCENE_DIR "/tmdsimpy_friction2d.yaml");
    auto& sys = *setup.system;
    hbm::FrictionContactParameters p;
    p.tangentialDirections = 1, p.kt = c.kt, p.kn = c.kn, p.mu = c.mu, p.preload = 0;
    sys.replaceElement(0, std::make_shared<hbm::FrictionContact>(p));
    sys.setDampingScale(c.dampingScale);
    // The static load comes from the scene (100); rescale it to the case's.
    sys.addStaticLoadCoefficients((c.staticLoad / 100.0 - 1.0) * sys.staticLoad());
    setup.excitationScale = c.excitation;
    setup.continuation.from = 3.0, setup.continuation.to = 5.0;
    setup.continuation.maxSteps = 3000;
    setup.continuation.tolerance = c.tolerance;
    const auto problem = response::continuationProblem(sys, setup.parameter, 0, setup.excitationScale);
    const auto branch =
        continuation::traceBranch(problem, sys.linearizedSolution(3.0, c.excitation), setup.continuation);
    // Every returned point solves the equations relative to the largest force in them.
    double worst = 0, worstLimit = 0, peak = 0;
    for (const auto& pt : branch.points) {
      Eigen::VectorXd R;  // rows relative to the forces acting on them (static, dynamic)
      problem.residual(pt.x, pt.parameter, R);
      worst = std::max(worst, R.norm());
      peak = std::max(peak, sys.amplitude(pt.x, 0, 1));
      if (c.limitKt >= 0) {
        Eigen::Matrix2d K = sys.K();
        K(0, 0) += c.limitKt, K(1, 1) += c.staticLoad > 0 ? c.kn : 0.0;
        const double w = pt.parameter;
        const Eigen::Matrix2cd Z = (K - w * w * sys.M()).cast<std::complex<double>>() +
                                   std::complex<double>(0, w) * sys.C().cast<std::complex<double>>();
        const double x = std::abs((Z.inverse() * Eigen::Vector2cd(c.excitation, 0.1 * c.excitation))(0));
        worstLimit = std::max(worstLimit, std::abs(sys.amplitude(pt.x, 0, 1) / x - 1));
      }
    }
    std::printf("%-34s %5zu points, %s; max relative residual %.1e; peak |x1| %.4g", c.name, branch.points.size(),
                branch.finished ? "end reached" : ("stopped: " + branch.stopReason).c_str(), worst, peak);
    if (c.limitKt >= 0) std::printf("; closed-form limit within %.1e", worstLimit);
    std::printf(" (%.2f s)\n", timer.seconds());
    EXPECT_TRUE(branch.finished || !branch.stopReason.empty()) << c.name;
    EXPECT_LT(worst, 100 * c.tolerance) << c.name;  // LOCA's test: ||R|| / sqrt(unknowns) < tolerance
    if (c.limitKt >= 0) {
      EXPECT_TRUE(branch.finished) << c.name << ": " << branch.stopReason;
      EXPECT_LT(worstLimit, 1e4 * c.tolerance) << c.name;
    }
  }
}
