// Friction contact with normal load variation (2D) and a circular friction
// limit (3D): its describing functions against closed forms and against the
// 1D elements it must reduce to, its coefficient Jacobian against finite
// differences, and its one-step law against its periodic march.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/HarmonicForce.hpp"
#include "cyclone/hbm/JenkinsElement.hpp"
#include "cyclone/hbm/UnilateralSpring.hpp"

using namespace cyclone;
using namespace cyclone::hbm;

namespace {

FrictionContactParameters params(int dirs, double kt, double kn, double mu, double n0) {
  FrictionContactParameters p;
  p.tangentialDirections = dirs, p.kt = kt, p.kn = kn, p.mu = mu, p.preload = n0;
  return p;
}

Eigen::MatrixXd force(const NonlinearElement& e, const Aft& aft, const Eigen::MatrixXd& W,
                      Eigen::MatrixXd* J = nullptr) {
  Eigen::MatrixXd F;
  e.harmonicForce(aft, W, 1.0, F, J);
  return F;
}

// Largest entry of (analytic - central-difference Jacobian) over the largest of the analytic one.
double jacobianError(const NonlinearElement& e, const Aft& aft, const Eigen::MatrixXd& W) {
  const Eigen::Index m = W.size();
  Eigen::MatrixXd J, fd(m, m);
  force(e, aft, W, &J);
  const double h = 1e-7;
  for (Eigen::Index j = 0; j < m; ++j) {
    Eigen::MatrixXd Wp = W, Wm = W;
    Wp.data()[j] += h, Wm.data()[j] -= h;
    const Eigen::MatrixXd dF = (force(e, aft, Wp) - force(e, aft, Wm)) / (2 * h);
    fd.col(j) = Eigen::Map<const Eigen::VectorXd>(dF.data(), m);
  }
  return (J - fd).cwiseAbs().maxCoeff() / J.cwiseAbs().maxCoeff();
}

// The one-step law marched from the relaxed state over `periods` periods of the
// motion W; the last period's force samples.
Eigen::MatrixXd marchedForceSamples(const FrictionContact& contact, const Aft& aft, const Eigen::MatrixXd& W,
                                    int periods) {
  const int d = int(W.cols());
  Eigen::MatrixXd w(aft.numSamples(), d), f(aft.numSamples(), d);
  for (int c = 0; c < d; ++c) w.col(c) = aft.toTime(Eigen::VectorXd(W.col(c)));
  Eigen::VectorXd state = contact.initialState(), none;
  Eigen::MatrixXd dfdw, dfdv;
  for (int period = 0; period < periods; ++period)
    for (int i = 0; i < aft.numSamples(); ++i)
      f.row(i) = contact.incremental(w.row(i).transpose(), none, state, dfdw, dfdv).transpose();
  return f;
}

}  // namespace

// Constant normal load (kn = 0): the tangential part is the Jenkins element
// (k = 2, slip force 3). Its describing function under u = U cos t (U = 5) is known
// in closed form, a1 = (k U / pi) (b - sin(2 b) / 2), b1 = -(4 fs / pi) (1 - fs / (k U)),
// cos b = 1 - 2 fs / (k U): the contact (its instants located between the samples)
// converges to it at fourth order in 1 / N, the sampled Jenkins element at first.
// On a multi-harmonic motion the two agree to the sampled element's error.
TEST(FrictionContact, ConstantNormalLoadIsJenkins) {
  const double k = 2.0, fs = 3.0, U = 5.0;
  const FrictionContact contact(params(1, k, 0.0, 0.5, 6.0));
  const JenkinsElement jenkins(k, fs);
  const double b = std::acos(1 - 2 * fs / (k * U));
  const Eigen::Vector2d exact(k * U / M_PI * (b - std::sin(2 * b) / 2), -4 * fs / M_PI * (1 - fs / (k * U)));
  std::printf("Jenkins under U cos t: samples, error and time of the located contact, of the sampled element\n");
  double located[2] = {0, 0};
  for (int samples : {64, 128, 256, 512}) {
    const Aft aft(HarmonicSet::upTo(5), samples);
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(aft.numCoefficients(), 2);
    W(aft.harmonics().cosIndex(1), 0) = U;
    W(aft.harmonics().cosIndex(0), 1) = 0.3;  // normal motion does nothing when kn = 0
    Timer timer;
    const Eigen::MatrixXd F = force(contact, aft, W);
    const double locatedSeconds = timer.seconds();
    timer.restart();
    const Eigen::VectorXd Fj = harmonicForce(jenkins, aft, Eigen::VectorXd(W.col(0)));
    const double sampledSeconds = timer.seconds();
    const int c1 = aft.harmonics().cosIndex(1), s1 = aft.harmonics().sinIndex(1);
    const double error = (Eigen::Vector2d(F(c1, 0), F(s1, 0)) - exact).norm() / exact.norm();
    const double sampled = (Eigen::Vector2d(Fj(c1), Fj(s1)) - exact).norm() / exact.norm();
    std::printf("  %4d  %.2e %.5f s  %.2e %.5f s\n", samples, error, locatedSeconds, sampled, sampledSeconds);
    EXPECT_NEAR(F(aft.harmonics().cosIndex(0), 1), 6.0, 1e-12);
    if (samples == 128) located[0] = error;
    if (samples == 512) located[1] = error;
  }
  EXPECT_LT(located[1], 1e-7);
  EXPECT_GT(located[0] / located[1], 64.0);  // fourth order: 256 from 128 to 512 samples
  const Aft aft(HarmonicSet::upTo(5), 4096);
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(aft.numCoefficients(), 2);
  W(aft.harmonics().cosIndex(1), 0) = U;
  W(aft.harmonics().cosIndex(3), 0) = 0.7;
  W(aft.harmonics().sinIndex(2), 0) = -0.9;
  const Eigen::MatrixXd F = force(contact, aft, W);
  const Eigen::VectorXd Fj = harmonicForce(jenkins, aft, Eigen::VectorXd(W.col(0)));
  EXPECT_LT((F.col(0) - Fj).norm(), 1e-3 * Fj.norm());
}

// The normal force is the unilateral spring's law max(N0 + kn n, 0) = kn max(n + N0/kn, 0),
// UnilateralSpring(kn, gap = -N0/kn) (closed forms tested elsewhere). Where the contact
// stays closed the two are the same sampled law to rounding; where it opens, the spring
// locates its instants between the samples and the contact samples them, and both give
// the harmonics of the law itself (by 2^16 samples of it) to 1e-4 at 512 samples.
TEST(FrictionContact, NormalForceIsTheUnilateralSpring) {
  const Aft aft(HarmonicSet::upTo(7), 512);
  const Aft fine(HarmonicSet::upTo(7), 1 << 16);
  for (double n0 : {15.0, 5.0, -2.0}) {  // closed throughout, a preload that opens, a clearance of 2/kn
    const FrictionContact contact(params(2, 3.0, 4.0, 0.3, n0));
    const UnilateralSpring spring(4.0, -n0 / 4.0);
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(aft.numCoefficients(), 3);
    W(aft.harmonics().cosIndex(1), 2) = 3.0;  // opens and closes every period unless n0 = 15
    W(aft.harmonics().sinIndex(2), 2) = 0.4;
    W(aft.harmonics().cosIndex(1), 0) = 1.0;
    W(aft.harmonics().sinIndex(1), 1) = 0.5;
    const Eigen::MatrixXd F = force(contact, aft, W);
    const Eigen::VectorXd Fs = harmonicForce(spring, aft, Eigen::VectorXd(W.col(2)));
    const Eigen::VectorXd n = fine.toTime(Eigen::VectorXd(W.col(2)));
    const Eigen::VectorXd exact = fine.toFrequency(Eigen::VectorXd((n0 + 4.0 * n.array()).max(0.0).matrix()));
    if (n0 > 13.6) {  // 15 - 4 (3 + 0.4) > 0: never opens
      EXPECT_LT((F.col(2) - Fs).norm(), 1e-12 * Fs.norm()) << n0;
    }
    EXPECT_LT((F.col(2) - exact).norm(), 1e-4 * exact.norm()) << n0;
    EXPECT_LT((Fs - exact).norm(), 1e-4 * exact.norm()) << n0;
  }
}

// Circular relative motion w_t = U (cos t, sin t) under constant N: after the
// first slip the slider lags on a circle and the friction force has constant
// magnitude mu N, leading the motion by beta with cos(beta) = (mu N / kt) / U.
// Its first harmonic is mu N [cos(t + beta), sin(t + beta)]. Two independent 1D
// sliders (a square friction limit) give a different, wrong force. The
// discrete march converges to the closed form at first order in 1/N.
TEST(FrictionContact, CircularSlipMatchesClosedForm) {
  const double kt = 10.0, mu = 0.4, N0 = 5.0, U = 0.5;
  const FrictionContact contact(params(2, kt, 0.0, mu, N0));
  const double beta = std::acos(mu * N0 / kt / U);
  const Eigen::Vector4d exact(mu * N0 * std::cos(beta), -mu * N0 * std::sin(beta), mu * N0 * std::sin(beta),
                              mu * N0 * std::cos(beta));
  double previous = 0;
  std::printf("circular slip: N, relative error of the first harmonic, time\n");
  for (int samples : {256, 1024, 4096, 16384}) {
    Timer t;
    const Aft aft(HarmonicSet::upTo(3), samples);
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(aft.numCoefficients(), 3);
    W(aft.harmonics().cosIndex(1), 0) = U;
    W(aft.harmonics().sinIndex(1), 1) = U;
    const Eigen::MatrixXd F = force(contact, aft, W);
    const int c = aft.harmonics().cosIndex(1);
    const Eigen::Vector4d got(F(c, 0), F(c + 1, 0), F(c, 1), F(c + 1, 1));
    const double err = (got - exact).norm() / exact.norm();
    std::printf("  %6d  %.3e  %.4f s", samples, err, t.seconds());
    if (previous > 0) std::printf("  order %.2f", std::log2(previous / err) / 2);
    std::printf("\n");
    if (previous > 0) {
      EXPECT_GT(std::log2(previous / err) / 2, 0.9);  // first order in 1/N
    }
    previous = err;
    if (samples == 16384) {
      EXPECT_LT(err, 1e-3);
    }
    // Higher harmonics vanish for steady circular slip.
    EXPECT_LT(std::hypot(F(aft.harmonics().cosIndex(3), 0), F(aft.harmonics().sinIndex(3), 0)), 1e-2 * mu * N0);
  }
  // Two 1D sliders in x and y under the same motion dissipate differently.
  const Aft aft(HarmonicSet::upTo(3), 4096);
  const JenkinsElement slider(kt, mu * N0);
  Eigen::VectorXd wx = Eigen::VectorXd::Zero(aft.numCoefficients());
  wx(aft.harmonics().cosIndex(1)) = U;
  const Eigen::VectorXd fx = harmonicForce(slider, aft, wx);
  const double dissipatedCircle = M_PI * U * mu * N0 * std::sin(beta) * 2;  // per period
  const double dissipatedSquare = 2 * M_PI * U * std::abs(fx(aft.harmonics().sinIndex(1)));  // x and y
  std::printf("energy per period: circular limit %.4f, two 1D sliders %.4f\n", dissipatedCircle, dissipatedSquare);
  EXPECT_GT(std::abs(dissipatedSquare / dissipatedCircle - 1), 0.05);
}

TEST(FrictionContact, JacobianMatchesFiniteDifferences) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int dirs : {1, 2})
    for (double n0 : {2.0, 0.0, -0.5}) {
      const FrictionContact contact(params(dirs, 3.0, 5.0, 0.6, n0));
      const Aft aft(HarmonicSet::upTo(4), 128);
      const int nc = aft.numCoefficients(), d = dirs + 1;
      Eigen::MatrixXd W(nc, d);
      for (int i = 0; i < W.size(); ++i) W.data()[i] = 0.4 * u(rng);
      for (int c = 0; c < d; ++c) W(aft.harmonics().cosIndex(1), c) += 1.0;  // slip, separation and stick
      W(aft.harmonics().cosIndex(0), d - 1) = 0.2;
      const double err = jacobianError(contact, aft, W);
      std::printf("friction %dD, N0 = %4.1f: Jacobian vs finite differences %.2e\n", dirs + 1, n0, err);
      EXPECT_LT(err, 1e-6);
    }
}

// The time integrator's one-step law, marched over the samples of a periodic
// motion from the relaxed state, settles on the harmonic balance's force samples.
TEST(FrictionContact, IncrementalLawMatchesThePeriodicMarch) {
  const FrictionContact contact(params(2, 3.0, 5.0, 0.6, 1.0));
  const Aft aft(HarmonicSet::upTo(3), 256);
  const int nc = aft.numCoefficients();
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(nc, 3);
  W(aft.harmonics().cosIndex(1), 0) = 1.0;
  W(aft.harmonics().sinIndex(1), 1) = 0.6;
  W(aft.harmonics().cosIndex(2), 2) = 0.3;
  const Eigen::MatrixXd F = force(contact, aft, W);
  const Eigen::MatrixXd f = marchedForceSamples(contact, aft, W, 10);
  for (int c = 0; c < 3; ++c)
    EXPECT_LT((aft.toFrequency(Eigen::VectorXd(f.col(c))) - F.col(c)).norm(), 1e-10 * F.norm()) << c;
}

// Just past the onset of slip a 3D slider drifts to its periodic state by a
// factor of about 1 - 2 eps per period (here eps = 1e-3: a tangential ellipse
// whose half-axis exceeds the slip radius by 0.1 %, offset sideways), so a march
// of a few hundred periods stops far from it. The harmonic force must still be
// the periodic one: the one-step law marched for 20 000 periods (to e^-40) is the
// reference, and the Jacobian must match finite differences there.
TEST(FrictionContact, SlowlySettlingSlipIsThePeriodicState) {
  const double kt = 10.0, mu = 0.4, N0 = 5.0, r = mu * N0 / kt, eps = 1e-3;
  const FrictionContact contact(params(2, kt, 0.0, mu, N0));
  const Aft aft(HarmonicSet::upTo(3), 256);
  const int nc = aft.numCoefficients();
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(nc, 3);
  W(aft.harmonics().cosIndex(1), 0) = r * (1 + eps);
  W(aft.harmonics().sinIndex(1), 1) = 0.25 * r;
  W(aft.harmonics().cosIndex(0), 1) = 0.5 * r;
  Timer timer;
  const Eigen::MatrixXd F = force(contact, aft, W);
  const double seconds = timer.seconds();
  const Eigen::MatrixXd f = marchedForceSamples(contact, aft, W, 20000);
  double err = 0;
  for (int c = 0; c < 2; ++c)
    err = std::max(err, (aft.toFrequency(Eigen::VectorXd(f.col(c))) - F.col(c)).norm() / (mu * N0));
  const double jac = jacobianError(contact, aft, W);
  std::printf("slip onset + 0.1 %%: force against 20 000 marched periods %.2e (%.4f s), Jacobian vs FD %.2e\n", err,
              seconds, jac);
  EXPECT_LT(err, 1e-10);
  EXPECT_LT(jac, 1e-6);
}

TEST(FrictionContact, BadParametersAreNamed) {
  EXPECT_THROW(FrictionContact(params(3, 1, 1, 0.3, 1)), InputError);
  EXPECT_THROW(FrictionContact(params(1, 0, 1, 0.3, 1)), InputError);
  EXPECT_THROW(FrictionContact(params(1, 1, -1, 0.3, 1)), InputError);
  EXPECT_THROW(FrictionContact(params(1, 1, 1, -0.3, 1)), InputError);
  EXPECT_THROW(FrictionContact(params(1, 1, 0, 0.3, 0)), InputError);  // no normal load at all
  try {
    FrictionContact(params(1, -2, 1, 0.3, 1));
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("kt"), std::string::npos) << e.what();
  }
}

// The contact stiffness of a study (kn = kt = the value) is one parameter: the element
// it gives is the one built with those stiffnesses, force for force.
TEST(FrictionContact, StiffnessParameterSetsKnAndKtTogether) {
  const FrictionContact base(params(2, 1.0, 2.0, 0.3, 0.5));
  const auto varied = base.withParameter("stiffness", 3.0);
  const auto& p = static_cast<const FrictionContact&>(*varied).parameters();
  EXPECT_EQ(p.kt, 3.0);
  EXPECT_EQ(p.kn, 3.0);
  const FrictionContact built(params(2, 3.0, 3.0, 0.3, 0.5));
  const Aft aft(HarmonicSet::upTo(3), 64);
  Eigen::MatrixXd W(aft.numCoefficients(), 3);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (Eigen::Index i = 0; i < W.size(); ++i) W.data()[i] = u(rng);
  EXPECT_EQ(force(*varied, aft, W), force(built, aft, W));
  EXPECT_THROW(base.withParameter("stifness", 3.0), InputError);
}

// Limits: mu = 0 transmits no tangential force; a huge preload holds the
// contact stuck, so the tangential force is the linear spring kt w_t.
TEST(FrictionContact, FrictionlessAndStuckLimits) {
  const Aft aft(HarmonicSet::upTo(3), 128);
  const int nc = aft.numCoefficients();
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(nc, 3);
  W(aft.harmonics().cosIndex(1), 0) = 1.0;
  W(aft.harmonics().sinIndex(1), 1) = 0.5;
  W(aft.harmonics().cosIndex(1), 2) = 0.2;
  const Eigen::MatrixXd F0 = force(FrictionContact(params(2, 3.0, 5.0, 0.0, 2.0)), aft, W);
  EXPECT_LT(F0.leftCols(2).norm(), 1e-14);
  const Eigen::MatrixXd Fs = force(FrictionContact(params(2, 3.0, 5.0, 0.5, 1e9)), aft, W);
  EXPECT_LT((Fs.leftCols(2) - 3.0 * W.leftCols(2)).norm(), 1e-12 * Fs.leftCols(2).norm());
}

// The cyclic reduction assumes a sector's contact force is the time-shifted
// copy of its neighbour's when the motion is: F(W shifted by s samples) must be
// F(W) shifted. The periodic state of the march may not depend on where in the
// period the march begins.
TEST(FrictionContact, TimeShiftInvariant) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const int samples = 256, H = 3;
  const Aft aft(HarmonicSet::upTo(H), samples);
  const HarmonicSet& hs = aft.harmonics();
  auto shifted = [&](const Eigen::MatrixXd& X, int s) {  // x(t + s dt)
    Eigen::MatrixXd Y = X;
    for (int h = 1; h <= H; ++h) {
      const double a = 2 * M_PI * h * s / samples, c = std::cos(a), sn = std::sin(a);
      for (int col = 0; col < X.cols(); ++col) {
        const double ch = X(hs.cosIndex(h), col), sh = X(hs.sinIndex(h), col);
        Y(hs.cosIndex(h), col) = c * ch + sn * sh;
        Y(hs.sinIndex(h), col) = -sn * ch + c * sh;
      }
    }
    return Y;
  };
  double worst = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int dirs = 1 + trial % 2;
    const FrictionContact contact(params(dirs, 1.0, trial % 3 == 0 ? 0.0 : 1.0, 0.4, 1.0 + 0.5 * u(rng)));
    Eigen::MatrixXd W(aft.numCoefficients(), dirs + 1);
    for (int i = 0; i < W.rows(); ++i)
      for (int c = 0; c <= dirs; ++c) W(i, c) = (i == 0 ? 1.0 : 1.0 / i) * u(rng);
    const Eigen::MatrixXd F = force(contact, aft, W);
    for (int s : {1, 37, 96, 200}) {
      const Eigen::MatrixXd Fs = force(contact, aft, shifted(W, s));
      const double e = (Fs - shifted(F, s)).norm() / F.norm();
      worst = std::max(worst, e);
      EXPECT_LT(e, 1e-10) << "trial " << trial << " dirs " << dirs << " shift " << s;
    }
  }
  std::printf("time-shift invariance: worst relative difference %.2e\n", worst);
}

// A 3D contact that can stay stuck rests at the stuck state nearest the
// relaxed slider. Closed forms with constant radius r = mu N0 / kt (kt = 1):
//  - w_t = (B + a cos t, 0): the disks' intersection nearest 0 is the
//    projection onto the disk at B + a, the 1D answer: mean f_t1 = r - a;
//  - w_t = (A cos t, B), B > sqrt(r^2 - A^2): the crossing of the extreme
//    circles, z = (0, B - sqrt(r^2 - A^2)): mean f_t2 = sqrt(r^2 - A^2).
// The sampled extremes are exact at 256 samples (t = 0 and pi are samples).
// The Jacobian of each branch (one and two active disks, with normal motion
// moving the radii) against central differences.
TEST(FrictionContact, StuckStateIsNearestTheRelaxedOne) {
  const double mu = 0.5, n0 = 4.0, r = mu * n0;  // kt = 1
  const FrictionContact contact(params(2, 1.0, 0.0, mu, n0));
  const Aft aft(HarmonicSet::upTo(3), 256);
  const HarmonicSet& hs = aft.harmonics();
  const int nc = aft.numCoefficients();
  {
    const double B = 3.0, a = 0.5;
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(nc, 3);
    W(hs.cosIndex(0), 0) = B, W(hs.cosIndex(1), 0) = a;
    const Eigen::MatrixXd F = force(contact, aft, W);
    EXPECT_NEAR(F(hs.cosIndex(0), 0), r - a, 1e-12);
    EXPECT_NEAR(F(hs.cosIndex(0), 1), 0.0, 1e-12);
    EXPECT_NEAR(F(hs.cosIndex(1), 0), a, 1e-12);  // stuck: the spring's own harmonic
  }
  {
    const double A = 1.2, B = 3.0;
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(nc, 3);
    W(hs.cosIndex(1), 0) = A, W(hs.cosIndex(0), 1) = B;
    const Eigen::MatrixXd F = force(contact, aft, W);
    EXPECT_NEAR(F(hs.cosIndex(0), 0), 0.0, 1e-12);
    EXPECT_NEAR(F(hs.cosIndex(0), 1), std::sqrt(r * r - A * A), 1e-12);
  }
  const FrictionContact pressing(params(2, 1.0, 2.0, mu, n0));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int active : {1, 2}) {
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(nc, 3);
    if (active == 1) W(hs.cosIndex(0), 0) = 3.0, W(hs.cosIndex(1), 0) = 0.5;
    else W(hs.cosIndex(1), 0) = 1.2, W(hs.cosIndex(0), 1) = 3.0;
    for (int i = 1; i < nc; ++i)
      for (int c = 0; c < 3; ++c) W(i, c) += 0.03 * u(rng);  // a general motion near the closed form
    const double err = jacobianError(pressing, aft, W);
    std::printf("stuck 3D contact, %d active disk(s): Jacobian vs finite differences %.2e\n", active, err);
    EXPECT_LT(err, 1e-6);
  }
}

// The force samples are the contact law itself, sampled: the slip plateau at exactly
// mu N0, and the same samples as the Jenkins element's sampled law (constant normal
// load: the same law, another implementation). (harmonicForce locates the instants
// between the samples instead: ConstantNormalLoadIsJenkins.) The truncated Fourier
// series of the harmonics (the base-class default) overshoots the plateau (Gibbs).
TEST(FrictionContact, ForceSamplesAreTheSampledLaw) {
  const FrictionContact contact(params(1, 2.0, 0.0, 0.5, 6.0));  // slip force 3
  const Aft aft(HarmonicSet::upTo(5), 256);
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(aft.numCoefficients(), 2);
  W(aft.harmonics().cosIndex(1), 0) = 5.0;
  const Eigen::MatrixXd f = contact.forceSamples(aft, W, 1.0);
  EXPECT_NEAR(f.col(0).cwiseAbs().maxCoeff(), 3.0, 1e-12);
  EXPECT_NEAR(f.col(1).minCoeff(), 6.0, 1e-12);
  const Eigen::VectorXd Fj = harmonicForce(JenkinsElement(2.0, 3.0), aft, Eigen::VectorXd(W.col(0)));
  EXPECT_LT((aft.toFrequency(Eigen::VectorXd(f.col(0))) - Fj).norm(), 1e-13 * Fj.norm());
  const Eigen::MatrixXd smooth = contact.NonlinearElement::forceSamples(aft, W, 1.0);
  EXPECT_GT(smooth.col(0).cwiseAbs().maxCoeff(), 3.0 + 1e-3);
}

// Just past the onset of circular slip, with the normal load varying, the period
// map settles slowly (the slip per period vanishes) and a march from the relaxed
// slider ended far from the periodic state: a force that jumped between nearby
// motions (0.023 of the friction limit), a wall no Newton crosses. Random H = 3
// orbits, each scaled to where its force changes fastest, the interval refined
// to 2e-8 of the amplitude: the force is continuous there (a square-root branch
// at the stuck set's vertex is, a jump is not).
TEST(FrictionContact, ForceIsContinuousThroughTheOnsetOfSlip) {
  const FrictionContact contact(params(2, 1.0, 1.0, 1.0, 1.0));
  const Aft aft(HarmonicSet::upTo(3), 256);
  const int nc = aft.numCoefficients();
  double largest = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> g;
    Eigen::MatrixXd mean = Eigen::MatrixXd::Zero(nc, 3), shape(nc, 3);
    mean(0, 0) = 0.5 * g(rng), mean(0, 1) = 0.5 * g(rng);
    for (int i = 0; i < shape.size(); ++i) shape.data()[i] = g(rng) / (1 + (i % nc));
    shape.row(0).setZero();
    shape.col(2) *= 0.3;
    auto F = [&](double a) {
      const Eigen::MatrixXd f = force(contact, aft, mean + a * shape);
      return Eigen::Map<const Eigen::VectorXd>(f.data(), f.size()).eval();
    };
    double lo = 0.2, hi = 3.0, at = lo, change = 0;
    for (int pass = 0; pass < 5; ++pass) {  // 100 intervals, then 100 around the steepest, 4 times
      change = -1;
      Eigen::VectorXd previous = F(lo);
      for (int k = 1; k <= 100; ++k) {
        const double a = lo + (hi - lo) * k / 100;
        const Eigen::VectorXd next = F(a);
        if ((next - previous).norm() > change) change = (next - previous).norm(), at = a;
        previous = next;
      }
      const double h = (hi - lo) / 100;
      lo = at - 2 * h, hi = at + h;
    }
    largest = std::max(largest, change);
    EXPECT_LT(change, 1e-3) << "seed " << seed << ": the force jumps near a = " << at;
  }
  std::printf("40 orbits through the onset of slip: largest force change over 2e-8 of the amplitude %.2e\n",
              largest);
}

// Where the contact opens, closes, sticks and slips every period, each instant crosses
// the samples as the motion changes. The sampled law's harmonics have a kink at every
// crossing. Along a path that moves the instants across many samples (64 of them; the
// normal mean and the tangential amplitude grow), the largest change of the
// finite-difference slope between neighbouring steps: for a 2D contact (one tangential
// direction) with its instants located it falls with the step (by 8 from 2e-3 to
// 2.5e-4), as a C1 function's must, while the sampled law's stays (2.8: a kink's jump
// does not fall).
TEST(FrictionContact, LocatedInstantsLeaveNoKinks) {
  for (int dirs : {1}) {  // (a 3D contact keeps the sampled law: docs/solvers.md)
    const FrictionContact contact(params(dirs, 2.0, 50.0, 0.3, 2.0));
    const Aft aft(HarmonicSet::upTo(5), 64);
    const int nc = aft.numCoefficients(), d = dirs + 1;
    Eigen::MatrixXd W0 = Eigen::MatrixXd::Zero(nc, d), V = Eigen::MatrixXd::Zero(nc, d);
    W0(aft.harmonics().cosIndex(1), 0) = 1.0, W0(aft.harmonics().sinIndex(2), 0) = 0.2;
    if (dirs == 2) W0(aft.harmonics().sinIndex(1), 1) = 0.7, W0(aft.harmonics().cosIndex(3), 1) = 0.1;
    W0(aft.harmonics().cosIndex(1), d - 1) = 0.5, W0(aft.harmonics().sinIndex(1), d - 1) = 0.2;
    V(aft.harmonics().cosIndex(0), d - 1) = 0.2, V(aft.harmonics().cosIndex(1), 0) = 0.3;
    auto largestSlopeJump = [&](bool located, double step) {
      auto F = [&](double a) {
        const Eigen::MatrixXd W = W0 + a * V;
        if (located) return Eigen::MatrixXd(force(contact, aft, W));
        const Eigen::MatrixXd f = contact.forceSamples(aft, W, 1.0);
        Eigen::MatrixXd Fs(nc, d);
        for (int c = 0; c < d; ++c) Fs.col(c) = aft.toFrequency(Eigen::VectorXd(f.col(c)));
        return Fs;
      };
      double jump = 0;
      Eigen::MatrixXd previous = F(0.0), slope;
      for (int k = 1; k * step <= 1.0 + 1e-12; ++k) {
        const Eigen::MatrixXd next = F(k * step), nextSlope = (next - previous) / step;
        if (k > 1) jump = std::max(jump, (nextSlope - slope).norm());
        slope = nextSlope, previous = next;
      }
      return jump;
    };
    const double located[2] = {largestSlopeJump(true, 2e-3), largestSlopeJump(true, 2.5e-4)};
    const double sampled[2] = {largestSlopeJump(false, 2e-3), largestSlopeJump(false, 2.5e-4)};
    std::printf("%dD contact: largest slope jump at steps 2e-3 and 2.5e-4: located %.2e %.2e, sampled law %.2e %.2e\n",
                d, located[0], located[1], sampled[0], sampled[1]);
    EXPECT_LT(sampled[0] / sampled[1], 2.0) << d << "D";
    EXPECT_GT(located[0] / located[1], 6.0);
  }
}
