// Aft against direct evaluation of the Fourier sum x0 + sum (c cos + s sin).
#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/Aft.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using cyclone::InputError;
using cyclone::hbm::Aft;
using cyclone::hbm::HarmonicSet;
using cyclone::hbm::peakMagnitude;

namespace {

constexpr double kPi = 3.14159265358979323846;

Eigen::VectorXd randomCoefficients(int nc, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd x(nc);
  for (int i = 0; i < nc; ++i) x[i] = u(rng);
  return x;
}

// The Fourier sum written out term by term, independent of FFTW and of Aft.
double fourierSum(const HarmonicSet& set, const Eigen::VectorXd& x, double tau) {
  double sum = 0;
  for (int h : set.harmonics()) {
    if (h == 0)
      sum += x[set.cosIndex(0)];
    else
      sum += x[set.cosIndex(h)] * std::cos(h * tau) + x[set.sinIndex(h)] * std::sin(h * tau);
  }
  return sum;
}

double fourierDerivative(const HarmonicSet& set, const Eigen::VectorXd& x, double tau) {
  double sum = 0;
  for (int h : set.harmonics())
    if (h > 0) sum += -h * x[set.cosIndex(h)] * std::sin(h * tau) + h * x[set.sinIndex(h)] * std::cos(h * tau);
  return sum;
}

struct Case {
  HarmonicSet set;
  int samples;
};

std::vector<Case> cases() {
  return {{HarmonicSet::upTo(5), 11}, {HarmonicSet::upTo(5), 16}, {HarmonicSet::odd(7), 32},
          {HarmonicSet({3, 0, 1}), 7}, {HarmonicSet({2, 7}), 64}, {HarmonicSet::upTo(20), 41}};
}

}  // namespace

TEST(Aft, RoundTripOfBandLimitedCoefficients) {
  unsigned seed = 1;
  for (const Case& c : cases()) {
    const Aft aft(c.set, c.samples);
    const Eigen::VectorXd x = randomCoefficients(aft.numCoefficients(), seed++);
    Eigen::VectorXd samples(c.samples), back(aft.numCoefficients());
    aft.toTime(x.data(), samples.data());
    aft.toFrequency(samples.data(), back.data());
    EXPECT_LT((back - x).cwiseAbs().maxCoeff(), 1e-13) << "N = " << c.samples;
    // And again: the plans are reused, and c2r must not have eaten our input.
    EXPECT_LT((aft.toFrequency(aft.toTime(x)) - x).cwiseAbs().maxCoeff(), 1e-13);
  }
}

TEST(Aft, ToTimeMatchesDirectFourierSum) {
  unsigned seed = 10;
  for (const Case& c : cases()) {
    const Aft aft(c.set, c.samples);
    const Eigen::VectorXd x = randomCoefficients(aft.numCoefficients(), seed++);
    const Eigen::VectorXd samples = aft.toTime(x);
    for (int n = 0; n < c.samples; ++n)
      EXPECT_NEAR(samples[n], fourierSum(c.set, x, 2 * kPi * n / c.samples), 1e-13);
    // The dense matrix is the same map.
    EXPECT_LT((aft.timeFromCoefficients() * x - samples).cwiseAbs().maxCoeff(), 1e-13);
  }
}

TEST(Aft, CoefficientsFromTimeIsTheProjection) {
  unsigned seed = 20;
  for (const Case& c : cases()) {
    const Aft aft(c.set, c.samples);
    const int nc = aft.numCoefficients();
    const Eigen::MatrixXd pe = aft.coefficientsFromTime() * aft.timeFromCoefficients();
    EXPECT_LT((pe - Eigen::MatrixXd::Identity(nc, nc)).cwiseAbs().maxCoeff(), 1e-13);
    // Any samples (not band-limited): the FFT path and the dense matrix agree.
    const Eigen::VectorXd samples = randomCoefficients(c.samples, seed++);
    EXPECT_LT((aft.toFrequency(samples) - aft.coefficientsFromTime() * samples).cwiseAbs().maxCoeff(), 1e-13);
  }
}


// Columns projected at once (a Jacobian's sensitivity columns, written into a block of a
// larger matrix): each equals the dense projection of that column, and nothing outside
// the block is touched.
TEST(Aft, ColumnsProjectedIntoABlockAreTheDenseProjection) {
  unsigned seed = 40;
  for (const Case& c : cases()) {
    const Aft aft(c.set, c.samples);
    const int nc = aft.numCoefficients(), k = 5;
    Eigen::MatrixXd samples(c.samples, k);
    for (int j = 0; j < k; ++j) samples.col(j) = randomCoefficients(c.samples, seed++);
    Eigen::MatrixXd target = Eigen::MatrixXd::Constant(3 * nc, k + 2, 7.0);
    aft.toFrequencyColumns(samples, target.block(nc, 1, nc, k));
    EXPECT_LT((target.block(nc, 1, nc, k) - aft.coefficientsFromTime() * samples).cwiseAbs().maxCoeff(), 1e-13);
    target.block(nc, 1, nc, k).setConstant(7.0);
    EXPECT_EQ(target, Eigen::MatrixXd::Constant(3 * nc, k + 2, 7.0)) << "N = " << c.samples;
  }
  const Aft aft(HarmonicSet::upTo(3), 16);
  Eigen::MatrixXd wrong(aft.numCoefficients(), 2);
  EXPECT_THROW(aft.toFrequencyColumns(Eigen::MatrixXd::Zero(15, 2), wrong), cyclone::Error);
}
TEST(Aft, DerivativeMatrixMatchesAnalyticDerivative) {
  unsigned seed = 30;
  for (const Case& c : cases()) {
    const Aft aft(c.set, c.samples);
    const Eigen::VectorXd x = randomCoefficients(aft.numCoefficients(), seed++);
    const Eigen::VectorXd samples = aft.toTime(Eigen::VectorXd(aft.derivativeMatrix() * x));
    for (int n = 0; n < c.samples; ++n)
      EXPECT_NEAR(samples[n], fourierDerivative(c.set, x, 2 * kPi * n / c.samples), 1e-12);
  }
}

TEST(Aft, RejectsTooFewSamples) {
  EXPECT_THROW(Aft(HarmonicSet::upTo(3), 6), InputError);
  EXPECT_NO_THROW(Aft(HarmonicSet::upTo(3), 7));
}

// The peak of |x(t)| from coefficients: closed forms, where the AFT samples
// alone would fall short by up to 1 - cos(pi h / N).
TEST(PeakMagnitude, ClosedForms) {
  const HarmonicSet H = HarmonicSet::upTo(3);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(H.numCoefficients());
  x(H.cosIndex(1)) = 0.3, x(H.sinIndex(1)) = -0.4;  // amplitude 0.5 at a phase off every grid point
  EXPECT_NEAR(peakMagnitude(H, x), 0.5, 1e-14);
  x(H.cosIndex(0)) = -0.25;  // the mean shifts the peak of |x| to the negative lobe
  EXPECT_NEAR(peakMagnitude(H, x), 0.75, 1e-14);
  // x = cos t + cos 3t / 9 peaks at t = 0 (x' = -sin t - sin 3t / 3 = 0), value 10/9.
  x.setZero();
  x(H.cosIndex(1)) = 1.0, x(H.cosIndex(3)) = 1.0 / 9;
  EXPECT_NEAR(peakMagnitude(H, x), 10.0 / 9, 1e-14);
}
