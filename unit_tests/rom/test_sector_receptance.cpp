// rom::SectorReceptance over per-nodal-diameter reduced models of a lumped
// cyclic sector (scalar DOFs: a disc mass, a 5-mass blade, a shroud spring to
// the next blade's tip), against the whole ring of N such sectors assembled
// densely and driven by the engine-order travelling wave
//   F_j = F e^{-i 2 pi p j / N}  (sector j + 1 across sector j's right face),
// whose sector-0 response at the retained DOFs is the receptance hbm expects for
// phase index p. The per-diameter models are Craig-Bampton with every interface
// mode (exact, so the ring is the reference to solver precision) on the real
// form K_k, M_k from cyclic::cyclicTransform; hybrid models with few modes
// check the Woodbury dynamic stiffness and the modal realization against the
// compliance they stand for.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

#include "DenseSystems.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/cyclic/CyclicTransform.hpp"
#include "cyclone/rom/CraigBamptonModel.hpp"
#include "cyclone/rom/HybridFrfModel.hpp"
#include "cyclone/rom/SectorReceptance.hpp"

using namespace cyclone;
using namespace rom_test;

namespace {

constexpr int kSectors = 8;     // even: nodal diameters 0 and N/2 have one copy, 1..3 two
constexpr int kOwnNodes = 6;    // 0 disc, 1..5 blade root to tip
constexpr int kNodes = 8;       // + 6: the next sector's disc, 7: the next sector's blade tip
const std::vector<int> kRetainedNodes{2, 4, 5};  // 3 scalar DOFs: what SectorReceptance reads as one node
constexpr double kEta = 0.01;

void spring(Eigen::MatrixXd& K, int a, int b, double k) {
  K(a, a) += k;
  K(b, b) += k;
  K(a, b) -= k;
  K(b, a) -= k;
}

struct Sector {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(kNodes, kNodes), M = Eigen::MatrixXd::Zero(kNodes, kNodes);
  cyclic::CyclicSector cyclic;
};

Sector lumpedSector() {
  Sector s;
  s.K(0, 0) += 4.0e5;            // disc to ground
  spring(s.K, 0, 1, 6.0e5);      // disc to blade root
  const double blade[] = {5.0e5, 4.2e5, 3.5e5, 3.1e5};
  for (int i = 1; i < 5; ++i) spring(s.K, i, i + 1, blade[i - 1]);
  spring(s.K, 0, 6, 2.0e5);      // disc to the next disc
  spring(s.K, 5, 7, 0.7e5);      // shroud: tip to the next tip
  const double mass[] = {1.5, 0.30, 0.25, 0.22, 0.20, 0.18};
  for (int i = 0; i < kOwnNodes; ++i) s.M(i, i) = mass[i];
  s.cyclic.sectors = kSectors;
  s.cyclic.left = {0, 5};
  s.cyclic.right = {6, 7};
  return s;
}

// The real-form K_k, M_k (sum over copies of T_c^T A T_c), reordered so that the
// retained DOFs come first, copy by copy (the ComplianceModel order), the other
// unknowns after: the retained DOFs are the boundary of the reductions.
struct RealForm {
  DenseSystem system;
  int copies = 1;
  Index retained = 0;
};

RealForm realForm(const Sector& s, int k) {
  std::vector<char> fixed(3 * kNodes, 0);
  for (int i = 0; i < kNodes; ++i) fixed[3 * i + 1] = fixed[3 * i + 2] = 1;  // only x is a DOF
  const auto T = cyclic::cyclicTransform(kNodes, s.cyclic, k, fixed, Eigen::Matrix3d::Identity());
  const auto n = Index(T.numEquations());
  DenseSystem full{Eigen::MatrixXd::Zero(n, n), Eigen::MatrixXd::Zero(n, n)};
  std::vector<int> boundary;
  for (int c = 0; c < T.copies(); ++c) {
    Eigen::MatrixXd Tc = Eigen::MatrixXd::Zero(kNodes, n);
    for (int i = 0; i < kNodes; ++i)
      for (const auto& t : T.terms(i, 0, c)) Tc(i, t.equation) += t.coefficient;
    full.K += Tc.transpose() * s.K * Tc;
    full.M += Tc.transpose() * s.M * Tc;
    for (int node : kRetainedNodes) {
      const auto terms = T.terms(node, 0, c);
      EXPECT_EQ(terms.end() - terms.begin(), 1);  // off the right face: the unknown itself
      EXPECT_EQ(terms.begin()->coefficient, 1.0);
      boundary.push_back(int(terms.begin()->equation));
    }
  }
  return {reordered(full, boundary), T.copies(), Index(boundary.size())};
}

// The ring: sector j's own node i is DOF j * 6 + i; its right-face nodes are the next sector's 0 and 5.
DenseSystem ring(const Sector& s) {
  const int n = kSectors * kOwnNodes;
  DenseSystem r{Eigen::MatrixXd::Zero(n, n), Eigen::MatrixXd::Zero(n, n)};
  for (int j = 0; j < kSectors; ++j) {
    const int next = (j + 1) % kSectors;
    std::vector<int> dof(kNodes);
    for (int i = 0; i < kOwnNodes; ++i) dof[i] = j * kOwnNodes + i;
    dof[6] = next * kOwnNodes + 0, dof[7] = next * kOwnNodes + 5;
    for (int a = 0; a < kNodes; ++a)
      for (int b = 0; b < kNodes; ++b) r.K(dof[a], dof[b]) += s.K(a, b), r.M(dof[a], dof[b]) += s.M(a, b);
  }
  return r;
}

// Sector 0's response at the retained DOFs to unit forces there on every sector,
// sector j's scaled by e^{-i 2 pi p j / N}: one column per retained DOF.
Eigen::MatrixXcd ringReceptance(const DenseSystem& r, double omega, long p, double eta) {
  const int nr = int(kRetainedNodes.size());
  Eigen::MatrixXcd F = Eigen::MatrixXcd::Zero(r.size(), nr);
  for (int j = 0; j < kSectors; ++j) {
    const double a = -2 * M_PI * double(p) * j / kSectors;
    for (int c = 0; c < nr; ++c) F(j * kOwnNodes + kRetainedNodes[c], c) = cd(std::cos(a), std::sin(a));
  }
  const Eigen::MatrixXcd X = exactResponse(r, F, omega, eta);
  Eigen::MatrixXcd out(nr, nr);
  for (int c = 0; c < nr; ++c) out.row(c) = X.row(kRetainedNodes[c]);
  return out;
}

std::map<int, std::shared_ptr<const rom::ComplianceModel>> craigBamptonModels(const Sector& s) {
  std::map<int, std::shared_ptr<const rom::ComplianceModel>> models;
  for (int k = 0; 2 * k <= kSectors; ++k) {
    const RealForm f = realForm(s, k);
    const auto reduction = boundaryReduction(f.system, f.retained, f.copies);
    models[k] = std::make_shared<rom::CraigBamptonModel>(reduction, reduction.numInterfaceModes() / f.copies, kEta);
  }
  return models;
}

// Hybrid models with the lowest 2 natural frequencies per diameter (pairs kept whole), static part at w0 = 0.
std::map<int, std::shared_ptr<const rom::ComplianceModel>> hybridModels(const Sector& s) {
  std::map<int, std::shared_ptr<const rom::ComplianceModel>> models;
  for (int k = 0; 2 * k <= kSectors; ++k) {
    const RealForm f = realForm(s, k);
    const auto modes = retainedModes(fullModes(f.system), f.retained, int(f.system.size()), f.copies).first(2);
    models[k] = std::make_shared<rom::HybridFrfModel>(modes, staticCompliance(f.system, f.retained, 0.0), kEta);
  }
  return models;
}

// Frequencies below, between and above the ring's natural frequencies (midway
// between neighbouring distinct ones), away from every resonance.
std::vector<double> testFrequencies(const DenseSystem& r) {
  const FullModes modes = fullModes(r);
  std::vector<double> out{0.4 * modes.omega(0)};
  for (int j : {0, 7, 15, 30}) {
    int next = j + 1;
    while (next < modes.eigenvalues.size() && modes.omega(next) - modes.omega(j) < 1e-3 * modes.omega(j)) ++next;
    out.push_back(0.5 * (modes.omega(j) + modes.omega(next)));
  }
  out.push_back(1.2 * modes.omega(int(modes.eigenvalues.size()) - 1));
  return out;
}

}  // namespace

// Every phase index maps to the right nodal diameter and travelling direction:
// the wrong direction gives the complex conjugate, an error of order one.
TEST(RomSectorReceptance, MatchesTheRingForEveryPhaseIndex) {
  const Sector s = lumpedSector();
  const DenseSystem r = ring(s);
  const rom::SectorReceptance receptance(kSectors, craigBamptonModels(s));
  ASSERT_EQ(receptance.numDofs(), 3);
  ASSERT_EQ(receptance.sectors(), kSectors);
  double worst = 0, otherDirection = 1e300;
  for (double w : testFrequencies(r))
    for (long p = 0; p < kSectors; ++p) {
      const Eigen::MatrixXcd reference = ringReceptance(r, w, p, kEta);
      const Eigen::MatrixXcd got = receptance.compliance(w, p);
      worst = std::max(worst, relativeError(got, reference));
      const int k = rom::SectorReceptance::nodalDiameter(kSectors, p).first;
      if (k != 0 && 2 * k != kSectors) {
        otherDirection = std::min(otherDirection, relativeError(got.conjugate(), reference));
      }
    }
  std::printf("sector receptance vs ring: %.2e (conjugate: >= %.2e)\n", worst, otherDirection);
  EXPECT_LT(worst, 1e-10);
  // The other direction is off by at least a few percent (least where Q is small against
  // P, far above the last resonance): the test tells the two apart by many orders.
  EXPECT_GT(otherDirection, 1e-3);
}

// Harmonic 0: the undamped static compliance of the in-phase motion, the ring under
// the same force on every sector.
TEST(RomSectorReceptance, MeanComplianceIsTheRingInPhaseStatics) {
  const Sector s = lumpedSector();
  const rom::SectorReceptance receptance(kSectors, craigBamptonModels(s));
  const Eigen::MatrixXcd reference = ringReceptance(ring(s), 0.0, 0, 0.0);
  const double err = relativeError(receptance.meanCompliance().cast<cd>().eval(), reference);
  std::printf("mean compliance vs ring: %.2e\n", err);
  EXPECT_LT(err, 1e-10);
}

// The Craig-Bampton models' modal form, seen per phase index as
//   A(w) = R / (1 + i eta) + U diag(1 / ((1 + i eta) l_j + i c_j w - w^2)) V^T,
// reproduces the ring; a pair of real-form modes is one travelling-wave mode.
TEST(RomSectorReceptance, ModalRealizationReproducesTheRing) {
  const Sector s = lumpedSector();
  const DenseSystem r = ring(s);
  const auto models = craigBamptonModels(s);
  const rom::SectorReceptance receptance(kSectors, models);
  double worst = 0;
  for (long p = 0; p < kSectors; ++p) {
    const auto realization = receptance.modalRealization(p);
    ASSERT_TRUE(realization.has_value()) << "p " << p;
    const int k = rom::SectorReceptance::nodalDiameter(kSectors, p).first;
    const int realModes = receptance.model(k).modalForm()->modes().numModes();
    const bool pair = k != 0 && 2 * k != kSectors;
    EXPECT_EQ(realization->numModes(), pair ? realModes / 2 : realModes) << "p " << p;
    for (double w : testFrequencies(r)) {
      Eigen::VectorXcd d(realization->numModes());
      for (int j = 0; j < d.size(); ++j)
        d(j) = 1.0 / (cd(1.0, realization->lossFactor) * realization->eigenvalues(j) +
                      cd(0.0, realization->viscous(j) * w) - w * w);
      const Eigen::MatrixXcd A = realization->R / cd(1.0, realization->lossFactor) +
                                 realization->U * d.asDiagonal() * realization->V.transpose();
      worst = std::max(worst, relativeError(A, ringReceptance(r, w, p, kEta)));
    }
  }
  std::printf("modal realization vs ring: %.2e\n", worst);
  EXPECT_LT(worst, 1e-10);
}

// Hybrid models (2 of up to 12 modes per diameter): their dynamic stiffness by the
// Woodbury identity equals the inverse of their own compliance, near and away from
// resonances, and their realization reproduces that compliance.
TEST(RomSectorReceptance, HybridDynamicStiffnessAndRealization) {
  const Sector s = lumpedSector();
  const DenseSystem r = ring(s);
  const rom::SectorReceptance receptance(kSectors, hybridModels(s));
  const FullModes ringModes = fullModes(r);
  std::vector<double> omegas = testFrequencies(r);
  omegas.push_back(ringModes.omega(0) * (1 + 1e-3));  // next to a resonance: |A| large, Z nearly singular
  double worstZ = 0, worstRealization = 0;
  for (long p = 0; p < kSectors; ++p) {
    const auto realization = receptance.modalRealization(p);
    ASSERT_TRUE(realization.has_value());
    EXPECT_EQ(realization->numModes(), 2) << "p " << p;  // 2 distinct frequencies, a pair counting once
    for (double w : omegas) {
      const Eigen::MatrixXcd A = receptance.compliance(w, p);
      // Exact in exact arithmetic: Woodbury's R^{-1} and the m x m solve against a dense LU inverse.
      worstZ = std::max(worstZ, relativeError(receptance.dynamicStiffness(w, p), A.inverse().eval()));
      Eigen::VectorXcd d(realization->numModes());
      for (int j = 0; j < d.size(); ++j)
        d(j) = 1.0 / (cd(1.0, kEta) * realization->eigenvalues(j) + cd(0.0, realization->viscous(j) * w) - w * w);
      const Eigen::MatrixXcd Ar =
          realization->R / cd(1.0, kEta) + realization->U * d.asDiagonal() * realization->V.transpose();
      worstRealization = std::max(worstRealization, relativeError(Ar, A));
    }
  }
  std::printf("hybrid: Woodbury dynamic stiffness vs inverse %.2e, realization %.2e\n", worstZ, worstRealization);
  EXPECT_LT(worstZ, 1e-10);
  EXPECT_LT(worstRealization, 1e-10);
}

TEST(RomSectorReceptance, InconsistentModelsAreRefused) {
  const Sector s = lumpedSector();
  auto models = craigBamptonModels(s);
  EXPECT_THROW(rom::SectorReceptance(1, models), InputError);
  EXPECT_THROW(rom::SectorReceptance(kSectors, {}), InputError);
  // A diameter beyond N / 2.
  auto beyond = models;
  beyond[kSectors / 2 + 1] = models[1];
  EXPECT_THROW(rom::SectorReceptance(kSectors, beyond), InputError);
  // Only diameter 1: phase indices that need another diameter are refused when asked for.
  const rom::SectorReceptance partial(kSectors, {{1, models[1]}});
  EXPECT_NO_THROW(partial.compliance(100.0, kSectors - 1));
  EXPECT_THROW(partial.compliance(100.0, 2), InputError);
  EXPECT_THROW(partial.meanCompliance(), InputError);
}
