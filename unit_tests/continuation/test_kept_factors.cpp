// The predictor-corrector with its Newton steps solved by kept factors (GMRES
// preconditioned by the last LU, ContinuationOptions::reuseFactorizations) against the
// same trace with an LU at every step, on a friction harmonic balance large enough for
// the single-precision LU (211 unknowns): the same curve to the Newton tolerance, with
// far fewer factorisations. Each point's residual is checked on its own, and the located
// maxima agree.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/continuation/DenseLu.hpp"
#include "FrictionSector.hpp"

using namespace cyclone;


TEST(KeptFactors, SameFrictionCurveWithFewerFactorisations) {
  const auto s = test_support::frictionSector(10, 3, 64, 7);
  const auto problem = test_support::frictionSectorProblem(*s);
  ASSERT_GE(problem.size + 1, continuation::DenseLu::reuseFrom);
  continuation::Branch branches[2];
  double peaks[2] = {0, 0};
  for (int reuse : {0, 1}) {
    continuation::ContinuationOptions o;
    o.from = 0.9, o.to = 1.6;
    o.reuseFactorizations = reuse == 1;
    branches[reuse] = continuation::traceBranch(problem, s->linearizedSolution(o.from), o);
    const auto& b = branches[reuse];
    ASSERT_TRUE(b.finished) << b.stopReason;
    const auto curve = test_support::checkSectorCurve(problem, *s, b);
    EXPECT_LT(curve.largestResidual, 1e-9) << "reuse " << reuse;
    peaks[reuse] = curve.peak;
    const auto& st = b.statistics;
    std::printf("reuse %d: %zu points, %d Newton iterations, %ld factorisations, %ld steps with kept factors, "
                "%ld GMRES iterations, peak %.9f\n",
                reuse, b.points.size(), st.newtonIterations, st.factorizations, st.reusedFactorizations,
                st.krylovIterations, peaks[reuse]);
  }
  const auto &fresh = branches[0].statistics, &kept = branches[1].statistics;
  EXPECT_EQ(fresh.reusedFactorizations, 0);
  EXPECT_GT(kept.reusedFactorizations, kept.newtonIterations / 2);
  EXPECT_LT(kept.factorizations, fresh.factorizations / 2);
  // The same path: its points differ only through the Newton steps' inexact solves.
  EXPECT_NEAR(double(branches[1].points.size()), double(branches[0].points.size()),
              0.05 * double(branches[0].points.size()));
  EXPECT_NEAR(peaks[1] / peaks[0], 1.0, 1e-8);
}
