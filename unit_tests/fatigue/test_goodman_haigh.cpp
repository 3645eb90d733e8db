// The Goodman-Haigh safety factor against its closed form on constructed points:
// zero mean, a tensile mean, a point on the line, a compressive mean, the Langer
// line where it governs; bad fatigue data named by key.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cyclone/core/Error.hpp"
#include "cyclone/fatigue/GoodmanHaigh.hpp"

using namespace cyclone::fatigue;

TEST(GoodmanHaigh, SafetyFactorAgainstTheClosedForm) {
  FatigueMaterial m;
  m.ultimateStrength = 1000, m.enduranceLimit = 400;
  EXPECT_DOUBLE_EQ(goodmanSafetyFactor(0, 100, m), 4.0);
  EXPECT_DOUBLE_EQ(goodmanSafetyFactor(500, 50, m), 400 * 0.5 / 50);  // S_a(500) = 200
  EXPECT_NEAR(goodmanSafetyFactor(250, 300, m), 1.0, 1e-15);          // on the line: 400 (1 - 1/4)
  EXPECT_DOUBLE_EQ(goodmanSafetyFactor(-300, 100, m), 4.0);           // no credit for compression
  EXPECT_DOUBLE_EQ(goodmanSafetyFactor(1000, 10, m), 0.0);            // the mean alone at S_u
  EXPECT_TRUE(std::isinf(goodmanSafetyFactor(100, 0, m)));
}

TEST(GoodmanHaigh, LangerLineGovernsNearTheUltimateStrength) {
  const auto ti = ti6al4vAnnealed();
  // Goodman: 510 (1 - 800/950) = 80.53; Langer: 880 - 800 = 80.
  EXPECT_NEAR(allowableAlternating(800, ti), 80.0, 1e-12);
  EXPECT_NEAR(goodmanSafetyFactor(800, 40, ti), 2.0, 1e-12);
  EXPECT_NEAR(allowableAlternating(100, ti), 510 * (1 - 100.0 / 950), 1e-12);
  // In Pa (SI units) the same material is 1e6 times larger.
  EXPECT_NEAR(ti6al4vAnnealed(1e-6).ultimateStrength, 950e6, 1e-3);
}

TEST(GoodmanHaigh, BadFatigueDataIsNamed) {
  FatigueMaterial m;
  m.ultimateStrength = 900, m.enduranceLimit = 950;
  try {
    m.validate("material/fatigue");
    FAIL() << "S_e above S_u accepted";
  } catch (const cyclone::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("material/fatigue/endurance_limit"), std::string::npos) << e.what();
  }
  m.enduranceLimit = 400, m.ultimateStrength = -1;
  EXPECT_THROW(m.validate("material/fatigue"), cyclone::InputError);
  m.ultimateStrength = 900, m.yieldStrength = 1200;
  EXPECT_THROW(m.validate("material/fatigue"), cyclone::InputError);
  EXPECT_THROW(goodmanSafetyFactor(0, -1, m), cyclone::InputError);
}
