// Analytic Jacobians of every element, in the time domain (df[n]/dw[m]) and in
// coefficient space (harmonicForce), against central finite differences.
#include "cyclone/hbm/Aft.hpp"
#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/HarmonicForce.hpp"
#include "cyclone/hbm/JenkinsElement.hpp"
#include "cyclone/hbm/QuadraticDamper.hpp"
#include "cyclone/hbm/UnilateralSpring.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace cyclone::hbm;

namespace {

// Generic multi-harmonic coefficients (random amplitudes, so no sample sits
// exactly on a stick/slip or contact transition).
Eigen::VectorXd randomCoefficients(const HarmonicSet& set, double scale, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd x(set.numCoefficients());
  for (int i = 0; i < x.size(); ++i) x[i] = scale * u(rng);
  x[set.cosIndex(1)] += 2 * scale;  // a dominant first harmonic
  return x;
}

double relativeError(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& fd) {
  return (analytic - fd).cwiseAbs().maxCoeff() / std::max(analytic.cwiseAbs().maxCoeff(), 1e-300);
}

struct Named {
  std::string name;
  std::shared_ptr<ScalarElement> element;
  double scale;  // amplitude that exercises the nonlinearity
};

std::vector<Named> elements() {
  return {{"cubic", std::make_shared<CubicSpring>(1.3), 1.0},
          {"unilateral", std::make_shared<UnilateralSpring>(4.0, 0.3), 1.0},
          {"unilateral preload", std::make_shared<UnilateralSpring>(4.0, -0.5), 1.0},
          {"quadratic damper", std::make_shared<QuadraticDamper>(0.8), 1.0},
          {"jenkins", std::make_shared<JenkinsElement>(2.0, 3.0), 2.5}};
}

}  // namespace

TEST(ElementJacobians, TimeDomainMatchesFiniteDifferences) {
  const Aft aft(HarmonicSet::upTo(5), 64);
  const int n = aft.numSamples();
  unsigned seed = 100;
  for (const Named& e : elements()) {
    const Eigen::VectorXd x = randomCoefficients(aft.harmonics(), e.scale, seed++);
    const Eigen::VectorXd w = aft.toTime(x);
    const Eigen::VectorXd wdot = aft.toTime(Eigen::VectorXd(1.7 * (aft.derivativeMatrix() * x)));
    Eigen::VectorXd f, fp, fm;
    Eigen::MatrixXd dfdw, dfdwdot;
    e.element->evaluate(w, wdot, f, &dfdw, &dfdwdot);
    ASSERT_EQ(dfdw.rows(), n);
    ASSERT_EQ(dfdw.cols(), n);
    Eigen::MatrixXd fdW(n, n), fdWdot(n, n);
    const double h = 1e-6 * e.scale;
    for (int m = 0; m < n; ++m) {
      Eigen::VectorXd wp = w, wm = w;
      wp[m] += h;
      wm[m] -= h;
      e.element->evaluate(wp, wdot, fp, nullptr, nullptr);
      e.element->evaluate(wm, wdot, fm, nullptr, nullptr);
      fdW.col(m) = (fp - fm) / (2 * h);
      Eigen::VectorXd vp = wdot, vm = wdot;
      vp[m] += h;
      vm[m] -= h;
      e.element->evaluate(w, vp, fp, nullptr, nullptr);
      e.element->evaluate(w, vm, fm, nullptr, nullptr);
      fdWdot.col(m) = (fp - fm) / (2 * h);
    }
    const Eigen::MatrixXd& nonzero = e.element->usesVelocity() ? dfdwdot : dfdw;
    const Eigen::MatrixXd& nonzeroFd = e.element->usesVelocity() ? fdWdot : fdW;
    std::printf("time-domain Jacobian %-18s relative error %.2e\n", e.name.c_str(), relativeError(nonzero, nonzeroFd));
    EXPECT_LT(relativeError(nonzero, nonzeroFd), 1e-6) << e.name;
    const Eigen::MatrixXd& zero = e.element->usesVelocity() ? dfdw : dfdwdot;
    const Eigen::MatrixXd& zeroFd = e.element->usesVelocity() ? fdW : fdWdot;
    EXPECT_EQ(zero.cwiseAbs().maxCoeff(), 0.0) << e.name;
    EXPECT_EQ(zeroFd.cwiseAbs().maxCoeff(), 0.0) << e.name;
  }
}

TEST(ElementJacobians, JenkinsJacobianIsFullAndNotTrivial) {
  // The hysteretic element must couple samples (a memoryless diagonal would
  // pass a weak test): check the FD columns see off-diagonal terms too.
  const Aft aft(HarmonicSet::upTo(3), 64);
  const Eigen::VectorXd w = aft.toTime(randomCoefficients(aft.harmonics(), 2.5, 7));
  Eigen::VectorXd f;
  Eigen::MatrixXd dfdw;
  JenkinsElement(2.0, 3.0).evaluate(w, Eigen::VectorXd(), f, &dfdw, nullptr);
  const Eigen::MatrixXd offDiagonal = dfdw - Eigen::MatrixXd(dfdw.diagonal().asDiagonal());
  EXPECT_GT(offDiagonal.cwiseAbs().maxCoeff(), 0.5);
  int stick = 0;
  for (int i = 0; i < f.size(); ++i) stick += std::abs(f[i]) < 3.0;
  EXPECT_GT(stick, 0);
  EXPECT_LT(stick, f.size());  // both stick and slip samples present
}

TEST(ElementJacobians, HarmonicForceMatchesFiniteDifferences) {
  const Aft aft(HarmonicSet::upTo(5), 128);
  const int nc = aft.numCoefficients();
  const double omega = 1.7;
  unsigned seed = 200;
  for (const Named& e : elements()) {
    const Eigen::VectorXd x = randomCoefficients(aft.harmonics(), e.scale, seed++);
    Eigen::MatrixXd jacobian;
    harmonicForce(*e.element, aft, x, &jacobian, omega);
    ASSERT_EQ(jacobian.rows(), nc);
    ASSERT_EQ(jacobian.cols(), nc);
    Eigen::MatrixXd fd(nc, nc);
    const double h = 1e-6 * e.scale;
    for (int m = 0; m < nc; ++m) {
      Eigen::VectorXd xp = x, xm = x;
      xp[m] += h;
      xm[m] -= h;
      fd.col(m) = (harmonicForce(*e.element, aft, xp, nullptr, omega) -
                   harmonicForce(*e.element, aft, xm, nullptr, omega)) / (2 * h);
    }
    std::printf("coefficient Jacobian %-18s relative error %.2e\n", e.name.c_str(), relativeError(jacobian, fd));
    EXPECT_LT(relativeError(jacobian, fd), 1e-6) << e.name;
  }
}

TEST(ElementJacobians, ForceSensitivityIsTheDenseJacobianTimesTheSensitivities) {
  // Each element's O(N m) forceSensitivity against evaluate()'s dense N x N
  // matrices times the same sensitivities (ScalarElement's default), with the AFT's
  // own ones: the samples' dependence on the coefficients and its time derivative.
  const Aft aft(HarmonicSet::upTo(5), 128);
  const double omega = 1.7;
  const Eigen::MatrixXd& e = aft.timeFromCoefficients();
  const Eigen::MatrixXd edot = omega * (e * aft.derivativeMatrix());
  unsigned seed = 300;
  for (const Named& el : elements()) {
    const Eigen::VectorXd x = randomCoefficients(aft.harmonics(), el.scale, seed++);
    const Eigen::VectorXd w = aft.toTime(x);
    const Eigen::VectorXd wdot = aft.toTime(Eigen::VectorXd(omega * (aft.derivativeMatrix() * x)));
    Eigen::VectorXd f, fDense;
    Eigen::MatrixXd df, dfdw, dfdwdot;
    el.element->forceSensitivity(w, wdot, e, edot, f, df);
    el.element->evaluate(w, wdot, fDense, &dfdw, &dfdwdot);
    const Eigen::MatrixXd dense = dfdw * e + dfdwdot * edot;
    std::printf("force sensitivity %-18s against the dense Jacobian %.2e, |df| %.2e\n", el.name.c_str(),
                relativeError(df, dense), dense.cwiseAbs().maxCoeff());
    EXPECT_GT(dense.cwiseAbs().maxCoeff(), 0.1) << el.name;
    EXPECT_LT(relativeError(df, dense), 1e-13) << el.name;
    EXPECT_LT((f - fDense).cwiseAbs().maxCoeff(), 1e-14 * std::max(1.0, fDense.cwiseAbs().maxCoeff())) << el.name;
  }
}
