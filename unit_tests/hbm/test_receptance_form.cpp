// The receptance form of the harmonic balance against the matrix form it
// stands for: with A = Z^{-1} per harmonic (MatrixReceptance of the same M, C,
// K and cyclic coupling), R_receptance = kappa A R_matrix for any X, so both
// have the same solutions; the analytic Jacobian against finite differences.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <map>
#include <memory>
#include <random>

#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/FullRingSystem.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/hbm/HillStability.hpp"
#include "cyclone/hbm/JenkinsElement.hpp"
#include "cyclone/hbm/ModalReceptance.hpp"
#include "cyclone/hbm/ReceptanceModel.hpp"
#include "cyclone/hbm/TimeIntegration.hpp"
#include "RingSector.hpp"

using namespace cyclone;
using namespace cyclone::hbm;

namespace {

using Matrices = test_support::RingMatrices;
using test_support::ringMatrices;

// Elements and loads shared by both forms: the ring's elements and a preload.
void addElementsAndLoads(HarmonicBalanceSystem& s) {
  test_support::addRingElements(s);
  s.addExcitation(1, 1, 0.8, 0.1);
  s.addExcitation(2, 1, 0.2);
  s.addStaticLoad(2, 0.3);
}

std::pair<std::unique_ptr<HarmonicBalanceSystem>, std::unique_ptr<HarmonicBalanceSystem>> bothForms(int N, int eo) {
  const auto m = ringMatrices();
  const int samples = 96;
  auto matrix = std::make_unique<HarmonicBalanceSystem>(m.M, m.C, m.K, HarmonicSet::upTo(3), samples);
  auto model = std::make_shared<MatrixReceptance>(m.M, m.C, m.K, N, m.Mn, m.Cn, m.Kn);
  auto receptance = std::make_unique<HarmonicBalanceSystem>(model, HarmonicSet::upTo(3), samples);
  CyclicCoupling c;
  c.sectors = N, c.engineOrder = eo;
  receptance->setCyclic(c);
  c.Knext = m.Kn, c.Cnext = m.Cn, c.Mnext = m.Mn;
  matrix->setCyclic(c);
  addElementsAndLoads(*matrix);
  addElementsAndLoads(*receptance);
  return {std::move(matrix), std::move(receptance)};
}

Eigen::VectorXd randomVector(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x(i) = u(rng);
  return x;
}

}  // namespace

TEST(ReceptanceForm, ResidualIsComplianceTimesMatrixResidual) {
  const int N = 6;
  for (int eo : {0, 1, 2, 3, 5, -1}) {
    auto [matrix, receptance] = bothForms(N, eo);
    const Eigen::VectorXd X = 0.8 * randomVector(matrix->numUnknowns(), 7 + eo);
    const double w = 1.3;
    Eigen::VectorXd Rm, Rr;
    Eigen::MatrixXd Jm, Jr;
    matrix->residual(X, w, Rm, &Jm);
    receptance->residual(X, w, Rr, &Jr);
    const Eigen::MatrixXd B = receptance->complianceOperator(w);
    const double kappa = receptance->receptanceStiffness();
    // Independent: B is the inverse of the matrix form's dynamic stiffness.
    const double inverseErr = (B * matrix->linearOperator(w) - Eigen::MatrixXd::Identity(B.rows(), B.cols())).norm();
    const double resErr = (Rr - kappa * B * Rm).norm() / Rr.norm();
    const double jacErr = (Jr - kappa * B * Jm).norm() / Jr.norm();
    std::printf("EO %2d: |B Z - I| %.1e, residual %.1e, Jacobian %.1e\n", eo, inverseErr, resErr, jacErr);
    EXPECT_LT(inverseErr, 1e-10) << eo;
    EXPECT_LT(resErr, 1e-12) << eo;
    EXPECT_LT(jacErr, 1e-12) << eo;
  }
}

TEST(ReceptanceForm, DynamicStiffnessStatementEqualsMatrixForm) {
  for (int eo : {0, 2, 3}) {
    auto [matrix, receptance] = bothForms(6, eo);
    receptance->useDynamicStiffness(true);
    const Eigen::VectorXd X = 0.8 * randomVector(matrix->numUnknowns(), 21 + eo);
    Eigen::VectorXd Rm, Rr;
    Eigen::MatrixXd Jm, Jr;
    matrix->residual(X, 1.3, Rm, &Jm);
    receptance->residual(X, 1.3, Rr, &Jr);
    const double resErr = (Rr - Rm).norm() / Rm.norm(), jacErr = (Jr - Jm).norm() / Jm.norm();
    std::printf("EO %d, Z = A^-1: residual %.1e, Jacobian %.1e\n", eo, resErr, jacErr);
    EXPECT_LT(resErr, 1e-12);
    EXPECT_LT(jacErr, 1e-12);
  }
}

TEST(ReceptanceForm, JacobianMatchesFiniteDifferences) {
  auto [matrix, receptance] = bothForms(6, 2);
  const Eigen::VectorXd X = 0.5 * randomVector(receptance->numUnknowns(), 3);
  Eigen::VectorXd R0, R1, R2;
  Eigen::MatrixXd J;
  receptance->residual(X, 1.1, R0, &J);
  const double h = 1e-6;
  double worst = 0;
  for (int j = 0; j < receptance->numUnknowns(); ++j) {
    Eigen::VectorXd Xp = X, Xm = X;
    Xp(j) += h, Xm(j) -= h;
    receptance->residual(Xp, 1.1, R1, nullptr);
    receptance->residual(Xm, 1.1, R2, nullptr);
    worst = std::max(worst, ((R1 - R2) / (2 * h) - J.col(j)).norm() / J.norm());
  }
  std::printf("receptance Jacobian vs central differences: %.1e\n", worst);
  EXPECT_LT(worst, 1e-6);
}

TEST(ReceptanceForm, SameSolutionAsMatrixForm) {
  auto [matrix, receptance] = bothForms(6, 2);
  const double w = 1.9;
  // Newton on each form from its own linearised start.
  auto solve = [w](const HarmonicBalanceSystem& s) {
    Eigen::VectorXd X = s.linearizedSolution(w), R;
    Eigen::MatrixXd J;
    for (int it = 0; it < 50; ++it) {
      s.residual(X, w, R, &J);
      if (R.norm() < 1e-13) break;
      X -= J.partialPivLu().solve(R);
    }
    return X;
  };
  const Eigen::VectorXd Xm = solve(*matrix), Xr = solve(*receptance);
  Eigen::VectorXd R;
  matrix->residual(Xr, w, R, nullptr);
  const double err = (Xm - Xr).norm() / Xm.norm();
  std::printf("solutions differ by %.1e, matrix residual at the receptance solution %.1e\n", err, R.norm());
  EXPECT_LT(err, 1e-10);
  EXPECT_LT(R.norm(), 1e-10);
}

TEST(ReceptanceForm, MatrixOnlyFeaturesSayWhy) {
  auto [matrix, receptance] = bothForms(6, 2);
  EXPECT_THROW(receptance->K(), InputError);
  EXPECT_THROW(receptance->setDampingScale(2.0), InputError);
  EXPECT_THROW(receptance->linearOperator(1.0), InputError);
  CyclicCoupling wrong;
  wrong.sectors = 5, wrong.engineOrder = 1;
  const auto m = ringMatrices();
  HarmonicBalanceSystem other(std::make_shared<MatrixReceptance>(m.M, m.C, m.K, 6, m.Mn, m.Cn, m.Kn),
                              HarmonicSet::upTo(1), 16);
  EXPECT_THROW(other.setCyclic(wrong), InputError);
}

namespace {

// The system's solution at w by Newton from the linearised one (empty if it does not
// converge to 1e-10).
Eigen::VectorXd newtonSolution(const HarmonicBalanceSystem& system, double w) {
  Eigen::VectorXd X = system.linearizedSolution(w), R;
  Eigen::MatrixXd J;
  for (int it = 0; it < 50; ++it) {
    system.residual(X, w, R, &J);
    if (R.norm() < 1e-13) break;
    X -= J.partialPivLu().solve(R);
  }
  return R.norm() < 1e-10 ? X : Eigen::VectorXd();
}

}  // namespace

// Hill's method on the receptance form (through the model's modal realization)
// is the same eigenproblem as on the matrix form, in other coordinates: every
// eigenvalue of the truncated Hill problem agrees, for every engine order, and
// so does the verdict (a time integration confirms it below).
TEST(ReceptanceForm, HillProblemEqualsMatrixForms) {
  const double w = 1.9;
  for (int eo : {0, 1, 2, 3, 5}) {
    auto [matrix, receptance] = bothForms(6, eo);
    // The realization reproduces the model's compliance (independent: an LU inverse of Z).
    const auto& model = *receptance->receptance();
    for (long p = 0; p < 6; ++p) {
      const auto r = model.modalRealization(p);
      ASSERT_TRUE(r.has_value());
      const Eigen::VectorXcd d = (r->eigenvalues.cast<std::complex<double>>() +
                                  std::complex<double>(0, w) * r->viscous.cast<std::complex<double>>())
                                     .array() -
                                 w * w;
      const Eigen::MatrixXcd A = r->R + r->U * d.cwiseInverse().asDiagonal() * r->V.transpose();
      EXPECT_LT((A - model.compliance(w, p)).norm() / A.norm(), 1e-12) << "phase " << p;
    }
    const Eigen::VectorXd X = newtonSolution(*matrix, w);
    ASSERT_GT(X.size(), 0);
    const auto hm = hillStability(*matrix, X, w), hr = hillStability(*receptance, X, w);
    ASSERT_EQ(hm.all.size(), hr.all.size());
    double worst = 0, scale = hm.all.cwiseAbs().maxCoeff();
    for (int i = 0; i < hm.all.size(); ++i) worst = std::max(worst, (hr.all.array() - hm.all(i)).abs().minCoeff());
    std::printf("EO %d: %d Hill eigenvalues, largest distance %.1e (of %.2f); max Re %+.5f (matrix), %+.5f "
                "(receptance, %d picked)\n",
                eo, int(hm.all.size()), worst, scale, hm.maxRealPart, hr.maxRealPart, int(hr.exponents.size()));
    EXPECT_LT(worst, 1e-9 * scale) << "EO " << eo;
    EXPECT_EQ(hm.stable, hr.stable) << "EO " << eo;
    EXPECT_EQ(hm.exponents.size(), hr.exponents.size()) << "EO " << eo;  // the same pick, 2 n
    EXPECT_NEAR(hm.maxRealPart, hr.maxRealPart, 1e-9 * scale) << "EO " << eo;
  }
}


// The size a curve's stability budget is estimated from (ForcedResponse.cpp) is the
// eigenproblem Hill's method solves: the count of its whole problem's eigenvalues in both
// forms, and whole or nearest as HillOptions::denseUpTo decides.
TEST(ReceptanceForm, HillProblemSizeIsTheEigenproblemSolved) {
  const double w = 1.9;
  auto [matrix, receptance] = bothForms(6, 2);
  const Eigen::VectorXd X = newtonSolution(*matrix, w);
  ASSERT_GT(X.size(), 0);
  HillOptions whole;
  whole.denseUpTo = 1 << 30;
  const auto hm = hillStability(*matrix, X, w), hr = hillStability(*receptance, X, w, whole);
  const auto sm = hillProblemSize(*matrix), sr = hillProblemSize(*receptance, whole);
  EXPECT_EQ(sm.unknowns, int(hm.all.size()));
  EXPECT_TRUE(sm.whole);
  EXPECT_EQ(sr.unknowns, int(hr.all.size()));
  EXPECT_TRUE(sr.whole);
  HillOptions nearest;
  nearest.denseUpTo = sr.unknowns - 1;
  EXPECT_FALSE(hillProblemSize(*receptance, nearest).whole);
  EXPECT_EQ(hillProblemSize(*receptance, nearest).unknowns, sr.unknowns);
}

// Hill's eigenvalues nearest zero only (ARPACK on the inverse, as a large problem gets
// them: HillOptions::denseUpTo) against the whole problem's (LAPACK): the same Floquet
// exponents and every eigenvalue up to the modulus covered, for every engine order.
TEST(ReceptanceForm, NearestEigenvaluesGiveTheWholeProblemsExponents) {
  const double w = 1.9;
  for (int eo : {0, 1, 2, 3, 5}) {
    auto [matrix, receptance] = bothForms(6, eo);
    const Eigen::VectorXd X = newtonSolution(*matrix, w);
    ASSERT_GT(X.size(), 0);
    HillOptions whole, nearest;
    whole.denseUpTo = 1 << 30, nearest.denseUpTo = 0;
    const auto a = hillStability(*receptance, X, w, whole), b = hillStability(*receptance, X, w, nearest);
    EXPECT_TRUE(std::isinf(a.covered));
    EXPECT_GE(b.covered, nearest.coverage * w) << "EO " << eo;
    EXPECT_LT(b.all.size(), a.all.size()) << "EO " << eo;
    const double scale = a.all.cwiseAbs().maxCoeff();
    double worst = 0;
    int within = 0;
    for (int i = 0; i < a.all.size(); ++i)
      if (std::abs(a.all(i)) <= b.covered * (1 + 1e-9)) {
        ++within;
        worst = std::max(worst, (b.all.array() - a.all(i)).abs().minCoeff());
      }
    ASSERT_EQ(a.exponents.size(), b.exponents.size()) << "EO " << eo;
    for (int i = 0; i < a.exponents.size(); ++i)
      worst = std::max(worst, (b.exponents.array() - a.exponents(i)).abs().minCoeff());
    std::printf("EO %d: %d of %d eigenvalues computed (up to |mu| = %.2f w), %d exponents, largest distance %.1e\n",
                eo, int(b.all.size()), int(a.all.size()), b.covered / w, int(b.exponents.size()), worst);
    EXPECT_EQ(within, int(b.all.size())) << "EO " << eo;
    EXPECT_LT(worst, 1e-9 * scale) << "EO " << eo;
    EXPECT_EQ(a.stable, b.stable) << "EO " << eo;
  }
}

// The verdict confirmed independently for one engine order: the full ring integrated in
// time from the solution perturbed in every sector (all travelling-wave classes) comes
// back to it. Hill's problem has eigenvalues with Re > 0 far off the axis (|Im| > w / 2),
// which the friction's harmonic balance Jacobian does not make exponents: the pick
// leaves them out. (Seconds of integration: the verification tier.)
TEST(ReceptanceFormVerification, HillVerdictMatchesTimeIntegration) {
  const double w = 1.9;
  auto [matrix, receptance] = bothForms(6, 2);
  const Eigen::VectorXd X = newtonSolution(*matrix, w);
  ASSERT_GT(X.size(), 0);
  const auto hr = hillStability(*receptance, X, w);
  EXPECT_TRUE(hr.stable);
  const Eigen::Index far = std::max_element(hr.all.data(), hr.all.data() + hr.all.size(),
                                            [](auto a, auto b) { return a.real() < b.real(); }) - hr.all.data();
  std::printf("EO 2: largest Re of all Hill eigenvalues %+.4f at Im %.3f w\n", hr.all(far).real(),
              hr.all(far).imag() / w);
  EXPECT_GT(hr.all(far).real(), 0.0);
  EXPECT_GT(std::abs(hr.all(far).imag()), 0.5 * w);
  auto ring = expandToFullRing(*matrix);
  const Eigen::VectorXd X0 = ringCoefficients(*matrix, X);
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  Eigen::VectorXd X1 = X0;
  for (int i = 0; i < X1.size(); ++i) X1(i) += 1e-3 * X0.norm() / std::sqrt(double(X1.size())) * g(rng);
  TimeIntegrationOptions o;
  o.stepsPerPeriod = 256, o.maxPeriods = 400, o.periodTolerance = 1e-10;
  const auto st = integrateToSteadyState(*ring, w, X1, o);
  const double back = (st.coefficients - X0).norm() / X0.norm();
  std::printf("EO 2: the perturbed ring (1e-3) integrated in time: %d periods, back to the solution within %.1e\n",
              st.periods, back);
  EXPECT_TRUE(st.converged);
  EXPECT_LT(back, 1e-2);  // H = 3 truncation and the time step, not the 1e-3 perturbation grown
}

// Every phase's static compliance: the matrix model's K_p^-1 against the closed form
// K_p = K + K_next e^{-i a} + K_next^T e^{i a}, and the default (from the modal
// realization, R + U diag(1 / l) V^T) of a model given by those realizations.
TEST(ReceptanceForm, StaticComplianceOfEveryPhase) {
  const Matrices m = ringMatrices();
  const int N = 6;
  const MatrixReceptance matrix(m.M, m.C, m.K, N, m.Mn, m.Cn, m.Kn);
  std::map<long, ModalRealization> realizations;
  for (long p = 0; p < N; ++p) realizations[p] = *matrix.modalRealization(p);
  const ModalReceptance modal(N, realizations);
  for (long p = 0; p < N; ++p) {
    const double a = 2 * M_PI * double(p) / N;
    const std::complex<double> e(std::cos(a), -std::sin(a));
    const Eigen::MatrixXcd Kp = m.K.cast<std::complex<double>>() + e * m.Kn.cast<std::complex<double>>() +
                                std::conj(e) * m.Kn.transpose().cast<std::complex<double>>();
    const Eigen::MatrixXcd S = Kp.inverse();
    const double eMatrix = (matrix.staticCompliance(p) - S).norm() / S.norm();
    const double eModal = (modal.staticCompliance(p) - S).norm() / S.norm();
    std::printf("phase %ld: matrix %.1e, from the modal realization %.1e\n", p, eMatrix, eModal);
    EXPECT_LT(eMatrix, 1e-12) << p;
    EXPECT_LT(eModal, 1e-12) << p;
  }
  EXPECT_LT((matrix.staticCompliance(0).real() - matrix.meanCompliance()).norm(), 1e-14);
  // A model without a modal form has no static compliance of a phase other than 0.
  class NoModes final : public ReceptanceModel {
  public:
    int numDofs() const override { return 1; }
    int sectors() const override { return 3; }
    Eigen::MatrixXcd compliance(double, long) const override { return Eigen::MatrixXcd::Ones(1, 1); }
    Eigen::MatrixXd meanCompliance() const override { return Eigen::MatrixXd::Ones(1, 1); }
  } none;
  EXPECT_NO_THROW(none.staticCompliance(0));
  EXPECT_THROW(none.staticCompliance(1), InputError);
}
