// The elements' states at a solution against closed forms: a Jenkins element (spring kt
// in series with a slider of slip force fs) driven by w = a cos(wt) traces the loop of
// area 4 fs (a - fs/kt) per cycle; the energy from the coefficients (only harmonic 1 of
// the force works on a pure cosine, so it is exact but for where the AFT's samples place
// the slip events) and the sampled loop's area must both give it, and the sampled force
// must stay within the slip force.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/ElementStates.hpp"
#include "cyclone/hbm/JenkinsElement.hpp"

using namespace cyclone;

namespace {

// One DOF with a Jenkins element to ground; x = a cos(w t) as coefficients (H = 0..3).
struct DrivenJenkins {
  std::unique_ptr<hbm::HarmonicBalanceSystem> system;
  Eigen::VectorXd x;
};

DrivenJenkins drivenJenkins(double kt, double fs, double a, int samples) {
  DrivenJenkins d;
  const Eigen::MatrixXd M = Eigen::MatrixXd::Identity(1, 1), C = Eigen::MatrixXd::Zero(1, 1), K = M;
  d.system = std::make_unique<hbm::HarmonicBalanceSystem>(M, C, K, hbm::HarmonicSet::upTo(3), samples);
  d.system->addElement(std::make_shared<hbm::JenkinsElement>(kt, fs), Eigen::VectorXd::Ones(1));
  d.x = Eigen::VectorXd::Zero(d.system->numCoefficients());
  d.x(d.system->aft().harmonics().cosIndex(1)) = a;
  return d;
}

}  // namespace

TEST(ElementStates, JenkinsLoopDissipatesTheClosedFormEnergy) {
  const double kt = 2.0, fs = 0.3, a = 0.5, omega = 1.3;
  const double exact = 4 * fs * (a - fs / kt);
  for (int samples : {256, 1024, 4096}) {
    const auto started = std::chrono::steady_clock::now();
    const auto d = drivenJenkins(kt, fs, a, samples);
    const auto states = hbm::elementStates(*d.system, d.x, omega);
    ASSERT_EQ(states.size(), 1u);
    EXPECT_NEAR(states[0].W(d.system->aft().harmonics().cosIndex(1), 0), a, 1e-15);
    const double fromCoefficients = hbm::dissipatedEnergyPerCycle(d.system->aft().harmonics(), states[0]);
    const auto period = hbm::elementPeriod(*d.system, 0, states[0], omega);
    ASSERT_EQ(period.w.rows(), samples);
    // The sampled loop's area, closed: sum of f dw by the trapezoid rule.
    double area = 0;
    for (int i = 0; i < samples; ++i) {
      const int j = (i + 1) % samples;
      area += 0.5 * (period.f(i, 0) + period.f(j, 0)) * (period.w(j, 0) - period.w(i, 0));
    }
    area = std::abs(area);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    std::printf("%d samples: energy error %.1e from the coefficients, %.1e from the loop (closed form %.2f); %.1e s\n",
                samples, std::abs(fromCoefficients / exact - 1), std::abs(area / exact - 1), exact, seconds);
    // The slip events fall between samples: both errors go as the sample spacing squared,
    // measured C / N^2 with C 0.5..4 (coefficients) and 2.4..7.5 (loop) at 256..4096.
    const double n2 = double(samples) * samples;
    EXPECT_NEAR(fromCoefficients, exact, 10.0 / n2 * exact);
    EXPECT_NEAR(area, exact, 20.0 / n2 * exact);
    EXPECT_LE(period.f.cwiseAbs().maxCoeff(), fs * (1 + 1e-12));
  }
}

TEST(ElementStates, ASolutionOfTheWrongSizeIsRefused) {
  const auto d = drivenJenkins(2.0, 0.3, 0.5, 64);
  EXPECT_THROW(hbm::elementStates(*d.system, Eigen::VectorXd::Zero(3), 1.0), InputError);
}
