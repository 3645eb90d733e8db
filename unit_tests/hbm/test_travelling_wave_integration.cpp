// The travelling-wave integration of a cyclic receptance system (explicit, on the
// phases' modes, every sector's contacts) against the full ring integrated by Newmark
// in its matrix form (FullRingSystem, TimeIntegration: implicit, on every DOF of every
// sector): two time integrations of the same ring that share no code but the element
// laws. The ring of RingSector.hpp (a 3D friction contact between neighbours, a Jenkins
// element, a cubic spring; a mass coupling between sectors), its model a
// MatrixReceptance: all its modes, viscous damping.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <memory>

#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/FullRingSystem.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/hbm/ModalReceptance.hpp"
#include "cyclone/hbm/TimeIntegration.hpp"
#include "cyclone/hbm/TravellingWaveIntegration.hpp"
#include "RingSector.hpp"

using namespace cyclone;
using namespace cyclone::hbm;

namespace {

void addLoads(HarmonicBalanceSystem& s) {
  test_support::addRingElements(s);
  s.addExcitation(1, 1, 0.8, 0.1);
  s.addExcitation(2, 1, 0.2);
  s.addStaticLoad(2, 0.3);
}

struct Ring {
  std::unique_ptr<HarmonicBalanceSystem> matrix, receptance;
};
Ring ring(int N, int eo) {
  const auto m = test_support::ringMatrices();
  Ring r;
  r.matrix = std::make_unique<HarmonicBalanceSystem>(m.M, m.C, m.K, HarmonicSet::upTo(3), 64);
  r.receptance = std::make_unique<HarmonicBalanceSystem>(
      std::make_shared<MatrixReceptance>(m.M, m.C, m.K, N, m.Mn, m.Cn, m.Kn), HarmonicSet::upTo(3), 64);
  CyclicCoupling c;
  c.sectors = N, c.engineOrder = eo;
  r.receptance->setCyclic(c);
  c.Knext = m.Kn, c.Cnext = m.Cn, c.Mnext = m.Mn;
  r.matrix->setCyclic(c);
  addLoads(*r.matrix);
  addLoads(*r.receptance);
  return r;
}

// Sector 0's Fourier coefficients up to harmonic 3 from a period's samples (HarmonicSet's layout).
Eigen::VectorXd coefficients(const Eigen::MatrixXd& motion, int dof) {
  const int S = int(motion.rows());
  Eigen::VectorXd c = Eigen::VectorXd::Zero(7);
  for (int k = 0; k < S; ++k) {
    const double a = 2 * M_PI * k / S, x = motion(k, dof);
    c(0) += x / S;
    for (int h = 1; h <= 3; ++h) c(2 * h - 1) += 2 * x * std::cos(h * a) / S, c(2 * h) += 2 * x * std::sin(h * a) / S;
  }
  return c;
}

}  // namespace

// EO 2 on 6 sectors reaches the even phases (0, 2 and its conjugate 4: harmonic 2 lives
// on phase 4, at negative frequency on the integrated phase 2), on which sector j + 3
// moves like sector j: 3 sectors integrated. EO 3 reaches phases 0 and 3 = N / 2, both
// real: 2 sectors. (EO 1 is not compared: at w = 1.5, 1.9 and 2.5 this ring's steady
// state depends on where it starts, measured 1e-2 apart from two starts, since an
// element that sticks all period keeps the slider where the transient left it.)
TEST(TravellingWaveIntegrationVerification, SteadyStateIsTheFullRingsNewmarkSteadyState) {
  for (int eo : {3, 2}) {
    const double w = 1.9;
    Ring r = ring(6, eo);
    TravellingWaveOptions o;
    o.stepsPerPeriod = 512, o.tolerance = 1e-9, o.amplitudeTolerance = 1e-12;  // periodic, not just steady
    const auto tw = integrateTravellingWave(*r.receptance, w, o);
    ASSERT_EQ(tw.ending, TravellingWaveResponse::Ending::Periodic);
    EXPECT_EQ(tw.sectors, 6 / eo);

    // Newmark from the harmonic balance's solution (H = 3): near the steady state, so
    // that the implicit ring needs few periods; the travelling wave starts from rest.
    Eigen::VectorXd X = r.matrix->linearizedSolution(w), R;
    Eigen::MatrixXd J;
    for (int it = 0; it < 50; ++it) {
      r.matrix->residual(X, w, R, &J);
      if (R.norm() < 1e-12) break;
      X -= J.partialPivLu().solve(R);
    }
    auto full = expandToFullRing(*r.matrix);
    TimeIntegrationOptions n;
    n.stepsPerPeriod = 512, n.maxPeriods = 600, n.periodTolerance = 1e-9;
    const auto st = integrateToSteadyState(*full, w, ringCoefficients(*r.matrix, X), n);
    EXPECT_TRUE(st.converged);
    const int nc = full->numCoefficients();
    double worst = 0, size = 0;
    for (int a = 0; a < 3; ++a) {
      const Eigen::VectorXd mine = coefficients(tw.motion, a), newmark = st.coefficients.segment(a * nc, nc);
      worst = std::max(worst, (mine - newmark).cwiseAbs().maxCoeff());
      size = std::max(size, newmark.cwiseAbs().maxCoeff());
    }
    std::printf("EO %d: travelling wave %d sectors, %d modes, %d periods (%.2f s); full ring by Newmark %d periods; "
                "sector 0's harmonics 0..3 differ by %.2e of the largest\n",
                eo, tw.sectors, tw.modes, tw.periods, tw.seconds, st.periods, worst / size);
    EXPECT_LT(worst / size, 1e-4);  // two second-order schemes at T / 512: 1e-6 apart at T / 2048
  }
}

// A contact with no preload is open at rest, but the explicit step must hold while it is
// closed: its step's limit is the stuck, closed contact's whatever the preload (sized at
// rest, the default disc's ring took 256 steps a period at no preload where closed it
// needs 630, and stayed bounded while it gave other amplitudes).
TEST(TravellingWaveIntegration, AContactOpenAtRestSizesTheStepClosed) {
  int steps[2] = {0, 0};
  for (int i = 0; i < 2; ++i) {
    const auto m = test_support::ringMatrices();
    HarmonicBalanceSystem s(std::make_shared<MatrixReceptance>(m.M, m.C, m.K, 6, m.Mn, m.Cn, m.Kn),
                            HarmonicSet::upTo(1), 16);
    CyclicCoupling c;
    c.sectors = 6, c.engineOrder = 2;
    s.setCyclic(c);
    FrictionContactParameters p;
    p.tangentialDirections = 2, p.kt = 500.0, p.kn = 1000.0, p.mu = 0.3, p.preload = i == 0 ? 0.0 : 0.5;
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(3, 3);
    W(1, 0) = 1, W(0, 1) = 0.3, W(2, 2) = 1;
    s.addElement(std::make_shared<FrictionContact>(p), W, -W);
    s.addExcitation(1, 1, 0.8, 0.1);
    TravellingWaveOptions o;
    o.stepsPerPeriod = 8, o.maxPeriods = 2;
    steps[i] = integrateTravellingWave(s, 1.9, o).stepsPerPeriod;
  }
  EXPECT_GT(steps[1], 8);  // the closed contact sets the step, not the 8 asked for
  EXPECT_EQ(steps[0], steps[1]);
}

TEST(TravellingWaveIntegration, RefusesWhatItCannotIntegrate) {
  Ring r = ring(6, 1);
  EXPECT_THROW(integrateTravellingWave(*r.matrix, 1.9), InputError);  // not a receptance
  // Structural damping and a constant part: not causal, not explicit.
  ModalRealization m;
  m.U = Eigen::MatrixXcd::Identity(3, 3), m.V = m.U;
  m.eigenvalues = Eigen::Vector3d(1, 2, 3);
  m.viscous = Eigen::Vector3d(0.05, 0.05, 0.05);
  m.lossFactor = 0.01;
  std::map<long, ModalRealization> byPhase;
  for (long p = 0; p <= 3; ++p) byPhase[p] = m;
  for (int fault : {0, 1}) {
    auto phases = byPhase;
    for (auto& [p, real] : phases) {
      if (fault == 1) real.R = 0.1 * Eigen::MatrixXcd::Identity(3, 3);  // refused before the loss factor
    }
    HarmonicBalanceSystem s(std::make_shared<ModalReceptance>(6, phases), HarmonicSet::upTo(1), 16);
    CyclicCoupling c;
    c.sectors = 6, c.engineOrder = 1;
    s.setCyclic(c);
    s.addExcitation(0, 1, 1.0);
    EXPECT_THROW(integrateTravellingWave(s, 1.0), InputError);
    // Its causal model is accepted and gives the linear steady state. The constant part
    // R = 0.1 I realized by modes at w_r = 20: its compliance at w = 0.5 is R's to (w / w_r)^2.
    auto causal = causalModalModel(*s.receptance(), {0, 1, 2, 3}, fault == 1 ? 20.0 : 0.0);
    if (fault == 1) {
      ModalRealization viscous = m;  // the loss factor as viscous damping, R kept constant
      viscous.lossFactor = 0;
      viscous.viscous += m.lossFactor * m.eigenvalues.cwiseSqrt();
      viscous.R = 0.1 * Eigen::MatrixXcd::Identity(3, 3);
      const Eigen::MatrixXcd given = ModalReceptance(6, {{1, viscous}}).compliance(0.5, 1);
      const double off = (causal->compliance(0.5, 1) - given).norm() / viscous.R.norm();
      const double x = 0.5 / 20;  // each residual mode's 1 / (1 + i eta w / w_r - (w / w_r)^2) - 1
      EXPECT_NEAR(off, std::abs(1.0 / std::complex<double>(1 - x * x, m.lossFactor * x) - 1.0), 1e-12);
      EXPECT_EQ(causal->modalRealization(1)->numModes(), 6);
    }
    HarmonicBalanceSystem t(causal, HarmonicSet::upTo(1), 16);
    t.setCyclic(c);
    t.addExcitation(0, 1, 1.0);
    TravellingWaveOptions o;
    o.tolerance = 1e-9;
    const auto tw = integrateTravellingWave(t, 0.5, o);
    ASSERT_TRUE(tw.converged);
    const double linear = std::abs(causal->compliance(0.5, 1)(0, 0));
    EXPECT_NEAR(tw.peak(0), linear, 1e-5 * linear);
    ASSERT_EQ(int(tw.amplitudeHistory.size()), tw.periods);  // one amplitude a period, the last the result's
    EXPECT_EQ(tw.amplitudeHistory.back(), tw.peak(0));
    // Started from the harmonic balance's (exact) linear solution, it is steady at once.
    Eigen::VectorXd X = t.linearSolution(0.5);
    const TravellingWaveState start = travellingWaveStart(t, X, 0.5);
    o.tolerance = 1e-6;  // the central difference's own periodic motion is 1e-6 off the exact one here
    const auto st = integrateTravellingWave(t, 0.5, o, &start);
    EXPECT_TRUE(st.converged);
    EXPECT_EQ(st.periods, 3);
    EXPECT_NEAR(st.peak(0), linear, 1e-5 * linear);
  }
}
