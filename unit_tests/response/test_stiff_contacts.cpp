// response::stiffContacts on tmdsimpy's 2-DOF friction system (springs 12 along the
// tangential DOF and 21 along the normal one): a contact's kt or kn set against K along
// the element's coordinate, named above the given ratio and not below it.
#include <gtest/gtest.h>

#include <memory>

#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/response/StiffContacts.hpp"

using namespace cyclone;

namespace {

response::ForcedResponseSetup frictionPair(double kt, double kn) {
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(2, 2), K = Eigen::MatrixXd::Zero(2, 2);
  K(0, 0) = 12, K(1, 1) = 21;
  response::ForcedResponseSetup setup;
  setup.system = std::make_unique<hbm::HarmonicBalanceSystem>(M, 0.1 * K, K, hbm::HarmonicSet::upTo(3), 128);
  // A cubic spring first: not a contact, so not counted, and the contact is element 1.
  setup.system->addElement(std::make_shared<hbm::CubicSpring>(1e20), Eigen::Vector2d(1, 0));
  hbm::FrictionContactParameters p;
  p.kt = kt, p.kn = kn, p.mu = 0.85;
  // W's columns: the tangential coordinate along DOF 0 (twice: w^T K w / w^T w is 12
  // whatever its length), the normal one along DOF 1.
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(2, 2);
  W(0, 0) = 2, W(1, 1) = 1;
  setup.system->addElement(std::make_shared<hbm::FrictionContact>(p), W);
  setup.elementNames = {"cubic", "contact"};
  return setup;
}

}  // namespace

TEST(StiffContacts, AContactFarStifferThanTheSystemAlongItsCoordinateIsNamed) {
  const auto stiff = response::stiffContacts(frictionPair(1e12, 21.0), 1e4);
  ASSERT_EQ(stiff.size(), 1u);
  EXPECT_EQ(stiff[0].element, 1);
  EXPECT_EQ(stiff[0].parameter, "kt");
  EXPECT_DOUBLE_EQ(stiff[0].systemStiffness, 12.0);
  EXPECT_DOUBLE_EQ(stiff[0].ratio(), 1e12 / 12.0);
  // Both, the stiffer relative to its coordinate first.
  const auto both = response::stiffContacts(frictionPair(1e7, 1e12), 1e4);
  ASSERT_EQ(both.size(), 2u);
  EXPECT_EQ(both[0].parameter, "kn");
  EXPECT_DOUBLE_EQ(both[0].systemStiffness, 21.0);
  EXPECT_EQ(both[1].parameter, "kt");
  // tmdsimpy's own values (kt 5, kn 21) and a contact 1e4 times stiffer than K are not.
  EXPECT_TRUE(response::stiffContacts(frictionPair(5.0, 21.0), 1e4).empty());
  EXPECT_TRUE(response::stiffContacts(frictionPair(12e4, 21e4), 1e4).empty());
}
