// A trace saved as it goes continues from any saved state to the curve an
// uninterrupted trace gives, point for point; a finished one is read back without
// computing; traces of other problems or options are filed under other keys.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>

#include "KinkedOscillator.hpp"
#include "SingleTermOscillator.hpp"
#include "cyclone/continuation/TraceCheckpoint.hpp"
#include "FrictionSector.hpp"

using namespace cyclone;
using continuation::TraceState;

namespace {

// Keeps every state saved (in order) and returns the one it is told to.
class MemoryCheckpoints : public continuation::TraceCheckpoints {
public:
  std::optional<TraceState> load(const std::string& key) override {
    ++loads;
    const auto it = stored.find(key);
    if (it == stored.end()) return std::nullopt;
    return it->second;
  }
  void save(const std::string& key, const TraceState& s) override {
    history.push_back(s);
    stored[key] = s;
  }
  std::map<std::string, TraceState> stored;
  std::vector<TraceState> history;
  int loads = 0;
};

// The hardening Duffing curve through both folds, its amplitude as the measure (so
// peaks are refined and inserted into the saved path).
continuation::ContinuationProblem duffing(double P) {
  auto p = test_support::singleTermOscillator(1, 0.05, 1, 0.1, P);
  p.measure = [](const Eigen::VectorXd& x) { return x.norm(); };
  return p;
}

continuation::ContinuationOptions rangeOnly() {
  continuation::ContinuationOptions o;
  o.engine = continuation::ContinuationOptions::Engine::PredictorCorrector;
  o.from = 0.5, o.to = 2.0;
  return o;
}

void expectSameBranch(const continuation::Branch& a, const continuation::Branch& b) {
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    EXPECT_EQ(a.points[i].parameter, b.points[i].parameter) << "point " << i;
    EXPECT_EQ((a.points[i].x - b.points[i].x).cwiseAbs().maxCoeff(), 0.0) << "point " << i;
  }
  EXPECT_EQ(a.finished, b.finished);
  EXPECT_EQ(a.stopReason, b.stopReason);
  EXPECT_EQ(a.statistics.newtonIterations, b.statistics.newtonIterations);
  EXPECT_EQ(a.statistics.rejectedSteps, b.statistics.rejectedSteps);
}

// A recorder of every step's state, set in `o`.
std::shared_ptr<MemoryCheckpoints> recordEveryStep(continuation::ContinuationOptions& o) {
  auto recorder = std::make_shared<MemoryCheckpoints>();
  recorder->intervalSeconds = 0;
  o.checkpoints = recorder;
  return recorder;
}

// The trace continued from `state`, saved under `key`.
continuation::Branch resumedFrom(const continuation::ContinuationProblem& problem, const Eigen::VectorXd& start,
                                 continuation::ContinuationOptions o, const std::string& key, const TraceState& state) {
  auto seeded = std::make_shared<MemoryCheckpoints>();
  seeded->stored[key] = state;
  o.checkpoints = seeded;
  return continuation::traceBranch(problem, start, o);
}

}  // namespace

TEST(TraceCheckpoint, AResumedTraceIsTheUninterruptedOne) {
  const auto problem = duffing(0.18);
  auto o = rangeOnly();
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(2);
  const auto reference = continuation::traceBranch(problem, rest, o);  // no checkpoints
  ASSERT_TRUE(reference.finished) << reference.stopReason;

  auto recorder = std::make_shared<MemoryCheckpoints>();
  recorder->intervalSeconds = 0;  // every step
  o.checkpoints = recorder;
  const auto saved = continuation::traceBranch(problem, rest, o);
  expectSameBranch(saved, reference);  // saving does not change the path
  const std::string key = continuation::traceKey(problem, rest, o);
  ASSERT_EQ(recorder->stored.size(), 1u);
  ASSERT_TRUE(recorder->stored.count(key));
  EXPECT_TRUE(recorder->stored.at(key).complete);
  ASSERT_GT(recorder->history.size(), 20u);

  // Continued from states early, in the middle (across the folds) and near the end.
  int resumed = 0;
  const std::size_t states = recorder->history.size() - 1;  // the last is the complete one
  for (std::size_t at : {std::size_t(1), states / 3, states / 2, 2 * states / 3, states - 1}) {
    const TraceState& state = recorder->history[at];
    ASSERT_FALSE(state.complete);
    SCOPED_TRACE("resumed from state " + std::to_string(at) + " with " + std::to_string(state.branch.points.size()) +
                 " points");
    auto seeded = std::make_shared<MemoryCheckpoints>();
    seeded->stored[key] = state;
    auto oSeeded = o;
    oSeeded.checkpoints = seeded;
    const auto branch = continuation::traceBranch(problem, rest, oSeeded);
    expectSameBranch(branch, reference);
    ++resumed;
  }
  std::printf("%zu points; %zu saved states; resumed from %d of them to the same curve bit for bit\n",
              reference.points.size(), states, resumed);
}

// Where the continuation keeps its factors from step to step (211 unknowns), the
// states are saved only where it drops them (every few points), so a trace continued
// from one is still the uninterrupted trace to the bit.
TEST(TraceCheckpoint, AResumedTraceWithKeptFactorsIsTheUninterruptedOne) {
  const auto sector = test_support::frictionSector(10, 3, 64, 7);
  const auto problem = test_support::frictionSectorProblem(*sector);
  auto o = rangeOnly();
  o.from = 0.9, o.to = 1.6;
  const Eigen::VectorXd start = sector->linearizedSolution(o.from);
  const auto reference = continuation::traceBranch(problem, start, o);
  ASSERT_TRUE(reference.finished) << reference.stopReason;
  ASSERT_GT(reference.statistics.reusedFactorizations, 0);
  const auto recorder = recordEveryStep(o);
  const auto saved = continuation::traceBranch(problem, start, o);
  expectSameBranch(saved, reference);
  const std::string key = continuation::traceKey(problem, start, o);
  ASSERT_GT(recorder->history.size(), 4u);
  const std::size_t states = recorder->history.size() - 1;
  for (std::size_t at : {std::size_t(1), states / 2, states - 1}) {
    SCOPED_TRACE("resumed from state " + std::to_string(at));
    expectSameBranch(resumedFrom(problem, start, o, key, recorder->history[at]), reference);
  }
}

TEST(TraceCheckpoint, AFinishedTraceIsReadBackWithoutComputing) {
  const auto base = duffing(0.18);
  auto o = rangeOnly();
  auto store = std::make_shared<MemoryCheckpoints>();
  o.checkpoints = store;
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(2);
  const auto first = continuation::traceBranch(base, rest, o);
  int residuals = 0;
  auto counted = base;
  counted.residual = [&](const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) {
    ++residuals;
    base.residual(x, p, F);
  };
  const auto again = continuation::traceBranch(counted, rest, o);
  expectSameBranch(again, first);
  EXPECT_EQ(residuals, 5);  // the key's, at the guess and four probes around it
}

TEST(TraceCheckpoint, OtherProblemsAndOptionsHaveOtherKeys) {
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(2);
  const auto o = rangeOnly();
  const std::string key = continuation::traceKey(duffing(0.18), rest, o);
  EXPECT_NE(key, continuation::traceKey(duffing(0.19), rest, o));  // another force: another residual at the guess
  // Another cubic stiffness, invisible at rest (the residual there is the force alone):
  // the probes around the guess tell it (a key of the residual at the guess alone read a
  // gap-clearance study's curve back from another clearance's trace).
  auto stiffer = test_support::singleTermOscillator(1, 0.05, 1, 0.2, 0.18);
  stiffer.measure = [](const Eigen::VectorXd& x) { return x.norm(); };
  Eigen::VectorXd F1, F2;
  duffing(0.18).residual(rest, o.from, F1);
  stiffer.residual(rest, o.from, F2);
  ASSERT_EQ((F1 - F2).norm(), 0.0);  // the same at the guess
  EXPECT_NE(key, continuation::traceKey(stiffer, rest, o));
  auto o2 = o;
  o2.to = 2.5;
  EXPECT_NE(key, continuation::traceKey(duffing(0.18), rest, o2));
  o2 = o;
  o2.turnAngle = 0.2;
  EXPECT_NE(key, continuation::traceKey(duffing(0.18), rest, o2));
  EXPECT_NE(key, continuation::traceKey(duffing(0.18), Eigen::VectorXd::Constant(2, 1e-3), o));
  o2 = o;
  o2.checkpoints = std::make_shared<MemoryCheckpoints>();  // where it is saved is not what it is
  EXPECT_EQ(key, continuation::traceKey(duffing(0.18), rest, o2));
}

// A trace continued from a state saved while it took secant steps over a stair of kinks
// (and from one before they began) is the uninterrupted trace to the bit: the secant
// mode and the steps' verdicts that switch it are part of the state.
TEST(TraceCheckpoint, AResumedTraceWithSecantStepsIsTheUninterruptedOne) {
  const auto problem = test_support::KinkedOscillator().problem();
  auto o = rangeOnly();
  o.from = 0.9, o.to = 1.1;
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(2);
  const auto reference = continuation::traceBranch(problem, rest, o);
  ASSERT_TRUE(reference.finished) << reference.stopReason;
  ASSERT_GT(reference.statistics.secantSteps, 0);
  const auto recorder = recordEveryStep(o);
  expectSameBranch(continuation::traceBranch(problem, rest, o), reference);
  const std::string key = continuation::traceKey(problem, rest, o);
  std::vector<std::size_t> secant, counting;  // states in secant steps; before, with verdicts counted
  for (std::size_t i = 0; i + 1 < recorder->history.size(); ++i) {
    const auto& s = recorder->history[i];
    if (s.secant) secant.push_back(i);
    else if (!s.heldSteps.empty() && std::count(s.heldSteps.begin(), s.heldSteps.end(), 1) > 0) counting.push_back(i);
  }
  ASSERT_FALSE(secant.empty());
  ASSERT_FALSE(counting.empty());
  for (std::size_t at : {counting[counting.size() / 2], secant.front(), secant[secant.size() / 2]}) {
    SCOPED_TRACE("resumed from state " + std::to_string(at));
    expectSameBranch(resumedFrom(problem, rest, o, key, recorder->history[at]), reference);
  }
}
