// The continuation engines' names: one table (engineKey) read both ways, so a scene's
// continuation/engine key and the files' names cannot drift apart.
#include <gtest/gtest.h>

#include "cyclone/continuation/ArclengthContinuation.hpp"

using cyclone::continuation::ContinuationOptions;
using cyclone::continuation::engineFromKey;
using cyclone::continuation::engineKey;

// The names docs/scenes.md gives for continuation/engine.
TEST(EngineKeys, TheScenesNamesAreTheEngines) {
  EXPECT_STREQ(engineKey(ContinuationOptions::Engine::PredictorCorrector), "predictor_corrector");
  EXPECT_STREQ(engineKey(ContinuationOptions::Engine::Loca), "loca");
  EXPECT_EQ(engineFromKey("predictor_corrector"), ContinuationOptions::Engine::PredictorCorrector);
  EXPECT_EQ(engineFromKey("loca"), ContinuationOptions::Engine::Loca);
}

TEST(EngineKeys, EachEngineReadsBackFromItsKey) {
  for (const auto engine : {ContinuationOptions::Engine::PredictorCorrector, ContinuationOptions::Engine::Loca})
    EXPECT_EQ(engineFromKey(engineKey(engine)), engine);
}

// Names are exact: no case folding, no abbreviations, nothing for an empty key.
TEST(EngineKeys, OtherNamesAreNoEngine) {
  for (const char* name : {"", "LOCA", "Loca", "predictor-corrector", "pc", "newton", "unknown"})
    EXPECT_FALSE(engineFromKey(name).has_value()) << name;
}
