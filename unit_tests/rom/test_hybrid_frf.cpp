// rom::HybridFrfModel (hybrid and plain modal truncation) on small dense systems,
// with the full model's modes and static compliance computed here by dense
// Eigen, against the exact dense receptance ((1 + i eta) K - w^2 M)^{-1} at the
// retained DOFs and the closed forms the header states:
//   all modes kept: both are exact;
//   truncated, the hybrid model misses exactly
//     E(w) = sum over dropped j of phi_j phi_j^T (w^2 - (1 + i eta) s) / (((1 + i eta) l_j - w^2)(1 + i eta)(l_j - s)),
//   s = w0^2: zero at w = w0 when undamped, small well below the dropped modes,
//   falling as modes are added; plain truncation misses sum_dropped phi phi^T / ((1 + i eta) l - w^2).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "DenseSystems.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/rom/GuyanModel.hpp"
#include "cyclone/rom/HybridFrfModel.hpp"

using namespace cyclone;
using namespace rom_test;

namespace {

constexpr Index kRetained = 4;

// A fully coupled 10-DOF system, its first 4 DOFs retained.
DenseSystem testSystem() { return randomSpd(10, 7); }

rom::HybridFrfModel hybrid(const DenseSystem& s, const FullModes& full, int m, double omega0, double eta,
                           const Eigen::MatrixXd& F = {}) {
  return rom::HybridFrfModel(retainedModes(full, kRetained, m, 1, F), staticCompliance(s, kRetained, omega0, F), eta);
}

// The closed-form error of the hybrid model with the lowest m modes kept.
Eigen::MatrixXcd hybridTruncationError(const FullModes& full, int m, double omega, double omega0, double eta) {
  const cd damped(1.0, eta);
  const double w2 = omega * omega, sigma = omega0 * omega0;
  Eigen::MatrixXcd E = Eigen::MatrixXcd::Zero(kRetained, kRetained);
  for (int j = m; j < full.eigenvalues.size(); ++j) {
    const double l = full.eigenvalues(j);
    const Eigen::VectorXd phi = full.shapes.col(j).head(kRetained);
    E += (phi * phi.transpose()).cast<cd>() * ((w2 - damped * sigma) / ((damped * l - w2) * damped * (l - sigma)));
  }
  return E;
}

}  // namespace

TEST(RomHybridFrf, AllModesIsExact) {
  const DenseSystem s = testSystem();
  const FullModes full = fullModes(s);
  const int n = int(s.size());
  const double eta = 0.03;
  double worst = 0;
  // The expansion point below the first mode, at 0 and between modes 3 and 4: with
  // every mode kept the static part cancels whatever it is.
  for (double omega0 : {0.0, 0.5 * full.omega(0), 0.5 * (full.omega(2) + full.omega(3))}) {
    const auto model = hybrid(s, full, n, omega0, eta);
    for (double w : {0.0, 0.3 * full.omega(0), 0.5 * (full.omega(4) + full.omega(5)), 1.2 * full.omega(n - 1)})
      worst = std::max(worst, relativeError(model.compliance(w), exactReceptance(s, kRetained, w, eta)));
  }
  const auto truncation = rom::HybridFrfModel::modalTruncation(retainedModes(full, kRetained, n), eta);
  double worstTruncation = 0;
  for (double w : {0.0, 0.3 * full.omega(0), 0.5 * (full.omega(4) + full.omega(5))})
    worstTruncation =
        std::max(worstTruncation, relativeError(truncation.compliance(w), exactReceptance(s, kRetained, w, eta)));
  std::printf("all %d modes: hybrid %.2e, truncation %.2e\n", n, worst, worstTruncation);
  EXPECT_LT(worst, 1e-10);
  EXPECT_LT(worstTruncation, 1e-10);
}

// Undamped, the hybrid model is exact at its expansion frequency whatever the modes
// kept (there E(w0) = 0), also with w0 between kept modes; plain truncation is not.
TEST(RomHybridFrf, ExactAtTheExpansionFrequency) {
  const DenseSystem s = testSystem();
  const FullModes full = fullModes(s);
  for (double omega0 : {0.0, 0.6 * full.omega(0), 0.5 * (full.omega(0) + full.omega(1))}) {
    const auto model = hybrid(s, full, 2, omega0, 0.0);
    const auto exact = exactReceptance(s, kRetained, omega0, 0.0);
    const double err = relativeError(model.compliance(omega0), exact);
    const double truncErr = relativeError(
        rom::HybridFrfModel::modalTruncation(retainedModes(full, kRetained, 2), 0.0).compliance(omega0), exact);
    std::printf("w0 = %.3f w1, 2 of 10 modes: hybrid %.2e, truncation %.2e\n", omega0 / full.omega(0), err, truncErr);
    EXPECT_LT(err, 1e-10);
    EXPECT_GT(truncErr, 1e-3);
  }
}

// With damping the expansion is about (1 + i eta) w0^2, so the error at any w is
// exactly E(w): checks the form of the static correction term by term (Petrov's
// form with a real A0, as the seed had, differs by about i eta A0).
TEST(RomHybridFrf, TruncationErrorIsTheDroppedModesClosedForm) {
  const DenseSystem s = testSystem();
  const FullModes full = fullModes(s);
  const double eta = 0.05;
  double worst = 0;
  for (double omega0 : {0.0, 0.7 * full.omega(0)})
    for (int m : {1, 3, 6})
      for (double w : {0.0, omega0, 0.4 * full.omega(0), 0.5 * (full.omega(1) + full.omega(2)), 1.1 * full.omega(m)}) {
        const auto exact = exactReceptance(s, kRetained, w, eta);
        const Eigen::MatrixXcd missing = exact - hybrid(s, full, m, omega0, eta).compliance(w);
        // Measured against |A(w)|: the closed form itself is small, so this is the test's precision.
        worst = std::max(worst, (missing - hybridTruncationError(full, m, w, omega0, eta)).norm() / exact.norm());
      }
  std::printf("hybrid error minus its closed form: %.2e of |A|\n", worst);
  EXPECT_LT(worst, 1e-10);
}

// Well below the first mode, plain truncation misses the dropped modes' static
// flexibility, sum phi phi^T / l (order one of the answer), while the hybrid model
// misses only its w^2 / l part: with 2 of 20 modes the hybrid error is smaller by
// far more than a factor 100. A wrong static correction shows here.
TEST(RomHybridFrf, StaticCorrectionBeatsTruncationBelowTheFirstMode) {
  const DenseSystem s = reordered(gradedChain(20), {9, 19});  // a mid mass and the tip
  const FullModes full = fullModes(s);
  const Index nb = 2;
  const double eta = 0.01, w = 0.1 * full.omega(0);
  const auto exact = exactReceptance(s, nb, w, eta);
  const rom::HybridFrfModel withStatic(retainedModes(full, nb, 2), staticCompliance(s, nb, 0.0), eta);
  const auto truncation = rom::HybridFrfModel::modalTruncation(retainedModes(full, nb, 2), eta);
  EXPECT_TRUE(withStatic.hasStaticCorrection());
  EXPECT_FALSE(truncation.hasStaticCorrection());
  const double hybridErr = relativeError(withStatic.compliance(w), exact);
  const double truncErr = relativeError(truncation.compliance(w), exact);
  std::printf("w = 0.1 w1, 2 of 20 modes: hybrid %.2e, truncation %.2e, ratio %.1f\n", hybridErr, truncErr,
              truncErr / hybridErr);
  EXPECT_GT(truncErr, 1e-2);  // truncation is visibly wrong here
  EXPECT_LT(hybridErr, 1e-3 * truncErr);
}

// The hybrid model's error falls with every mode added (each dropped mode's term has
// the same phase up to O(eta), so removing one shrinks the sum) and is always below
// that of plain truncation with the same modes; all modes: exact.
TEST(RomHybridFrf, ErrorFallsWithTheModeCount) {
  const DenseSystem s = testSystem();
  const FullModes full = fullModes(s);
  const int n = int(s.size());
  const double eta = 0.02, w = 0.5 * full.omega(0);
  const auto exact = exactReceptance(s, kRetained, w, eta);
  double previous = 1e300;
  for (int m = 1; m <= n; ++m) {
    const double err = relativeError(hybrid(s, full, m, 0.0, eta).compliance(w), exact);
    const double truncErr = relativeError(
        rom::HybridFrfModel::modalTruncation(retainedModes(full, kRetained, m), eta).compliance(w), exact);
    std::printf("m = %2d: hybrid %.2e, truncation %.2e\n", m, err, truncErr);
    EXPECT_LT(err, previous) << "m " << m;
    if (m < n) {
      EXPECT_LT(err, truncErr) << "m " << m;
    }
    previous = err;
  }
  EXPECT_LT(previous, 1e-10);
}

// The mean (harmonic 0) sees the undamped compliance at w = 0: with the static
// correction at w0 = 0 it is K^{-1} at the retained DOFs exactly, whatever the
// modes kept; with w0 > 0 and all modes kept also; truncated with w0 > 0 it misses
// sum_dropped phi phi^T (1 / l - 1 / (l - s)).
TEST(RomHybridFrf, ZeroFrequencyCompliance) {
  const DenseSystem s = testSystem();
  const FullModes full = fullModes(s);
  const int n = int(s.size());
  const Eigen::MatrixXd flexibility = s.K.inverse().topLeftCorner(kRetained, kRetained);
  const double omega0 = 0.8 * full.omega(0), sigma = omega0 * omega0;
  Eigen::MatrixXd missing = Eigen::MatrixXd::Zero(kRetained, kRetained);
  for (int j = 2; j < n; ++j) {
    const Eigen::VectorXd phi = full.shapes.col(j).head(kRetained);
    const double l = full.eigenvalues(j);
    missing += phi * phi.transpose() * (1 / l - 1 / (l - sigma));
  }
  const double atZero = relativeError(hybrid(s, full, 2, 0.0, 0.02).zeroFrequencyCompliance(), flexibility);
  const double allModes = relativeError(hybrid(s, full, n, omega0, 0.02).zeroFrequencyCompliance(), flexibility);
  const double truncated =
      (flexibility - hybrid(s, full, 2, omega0, 0.02).zeroFrequencyCompliance() - missing).norm() / flexibility.norm();
  const double truncation = relativeError(
      rom::HybridFrfModel::modalTruncation(retainedModes(full, kRetained, n), 0.02).zeroFrequencyCompliance(),
      flexibility);
  std::printf("zero-frequency compliance: w0 = 0 with 2 modes %.2e, w0 > 0 all modes %.2e, w0 > 0 2 modes against "
              "closed form %.2e, truncation all modes %.2e\n",
              atZero, allModes, truncated, truncation);
  EXPECT_LT(atZero, 1e-10);
  EXPECT_LT(allModes, 1e-10);
  EXPECT_LT(truncated, 1e-10);
  EXPECT_LT(truncation, 1e-10);
}

// The split the Woodbury dynamic stiffness and Hill's method use,
// A(w) = R + Phi diag(d(w)) Phi^T: R is the dropped modes' constant part,
// sum_dropped phi phi^T / ((1 + i eta)(l - s)), zero with all modes kept.
TEST(RomHybridFrf, ResidualIsTheDroppedModes) {
  const DenseSystem s = testSystem();
  const FullModes full = fullModes(s);
  const int n = int(s.size()), m = 3;
  const double eta = 0.04, omega0 = 0.5 * full.omega(0), sigma = omega0 * omega0;
  const auto model = hybrid(s, full, m, omega0, eta);
  Eigen::MatrixXcd dropped = Eigen::MatrixXcd::Zero(kRetained, kRetained);
  for (int j = m; j < n; ++j) {
    const Eigen::VectorXd phi = full.shapes.col(j).head(kRetained);
    dropped += (phi * phi.transpose()).cast<cd>() / (cd(1.0, eta) * (full.eigenvalues(j) - sigma));
  }
  const double residualErr = relativeError(model.residualCompliance(), dropped);
  const Eigen::MatrixXd& phi = model.modes().shapes;
  double splitErr = 0;
  for (double w : {0.2 * full.omega(0), 0.5 * (full.omega(3) + full.omega(4))}) {
    // Against the exact receptance, with the modal part from the dense modes and R's closed form.
    Eigen::VectorXcd d(m);
    for (int j = 0; j < m; ++j) d(j) = 1.0 / (cd(1.0, eta) * full.eigenvalues(j) - w * w);
    EXPECT_LT(relativeError(model.modalWeights(w), d), 1e-14);
    const Eigen::MatrixXcd split =
        model.residualCompliance() + phi.cast<cd>() * d.asDiagonal() * phi.transpose().cast<cd>();
    const Eigen::MatrixXcd reference =
        exactReceptance(s, kRetained, w, eta) - hybridTruncationError(full, m, w, omega0, eta);
    splitErr = std::max(splitErr, relativeError(split, reference));
  }
  const double allModesResidual = hybrid(s, full, n, omega0, eta).residualCompliance().norm() /
                                  staticCompliance(s, kRetained, omega0).matrix.norm();
  std::printf("residual: %.2e, split %.2e, all modes |R| / |A0| %.2e\n", residualErr, splitErr, allModesResidual);
  EXPECT_LT(residualErr, 1e-10);
  EXPECT_LT(splitErr, 1e-10);
  EXPECT_LT(allModesResidual, 1e-10);
  const auto truncation = rom::HybridFrfModel::modalTruncation(retainedModes(full, kRetained, m), eta);
  EXPECT_EQ(truncation.residualCompliance().norm(), 0.0);
}

// The excitation part: loads on interior DOFs (not retained), the response at the
// retained DOFs against the exact dense ((1 + i eta) K - w^2 M)^{-1} F.
TEST(RomHybridFrf, LoadResponse) {
  const DenseSystem s = testSystem();
  const FullModes full = fullModes(s);
  const int n = int(s.size());
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(n, 2);
  F(6, 0) = 1.0, F(9, 0) = -0.4;  // a force pair
  F(5, 1) = 2.0;                  // a single force
  const double eta = 0.02, w = 0.5 * (full.omega(1) + full.omega(2));
  const auto exactAt = [&](double omega, double damping) {
    return Eigen::MatrixXcd(exactResponse(s, F.cast<cd>(), omega, damping).topRows(kRetained));
  };
  const double allModes = relativeError(hybrid(s, full, n, 0.0, eta, F).loadResponse(w), exactAt(w, eta));
  const auto allModesTruncation = rom::HybridFrfModel::modalTruncation(retainedModes(full, kRetained, n, 1, F), eta);
  const double truncation = relativeError(allModesTruncation.loadResponse(w), exactAt(w, eta));
  // Undamped and truncated: exact at the expansion frequency (same weights as the compliance).
  const double omega0 = 0.6 * full.omega(0);
  const double atOmega0 = relativeError(hybrid(s, full, 2, omega0, 0.0, F).loadResponse(omega0), exactAt(omega0, 0.0));
  // Truncated, damped: it misses the dropped modes' terms phi_b (phi^T F) with the weights of E(w).
  double closedForm = 0;
  for (int m : {1, 3, 6})
    for (double omega : {0.4 * full.omega(0), w}) {
      const Eigen::MatrixXcd exact = exactAt(omega, eta);
      const Eigen::MatrixXcd missing = exact - hybrid(s, full, m, omega0, eta, F).loadResponse(omega);
      Eigen::MatrixXcd expected = Eigen::MatrixXcd::Zero(kRetained, 2);
      const cd damped(1.0, eta);
      const double sigma = omega0 * omega0;
      for (int j = m; j < n; ++j) {
        const double l = full.eigenvalues(j);
        const cd weight = (omega * omega - damped * sigma) / ((damped * l - omega * omega) * damped * (l - sigma));
        expected += weight * (full.shapes.col(j).head(kRetained) * (full.shapes.col(j).transpose() * F)).cast<cd>();
      }
      closedForm = std::max(closedForm, (missing - expected).norm() / exact.norm());
    }
  std::printf("load response: all modes hybrid %.2e, truncation %.2e; 2 modes at w0 %.2e; truncated minus closed form "
              "%.2e\n", allModes, truncation, atOmega0, closedForm);
  EXPECT_LT(allModes, 1e-10);
  EXPECT_LT(truncation, 1e-10);
  EXPECT_LT(atOmega0, 1e-10);
  EXPECT_LT(closedForm, 1e-10);
  // A model without load patterns has no excitation part.
  EXPECT_THROW(hybrid(s, full, 2, 0.0, eta).loadResponse(w), InputError);
  EXPECT_THROW(rom::GuyanModel(boundaryReduction(s, kRetained), eta).loadResponse(w), InputError);
}

TEST(RomHybridFrf, InconsistentInputIsRefused) {
  const DenseSystem s = testSystem();
  const FullModes full = fullModes(s);
  EXPECT_THROW(rom::HybridFrfModel(retainedModes(full, kRetained, 2), staticCompliance(s, kRetained + 1, 0.0), 0.01),
               InputError);
  EXPECT_THROW(rom::HybridFrfModel::modalTruncation(retainedModes(full, kRetained, 2), -0.01), InputError);
  EXPECT_THROW(rom::HybridFrfModel::modalTruncation(rom::RetainedModes{}, 0.01), InputError);
}
