// The Jacobian kept as blocks (JacobianBlocks) against the system's formed Jacobian:
// its products are the dense matrix's, in the matrix form (a cyclic sector with a 3D
// friction contact to the next sector, a Jenkins element and a cubic spring) and in
// the dynamic-stiffness receptance form of the same system and of a model in Woodbury's
// parts (a residual part plus modes, as a hybrid reduced model's); the preconditioner's
// blocks are the dense matrix's harmonic-diagonal blocks, and it inverts them (to its
// single-precision factors' accuracy).
#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/hbm/JacobianBlocks.hpp"
#include "cyclone/hbm/ProjectedReceptance.hpp"
#include "cyclone/hbm/ReceptanceModel.hpp"
#include "ModalTestModel.hpp"
#include "RingSector.hpp"

using namespace cyclone;
using namespace cyclone::hbm;

namespace {

using test_support::addRingElements;
using test_support::ringMatrices;

// A motion with every harmonic present, large enough that the contact slips and opens.
Eigen::VectorXd motion(const HarmonicBalanceSystem& s, double size = 0.3) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd X(s.numUnknowns());
  for (Eigen::Index i = 0; i < X.size(); ++i) X(i) = u(rng) * size;
  return X;
}

void expectBlocksAreTheJacobian(const HarmonicBalanceSystem& s, double omega, double size = 0.3,
                                int sparseElements = 0) {
  const Eigen::VectorXd X = motion(s, size);
  Eigen::VectorXd R;
  Eigen::MatrixXd J;
  s.residual(X, omega, R, &J);
  auto blocks = s.jacobianBlocks(X, omega, ElementJacobians::Formed);
  EXPECT_EQ(blocks->sparseElements(), sparseElements);
  const Eigen::MatrixXd D = blocks->dense();
  EXPECT_LE((D - J).norm(), 1e-12 * J.norm()) << "the blocks' products are not the formed Jacobian";

  // Row scaling, then each harmonic's block against the scaled dense one.
  Eigen::VectorXd scale(s.numUnknowns());
  for (Eigen::Index i = 0; i < scale.size(); ++i) scale(i) = 1.0 + 0.1 * double(i % 5);
  blocks->scaleRows(scale);
  const Eigen::MatrixXd Js = scale.asDiagonal() * J;
  EXPECT_LE((blocks->dense() - Js).norm(), 1e-12 * Js.norm());
  blocks->factorPreconditioner();
  const auto& H = s.aft().harmonics();
  const int nc = s.numCoefficients(), n = s.numDofs();
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(Js.rows(), Js.cols());  // the block diagonal of Js
  for (std::size_t i = 0; i < H.harmonics().size(); ++i) {
    const int h = H.harmonics()[i];
    std::vector<int> slots{H.cosIndex(h)};
    if (h != 0) slots.push_back(H.sinIndex(h));
    const Eigen::MatrixXd B = blocks->harmonicBlock(i);
    const int m = int(slots.size());
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        for (int r = 0; r < m; ++r)
          for (int q = 0; q < m; ++q) {
            EXPECT_NEAR(B(a * m + r, b * m + q), J(a * nc + slots[r], b * nc + slots[q]), 1e-12 * J.norm());
            P(a * nc + slots[r], b * nc + slots[q]) = Js(a * nc + slots[r], b * nc + slots[q]);
          }
  }
  const Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(s.numUnknowns(), -1.0, 2.0);
  Eigen::VectorXd z;
  blocks->precondition(r, z);
  // The blocks are factored in single precision (a preconditioner's accuracy): the
  // solve's residual is a float LU's, about eps_f = 6e-8 times the blocks' conditioning.
  const double singleLu = 1e-5;
  EXPECT_LE((P * z - r).norm(), singleLu * r.norm()) << "the preconditioner is not the block diagonal's inverse";

  // A homotopy's blended rows (harmonic 1's of every DOF): rows i become b J_i + c e_i,
  // in the products and in the preconditioner's block diagonal.
  std::vector<int> rows;
  for (int a = 0; a < n; ++a) rows.push_back(a * nc + H.cosIndex(1)), rows.push_back(a * nc + H.sinIndex(1));
  const double b = 0.3, shift = 2.5;
  blocks->blendRows(rows, b, shift);
  Eigen::MatrixXd Jb = Js, Pb = P;
  for (int i : rows) {
    Jb.row(i) *= b, Pb.row(i) *= b;
    Jb(i, i) += shift, Pb(i, i) += shift;
  }
  EXPECT_LE((blocks->dense() - Jb).norm(), 1e-12 * Jb.norm());
  blocks->factorPreconditioner();
  blocks->precondition(r, z);
  EXPECT_LE((Pb * z - r).norm(), singleLu * r.norm()) << "the blended preconditioner is not the blended block diagonal's inverse";
}

// The blocks with the 3D contact applied by its tangent per sample (ElementLinearization)
// against the formed Jacobian: the same products to rounding, with row scales and
// blended rows; the preconditioner's blocks are the tangent's own. `exactBlocks`: the
// contact has no memory (frictionless), so its instantaneous tangent's (h, h) blocks
// are the Jacobian's.
void expectTangentProductsAreTheJacobian(const HarmonicBalanceSystem& s, double omega, bool exactBlocks) {
  const Eigen::VectorXd X = motion(s);
  Eigen::VectorXd R;
  Eigen::MatrixXd J;
  s.residual(X, omega, R, &J);
  auto blocks = s.jacobianBlocks(X, omega, ElementJacobians::Tangents);
  EXPECT_EQ(blocks->sparseElements(), 0);
  EXPECT_LE((blocks->dense() - J).norm(), 1e-12 * J.norm()) << "the tangent's products are not the formed Jacobian";
  auto formed = s.jacobianBlocks(X, omega, ElementJacobians::Formed);
  Eigen::VectorXd scale(s.numUnknowns());
  for (Eigen::Index i = 0; i < scale.size(); ++i) scale(i) = 1.0 + 0.1 * double(i % 5);
  blocks->scaleRows(scale);
  EXPECT_LE((blocks->dense() - scale.asDiagonal() * J).norm(), 1e-12 * J.norm());
  double blockDifference = 0, blockSize = 0;
  for (std::size_t i = 0; i < s.aft().harmonics().harmonics().size(); ++i) {
    blockDifference = std::max(blockDifference, (blocks->harmonicBlock(i) - formed->harmonicBlock(i)).norm());
    blockSize = std::max(blockSize, formed->harmonicBlock(i).norm());
  }
  if (exactBlocks)
    EXPECT_LE(blockDifference, 1e-12 * blockSize);
  else  // the slider's memory left out: the blocks differ (else this checks nothing)
    EXPECT_GT(blockDifference, 1e-3 * blockSize);
  std::vector<int> rows{0, 3, 5};
  blocks->blendRows(rows, 0.3, 2.5);
  Eigen::MatrixXd Jb = scale.asDiagonal() * J;
  for (int i : rows) Jb.row(i) *= 0.3, Jb(i, i) += 2.5;
  EXPECT_LE((blocks->dense() - Jb).norm(), 1e-12 * Jb.norm());
}

// The ring's matrix-form sector with its elements.
HarmonicBalanceSystem matrixFormSector() {
  const auto m = ringMatrices();
  HarmonicBalanceSystem s(m.M, m.C, m.K, HarmonicSet::upTo(5), 64);
  CyclicCoupling c;
  c.sectors = 7, c.engineOrder = 2, c.Mnext = m.Mn, c.Cnext = m.Cn, c.Knext = m.Kn;
  s.setCyclic(c);
  addRingElements(s);
  return s;
}

}  // namespace

TEST(JacobianBlocks, MatrixFormCyclicSector) { expectBlocksAreTheJacobian(matrixFormSector(), 1.7); }

// A motion small enough that the friction contact stays stuck and closed all period: its
// block (kt and kn on the diagonal, the mean's rows) is held sparse, the same products.
TEST(JacobianBlocks, StuckContactHeldSparse) { expectBlocksAreTheJacobian(matrixFormSector(), 1.7, 1e-3, 1); }

// A slipping and opening 3D contact (the motion makes it do both) applied by its tangent
// per sample: exactly the formed Jacobian's products.
TEST(JacobianBlocks, ContactTangentProductsAreTheFormedJacobian) {
  expectTangentProductsAreTheJacobian(matrixFormSector(), 1.7, false);
}

// A frictionless contact whose normal load varies and opens: no memory, so even the
// preconditioner's blocks of the tangent per sample are the Jacobian's.
TEST(JacobianBlocks, FrictionlessContactTangentBlocksAreExact) {
  const auto m = ringMatrices();
  HarmonicBalanceSystem s(m.M, m.C, m.K, HarmonicSet::upTo(5), 64);
  CyclicCoupling c;
  c.sectors = 7, c.engineOrder = 2, c.Mnext = m.Mn, c.Cnext = m.Cn, c.Knext = m.Kn;
  s.setCyclic(c);
  FrictionContactParameters p;
  p.tangentialDirections = 2, p.kt = 5.0, p.kn = 6.0, p.mu = 0.0, p.preload = 0.5;
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(3, 3), Wn = Eigen::MatrixXd::Zero(3, 3);
  W(1, 0) = 1, W(0, 1) = 0.3, W(2, 2) = 1;
  Wn(1, 0) = -1, Wn(0, 1) = -0.3, Wn(2, 2) = -1;
  s.addElement(std::make_shared<FrictionContact>(p), W, Wn);
  expectTangentProductsAreTheJacobian(s, 1.7, true);
}

// The automatic choice keeps whichever holds fewer numbers: at H = 5 and 64 samples the
// contact's formed Jacobian (33^2 = 1089 against the tangent's 25 x 64 = 1600), at H = 20
// its tangent (123^2 = 15129 against 1600). Told apart by the preconditioner's blocks,
// which are the formed Jacobian's only where it is kept.
TEST(JacobianBlocks, AutomaticKeepsTheSmallerOfFormedAndTangent) {
  for (const int H : {5, 20}) {
    const auto m = ringMatrices();
    HarmonicBalanceSystem s(m.M, m.C, m.K, HarmonicSet::upTo(H), 64);
    CyclicCoupling c;
    c.sectors = 7, c.engineOrder = 2, c.Mnext = m.Mn, c.Cnext = m.Cn, c.Knext = m.Kn;
    s.setCyclic(c);
    addRingElements(s);
    const Eigen::VectorXd X = motion(s);
    auto automatic = s.jacobianBlocks(X, 1.7);
    auto formed = s.jacobianBlocks(X, 1.7, ElementJacobians::Formed);
    const double difference = (automatic->harmonicBlock(1) - formed->harmonicBlock(1)).norm();
    if (H == 5)
      EXPECT_EQ(difference, 0.0) << "H = 5: the formed Jacobian holds fewer numbers";
    else
      EXPECT_GT(difference, 1e-3 * formed->harmonicBlock(1).norm()) << "H = 20: the tangent holds fewer numbers";
    EXPECT_LE((automatic->dense() - formed->dense()).norm(), 1e-12 * formed->dense().norm());
  }
}

TEST(JacobianBlocks, DynamicStiffnessReceptanceForm) {
  const auto m = ringMatrices();
  auto receptance = std::make_shared<MatrixReceptance>(m.M, m.C, m.K, 7, m.Mn, m.Cn, m.Kn);
  HarmonicBalanceSystem s(receptance, HarmonicSet({0, 1, 2, 3, 5}), 64);
  CyclicCoupling c;
  c.sectors = 7, c.engineOrder = 2;
  s.setCyclic(c);
  s.useDynamicStiffness(true);
  addRingElements(s);
  ASSERT_TRUE(s.hasJacobianBlocks());
  expectBlocksAreTheJacobian(s, 1.7);
}

TEST(JacobianBlocks, ComplianceFormHasNone) {
  const auto m = ringMatrices();
  auto receptance = std::make_shared<MatrixReceptance>(m.M, m.C, m.K);
  HarmonicBalanceSystem s(receptance, HarmonicSet::upTo(2), 16);
  EXPECT_FALSE(s.hasJacobianBlocks());
  EXPECT_ANY_THROW(s.jacobianBlocks(Eigen::VectorXd::Zero(s.numUnknowns()), 1.0));
}

namespace {

// 5 base DOFs with 3 modes and a residual part, seen through 3 coordinates: a reduced
// model's receptance, whose dynamic stiffness has Woodbury's parts for every phase.
std::shared_ptr<const ProjectedReceptance> woodburyModel() {
  std::mt19937 rng(11);
  std::normal_distribution<double> g;
  Eigen::MatrixXd T(3, 5);
  for (Eigen::Index i = 0; i < T.size(); ++i) T.data()[i] = g(rng);
  return std::make_shared<ProjectedReceptance>(std::make_shared<test_support::ModalTestModel>(5, 3, 7, true), T);
}

HarmonicBalanceSystem woodburySystem() {
  HarmonicBalanceSystem s(woodburyModel(), HarmonicSet({0, 1, 2, 3, 5, 9}), 64);
  CyclicCoupling c;
  c.sectors = 7, c.engineOrder = 2;  // harmonics 2 and 9 share phase 4, 1 and 5 do not
  s.setCyclic(c);
  s.useDynamicStiffness(true);
  addRingElements(s);
  return s;
}

}  // namespace

TEST(JacobianBlocks, WoodburyReceptanceForm) {
  const HarmonicBalanceSystem s = woodburySystem();
  ASSERT_NE(s.modalStiffnessBlocks(1.7), nullptr) << "the model's parts were not taken";
  expectBlocksAreTheJacobian(s, 1.7);
}

// The residual of a model in Woodbury's parts (its blocks formed from them) against each
// harmonic's plain inverse of the model's compliance (no parts used).
TEST(JacobianBlocks, WoodburyModelResidualIsThePlainInverses) {
  const HarmonicBalanceSystem s = woodburySystem();
  const double omega = 1.7;
  const Eigen::VectorXd X = motion(s);
  Eigen::VectorXd R, F;
  s.residual(X, omega, R, nullptr);
  s.nonlinearForces(X, omega, F, nullptr);
  const auto& H = s.aft().harmonics();
  const int n = s.numDofs(), nc = s.numCoefficients();
  Eigen::VectorXd expected = F;
  for (int h : H.harmonics()) {
    const int c = H.cosIndex(h);
    Eigen::VectorXcd x(n);
    for (int a = 0; a < n; ++a) x(a) = h == 0 ? std::complex<double>(X(a * nc + c), 0) : std::complex<double>(X(a * nc + c), -X(a * nc + c + 1));
    const Eigen::MatrixXcd Z = h == 0 ? Eigen::MatrixXcd(s.receptance()->meanCompliance().inverse().cast<std::complex<double>>())
                                      : Eigen::MatrixXcd(s.receptance()->compliance(h * omega, s.phaseIndex(h)).inverse());
    const Eigen::VectorXcd y = Z * x;
    for (int a = 0; a < n; ++a) {
      expected(a * nc + c) += y(a).real();
      if (h != 0) expected(a * nc + c + 1) -= y(a).imag();
    }
  }
  EXPECT_LE((R - expected).norm(), 1e-10 * expected.norm());
}
