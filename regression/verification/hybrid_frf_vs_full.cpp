// Verification: the hybrid FRF model (Petrov 2011, exact static correction) and
// plain modal truncation against the full FE dynamic compliance at retained DOFs,
// for one nodal diameter (a travelling pair, real form) of the built-in shrouded
// sector, cantilever (shroud faces free), prestressed at 10 000 rpm, structural
// damping. The reference is a direct complex solve of (1 + i eta) K - w^2 M per
// frequency; the band covers the first 5 natural frequencies, at, next to and
// between the resonances. Prints error and run time against the modes retained.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Timer.hpp"
#include "ShroudedSectorCase.hpp"
#include "cyclone/rom/NodalDiameterModel.hpp"
#include "cyclone/solvers/ModalSolver.hpp"

using namespace cyclone;

namespace {

constexpr int kHarmonic = 2;
constexpr double kEta = 0.005;
constexpr double kRpm = regression::ShroudedSectorCase::kRpm;
using regression::relativeError;

struct SectorCase : regression::ShroudedSectorCase {
  explicit SectorCase(std::vector<std::string> fixedSets)
      : ShroudedSectorCase(std::move(fixedSets), kHarmonic, kEta) {}
};

std::vector<double> band(const rom::RetainedModes& modes, int families) {
  return regression::frequencyBand(modes, families);
}

}  // namespace

namespace {

// The expansion point: at zero frequency (what the mean harmonic of a harmonic balance
// sees) the hybrid model with A0 at sigma = 0 is exact; inside the band an indefinite
// factorization; on a natural frequency a clear error.
void checkExpansionPoints(const rom::NodalDiameterModel& full, const rom::RetainedModes& allModes,
                          const rom::StaticCompliance& A0, const std::vector<double>& w,
                          const std::vector<Eigen::MatrixXcd>& reference) {
  // Zero frequency without damping (what the mean harmonic of a harmonic balance sees):
  // with A0 at sigma = 0 the hybrid model is exact there whatever the modes kept.
  const Eigen::MatrixXd Az = full.zeroFrequencyCompliance();
  const double ez = (rom::HybridFrfModel(allModes.first(5), A0, kEta).zeroFrequencyCompliance() - Az).norm() / Az.norm();
  const double ezt =
      (rom::HybridFrfModel::modalTruncation(allModes.first(5), kEta).zeroFrequencyCompliance() - Az).norm() / Az.norm();
  std::printf("zero frequency, 5 modes: hybrid %.3e, truncation %.3e\n", ez, ezt);
  EXPECT_LT(ez, 1e-10);
  EXPECT_GT(ezt, 1e-3);

  // Expansion point inside the band (between families 2 and 3): an indefinite factorization.
  const double w0 = 0.5 * (std::sqrt(allModes.eigenvalues[2]) + std::sqrt(allModes.eigenvalues[4]));
  const auto A0mid = full.staticCompliance(w0, allModes);
  const rom::HybridFrfModel mid(allModes.first(20), A0mid, kEta);
  double emid = 0;
  for (std::size_t i = 0; i < w.size(); ++i) emid = std::max(emid, relativeError(mid.compliance(w[i]), reference[i]));
  const rom::HybridFrfModel zero(allModes.first(20), A0, kEta);
  double ezero = 0;
  for (std::size_t i = 0; i < w.size(); ++i)
    ezero = std::max(ezero, relativeError(zero.compliance(w[i]), reference[i]));
  std::printf("20 modes, w0 = %.1f Hz (in the band): %.3e (w0 = 0: %.3e)\n", w0 / (2 * M_PI), emid, ezero);
  EXPECT_LT(emid, ezero);

  // w0 on a natural frequency: a clear error naming it.
  const double w3 = std::sqrt(allModes.eigenvalues[4]);
  try {
    full.staticCompliance(w3 * (1 + 1e-5), allModes);
    ADD_FAILURE() << "w0 on natural frequency 5 was accepted";
  } catch (const InputError& e) {
    std::printf("w0 on a natural frequency: %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("natural frequency"), std::string::npos);
  }
}

}  // namespace

TEST(HybridFrf, ConvergesToFullFeCompliance) {
  Timer timer;
  const SectorCase s({"bore"});
  const rom::NodalDiameterModel full(s.mesh, s.sector, s.problem, Tpetra::getDefaultComm());
  ASSERT_EQ(full.copies(), 2);
  const double setupSeconds = timer.seconds();

  const int maxModes = 60;
  const auto allModes = full.modes(maxModes);
  const auto A0 = full.staticCompliance(0.0, allModes);
  const auto w = band(allModes, 5);
  std::printf("shrouded sector N = 8, cantilever, k = %d, %.0f rpm, eta = %g: %lld equations, %ld retained DOFs, "
              "setup %.2f s, %d modes %.2f s, A0 %.2f s\n",
              kHarmonic, kRpm, kEta, full.equations(), long(full.size()), setupSeconds, maxModes,
              allModes.seconds, A0.seconds);
  for (int j = 0; j < 6; ++j)
    std::printf("  natural frequency %d: %.3f Hz\n", j + 1,
                std::sqrt(allModes.eigenvalues[std::size_t(2 * j)]) / (2 * M_PI));

  timer.restart();
  std::vector<Eigen::MatrixXcd> reference;
  for (double omega : w) reference.push_back(full.compliance(omega));
  const double fullSeconds = timer.seconds() / double(w.size());
  std::printf("full FE compliance: %.3f s per frequency (complex LU, %ld right-hand sides)\n", fullSeconds,
              long(full.size()));

  std::printf("%6s %14s %14s %14s %12s\n", "modes", "hybrid err", "truncation err", "seed-A0 err", "eval [s]");
  double previous = 1e300, best = 1e300;
  for (int m : {5, 10, 20, 40, 60}) {
    const auto modes = allModes.first(m);
    const rom::HybridFrfModel hybrid(modes, A0, kEta);
    const auto truncation = rom::HybridFrfModel::modalTruncation(modes, kEta);
    double eh = 0, et = 0, es = 0;
    Timer eval;
    for (std::size_t i = 0; i < w.size(); ++i) eh = std::max(eh, relativeError(hybrid.compliance(w[i]), reference[i]));
    const double evalSeconds = eval.seconds() / double(w.size());
    for (std::size_t i = 0; i < w.size(); ++i)
      et = std::max(et, relativeError(truncation.compliance(w[i]), reference[i]));
    // The seed's combination: an undamped A0 (CalculiX *GREEN) in Petrov's damped formula.
    const std::complex<double> d(1.0, kEta);
    for (std::size_t i = 0; i < w.size(); ++i) {
      Eigen::MatrixXcd As = A0.matrix.cast<std::complex<double>>();
      for (int j = 0; j < modes.numModes(); ++j) {
        const double l = modes.eigenvalues[std::size_t(j)];
        const Eigen::VectorXcd phi = modes.shapes.col(j).cast<std::complex<double>>();
        As += phi * phi.transpose() * (w[i] * w[i] / ((d * l - w[i] * w[i]) * (d * l)));
      }
      es = std::max(es, relativeError(As, reference[i]));
    }
    std::printf("%6d %14.3e %14.3e %14.3e %12.2e\n", m, eh, et, es, evalSeconds);
    EXPECT_LT(eh, previous * 1.01) << m << " modes: the hybrid error must not grow as modes are added";
    // Once the band's modes are in, the static correction is what makes the difference.
    EXPECT_GT(et, (m >= 20 ? 100 : 1) * eh) << m << " modes: modal truncation must miss the static correction";
    if (m >= 20) {
      EXPECT_GT(es, 100 * eh) << m << " modes: the undamped A0 in the damped formula must show";
    }
    previous = eh;
    best = eh;
  }
  EXPECT_LT(best, 1e-3);

  checkExpansionPoints(full, allModes, A0, w, reference);
}

TEST(HybridFrf, RigidBodyModesShiftW0) {
  // A free sector (no fixed nodes) at k = 0: rotation about and translation along the axis.
  SectorCase s({});
  s.problem.nodalDiameter = 0;
  const rom::NodalDiameterModel full(s.mesh, s.sector, s.problem, Tpetra::getDefaultComm());
  const auto modes = full.modes(40, solvers::ModalOptions::automaticShift());
  ASSERT_EQ(modes.numRigidBodyModes(), 2);
  const auto A0 = full.staticCompliance(0.0, modes);
  std::printf("free sector k = 0: %s\n", A0.note.c_str());
  EXPECT_GT(A0.shift, 0.0);
  EXPECT_LT(A0.shift, modes.eigenvalues[2]);
  EXPECT_NE(A0.note.find("rigid-body"), std::string::npos);
  const rom::HybridFrfModel hybrid(modes, A0, kEta);
  const double worst = regression::worstErrorAround(hybrid, full, std::sqrt(modes.eigenvalues[2]));
  std::printf("free sector k = 0, 40 modes, shifted w0: max relative error %.3e\n", worst);
  EXPECT_LT(worst, 1e-3);
}

TEST(HybridFrf, BadInput) {
  SectorCase s({"bore"});
  auto problem = s.problem;
  problem.nodalDiameter = 5;  // N = 8: 0..4
  EXPECT_THROW(rom::NodalDiameterModel(s.mesh, s.sector, problem, Tpetra::getDefaultComm()), InputError);
  problem = s.problem;
  problem.retainedNodeSets = {"no_such_set"};
  EXPECT_THROW(rom::NodalDiameterModel(s.mesh, s.sector, problem, Tpetra::getDefaultComm()), InputError);
  problem.retainedNodeSets = {};
  EXPECT_THROW(rom::NodalDiameterModel(s.mesh, s.sector, problem, Tpetra::getDefaultComm()), InputError);
}
