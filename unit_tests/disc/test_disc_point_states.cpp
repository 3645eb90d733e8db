// disc::discPointStates on a two-DOF system whose DOFs are a friction contact's
// tangential and normal coordinates, moved by hand: U cos t tangentially at a constant
// normal load (kn = 0). The contact is then Jenkins' element, whose energy per cycle is
// closed-form: 4 mu N (U - mu N / kt) where it slips (U > mu N / kt), 0 where it sticks.
#include <gtest/gtest.h>

#include <cmath>

#include "cyclone/disc/DiscPointStates.hpp"
#include "cyclone/hbm/FrictionContact.hpp"

using namespace cyclone;

namespace {

// The point at U cos(omega t) on DOF 0 (the contact's tangential coordinate), DOF 1 at rest.
struct JenkinsPoint {
  response::ForcedResponseSetup setup;
  disc::PeakPoint point;
};

JenkinsPoint jenkinsPoint(double U, double kt, double mu, double N, int H) {
  JenkinsPoint p;
  const hbm::HarmonicSet harmonics = hbm::HarmonicSet::upTo(H);
  p.setup.system = std::make_unique<hbm::HarmonicBalanceSystem>(Eigen::MatrixXd::Identity(2, 2),
                                                                Eigen::MatrixXd::Zero(2, 2),
                                                                Eigen::MatrixXd::Identity(2, 2), harmonics, 256);
  hbm::FrictionContactParameters c;
  c.tangentialDirections = 1, c.kt = kt, c.kn = 0, c.mu = mu, c.preload = N;
  p.setup.system->addElement(std::make_shared<hbm::FrictionContact>(c), Eigen::MatrixXd::Identity(2, 2));
  p.setup.outputDofs = {0, 1};
  p.setup.dofNames = {"tangential", "normal"};
  const int nc = harmonics.numCoefficients();
  p.point.system = p.setup.system.get();
  p.point.x = Eigen::VectorXd::Zero(2 * nc);
  p.point.x(harmonics.cosIndex(1)) = U;  // DOF 0's coefficients first
  p.point.omega = 1.3;
  return p;
}

}  // namespace

TEST(DiscPointStates, AJenkinsContactsEnergySlipAndLoopAreItsClosedForm) {
  const double kt = 100, mu = 0.3, N = 10, U = 0.2;  // slips: mu N / kt = 0.03 < U
  auto p = jenkinsPoint(U, kt, mu, N, 7);
  const auto states = disc::discPointStates(p.setup, p.point, {});
  ASSERT_EQ(states.contacts.size(), 1u);
  const auto& c = states.contacts[0];
  const double exact = 4 * mu * N * (U - mu * N / kt);
  std::printf("energy per cycle %.12g, closed form %.12g; mean normal force %g, slip amplitude %g\n",
              c.energyPerCycle, exact, c.meanNormalForce, c.slipAmplitude);
  EXPECT_NEAR(c.energyPerCycle / exact, 1.0, 1e-6);  // the located law: exact to its integration
  EXPECT_NEAR(std::abs(c.meanNormalForce), N, 1e-9);
  EXPECT_NEAR(c.slipAmplitude, U, 1e-12);
  EXPECT_EQ(states.mostDissipating, 0);
  // The loop of the contact that dissipates most: its force within the slip limit, at it
  // while slipping; the period's response the motion put in.
  ASSERT_EQ(states.loops.size(), 1u);
  const auto& loop = states.loops[0].period;
  ASSERT_EQ(loop.w.rows(), Eigen::Index(states.phase.size()));
  EXPECT_NEAR(loop.f.col(0).cwiseAbs().maxCoeff(), mu * N, 1e-9);
  for (std::size_t i = 0; i < states.phase.size(); ++i) {
    EXPECT_NEAR(states.response(Eigen::Index(i), 0), U * std::cos(2 * M_PI * states.phase[i]), 1e-12);
    EXPECT_NEAR(loop.w(Eigen::Index(i), 0), U * std::cos(2 * M_PI * states.phase[i]), 1e-12);
  }
  // Stuck (U below mu N / kt): no energy.
  auto stuck = jenkinsPoint(0.01, kt, mu, N, 7);
  EXPECT_NEAR(disc::discPointStates(stuck.setup, stuck.point, {}).contacts[0].energyPerCycle, 0.0, 1e-12);
  // A contact that is not one of the system's is refused, naming the key.
  try {
    disc::discPointStates(p.setup, p.point, {3});
    ADD_FAILURE() << "contact 3 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("hysteresis_contacts"), std::string::npos) << e.what();
  }
}
