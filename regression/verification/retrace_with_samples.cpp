// Verification of when an incomplete friction curve is traced again with more AFT
// samples (response::traceForcedResponse). A sampled friction law's corners move and
// shrink with the samples, so a curve stopped by one may pass with twice or four times
// as many; a stop that stays where it was with twice the samples is the curve's own (or
// the point budget's) and four times is not tried: on the default disc at H = 5 the
// retraces of a curve stopped at 1394.4 Hz by its wall (1394.0 Hz with 512 samples)
// cost 10 minutes each.
#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>

#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/response/ForcedResponseTrace.hpp"

using namespace cyclone;

namespace {

// Two DOFs, a friction contact from DOF 0 to ground under a constant normal load (kn =
// 0: a Jenkins element of slip force mu N0 = 0.05, as hbm_vs_time_integration's friction
// damper; the contact element, which asks for its samples), forced on DOF 0, traced in
// the frequency over 0.3..2. With tangentialDirections = 2 (a 3D contact moved along one
// tangential direction: the same law) the contact's force is the sampled law, whose
// corners move with the samples; with 1 its instants are located between the samples.
response::ForcedResponseSetup jenkinsChain(int maxPoints, int tangentialDirections = 1) {
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(2, 2), K(2, 2);
  K << 2.0, -1.0, -1.0, 1.0;
  const Eigen::MatrixXd C = 0.01 * K;
  auto sys = std::make_unique<hbm::HarmonicBalanceSystem>(M, C, K, hbm::HarmonicSet::upTo(3), 256);
  hbm::FrictionContactParameters p;
  p.tangentialDirections = tangentialDirections;
  p.kt = 1.0, p.kn = 0.0, p.mu = 0.05, p.preload = 1.0;
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(2, tangentialDirections + 1);  // w = [t1, (t2), n]: t1 = x0
  W(0, 0) = 1.0;
  sys->addElement(std::make_shared<hbm::FrictionContact>(p), W);
  sys->addExcitation(0, 1, 0.2);
  response::ForcedResponseSetup s;
  s.system = std::move(sys);
  s.continuation.from = 0.3, s.continuation.to = 2.0;
  s.continuation.maxSteps = maxPoints;
  s.outputDofs = {1};
  s.stability = response::ForcedResponseSetup::Stability::Never;
  return s;
}

// A contact whose force cannot be evaluated for frequencies inside (from, to): a wall
// of the curve's own, the same at any sample count (as the disc's H = 5 wall stays where
// it is with 512 samples), a test double for what the tracer cannot pass.
class WalledContact : public hbm::NonlinearElement {
public:
  WalledContact(std::shared_ptr<const hbm::NonlinearElement> contact, double from, double to)
      : contact_(std::move(contact)), from_(from), to_(to) {}
  int dimension() const override { return contact_->dimension(); }
  int recommendedSamples() const override { return contact_->recommendedSamples(); }
  void harmonicForce(const hbm::Aft& aft, const Eigen::MatrixXd& W, double omega, Eigen::MatrixXd& F,
                     Eigen::MatrixXd* jacobian) const override {
    if (omega > from_ && omega < to_) throw std::runtime_error("the wall");
    contact_->harmonicForce(aft, W, omega, F, jacobian);
  }
  Eigen::VectorXd incremental(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, Eigen::VectorXd& state,
                              Eigen::MatrixXd& dfdw, Eigen::MatrixXd& dfdwdot) const override {
    return contact_->incremental(w, wdot, state, dfdw, dfdwdot);
  }

private:
  std::shared_ptr<const hbm::NonlinearElement> contact_;
  double from_, to_;
};

}  // namespace

// Two stops. A wall inside the range (0.9 < W < 1.0): from both ends the sweeps stop at
// it, with 512 samples at the same places, so 1024 is not tried and the reason says why
// (a first sweep that folds back to the range's start is not judged so: the loss-factor
// scene test's curve at 0.003 does that at 256 and 512 samples, and is whole at 1024,
// where the sweep from the end finds its start).
// A curve cut short by its point budget (max_points 10) is not traced again, with more
// samples or otherwise: the budget is the caller's (issue 49: a budget of 2 gave 508
// points). With the default budget and no wall the curve is whole at 256 samples,
// nothing traced again.
TEST(RetraceWithSamples, AStopThatStaysWithTwiceTheSamplesIsNotRetracedAgain) {
  auto walled = jenkinsChain(continuation::ContinuationOptions().maxSteps);
  walled.system->replaceElement(0, std::make_shared<WalledContact>(walled.system->elements()[0].element, 0.9, 1.0));
  const auto wall = response::traceForcedResponse(walled);
  std::printf("a wall at 0.9 .. 1.0: %zu points, %s\n", wall.points.size(), wall.stopReason.c_str());
  EXPECT_FALSE(wall.finished);
  EXPECT_EQ(wall.end, continuation::BranchEnd::Wall) << wall.stopReason;
  EXPECT_EQ(wall.retraces.samplesFactorsTried, std::vector<int>{2}) << wall.stopReason;  // four times not tried
  EXPECT_EQ(wall.retraces.samplesFactor, 1) << wall.stopReason;                        // the first curve kept
  EXPECT_NE(wall.stopReason.find("not a sampling corner, four times not tried"), std::string::npos)
      << wall.stopReason;
  EXPECT_EQ(walled.system->aft().numSamples(), 256);  // the first curve and its system kept

  auto budget = jenkinsChain(10, 2);
  const auto stopped = response::traceForcedResponse(budget);
  std::printf("budget of 10 points: %zu points, %s\n", stopped.points.size(), stopped.stopReason.c_str());
  EXPECT_FALSE(stopped.finished);
  EXPECT_EQ(stopped.points.size(), 10u);
  EXPECT_EQ(stopped.end, continuation::BranchEnd::PointBudget) << stopped.stopReason;
  EXPECT_NE(stopped.stopReason.find("max_points 10"), std::string::npos) << stopped.stopReason;
  EXPECT_TRUE(stopped.retraces.samplesFactorsTried.empty()) << stopped.stopReason;
  EXPECT_FALSE(stopped.retraces.otherEngineTried) << stopped.stopReason;
  EXPECT_EQ(budget.system->aft().numSamples(), 256);

  auto whole = jenkinsChain(continuation::ContinuationOptions().maxSteps);
  const auto traced = response::traceForcedResponse(whole);
  std::printf("default budget: %zu points, %s\n", traced.points.size(), traced.stopReason.c_str());
  EXPECT_TRUE(traced.finished) << traced.stopReason;
  EXPECT_EQ(traced.end, continuation::BranchEnd::RangeEnd) << traced.stopReason;
  EXPECT_TRUE(traced.retraces.samplesFactorsTried.empty()) << traced.stopReason;
  EXPECT_FALSE(traced.retraces.otherEngineTried) << traced.stopReason;
}
