// The subset of nominal modes (mistuning/SubsetOfNominalModes.hpp) on a small cyclic matrix
// system where the mistuned ring can be assembled directly: the sector's 3 DOFs
// (test_support::ringMatrices), its "blade" the stiffness K_blade of DOFs 1 and 2, blade j's
// scaled by 1 + delta_j. With every mode of every phase kept (3 N, no constant part) SNM
// is exact: its compliance and natural frequencies against the assembled ring's to
// round-off. Zero scatter gives the tuned ring exactly (dK identically zero). And the
// mistuning input's validation (BladeMistuning.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <memory>

#include "RingSystems.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/FullRingSystem.hpp"
#include "cyclone/hbm/ModalStiffness.hpp"
#include "cyclone/mistuning/AmplificationStatistics.hpp"
#include "cyclone/mistuning/BladeMistuning.hpp"
#include "cyclone/mistuning/MistunedRingSweep.hpp"
#include "cyclone/mistuning/MistuningPattern.hpp"
#include "cyclone/mistuning/ReducedSectorRing.hpp"
#include "cyclone/mistuning/RingReceptance.hpp"
#include "cyclone/mistuning/SubsetOfNominalModes.hpp"

using namespace cyclone;
using cd = std::complex<double>;

namespace {

Eigen::MatrixXd bladeStiffness() {
  Eigen::MatrixXd Kb = Eigen::MatrixXd::Zero(3, 3);
  Kb(1, 1) = 2.5, Kb(2, 2) = 3.5, Kb(1, 2) = Kb(2, 1) = 0.2;
  return Kb;
}

/// The sector's modes of every phase (the full shapes are the retained DOFs here) and
/// the blade projection Phi^H K_blade Phi stacked phase by phase.
struct Nominal {
  std::shared_ptr<hbm::MatrixReceptance> sector;
  std::vector<int> modesPerPhase;
  Eigen::MatrixXcd projection;
};

Nominal nominal(int N, const test_support::RingMatrices& m) {
  Nominal out;
  out.sector = std::make_shared<hbm::MatrixReceptance>(m.M, m.C, m.K, N, m.Mn, m.Cn, m.Kn);
  std::vector<Eigen::MatrixXcd> shapes;
  Eigen::Index total = 0;
  for (int p = 0; p < N; ++p) {
    shapes.push_back(out.sector->modalRealization(p)->U);
    out.modesPerPhase.push_back(int(shapes.back().cols()));
    total += shapes.back().cols();
  }
  Eigen::MatrixXcd S(3, total);
  Eigen::Index c = 0;
  for (const auto& s : shapes) S.middleCols(c, s.cols()) = s, c += s.cols();
  out.projection = S.adjoint() * bladeStiffness() * S;
  return out;
}

struct Assembled {
  Eigen::MatrixXd M, C, K;
};

/// The mistuned ring assembled: the tuned ring's matrices (hbm::expandToFullRing) plus
/// delta_j K_blade on sector j's block.
Assembled assembledRing(int N, const test_support::RingMatrices& m, const std::vector<double>& delta) {
  hbm::HarmonicBalanceSystem sector(m.M, m.C, m.K, hbm::HarmonicSet::upTo(1), 8);
  hbm::CyclicCoupling c;
  c.sectors = N, c.engineOrder = 1, c.Mnext = m.Mn, c.Cnext = m.Cn, c.Knext = m.Kn;
  sector.setCyclic(c);
  const auto ring = hbm::expandToFullRing(sector);
  Assembled out{ring->M(), ring->C(), ring->K()};
  for (int j = 0; j < N; ++j) out.K.block(3 * j, 3 * j, 3, 3) += delta[j] * bladeStiffness();
  return out;
}

double relative(const Eigen::MatrixXcd& a, const Eigen::MatrixXcd& b) { return (a - b).norm() / b.norm(); }

}  // namespace

TEST(SubsetOfNominalModes, EveryModeKeptIsExact) {
  const auto m = test_support::ringMatrices();
  for (int N : {5, 6}) {
    std::vector<double> delta{0.05, -0.03, 0.02, -0.04, 0.01, 0.035};
    delta.resize(N);
    const auto nom = nominal(N, m);
    const mistuning::RingReceptance ring(nom.sector);
    const auto tuned = ring.modalRealization(0);
    ASSERT_TRUE(tuned.has_value());
    ASSERT_EQ(tuned->numModes(), 3 * N);
    const mistuning::MistunedRingReceptance snm(
        *tuned, mistuning::subsetOfNominalModesStiffness(nom.modesPerPhase, nom.projection, delta));
    const auto direct = assembledRing(N, m, delta);
    double worst = 0;
    for (double w : {0.7, 2.6, 2.95, 3.3, 5.0}) {
      const Eigen::MatrixXcd Z = direct.K.cast<cd>() + cd(0, w) * direct.C.cast<cd>() - w * w * direct.M.cast<cd>();
      const double e = relative(snm.compliance(w, 0), Z.partialPivLu().inverse());
      worst = std::max(worst, e);
      EXPECT_LT(e, 1e-10) << "N " << N << ", w " << w;
    }
    // Natural frequencies: diag(l) + dK against the assembled (K, M).
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ref(direct.K, direct.M);
    const auto modes = snm.modes();
    const double eL = (modes.eigenvalues - ref.eigenvalues()).norm() / ref.eigenvalues().norm();
    const Eigen::MatrixXd mean = direct.K.inverse();
    const double eMean = (snm.meanCompliance() - mean).norm() / mean.norm();
    std::printf("N %d: SNM with every mode against the assembled mistuned ring: compliance %.1e, "
                "eigenvalues %.1e, mean compliance %.1e\n", N, worst, eL, eMean);
    EXPECT_LT(eL, 1e-12);
    EXPECT_LT(eMean, 1e-10);
    // The scatter matters at this level (the check would not pass tuned).
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> tunedRef(
        assembledRing(N, m, std::vector<double>(N, 0.0)).K, direct.M);
    EXPECT_GT((tunedRef.eigenvalues() - ref.eigenvalues()).norm() / ref.eigenvalues().norm(), 1e-3);
  }
}

TEST(SubsetOfNominalModes, ZeroScatterIsTheTunedRing) {
  const auto m = test_support::ringMatrices();
  const int N = 6;
  const auto nom = nominal(N, m);
  const mistuning::RingReceptance ring(nom.sector);
  const auto tuned = ring.modalRealization(0);
  const Eigen::MatrixXcd dK =
      mistuning::subsetOfNominalModesStiffness(nom.modesPerPhase, nom.projection, std::vector<double>(N, 0.0));
  EXPECT_EQ(dK.cwiseAbs().maxCoeff(), 0.0) << "exactly zero";
  const mistuning::MistunedRingReceptance snm(*tuned, dK);
  for (double w : {0.7, 2.95, 5.0}) {
    const Eigen::MatrixXcd tunedA = hbm::ModalStiffness::compliance(*tuned, w);
    EXPECT_LT(relative(snm.compliance(w, 0), tunedA), 1e-13) << w;
    EXPECT_LT(relative(snm.compliance(w, 0), ring.compliance(w, 0)), 1e-10) << w;
  }
  EXPECT_LT((snm.meanCompliance() - ring.meanCompliance()).norm() / ring.meanCompliance().norm(), 1e-10);
}

TEST(BladeMistuning, ValidatesAndNamesTheKey) {
  const auto where = [](auto&& f) {
    try {
      f();
    } catch (const InputError& e) {
      return e.where();
    }
    return std::string("no error");
  };
  EXPECT_EQ(where([] { mistuning::youngsModulusFactors({1.0, 1.02}, 3); }), "mistuning/youngs_modulus_factors");
  EXPECT_EQ(where([] { mistuning::youngsModulusFactors({1.0, 0.0, 1.0}, 3); }), "mistuning/youngs_modulus_factors");
  EXPECT_EQ(where([] { mistuning::youngsModulusFactors({1.0, -0.1, 1.0}, 3); }), "mistuning/youngs_modulus_factors");
  EXPECT_EQ(where([] { mistuning::youngsModulusFactors({1.0, std::nan(""), 1.0}, 3); }),
            "mistuning/youngs_modulus_factors");
  EXPECT_EQ(where([] { mistuning::fromFrequencyDeviations({0.0, -1.0, 0.0}, 3); }), "mistuning/frequency_deviations");
  EXPECT_EQ(where([] { mistuning::fromFrequencyDeviations({0.0, 0.0}, 3); }), "mistuning/frequency_deviations");
  EXPECT_EQ(where([] { mistuning::randomBladeMistuning(8, -0.01, 1); }), "mistuning/standard_deviation");
  EXPECT_EQ(where([] { mistuning::randomBladeMistuning(8, std::nan(""), 1); }), "mistuning/standard_deviation");
  EXPECT_EQ(where([] { mistuning::bladeElements(mesh::Mesh(), "blade"); }), "mistuning/blade_element_set");

  const auto fixed = mistuning::youngsModulusFactors({1.02, 0.97, 1.0}, 3);
  EXPECT_NEAR(fixed.deviations()[1], -0.03, 1e-15);
  const auto fromDelta = mistuning::fromFrequencyDeviations({0.02, -0.03, 0.0}, 3);
  EXPECT_EQ(fromDelta.youngsFactors[0], 1.02);
  const auto a = mistuning::randomBladeMistuning(24, 0.01, 7), b = mistuning::randomBladeMistuning(24, 0.01, 7);
  EXPECT_EQ(a.youngsFactors, b.youngsFactors) << "seeded: reproducible";
  EXPECT_NE(a.youngsFactors, mistuning::randomBladeMistuning(24, 0.01, 8).youngsFactors);
}

// The mistuned ring's harmonic balance (ringOfSectors with the SNM model, every mode kept:
// the sector's contact to the next sector, a Jenkins element, a cubic spring, the
// travelling excitation and a static load attached as in the tuned ring) against the
// matrix-form ring with the blade scatter added to its K: the same residual, Jacobian and
// stuck response.
TEST(SubsetOfNominalModes, MistunedRingSystemEqualsAssembledRing) {
  const auto m = test_support::ringMatrices();
  const int N = 6, eo = 2, samples = 96;
  const std::vector<double> delta{0.05, -0.03, 0.02, -0.04, 0.01, 0.035};
  const auto harmonics = hbm::HarmonicSet::upTo(2);
  const auto nom = nominal(N, m);
  const auto sectorPtr = test_support::receptanceRingSector(nom.sector, harmonics, samples, N, eo);
  const auto& sector = *sectorPtr;

  const mistuning::RingReceptance tunedModel(nom.sector);
  auto snm = std::make_shared<mistuning::MistunedRingReceptance>(
      *tunedModel.modalRealization(0), mistuning::subsetOfNominalModesStiffness(nom.modesPerPhase, nom.projection, delta));
  const auto ring = mistuning::ringOfSectors(sector, snm);
  const auto tuned = mistuning::ringOfSectors(sector);
  const auto direct = assembledRing(N, m, delta);
  hbm::HarmonicBalanceSystem reference(direct.M, direct.C, direct.K, harmonics, samples);
  for (const auto& e : tuned->elements()) reference.addElement(e.element, e.W);
  reference.addExcitationCoefficients(tuned->excitation());
  reference.addStaticLoadCoefficients(tuned->staticLoad());
  test_support::expectSameRing(*ring, reference, "mistuned ring");
  EXPECT_THROW(mistuning::ringOfSectors(sector, nom.sector), InputError) << "a cyclic model is not a ring's";
}

// The linear forced response of the mistuned ring over a sweep (MistunedRingSweep.hpp),
// with the sector's viscous damping (an LU per frequency) and with the structural loss
// factor alone (one eigendecomposition per pattern).
namespace {

hbm::ModalRealization structuralOnly(hbm::ModalRealization r) {
  r.viscous = Eigen::VectorXd::Zero(r.numModes());
  r.lossFactor = 0.01;
  return r;
}

}  // namespace

TEST(MistunedRingSweep, ZeroScatterIsTheTunedCyclicResponse) {
  const auto m = test_support::ringMatrices();
  const int N = 6, eo = 2, dof = 1;
  const auto nom = nominal(N, m);
  const mistuning::RingReceptance ring(nom.sector);
  const auto tuned = *ring.modalRealization(0);
  const mistuning::MistunedRingSweep sweep(tuned, N, 3, nom.modesPerPhase, nom.projection, eo, dof, dof);
  const std::vector<double> omegas{0.7, 2.6, 2.95, 3.3, 5.0};
  const Eigen::MatrixXcd X = sweep.responses(std::vector<double>(N, 0.0), omegas);
  double worst = 0;
  for (std::size_t k = 0; k < omegas.size(); ++k) {
    // The cyclic sector at phase EO, unit force on the excitation DOF, turned to blade j.
    const cd x0 = nom.sector->compliance(omegas[k], eo)(dof, dof);
    for (int j = 0; j < N; ++j) {
      const double a = -2 * M_PI * eo * j / N;
      worst = std::max(worst, std::abs(X(j, Eigen::Index(k)) - x0 * cd(std::cos(a), std::sin(a))) / std::abs(x0));
    }
  }
  std::printf("zero scatter against the cyclic sector: %.1e\n", worst);
  EXPECT_LT(worst, 1e-11);
  // Amplification 1 on every pattern of zero scatter.
  std::vector<double> band;
  for (int k = 0; k <= 200; ++k) band.push_back(2.0 + 2.0 * k / 200);
  const auto stats = mistuning::monteCarloAmplification(
      N, [&](const std::vector<double>& d) { return sweep.peaks(d, band); }, 0.0, 3, 7);
  for (double f : stats.factors) EXPECT_NEAR(f, 1.0, 1e-12);
}

TEST(MistunedRingSweep, AgainstTheMistunedRingCompliance) {
  const auto m = test_support::ringMatrices();
  const int N = 6, eo = 1, dof = 2, resp = 1;
  const auto nom = nominal(N, m);
  const mistuning::RingReceptance ring(nom.sector);
  const std::vector<double> delta{0.05, -0.03, 0.02, -0.04, 0.01, 0.035};
  const std::vector<double> omegas{0.7, 2.6, 2.95, 3.3, 5.0};
  for (bool viscous : {true, false}) {
    const auto tuned = viscous ? *ring.modalRealization(0) : structuralOnly(*ring.modalRealization(0));
    const mistuning::MistunedRingSweep sweep(tuned, N, 3, nom.modesPerPhase, nom.projection, eo, dof, resp,
                                             cd(0.8, 0.1));
    const mistuning::MistunedRingReceptance snm(
        tuned, mistuning::subsetOfNominalModesStiffness(nom.modesPerPhase, nom.projection, delta));
    EXPECT_LT(relative(sweep.stiffnessPerturbation(delta), snm.stiffnessPerturbation()), 1e-14);
    const Eigen::MatrixXcd X = sweep.responses(delta, omegas);
    double worst = 0;
    for (std::size_t k = 0; k < omegas.size(); ++k) {
      const Eigen::VectorXcd x = snm.compliance(omegas[k], 0) * sweep.load();
      Eigen::VectorXcd ref(N);
      for (int j = 0; j < N; ++j) ref(j) = x(3 * j + resp);
      worst = std::max(worst, (X.col(Eigen::Index(k)) - ref).norm() / ref.norm());
    }
    std::printf("%s: blade responses against the mistuned compliance applied to the load: %.1e\n",
                viscous ? "viscous" : "structural", worst);
    EXPECT_LT(worst, 1e-11);
  }
  EXPECT_THROW(mistuning::MistunedRingSweep(*ring.modalRealization(0), N, 3, nom.modesPerPhase, nom.projection, N,
                                            dof, dof),
               InputError);
}

TEST(MistunedRingSweep, CircularShiftsGiveTheSameAmplification) {
  const auto m = test_support::ringMatrices();
  const int N = 6, eo = 2, dof = 1;
  const auto nom = nominal(N, m);
  const mistuning::RingReceptance ring(nom.sector);
  const mistuning::MistunedRingSweep sweep(structuralOnly(*ring.modalRealization(0)), N, 3, nom.modesPerPhase,
                                           nom.projection, eo, dof, dof);
  std::vector<double> band;
  for (int k = 0; k <= 400; ++k) band.push_back(2.0 + 2.0 * k / 400);
  const auto delta = mistuning::randomPattern(N, 0.03, 11);
  const auto base = sweep.peaks(delta, band);
  double worst = 0;
  for (int s = 1; s < N; ++s) {
    const auto p = sweep.peaks(mistuning::shiftedPattern(delta, s), band);
    worst = std::max(worst, std::abs(p.largest() - base.largest()) / base.largest());
    EXPECT_EQ(p.worstBlade, (base.worstBlade + s) % N);
  }
  std::printf("circular shifts: largest peak within %.1e\n", worst);
  EXPECT_LT(worst, 1e-12);
}
