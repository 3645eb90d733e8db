// response::checkSolverSize on matrix systems: Krylov's preconditioner factors the linear
// block of each harmonic, dense over the DOFs, (2/3) (2 n)^3 flops a time. A 3000-DOF
// matrix scene at H = 7 spent 113 s on its first point without a word (issue 49; the
// estimate says 116 s); now a warning says so before the trace. A system of a tenth the
// DOFs, a thousandth the cost, is not warned about.
#include <gtest/gtest.h>

#include <string>

#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/response/ForcedResponseChecks.hpp"

using namespace cyclone;

namespace {

std::string warningsFor(int dofs, int H) {
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(dofs, dofs);
  hbm::HarmonicBalanceSystem hb(I, 0.05 * I, I, hbm::HarmonicSet::upTo(H), 64);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(dofs);
  w(0) = 1;
  hb.addElement(std::make_shared<hbm::CubicSpring>(0.1), w);
  testing::internal::CaptureStderr();
  response::checkSolverSize(hb, "harmonics");
  return testing::internal::GetCapturedStderr();
}

}  // namespace

TEST(SolverSizeChecks, AKrylovPreconditionerOfMinutesIsSaidBeforeTheTrace) {
  const std::string big = warningsFor(3000, 7);
  EXPECT_NE(big.find("8 harmonics (up to 7) on 3000 DOFs make 45000 unknowns"), std::string::npos) << big;
  EXPECT_NE(big.find("preconditioner factors a dense 6000-square block per harmonic"), std::string::npos) << big;
  const std::string small = warningsFor(300, 7);
  EXPECT_EQ(small.find("preconditioner"), std::string::npos) << small;
}
