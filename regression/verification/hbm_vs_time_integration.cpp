// Verification: harmonic balance against time integration of the same system
// and element laws (Newmark, from rest, run until the response repeats).
// The first-harmonic amplitudes must agree up to the truncation of each method;
// the HB error is printed against H with its run time. The vibro-impact
// oscillator with friction (a contact that opens for most of each period, its
// force spectrum decaying slowly) is carried to H = 50.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/Aft.hpp"
#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/ElementStates.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/hbm/JenkinsElement.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"
#include "cyclone/hbm/TimeIntegration.hpp"
#include "cyclone/hbm/TruncatedForce.hpp"
#include "cyclone/hbm/UnilateralSpring.hpp"
#include "cyclone/response/ForcedResponse.hpp"

using namespace cyclone;

namespace {

// Newton at a fixed frequency from X (updated in place).
continuation::NewtonResult newtonAt(const hbm::HarmonicBalanceSystem& sys, double omega, Eigen::VectorXd& X,
                                    double tolerance) {
  continuation::ContinuationProblem problem;
  problem.size = sys.numUnknowns();
  problem.residual = [&](const Eigen::VectorXd& Y, double w, Eigen::VectorXd& R) { sys.residual(Y, w, R, nullptr); };
  problem.jacobian = [&](const Eigen::VectorXd& Y, double w, Eigen::MatrixXd& J) {
    Eigen::VectorXd R;
    sys.residual(Y, w, R, &J);
  };
  return continuation::solveNewton(problem, X, omega, tolerance, 100);
}

// Newton at a fixed frequency from the linear solution (the solution is unique there).
Eigen::VectorXd solveAt(const hbm::HarmonicBalanceSystem& sys, double omega) {
  Eigen::VectorXd X = sys.linearSolution(omega);
  const auto newton = newtonAt(sys, omega, X, 1e-12);
  EXPECT_TRUE(newton.converged) << "harmonic balance did not converge at omega " << omega << " (residual "
                                << newton.residualNorm << ")";
  return X;
}

}  // namespace

TEST(HbmVsTimeIntegration, DuffingAwayFromTheFolds) {
  Eigen::MatrixXd M(1, 1), C(1, 1), K(1, 1);
  M << 1.0;
  C << 0.05;
  K << 1.0;
  for (double omega : {0.8, 1.6}) {
    hbm::HarmonicBalanceSystem sys(M, C, K, hbm::HarmonicSet::upTo(7), 64);
    sys.addElement(std::make_shared<hbm::CubicSpring>(0.1), Eigen::VectorXd::Ones(1));
    sys.addExcitation(0, 1, 0.18);
    const Eigen::VectorXd X = solveAt(sys, omega);
    Timer timer;
    const auto ti = hbm::integrateToSteadyState(sys, omega, Eigen::VectorXd::Zero(sys.numUnknowns()));
    ASSERT_TRUE(ti.converged) << "no steady state after " << ti.periods << " periods";
    const double a1 = sys.amplitude(X, 0, 1), t1 = sys.amplitude(ti.coefficients, 0, 1);
    const double a3 = sys.amplitude(X, 0, 3), t3 = sys.amplitude(ti.coefficients, 0, 3);
    std::printf("Duffing W = %.1f: |x1| HB %.8f, time integration %.8f (rel. diff %.1e); |x3| %.3e vs %.3e; "
                "%d periods, %.2f s\n", omega, a1, t1, std::abs(t1 / a1 - 1), a3, t3, ti.periods, timer.seconds());
    // Newmark with 1024 steps per period: phase error ~ (w dt)^2 / 12 ~ 3e-6.
    EXPECT_NEAR(t1 / a1, 1.0, 2e-5);
    EXPECT_NEAR(t3, a3, 2e-5 * a1);
  }
}

TEST(HbmVsTimeIntegration, JenkinsFrictionDamperConvergesInH) {
  // Two DOFs, a Jenkins friction element from DOF 0 to ground, forced on DOF 0.
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(2, 2), K(2, 2);
  K << 2.0, -1.0, -1.0, 1.0;
  const Eigen::MatrixXd C = 0.01 * K;
  const double omega = 0.7;
  auto build = [&](int H, int samples) {
    hbm::HarmonicBalanceSystem sys(M, C, K, hbm::HarmonicSet::upTo(H), samples);
    sys.addElement(std::make_shared<hbm::JenkinsElement>(1.0, 0.05), Eigen::Vector2d(1.0, 0.0));
    sys.addExcitation(0, 1, 0.2);
    return sys;
  };
  auto reference = build(3, 2048);
  const auto ti = hbm::integrateToSteadyState(reference, omega, Eigen::VectorXd::Zero(reference.numUnknowns()));
  ASSERT_TRUE(ti.converged);
  const double t1 = reference.amplitude(ti.coefficients, 1, 1);
  std::printf("Jenkins damper, W = %.1f: time integration |x1| of DOF 1 = %.7f (%d periods)\n", omega, t1, ti.periods);
  std::vector<double> errors;
  for (int H : {1, 3, 7, 15}) {
    Timer timer;
    auto sys = build(H, 2048);
    const Eigen::VectorXd X = solveAt(sys, omega);
    const double a1 = sys.amplitude(X, 1, 1);
    errors.push_back(std::abs(a1 / t1 - 1));
    std::printf("  H = %2d: |x1| %.7f, relative difference %.2e, %.2f s\n", H, a1, errors.back(), timer.seconds());
  }
  EXPECT_LT(errors.back(), 1e-3);
  EXPECT_LT(errors.back(), errors.front());
}

namespace {

// The lumped vibro-impact oscillator with friction. One mass (m = 1) with a
// tangential DOF x (0) and a normal DOF y (1), each on a spring to ground
// (kx = ky = 1) with viscous damping c = 0.1, pressed against a wall by a static
// force P = 0.1 and driven by F0 cos(W t), F0 = 0.5, in both directions. The wall
// is a 2D FrictionContact at zero gap on w = (x, y): normal force N = kn max(y, 0),
// kn = 50 (the closed normal frequency sqrt(51) = 7.1 against 1 open), a Jenkins
// slider kt = 2, mu = 0.3 while closed, reset while open. P / F0 = 0.2: the mass
// hammers the wall once a period (open about 87-90 % of it, in short impacts
// whose force spectrum decays slowly), stuck or slipping while they last; y is a
// bilinear impact oscillator, its resonance near W = 1.8, and the friction during
// the impacts changes max |x(t)| by up to 15 % (W = 1.8) against mu = 0.
struct ImpactOscillator {
  double kx = 1, ky = 1, c = 0.1, kt = 2, kn = 50, mu = 0.3, staticLoad = 0.1, force = 0.5;

  std::shared_ptr<const hbm::FrictionContact> contact() const {
    hbm::FrictionContactParameters p;
    p.tangentialDirections = 1, p.kt = kt, p.kn = kn, p.mu = mu, p.preload = 0;
    return std::make_shared<hbm::FrictionContact>(p);
  }
  hbm::HarmonicBalanceSystem build(int H, int samples) const {
    const Eigen::MatrixXd M = Eigen::MatrixXd::Identity(2, 2), C = c * Eigen::MatrixXd::Identity(2, 2);
    Eigen::MatrixXd K(2, 2);
    K << kx, 0, 0, ky;
    hbm::HarmonicBalanceSystem sys(M, C, K, hbm::HarmonicSet::upTo(H), samples);
    sys.addElement(contact(), Eigen::MatrixXd::Identity(2, 2));
    sys.addExcitation(0, 1, force);
    sys.addExcitation(1, 1, force);
    sys.addStaticLoad(1, staticLoad);
    return sys;
  }
};

// AFT samples for H harmonics: perPeriod (2H + 1) rounded up to a power of two, at
// least the contact's recommendedSamples(). 8 (2H + 1) (16 or more per period of the
// highest harmonic) avoid aliasing and, the contact's instants located between the
// samples, give the errors of 32 (2H + 1) (the study's last line); with the sampled law,
// which put the closing instant at a sample, 32 were needed (1.7e-3 in max |x(t)| at
// the resonance with 1024 samples at H = 50, 5e-6 with 4096).
int impactSamples(int H, int perPeriod = 32) {
  int n = 1;
  while (n < perPeriod * (2 * H + 1)) n *= 2;
  return std::max(n, ImpactOscillator().contact()->recommendedSamples());
}

// What is compared, per DOF: the first-harmonic amplitude and max |x(t)| over the period.
struct Measures {
  double a1[2] = {0, 0}, peak[2] = {0, 0};
};
Measures measure(const hbm::HarmonicBalanceSystem& sys, const Eigen::VectorXd& X) {
  Measures m;
  const int nc = sys.numCoefficients();
  for (int d = 0; d < 2; ++d) {
    m.a1[d] = sys.amplitude(X, d, 1);
    m.peak[d] = hbm::peakMagnitude(sys.aft().harmonics(), X.segment(d * nc, nc));
  }
  return m;
}
// The largest relative difference over both DOFs and both measures.
double relativeDifference(const Measures& a, const Measures& ref) {
  double e = 0;
  for (int d = 0; d < 2; ++d)
    e = std::max({e, std::abs(a.a1[d] / ref.a1[d] - 1), std::abs(a.peak[d] / ref.peak[d] - 1)});
  return e;
}

// The time integration's period kept to this harmonic: max |x(t)| from its
// coefficients (dropping harmonics 51..64 changes it by under 4e-6, printed).
constexpr int kReferenceHarmonics = 64;

struct ImpactReference {
  Measures m;
  double change = 0;      // against half the steps per period: its error estimate
  double truncation = 0;  // max |x(t)| from 50 harmonics against 64
  double open = 0;        // share of the period with y < 0 (the contact open)
  int periods = 0;
  double seconds = 0;
};

// Newmark from rest at steps / 2 and steps per period, each until a period repeats to 1e-9.
ImpactReference integrateImpact(const ImpactOscillator& osc, double omega, int steps) {
  const auto sys = osc.build(kReferenceHarmonics, 2 * kReferenceHarmonics + 2);
  ImpactReference ref;
  Timer timer;
  Measures coarse;
  Eigen::VectorXd X;
  for (int n : {steps / 2, steps}) {
    hbm::TimeIntegrationOptions o;
    o.stepsPerPeriod = n;
    const auto steady = hbm::integrateToSteadyState(sys, omega, Eigen::VectorXd::Zero(sys.numUnknowns()), o);
    EXPECT_TRUE(steady.converged) << "no steady state at W = " << omega << " with " << n << " steps per period after "
                                  << steady.periods << " periods (change " << steady.periodChange << ")";
    coarse = ref.m;
    ref.m = measure(sys, steady.coefficients);
    ref.periods = steady.periods;
    X = steady.coefficients;
  }
  ref.change = relativeDifference(coarse, ref.m);
  const auto sys50 = osc.build(50, 128);
  ref.truncation = relativeDifference(
      measure(sys50, hbm::transferCoefficients(X, 2, sys.aft().harmonics(), sys50.aft().harmonics())), ref.m);
  const hbm::Aft fine(sys.aft().harmonics(), 8192);
  const Eigen::VectorXd y = fine.toTime(Eigen::VectorXd(X.segment(sys.numCoefficients(), sys.numCoefficients())));
  ref.open = double((y.array() < 0).count()) / y.size();
  ref.seconds = timer.seconds();
  std::printf("  W = %.2f: |x1| %.6f %.6f, max|x| %.6f %.6f; %d vs %d steps per period: change %.1e; "
              "50 vs %d harmonics: %.1e; open %.1f %% of the period; %d periods, %.1f s\n",
              omega, ref.m.a1[0], ref.m.a1[1], ref.m.peak[0], ref.m.peak[1], steps / 2, steps, ref.change,
              kReferenceHarmonics, ref.truncation, 100 * ref.open, ref.periods, ref.seconds);
  return ref;
}

struct ImpactLevel {
  int H = 0, samples = 0;
  std::vector<double> error, open, dropped;
  double seconds = 0;
};

// The harmonic balance at every frequency and level, each solve by Newton:
// - the start: H = 1 from the linearized solution at W0 = 1.25 (the contact
//   stuck and closed), carried up to H = 5 (Newton from the linearized solution at
//   H = 5 itself, or at the resonance even at H = 1, stalls at a spurious minimum of
//   |R| where a sample of the contact grazes), then to H = 20 and swept in steps of
//   0.01 through the frequencies (Newton from the last point; a low-H sweep stalls
//   near the resonance, where the H = 5 and 10 curves differ most);
// - the first level from that sweep's solution, each next level from the previous
//   level's carried over. Then the last level again with 8 (2H + 1) samples.
std::vector<ImpactLevel> impactLevels(const ImpactOscillator& osc, const std::vector<double>& omegas,
                                      const std::vector<int>& levels, const std::vector<ImpactReference>& refs) {
  const int sweepH = 20;
  const double omega0 = 1.25, step = 0.01;
  Timer timer;
  Eigen::VectorXd X;
  int H0 = 0;
  for (int H = 1; H <= 5; ++H) {
    const auto sys = osc.build(H, impactSamples(H));
    X = H0 ? hbm::transferCoefficients(X, 2, hbm::HarmonicSet::upTo(H0), sys.aft().harmonics())
           : sys.linearizedSolution(omega0);
    const auto newton = newtonAt(sys, omega0, X, 1e-10);
    EXPECT_TRUE(newton.converged) << "start: H = " << H << " at W = " << omega0 << " (residual "
                                  << newton.residualNorm << ")";
    H0 = H;
  }
  const auto sweep = osc.build(sweepH, impactSamples(sweepH, 8));
  X = hbm::transferCoefficients(X, 2, hbm::HarmonicSet::upTo(H0), sweep.aft().harmonics());
  std::vector<Eigen::VectorXd> start(omegas.size());
  double w = omega0;
  int points = 0;
  for (std::size_t k = 0; k < omegas.size(); ++k) {
    do {
      w = omegas[k] > w ? std::min(omegas[k], w + step) : std::max(omegas[k], w - step);
      const auto newton = newtonAt(sweep, w, X, 1e-10);
      ++points;
      EXPECT_TRUE(newton.converged) << "sweep at H = " << sweepH << ": no solution at W = " << w << " (residual "
                                    << newton.residualNorm << ")";
    } while (std::abs(w - omegas[k]) > 1e-12);
    start[k] = X;
  }
  std::printf("  start: H = 1..5 at W = %.2f, H = %d swept through %d frequencies: %.2f s\n", omega0, sweepH, points,
              timer.seconds());

  std::vector<ImpactLevel> out;
  std::vector<Eigen::VectorXd> previous = start;
  int previousH = sweepH;
  for (int H : levels) {
    ImpactLevel level;
    level.H = H, level.samples = impactSamples(H);
    timer.restart();
    const auto sys = osc.build(H, level.samples);
    std::vector<Eigen::VectorXd> solutions(omegas.size());
    for (std::size_t k = 0; k < omegas.size(); ++k) {
      const bool fromSweep = out.empty();
      X = hbm::transferCoefficients(fromSweep ? start[k] : previous[k], 2,
                                    hbm::HarmonicSet::upTo(fromSweep ? sweepH : previousH), sys.aft().harmonics());
      const auto newton = newtonAt(sys, omegas[k], X, 1e-10);
      EXPECT_TRUE(newton.converged) << "H = " << H << ", W = " << omegas[k] << ": Newton did not converge (residual "
                                    << newton.residualNorm << ")";
      solutions[k] = X;
    }
    level.seconds = timer.seconds();  // the solves alone: the level's run time
    std::printf("  H = %2d, N = %4d:", H, level.samples);
    for (std::size_t k = 0; k < omegas.size(); ++k) {
      level.error.push_back(relativeDifference(measure(sys, solutions[k]), refs[k].m));
      const auto states = hbm::elementStates(sys, solutions[k], omegas[k]);
      const auto period = hbm::elementPeriod(sys, 0, states[0], omegas[k]);
      level.open.push_back(double((period.f.col(1).array() <= 0).count()) / level.samples);
      level.dropped.push_back(hbm::truncatedForce(sys, solutions[k], omegas[k]).share);
      std::printf(" %9.2e", level.error.back());
    }
    std::printf("  | %5.3f | %6.3f s\n", *std::max_element(level.dropped.begin(), level.dropped.end()),
                level.seconds);
    out.push_back(level);
    previous = solutions, previousH = H;
  }
  // The sample count: the last level with 8 instead of 32 samples per period of H.
  const int fewer = impactSamples(previousH, 8);
  const auto sys = osc.build(previousH, fewer);
  std::printf("  H = %2d, N = %4d:", previousH, fewer);
  for (std::size_t k = 0; k < omegas.size(); ++k) {
    X = previous[k];
    const auto newton = newtonAt(sys, omegas[k], X, 1e-10);
    EXPECT_TRUE(newton.converged);
    std::printf(" %9.2e", relativeDifference(measure(sys, X), refs[k].m));
  }
  std::printf("  (8 (2H + 1) samples: the closing instants located to 1/%d of the period)\n", fewer);
  return out;
}

// The study: reference per frequency, then the levels; returns them for the checks.
std::vector<ImpactLevel> impactStudy(const std::vector<double>& omegas, const std::vector<int>& levels, int steps,
                                     std::vector<ImpactReference>& refs) {
  const ImpactOscillator osc;
  std::printf("Vibro-impact oscillator with friction (kn %.0f, kt %.0f, mu %.1f, P %.1f, F0 %.1f, c %.1f)\n"
              "time integration (Newmark from rest):\n",
              osc.kn, osc.kt, osc.mu, osc.staticLoad, osc.force, osc.c);
  for (double w : omegas) refs.push_back(integrateImpact(osc, w, steps));
  std::printf("harmonic balance: largest relative difference in |x1| and max|x(t)| of both DOFs per frequency,\n"
              "the largest force share the harmonics leave out (TruncatedForce), run time of the level's solves\n"
              "                ");
  for (double w : omegas) std::printf("  W = %.2f", w);
  std::printf("  | dropped | time\n");
  const auto out = impactLevels(osc, omegas, levels, refs);
  for (std::size_t k = 0; k < omegas.size(); ++k) {
    const auto& last = out.back();
    std::printf("  W = %.2f: contact open %.1f %% of the period (H = %d; time integration %.1f %%)\n", omegas[k],
                100 * last.open[k], last.H, 100 * refs[k].open);
    // A real vibro-impact: open for most of each period, by both methods.
    EXPECT_GT(last.open[k], 0.8);
    EXPECT_NEAR(last.open[k], refs[k].open, 0.01);
  }
  return out;
}

double largest(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }

}  // namespace

// H = 5..20 at the impact resonance (W = 1.8) and on its flank: the quick check.
TEST(HbmVsTimeIntegration, VibroImpactWithFrictionUpToH20) {
  Timer timer;
  std::vector<ImpactReference> refs;
  const auto levels = impactStudy({1.7, 1.8}, {5, 10, 20}, 8192, refs);
  // The reference's own error estimate at most a quarter of the tolerance it checks.
  for (const auto& r : refs) EXPECT_LT(r.change, 0.25 * 2e-3);
  // Measured: 1.2e-4 and 5.8e-4 at H = 20, 9.2e-2 and 2.1e-2 at H = 5.
  EXPECT_LE(largest(levels.back().error), 2e-3);
  for (std::size_t k = 0; k < refs.size(); ++k) EXPECT_LT(levels.back().error[k], levels.front().error[k] / 10);
  std::printf("total %.1f s\n", timer.seconds());
}

// H = 5..50 around the impact resonance and on the flank towards the tangential one
// (around that one, at W = 1.0-1.2, Newmark from rest finds no periodic steady state
// in 2000 periods): 1e-3 at H = 50. About a minute (slow label), the time
// integration most of it.
TEST(HbmVsTimeIntegration, VibroImpactWithFrictionUpToH50) {
  Timer timer;
  std::vector<ImpactReference> refs;
  const auto levels = impactStudy({1.25, 1.7, 1.8, 1.9}, {5, 10, 20, 30, 40, 50}, 16384, refs);
  for (const auto& r : refs) EXPECT_LT(r.change, 0.25 * 1e-3);
  // Measured: at most 4.3e-5 at H = 50 (W = 1.9), 1.6e-1 at H = 5 (with the contact's
  // instants at the samples, 3.5e-4 at H = 50).
  EXPECT_LE(largest(levels.back().error), 1e-3);
  EXPECT_LT(largest(levels.back().error), largest(levels.front().error) / 100);
  for (std::size_t k = 0; k < refs.size(); ++k) EXPECT_LT(levels.back().error[k], levels.front().error[k] / 10);
  std::printf("total %.1f s\n", timer.seconds());
}

// The library's curve over W = 0.5..2.5 traced as a user's is (its start, a second sweep
// from the range's end where the first turns back, stability by Hill), expected whole; at
// its stable points nearest each of `at`, Newmark (4096 steps a period, from the HB
// solution) on the curve's system (a retrace with more samples replaces it), compared by
// `difference`: 1 where there is no stable point or no steady state.
struct WholeCurve {
  response::ForcedResponseResult curve;
  double seconds = 0;
  std::vector<double> errors;
};
template <class Difference>
WholeCurve traceWholeAgainstNewmark(response::ForcedResponseSetup& setup, int H, const std::vector<double>& at,
                                    Difference difference) {
  setup.continuation.from = 0.5, setup.continuation.to = 2.5;
  setup.stability = response::ForcedResponseSetup::Stability::Always;
  setup.harmonicsCheckTo = -1;
  WholeCurve out;
  Timer timer;
  out.curve = response::solveForcedResponse(setup);
  out.seconds = timer.seconds();
  const auto& curve = out.curve;
  const auto& pts = curve.branch.points;
  out.errors.assign(at.size(), 1.0);
  EXPECT_FALSE(pts.empty()) << "H = " << H << ": " << curve.branch.stopReason;
  if (pts.empty()) return out;
  double lo = pts.front().parameter, hi = lo;
  for (const auto& pt : pts) lo = std::min(lo, pt.parameter), hi = std::max(hi, pt.parameter);
  EXPECT_EQ(curve.branch.stopReason.find("not traced"), std::string::npos) << "H = " << H << ": " << curve.branch.stopReason;
  EXPECT_NEAR(lo, 0.5, 1e-9) << "H = " << H << ": " << curve.branch.stopReason;
  EXPECT_NEAR(hi, 2.5, 1e-9) << "H = " << H << ": " << curve.branch.stopReason;
  for (std::size_t k = 0; k < at.size(); ++k) {
    std::size_t best = pts.size();
    for (std::size_t i = 0; i < pts.size(); ++i)
      if (curve.stable[i] == 1 &&
          (best == pts.size() || std::abs(pts[i].parameter - at[k]) < std::abs(pts[best].parameter - at[k])))
        best = i;
    EXPECT_LT(best, pts.size()) << "H = " << H << ": no stable point";
    if (best == pts.size()) continue;
    hbm::TimeIntegrationOptions ti;
    ti.stepsPerPeriod = 4096;
    const auto steady = hbm::integrateToSteadyState(*setup.system, pts[best].parameter, pts[best].x, ti);
    EXPECT_TRUE(steady.converged) << "H = " << H << ", W = " << pts[best].parameter;
    if (steady.converged) out.errors[k] = difference(pts[best].x, steady.coefficients);
  }
  std::printf("H = %2d (%4d samples): curve in %zu points, %.2f s (first point by %s), peak %.6f; against Newmark at "
              "the stable points nearest", H, setup.system->aft().numSamples(), pts.size(), out.seconds,
              curve.startMethod.c_str(), curve.peak);
  for (std::size_t k = 0; k < at.size(); ++k) std::printf("%s W = %.2f: %.2e", k ? "," : "", at[k], out.errors[k]);
  std::printf("\n");
  return out;
}

// The vibro-impact oscillator with friction traced whole over W = 0.5..2.5, as a user's
// curve is (its start, a second sweep from the range's end, stability by Hill). With the
// sampled contact law its stick, slip, lift-off and closing instants put a kink (and
// through the slider's periodic state a jump) into the force wherever one crossed a
// sample, and walls of hairpins left W = 0.56..1.8 untraced from H = 6 on (no point at
// all at H = 8); with the instants located between the samples (FrictionContact, one
// tangential direction) the curve is whole at every H. At its stable points nearest
// W = 1.9 (the impact resonance's flank) and 1.25 (below it) harmonic balance and Newmark
// (4096 steps a period, from the HB solution) agree as H grows; error and run time per H
// (at H = 32, 18 s when this was written: 1e-5 and 2e-5).
TEST(HbmVsTimeIntegration, VibroImpactWithFrictionTracedWhole) {
  const ImpactOscillator osc;
  std::vector<double> last;
  for (int H : {8, 16}) {
    response::ForcedResponseSetup setup;
    setup.system = std::make_unique<hbm::HarmonicBalanceSystem>(osc.build(H, impactSamples(H, 8)));
    setup.outputDofs = {1, 0};
    const auto whole = traceWholeAgainstNewmark(setup, H, {1.9, 1.25}, [&](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
      return relativeDifference(measure(*setup.system, a), measure(*setup.system, b));
    });
    last = whole.errors;
  }
  EXPECT_LT(last[0], 1e-3);
  EXPECT_LT(last[1], 1e-3);
}

// A bilinear impact oscillator: m = k = 1, c = 0.1, pressed by a static 0.1 against a
// unilateral spring kn = 50 at zero gap (closed frequency sqrt(51)), driven by 0.5 cos(W t):
// it hammers once a period. With the sampled law each instant crossing a time sample put a
// kink into the residual, and at H = 6, 12 and 20 (256 samples) the curve over W = 0.5..2.5
// met walls of hairpins no step passed (no start at all from W = 0.5). With the instants
// located between the samples (UnilateralSpring) the library's curve covers the whole
// range at every H; at its stable points nearest W = 2.2 and 1.4 (Hill) harmonic balance
// and Newmark (4096 steps a period, from the HB solution) agree as H grows, the error and
// the run time printed per H.
TEST(HbmVsTimeIntegration, UnilateralImpactTracedWholeAndAgainstNewmark) {
  const Eigen::MatrixXd M = Eigen::MatrixXd::Identity(1, 1), K = M, C = 0.1 * M;
  std::vector<double> last, atStart;
  for (int H : {6, 12, 24}) {
    const hbm::HarmonicSet set = hbm::HarmonicSet::upTo(H);
    auto sys = std::make_unique<hbm::HarmonicBalanceSystem>(M, C, K, set, std::max(256, set.nonsmoothSamples()));
    sys->addElement(std::make_shared<hbm::UnilateralSpring>(50.0, 0.0), Eigen::VectorXd::Ones(1));
    sys->addStaticLoad(0, 0.1);
    sys->addExcitation(0, 1, 0.5);
    const int nc = sys->numCoefficients();
    response::ForcedResponseSetup setup;
    setup.system = std::move(sys);
    setup.outputDofs = {0};
    // Newmark at the stable points nearest W = 2.2 (past the resonance), 1.4 (below it)
    // and 0.5 (the first point: from H = 12 on, Newton from rest stalls there and the
    // first harmonics' solution carried up starts the curve; there the impacts excite
    // the closed frequency sqrt(51) through the 14th harmonic, so it converges slowly:
    // 0.17, 0.035, 0.0069 at H = 6, 12, 24).
    const auto whole = traceWholeAgainstNewmark(setup, H, {2.2, 1.4, 0.5}, [&](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
      return std::abs(hbm::peakMagnitude(set, a.head(nc)) / hbm::peakMagnitude(set, b.head(nc)) - 1);
    });
    if (H >= 12) {
      EXPECT_NE(whole.curve.startMethod.find("first harmonics' solution carried up"), std::string::npos)
          << whole.curve.startMethod;
    }
    last = whole.errors;
    atStart.push_back(whole.errors[2]);
  }
  // At H = 24: 4e-6 and 1.2e-5 when this was written (H = 6: 1.6e-3 and 2.5e-2).
  EXPECT_LT(last[0], 1e-4);
  EXPECT_LT(last[1], 1e-4);
  EXPECT_LT(atStart[1], atStart[0] / 3);
  EXPECT_LT(atStart[2], atStart[1] / 3);
}
