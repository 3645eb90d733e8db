// Newton steps by GMRES on the Jacobian's blocks (ContinuationOptions::LinearSolver::
// Krylov: KrylovSolve.hpp, hbm::JacobianBlocks) against dense LUs: GMRES against LU on
// a nonsymmetric system and on a bordered one whose J is singular (a fold), and the
// predictor-corrector's friction curve traced both ways: the same curve to the Newton
// tolerance, each point's residual checked on its own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/continuation/HomotopySolve.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/continuation/KrylovSolve.hpp"
#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Timer.hpp"
#include "FrictionSector.hpp"

using namespace cyclone;
using namespace cyclone::continuation;

namespace {

// A nonsymmetric matrix near a diagonal one, and that diagonal as the preconditioner.
struct Diagonal final : JacobianOperator {
  Eigen::MatrixXd A;
  Eigen::VectorXd d;
  int size() const override { return int(A.rows()); }
  void apply(const Eigen::VectorXd& v, Eigen::VectorXd& y) const override { y = A * v; }
  void preparePreconditioner() override { d = A.diagonal(); }
  void precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z) const override {
    z = r.cwiseQuotient(d.cwiseMax(1e-3));  // a zero diagonal entry: the row left nearly as it is
  }
};

std::shared_ptr<Diagonal> nearDiagonal(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  auto op = std::make_shared<Diagonal>();
  op->A = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    op->A(i, i) = 1.0 + i;
    for (int j = 0; j < n; ++j)
      if (j != i) op->A(i, j) = 0.3 * g(rng) / std::sqrt(double(n));
  }
  return op;
}

}  // namespace

TEST(KrylovSolve, AgainstLu) {
  auto op = nearDiagonal(300, 3);
  op->preparePreconditioner();
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(300, -1.0, 1.0);
  Eigen::VectorXd x;
  const KrylovResult r = solveKrylov([&](const Eigen::VectorXd& v, Eigen::VectorXd& y) { op->apply(v, y); },
                                     [&](const Eigen::VectorXd& v, Eigen::VectorXd& y) { op->precondition(v, y); }, b, x,
                                     KrylovOptions{1e-12, 300, 100});
  ASSERT_TRUE(r.converged) << r.relativeResidual;
  const Eigen::VectorXd exact = op->A.partialPivLu().solve(b);
  EXPECT_LE((x - exact).norm(), 1e-10 * exact.norm());
  EXPECT_LE(r.relativeResidual, 1e-11);
  std::printf("GMRES n = 300: %d iterations, relative residual %.2e\n", r.iterations, r.relativeResidual);
}

// A bordered system whose J is singular (a fold of the curve: J has a null vector, the
// border makes the whole regular): GMRES with the bordered preconditioner solves it.
TEST(KrylovSolve, BorderedSystemAtAFold) {
  const int n = 200;
  auto op = nearDiagonal(n, 5);
  // Make J singular: J = A - A u v^T / (v^T u) ... with u = e_0 and v^T = e_0^T A / A00
  // (row 0 a combination of the others would do as well); here row 0 is replaced by the
  // sum of rows 1 and 2.
  op->A.row(0) = op->A.row(1) + op->A.row(2);
  op->preparePreconditioner();
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 0.5, 1.5), c = Eigen::VectorXd::LinSpaced(n, 1.0, -0.5);
  const double d = 0.3;
  BorderedKrylovSolve solver(op, b, c, d, KrylovOptions{1e-12, 400, 200});
  Eigen::MatrixXd B(n + 1, n + 1);
  B.topLeftCorner(n, n) = op->A;
  B.topRightCorner(n, 1) = b;
  B.bottomLeftCorner(1, n) = c.transpose();
  B(n, n) = d;
  ASSERT_LT(Eigen::FullPivLU<Eigen::MatrixXd>(op->A).rank(), n);
  const Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(n + 1, 2.0, -1.0);
  const Eigen::VectorXd x = solver.solve(rhs);
  ASSERT_TRUE(x.allFinite());
  const Eigen::VectorXd exact = B.fullPivLu().solve(rhs);
  EXPECT_LE((x - exact).norm(), 1e-9 * exact.norm());
  std::printf("bordered GMRES at a fold, n = %d: %ld iterations\n", n + 1, solver.iterations());
}

TEST(KrylovSolve, NonConvergenceIsNotAnAnswer) {
  auto op = nearDiagonal(200, 9);
  op->preparePreconditioner();
  BorderedKrylovSolve solver(op, Eigen::VectorXd::Ones(200), Eigen::VectorXd::Ones(200), 1.0, KrylovOptions{1e-14, 2, 2});
  const Eigen::VectorXd x = solver.solve(Eigen::VectorXd::LinSpaced(201, 1.0, 2.0));
  EXPECT_FALSE(x.allFinite());
  EXPECT_EQ(solver.failures(), 1);
}

// The friction sector's curve (a 3D friction contact on 9 of 10 nodes, harmonics 0..3):
// Krylov against dense, the same path.
TEST(KrylovSolve, SameFrictionCurveAsDense) {
  const auto s = test_support::frictionSector(10, 3, 64, 7);
  const auto problem = test_support::frictionSectorProblem(*s);
  Branch branches[2];
  double peaks[2] = {0, 0};
  for (int krylov : {0, 1}) {
    ContinuationOptions o;
    o.from = 0.9, o.to = 1.6;
    o.linearSolver = krylov ? ContinuationOptions::LinearSolver::Krylov : ContinuationOptions::LinearSolver::Dense;
    Timer t;
    branches[krylov] = traceBranch(problem, s->linearizedSolution(o.from), o);
    const auto& b = branches[krylov];
    ASSERT_TRUE(b.finished) << b.stopReason;
    const auto curve = test_support::checkSectorCurve(problem, *s, b);
    EXPECT_LT(curve.largestResidual, 1e-9) << "krylov " << krylov;
    peaks[krylov] = curve.peak;
    const auto& st = b.statistics;
    std::printf("%s: %zu points, %d Newton iterations, %ld factorisations, %ld Krylov solves, %ld GMRES iterations "
                "(%.1f a solve), peak %.9f, %.2f s\n",
                krylov ? "Krylov" : "dense", b.points.size(), st.newtonIterations, st.factorizations, st.krylovSolves,
                st.krylovIterations, st.krylovSolves ? double(st.krylovIterations) / double(st.krylovSolves) : 0.0,
                peaks[krylov], t.seconds());
  }
  EXPECT_EQ(branches[1].statistics.factorizations, 0);
  EXPECT_GT(branches[1].statistics.krylovSolves, 0);
  EXPECT_NEAR(double(branches[1].points.size()), double(branches[0].points.size()),
              0.1 * double(branches[0].points.size()));
  EXPECT_NEAR(peaks[1] / peaks[0], 1.0, 1e-7);
}

TEST(KrylovSolve, NewtonAtOneFrequency) {
  const auto s = test_support::frictionSector(10, 3, 64, 7);
  const auto problem = test_support::frictionSectorProblem(*s);
  Eigen::VectorXd dense = s->linearizedSolution(1.2), krylov = dense;
  const auto a = solveNewton(problem, dense, 1.2, 1e-11, 50, nullptr, ContinuationOptions::LinearSolver::Dense);
  const auto b = solveNewton(problem, krylov, 1.2, 1e-11, 50, nullptr, ContinuationOptions::LinearSolver::Krylov);
  ASSERT_TRUE(a.converged);
  ASSERT_TRUE(b.converged);
  EXPECT_GT(b.krylovIterations, 0);
  EXPECT_LE((krylov - dense).norm(), 1e-8 * dense.norm());
}

// A solution carried to one more harmonic on a sector large enough for Krylov by
// default (45 nodes, harmonics 0..7: 2025 unknowns): solveByHomotopy by Krylov steps
// (its added-rows block from operator products) reaches the dense Newton's solution.
TEST(KrylovSolve, CarriedToOneMoreHarmonic) {
  {
  const auto s6 = test_support::frictionSector(45, 6, 64, 7);
  const auto s7 = test_support::frictionSector(45, 7, 64, 7);
  const auto p6 = test_support::frictionSectorProblem(*s6), p7 = test_support::frictionSectorProblem(*s7);
  ASSERT_GE(p7.size, ContinuationOptions::krylovFrom);
  const double w = 1.45;  // the contacts slip (below about 1.3 they stick: the carried guess solves H = 7)
  Eigen::VectorXd x6 = s6->linearizedSolution(w);
  ASSERT_TRUE(solveNewton(p6, x6, w, 1e-11, 50).converged);
  const auto& set6 = s6->aft().harmonics();
  const auto& set7 = s7->aft().harmonics();
  Eigen::VectorXd carried = hbm::transferCoefficients(x6, s6->numDofs(), set6, set7), dense = carried;
  std::vector<int> added;
  for (int d = 0; d < s7->numDofs(); ++d)
    added.push_back(d * s7->numCoefficients() + set7.cosIndex(7)), added.push_back(d * s7->numCoefficients() + set7.sinIndex(7));
  Eigen::VectorXd R;
  p7.residual(carried, w, R);
  std::printf("carried to H = 7 at w = %g: ||R|| %.3e\n", w, R.norm());
  ASSERT_GT(R.norm(), 1e-6) << "the carried guess already solves the raised system: nothing is tested";
  const HomotopyResult h = solveByHomotopy(p7, carried, w, added, 1e-11);
  ASSERT_TRUE(h.newton.converged) << h.reason;
  EXPECT_GT(h.newton.krylovIterations, 0);
  ASSERT_TRUE(solveNewton(p7, dense, w, 1e-11, 50, nullptr, ContinuationOptions::LinearSolver::Dense).converged);
  EXPECT_LE((carried - dense).norm(), 1e-8 * dense.norm());
  }
}
