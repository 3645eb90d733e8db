// The condensed harmonic balance (Petrov: unknowns are the elements' relative
// coordinates and the excited DOFs) against the full receptance form it comes
// from: the same solutions at several engine orders and frequencies (the
// condensed solution is the full one's coordinates, and the full one is
// recovered from it), a projected compliance equal to the modal realization's,
// and dependent coordinates refused.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <memory>

#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/CondensedSystem.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/hbm/HarmonicLoads.hpp"
#include "cyclone/hbm/JenkinsElement.hpp"
#include "cyclone/hbm/ReceptanceModel.hpp"

using namespace cyclone;
using namespace cyclone::hbm;

namespace {

constexpr int kDofs = 10;

// A sector of 10 DOFs: a contact "right node" (DOFs 0-2) coupled elastically to the
// next sector's "left node" (DOFs 3-5), a grounded DOF 6, the excited DOF 8 and a
// watched DOF 9; proportional damping (so a modal realization exists).
std::shared_ptr<MatrixReceptance> sectorModel(int N) {
  Eigen::MatrixXd K = 6.0 * Eigen::MatrixXd::Identity(kDofs, kDofs), Kn = Eigen::MatrixXd::Zero(kDofs, kDofs);
  for (int i = 0; i + 1 < kDofs; ++i) K(i, i + 1) = K(i + 1, i) = -1.0 - 0.1 * i;
  K(2, 8) = K(8, 2) = -0.7, K(5, 9) = K(9, 5) = 0.4;
  for (int i = 0; i < 3; ++i) Kn(i, 3 + i) = -1.2;
  const Eigen::VectorXd m = Eigen::VectorXd::LinSpaced(kDofs, 0.6, 1.5);
  const Eigen::MatrixXd M = m.asDiagonal();
  return std::make_shared<MatrixReceptance>(M, 0.02 * K, K, N, Eigen::MatrixXd(), 0.02 * Kn, Kn);
}

std::unique_ptr<HarmonicBalanceSystem> fullSystem(int N, int eo, int H = 3) {
  auto s = std::make_unique<HarmonicBalanceSystem>(sectorModel(N), HarmonicSet::upTo(H), 128);
  CyclicCoupling c;
  c.sectors = N, c.engineOrder = eo;
  s->setCyclic(c);
  FrictionContactParameters p;
  p.tangentialDirections = 2, p.kt = 3.0, p.kn = 4.0, p.mu = 0.3, p.preload = 0.2;
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(kDofs, 3), Wn = Eigen::MatrixXd::Zero(kDofs, 3);
  for (int i = 0; i < 3; ++i) W(i, i) = -1, Wn(3 + i, i) = 1;
  W(1, 0) = 0.2;  // a frame not aligned with the DOFs
  s->addElement(std::make_shared<FrictionContact>(p), W, Wn);
  Eigen::VectorXd ground = Eigen::VectorXd::Zero(kDofs);
  ground(6) = 1;
  s->addElement(std::make_shared<JenkinsElement>(2.0, 0.05), ground);
  s->addExcitation(8, 1, 0.6, 0.1);
  s->addStaticLoad(8, 0.05);
  return s;
}

Eigen::VectorXd solve(const HarmonicBalanceSystem& s, double w) {
  Eigen::VectorXd X = s.linearizedSolution(w), R;
  Eigen::MatrixXd J;
  for (int it = 0; it < 60; ++it) {
    s.residual(X, w, R, &J);
    if (R.norm() < 1e-13) break;
    X -= J.partialPivLu().solve(R);
  }
  s.residual(X, w, R, nullptr);
  EXPECT_LT(R.norm(), 1e-11) << "Newton did not converge at w = " << w;
  return X;
}

// q of a full solution: the kept DOFs, then each element's W^T x + W_next^T x_next.
Eigen::VectorXd coordinatesOf(const HarmonicBalanceSystem& full, const CondensedSystem& c, const Eigen::VectorXd& X) {
  const int nc = full.numCoefficients();
  const Eigen::Map<const Eigen::MatrixXd> Xm(X.data(), nc, full.numDofs());
  Eigen::VectorXd Q(c.system->numUnknowns());
  for (std::size_t i = 0; i < c.keptDofs.size(); ++i) Q.segment(int(i) * nc, nc) = Xm.col(c.keptDofs[i]);
  for (std::size_t e = 0; e < full.elements().size(); ++e) {
    const auto& el = full.elements()[e];
    Eigen::MatrixXd w = Xm * el.W;
    if (el.Wnext.size() != 0) w += full.nextSectorMap() * (Xm * el.Wnext);
    for (int k = 0; k < w.cols(); ++k) Q.segment((c.elementCoordinate[e] + k) * nc, nc) = w.col(k);
  }
  return Q;
}

}  // namespace

TEST(CondensedSystem, SameSolutionsAsTheFullReceptanceForm) {
  const int N = 6;
  double worstQ = 0, worstX = 0;
  for (int eo : {1, 2, 3}) {
    for (bool stiffness : {false, true}) {
      auto full = fullSystem(N, eo);
      full->useDynamicStiffness(stiffness);
      const auto c = condenseOntoElements(*full, {8, 9});
      ASSERT_EQ(c.system->numDofs(), 2 + 3 + 1);
      for (double w : {0.9, 1.7, 2.6}) {
        const Eigen::VectorXd X = solve(*full, w), Q = solve(*c.system, w);
        const double errQ = (Q - coordinatesOf(*full, c, X)).norm() / Q.norm();
        const double errX = (expandToAllDofs(*full, c, Q, w) - X).norm() / X.norm();
        worstQ = std::max(worstQ, errQ), worstX = std::max(worstX, errX);
        EXPECT_LT(errQ, 1e-10) << "EO " << eo << ", w " << w;
        EXPECT_LT(errX, 1e-10) << "EO " << eo << ", w " << w;
      }
    }
  }
  std::printf("condensed (6 unknowns per coefficient) vs full (10): coordinates %.1e, recovered DOFs %.1e\n", worstQ,
              worstX);
}

TEST(CondensedSystem, JacobianMatchesFiniteDifferences) {
  auto full = fullSystem(6, 2);
  full->useDynamicStiffness(true);
  const auto c = condenseOntoElements(*full, {8, 9});
  const double w = 1.4;
  const Eigen::VectorXd Q = solve(*c.system, w) * 1.3;  // off the solution: sticking and slipping
  Eigen::VectorXd R0, Rp, Rm;
  Eigen::MatrixXd J;
  c.system->residual(Q, w, R0, &J);
  double worst = 0;
  for (int j = 0; j < Q.size(); ++j) {
    Eigen::VectorXd Qp = Q, Qm = Q;
    const double h = 1e-6 * std::max(1.0, std::abs(Q(j)));
    Qp(j) += h, Qm(j) -= h;
    c.system->residual(Qp, w, Rp, nullptr);
    c.system->residual(Qm, w, Rm, nullptr);
    worst = std::max(worst, ((Rp - Rm) / (2 * h) - J.col(j)).norm() / J.norm());
  }
  std::printf("condensed Jacobian vs central differences: %.1e\n", worst);
  EXPECT_LT(worst, 1e-6);
}

TEST(CondensedSystem, ProjectedModalRealizationIsTheProjectedCompliance) {
  auto full = fullSystem(6, 2);
  const auto c = condenseOntoElements(*full, {8, 9});
  for (long p : {1L, 2L, 4L}) {
    const auto r = c.receptance->modalRealization(p);
    ASSERT_TRUE(r.has_value());
    for (double w : {0.7, 2.1}) {
      Eigen::VectorXcd d(r->numModes());
      for (int j = 0; j < r->numModes(); ++j)
        d(j) = 1.0 / std::complex<double>(r->eigenvalues(j) - w * w, r->viscous(j) * w);
      const Eigen::MatrixXcd fromModes = r->R + r->U * d.asDiagonal() * r->V.transpose();
      const Eigen::MatrixXcd A = c.receptance->compliance(w, p);
      EXPECT_LT((fromModes - A).norm() / A.norm(), 1e-10) << "p " << p << ", w " << w;
    }
  }
}

TEST(CondensedSystem, RefusesDependentCoordinatesAndUnkeptLoads) {
  auto full = fullSystem(6, 2);
  // Both contact nodes kept: the contact's relative motion is a combination of them.
  EXPECT_THROW(condenseOntoElements(*full, {0, 1, 2, 3, 4, 5, 8}), InputError);
  // The excitation's DOF 8 not kept.
  EXPECT_THROW(condenseOntoElements(*full, {9}), InputError);
  EXPECT_THROW(condenseOntoElements(*full, {8, 10}), InputError);
}

// The loads a condensed solution puts on the base model's DOFs (T_p^H f_q), driven
// through the base model, give back the full system's solution at every DOF; and
// they are the loads the full system's own solution puts there.
TEST(HarmonicLoads, CondensedLoadsOnTheBaseModelReproduceTheFullSolution) {
  const int N = 6;
  double worstX = 0, worstF = 0;
  for (int eo : {1, 2}) {
    auto full = fullSystem(N, eo);
    const auto c = condenseOntoElements(*full, {8, 9});
    const auto& H = full->aft().harmonics();
    const int nc = full->numCoefficients();
    for (double w : {0.9, 1.7}) {
      const Eigen::VectorXd X = solve(*full, w), Q = solve(*c.system, w);
      const auto loads = harmonicLoads(*c.system, Q, w), direct = harmonicLoads(*full, X, w);
      ASSERT_EQ(loads.size(), std::size_t(H.size()));
      const auto x = harmonicResponse(c.receptance->base(), loads, w);
      for (std::size_t k = 0; k < loads.size(); ++k) {
        const int h = loads[k].harmonic;
        ASSERT_EQ(loads[k].force.size(), kDofs);
        for (int i = 0; i < kDofs; ++i) {
          const std::complex<double> expected(X(i * nc + H.cosIndex(h)), h == 0 ? 0.0 : -X(i * nc + H.sinIndex(h)));
          worstX = std::max(worstX, std::abs(x[k](i) - expected) / X.cwiseAbs().maxCoeff());
        }
        worstF = std::max(worstF, (loads[k].force - direct[k].force).norm() / (1 + direct[k].force.norm()));
      }
    }
  }
  std::printf("base model driven by the condensed solution's loads vs the full solution: %.1e; loads %.1e\n", worstX,
              worstF);
  EXPECT_LT(worstX, 1e-10);
  EXPECT_LT(worstF, 1e-10);
}
