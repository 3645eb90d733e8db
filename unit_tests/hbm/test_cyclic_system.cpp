// The engine-order cyclic constraint of the harmonic balance system against
// the full ring it stands for: with sector j's coefficients S^j X, the ring's
// residual and Jacobian are those of the sector, sector by sector. With a
// sample count that N divides, the sectors' samples are the same instants
// shifted, so the identity holds to round-off (otherwise to the aliasing error).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/FullRingSystem.hpp"
#include "cyclone/hbm/JenkinsElement.hpp"
#include "cyclone/hbm/ScalarElementAdapter.hpp"

using namespace cyclone;
using namespace cyclone::hbm;

namespace {

// Two DOFs per sector: a disc DOF (x) and a blade tip with two directions (y, z);
// neighbouring discs coupled by springs and dampers; the tips of neighbours
// joined by a 3D friction contact (normal along z), the disc to ground by a
// Jenkins element, a cubic spring inside the sector.
std::unique_ptr<HarmonicBalanceSystem> sector(int N, int eo, int samples) {
  Eigen::Matrix3d M = Eigen::Vector3d(1.2, 0.4, 0.4).asDiagonal(), K, Kn = Eigen::Matrix3d::Zero();
  K << 9.0, -1.0, -0.5, -1.0, 3.0, 0.2, -0.5, 0.2, 4.0;
  Kn(0, 0) = -2.0, Kn(1, 0) = -0.3;  // not symmetric on purpose: A_next^T couples the other way
  K(0, 0) += 4.0;                    // stays positive definite in the ring
  auto s = std::make_unique<HarmonicBalanceSystem>(M, 0.01 * K, K, HarmonicSet::upTo(3), samples);
  CyclicCoupling c;
  c.sectors = N, c.engineOrder = eo, c.Knext = Kn, c.Cnext = 0.01 * Kn;
  c.Mnext = Eigen::Matrix3d::Zero();
  c.Mnext(0, 0) = 0.05;
  s->setCyclic(c);
  FrictionContactParameters p;
  p.tangentialDirections = 2, p.kt = 5.0, p.kn = 6.0, p.mu = 0.3, p.preload = 0.5;
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(3, 3), Wn = Eigen::MatrixXd::Zero(3, 3);
  W(1, 0) = 1, W(0, 1) = 0.3, W(2, 2) = 1;     // this tip ...
  Wn(1, 0) = -1, Wn(0, 1) = -0.3, Wn(2, 2) = -1;  // ... against the next sector's
  s->addElement(std::make_shared<FrictionContact>(p), W, Wn);
  s->addElement(std::make_shared<JenkinsElement>(3.0, 0.2), Eigen::Vector3d(1, 0, 0));
  s->addElement(std::make_shared<CubicSpring>(0.5), Eigen::Vector3d(0, 1, -1));
  s->addExcitation(1, 1, 0.8, 0.1);
  s->addExcitation(2, 1, 0.2);
  return s;
}

Eigen::VectorXd randomVector(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x(i) = u(rng);
  return x;
}

}  // namespace

TEST(CyclicHarmonicBalance, SectorEqualsFullRing) {
  const int N = 6;
  for (int eo : {0, 1, 2, 3, 5, 8, -1}) {
    const auto s = sector(N, eo, 96);
    const auto ring = expandToFullRing(*s);
    ASSERT_EQ(ring->numDofs(), N * s->numDofs());
    const Eigen::VectorXd X = 0.8 * randomVector(s->numUnknowns(), 11 + eo);
    const double w = 1.7;
    Eigen::VectorXd Rs, Rr;
    Eigen::MatrixXd Js, Jr;
    s->residual(X, w, Rs, &Js);
    ring->residual(ringCoefficients(*s, X), w, Rr, &Jr);
    const double resErr = (Rr - ringCoefficients(*s, Rs)).norm() / Rr.norm();
    const Eigen::VectorXd v = randomVector(s->numUnknowns(), 99);
    const double jacErr = (Jr * ringCoefficients(*s, v) - ringCoefficients(*s, Js * v)).norm() / (Js * v).norm();
    std::printf("EO %2d (harmonic 1 on ND %d): residual %.1e, Jacobian %.1e\n", eo, s->nodalDiameter(1), resErr,
                jacErr);
    EXPECT_LT(resErr, 1e-12) << eo;
    EXPECT_LT(jacErr, 1e-12) << eo;
    // The linear responses agree too (the ring's excitation is the delayed sector's).
    const Eigen::VectorXd Xl = s->linearSolution(w);
    EXPECT_LT((ring->linearSolution(w) - ringCoefficients(*s, Xl)).norm(), 1e-12 * Xl.norm() * N);
  }
}

TEST(CyclicHarmonicBalance, JacobianMatchesFiniteDifferences) {
  const auto s = sector(7, 3, 128);
  const Eigen::VectorXd X = 0.8 * randomVector(s->numUnknowns(), 5);
  Eigen::VectorXd R, Rp, Rm;
  Eigen::MatrixXd J;
  s->residual(X, 1.3, R, &J);
  Eigen::MatrixXd fd(J.rows(), J.cols());
  const double h = 1e-7;
  for (int j = 0; j < X.size(); ++j) {
    Eigen::VectorXd Xp = X, Xm = X;
    Xp(j) += h, Xm(j) -= h;
    s->residual(Xp, 1.3, Rp, nullptr);
    s->residual(Xm, 1.3, Rm, nullptr);
    fd.col(j) = (Rp - Rm) / (2 * h);
  }
  const double err = (J - fd).cwiseAbs().maxCoeff() / J.cwiseAbs().maxCoeff();
  std::printf("cyclic sector Jacobian vs finite differences: %.2e\n", err);
  EXPECT_LT(err, 1e-6);
}

TEST(CyclicHarmonicBalance, NodalDiameterOfEachHarmonic) {
  const auto s = sector(24, 5, 64);
  EXPECT_EQ(s->nodalDiameter(0), 0);
  EXPECT_EQ(s->nodalDiameter(1), 5);
  EXPECT_EQ(s->nodalDiameter(2), 10);
  EXPECT_EQ(s->nodalDiameter(3), 9);  // 15 folds to 24 - 15
  const auto t = sector(24, 29, 64);   // EO 29 excites ND 5 like EO 5
  EXPECT_EQ(t->nodalDiameter(1), 5);
  EXPECT_LT((t->nextSectorMap() - s->nextSectorMap()).norm(), 1e-12);
}

TEST(CyclicHarmonicBalance, BadInputIsNamed) {
  Eigen::MatrixXd I = Eigen::MatrixXd::Identity(2, 2);
  HarmonicBalanceSystem lone(I, 0.1 * I, I, HarmonicSet::upTo(1), 8);
  auto element = std::make_shared<CubicSpring>(1.0);
  auto adapted = std::make_shared<ScalarElementAdapter>(element);
  EXPECT_THROW(lone.addElement(adapted, Eigen::MatrixXd::Ones(2, 1), Eigen::MatrixXd::Ones(2, 1)), InputError);
  EXPECT_THROW(lone.addElement(adapted, Eigen::MatrixXd::Ones(3, 1)), InputError);
  CyclicCoupling one;
  one.sectors = 1;
  EXPECT_THROW(lone.setCyclic(one), InputError);
  CyclicCoupling wrong;
  wrong.sectors = 4, wrong.Knext = Eigen::MatrixXd::Identity(3, 3);
  EXPECT_THROW(lone.setCyclic(wrong), InputError);
  EXPECT_THROW(expandToFullRing(lone), InputError);
}
