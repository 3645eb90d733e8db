// The ring of sectors from a cyclic model's phases (mistuning/RingReceptance.hpp,
// ReducedSectorRing.hpp) against the ring assembled directly: a small cyclic matrix
// system (3 DOFs, a coupling to the next sector that is not symmetric, so a wrong sign of
// the phase shows), its N sectors placed in one ring's M, C and K (the blocks A on the
// diagonal, A_next above, A_next^T below, sector N-1 joined to 0: hbm::expandToFullRing of
// the matrix form), and that ring's compliance by an LU of its dynamic stiffness. No cyclic
// transform on the reference side.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "RingSystems.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/FullRingSystem.hpp"
#include "cyclone/hbm/ModalStiffness.hpp"
#include "cyclone/mistuning/ReducedSectorRing.hpp"
#include "cyclone/mistuning/RingReceptance.hpp"

using namespace cyclone;
using cd = std::complex<double>;

namespace {

struct DirectRing {
  Eigen::MatrixXd M, C, K;
  Eigen::MatrixXcd Z(double w) const {
    return K.cast<cd>() + cd(0, w) * C.cast<cd>() - w * w * M.cast<cd>();
  }
};

/// The sector's matrices placed in the ring's (hbm::expandToFullRing of the matrix form).
DirectRing directRing(int N, const test_support::RingMatrices& m) {
  hbm::HarmonicBalanceSystem sector(m.M, m.C, m.K, hbm::HarmonicSet::upTo(1), 8);
  hbm::CyclicCoupling c;
  c.sectors = N, c.engineOrder = 1, c.Mnext = m.Mn, c.Cnext = m.Cn, c.Knext = m.Kn;
  sector.setCyclic(c);
  const auto ring = hbm::expandToFullRing(sector);
  return {ring->M(), ring->C(), ring->K()};
}

double relative(const Eigen::MatrixXcd& a, const Eigen::MatrixXcd& b) { return (a - b).norm() / b.norm(); }

}  // namespace

// The ring's compliance, dynamic stiffness, mean compliance and modal realization from
// the sector's phases against the assembled ring, for odd and even N (N/2 a phase of its own).
TEST(RingReceptance, EqualsAssembledRing) {
  const auto m = test_support::ringMatrices();
  for (int N : {5, 6}) {
    auto sector = std::make_shared<hbm::MatrixReceptance>(m.M, m.C, m.K, N, m.Mn, m.Cn, m.Kn);
    const mistuning::RingReceptance ring(sector);
    ASSERT_EQ(ring.numDofs(), 3 * N);
    ASSERT_EQ(ring.sectors(), 1);
    const auto direct = directRing(N, m);
    const auto realization = ring.modalRealization(0);
    ASSERT_TRUE(realization.has_value()) << "every phase has a modal realization (C = 0.01 K)";
    EXPECT_EQ(realization->numModes(), 3 * N);
    double worst = 0;
    for (double w : {0.7, 2.6, 2.95, 3.3, 5.0}) {
      const Eigen::MatrixXcd Zd = direct.Z(w), Ad = Zd.partialPivLu().inverse();
      const double eA = relative(ring.compliance(w, 0), Ad), eZ = relative(ring.dynamicStiffness(w, 0), Zd);
      const double eM = relative(hbm::ModalStiffness::compliance(*realization, w), Ad);
      std::printf("N %d, w %.2f: compliance %.1e, dynamic stiffness %.1e, modal realization %.1e\n", N, w, eA, eZ, eM);
      EXPECT_LT(eA, 1e-10) << N << " " << w;
      EXPECT_LT(eZ, 1e-10) << N << " " << w;
      EXPECT_LT(eM, 1e-10) << N << " " << w;
      worst = std::max({worst, eA, eZ, eM});
    }
    const Eigen::MatrixXd mean = direct.K.partialPivLu().inverse();
    const double eMean = (ring.meanCompliance() - mean).norm() / mean.norm();
    std::printf("N %d: mean compliance %.1e against K_ring^-1\n", N, eMean);
    EXPECT_LT(eMean, 1e-10) << N;
  }
}

// The ring's harmonic balance system (ringOfSectors over a cyclic receptance-form sector:
// its contact to the next sector, a Jenkins element to ground, a cubic spring and the
// travelling excitation) against the matrix-form full ring (hbm::expandToFullRing of the
// same sector given by M, C, K): the same residual and Jacobian at an arbitrary state.
TEST(RingReceptance, RingSystemEqualsExpandedMatrixRing) {
  const auto m = test_support::ringMatrices();
  const int N = 6, eo = 2, samples = 96;
  const auto harmonics = hbm::HarmonicSet::upTo(2);
  auto model = std::make_shared<hbm::MatrixReceptance>(m.M, m.C, m.K, N, m.Mn, m.Cn, m.Kn);
  const auto sector = test_support::receptanceRingSector(model, harmonics, samples, N, eo);

  hbm::HarmonicBalanceSystem matrix(m.M, m.C, m.K, harmonics, samples);
  hbm::CyclicCoupling c;
  c.sectors = N, c.engineOrder = eo;
  c.Mnext = m.Mn, c.Cnext = m.Cn, c.Knext = m.Kn;
  matrix.setCyclic(c);
  test_support::addRingElements(matrix);
  matrix.addExcitation(1, 1, 0.8, 0.1);
  matrix.addExcitation(2, 1, 0.2);
  matrix.addStaticLoad(2, 0.3);
  const auto reference = hbm::expandToFullRing(matrix);

  const auto ring = mistuning::ringOfSectors(*sector);
  test_support::expectSameRing(*ring, *reference, "ring of sectors");
}

namespace {
// A cyclic model that has no static compliance for one phase (a disc's reduced models
// without that phase's nodal diameter).
class MissingPhase final : public hbm::ReceptanceModel {
public:
  int numDofs() const override { return 2; }
  int sectors() const override { return 4; }
  Eigen::MatrixXcd compliance(double, long) const override { return Eigen::MatrixXcd::Identity(2, 2); }
  Eigen::MatrixXd meanCompliance() const override { return Eigen::MatrixXd::Identity(2, 2); }
  Eigen::MatrixXcd staticCompliance(long p) const override {
    if (p == 2) throw InputError("reduced model", "no model for nodal diameter 2");
    return Eigen::MatrixXcd::Identity(2, 2);
  }
};
}  // namespace

TEST(RingReceptance, InputErrorsNamed) {
  const auto m = test_support::ringMatrices();
  auto lone = std::make_shared<hbm::MatrixReceptance>(m.M, m.C, m.K);
  try {
    mistuning::RingReceptance r(lone);
    FAIL() << "a model that is not cyclic was taken";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "ring");
  }
  try {
    mistuning::RingReceptance r(std::make_shared<MissingPhase>());
    FAIL() << "a model without phase 2 was taken";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "reduced model");
    EXPECT_NE(std::string(e.what()).find("phase index 2"), std::string::npos) << e.what();
  }
  // The matrix form is hbm::expandToFullRing's, not refused silently.
  hbm::HarmonicBalanceSystem matrix(m.M, m.C, m.K, hbm::HarmonicSet::upTo(1), 16);
  hbm::CyclicCoupling c;
  c.sectors = 4, c.engineOrder = 1;
  matrix.setCyclic(c);
  EXPECT_THROW(mistuning::ringOfSectors(matrix), InputError);
  // A disc's models lacking nodal diameters: named with the key and the diameters.
  disc::DiscReducedModels models;
  models.sectors = 8;
  try {
    mistuning::checkRingModels(models);
    FAIL() << "models without any nodal diameter were taken";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "reduced_model/nodal_diameters");
    EXPECT_NE(std::string(e.what()).find("missing: 0, 1, 2, 3, 4"), std::string::npos) << e.what();
  }
  EXPECT_EQ(mistuning::everyNodalDiameter(8), (std::vector<int>{0, 1, 2, 3, 4}));
  EXPECT_EQ(mistuning::everyNodalDiameter(7), (std::vector<int>{0, 1, 2, 3}));
}
