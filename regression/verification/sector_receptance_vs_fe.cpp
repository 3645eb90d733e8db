// Verification: the receptance the harmonic balance gets from a cyclic
// sector's per-nodal-diameter models (rom::SectorReceptance over the full FE
// compliance of NodalDiameterModel, real form) against the sector equations
// the harmonic balance's matrix form states: the sector's own physical K and M,
// split into x_j (every free DOF but the disc's right face) and the neighbour's
// left face, A x_j + A_next x_{j+1} + A_next^T x_{j-1}, with x_{j+1} = e^{-i 2 pi p/N} x_j
// (the convention hbm's unit tests prove for the matrix form). Solved by a
// sparse complex LU. This fixes the mapping of every phase index p to a nodal
// diameter and to the sign of the travelling direction; a wrong sign gives the
// complex conjugate and an error of order one.
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <gtest/gtest.h>

#include <Eigen/SparseLU>
#include <cmath>
#include <complex>
#include <cstdio>
#include <map>

#include "cyclone/core/Timer.hpp"
#include "cyclone/fe/Assembler.hpp"
#include "cyclone/fe/DofMap.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/rom/NodalDiameterModel.hpp"
#include "cyclone/rom/HybridFrfModel.hpp"
#include "cyclone/rom/SectorReceptance.hpp"

using namespace cyclone;
using Sparse = Eigen::SparseMatrix<double>;
using SparseC = Eigen::SparseMatrix<std::complex<double>>;

namespace {

Sparse toSparse(const linalg::Matrix& A) {
  const auto n = Eigen::Index(A.getGlobalNumRows());
  std::vector<Eigen::Triplet<double>> t;
  for (Eigen::Index r = 0; r < n; ++r) {
    std::size_t len = A.getNumEntriesInGlobalRow(r);
    linalg::Matrix::nonconst_global_inds_host_view_type c("c", len);
    linalg::Matrix::nonconst_values_host_view_type v("v", len);
    A.getGlobalRowCopy(r, c, v, len);
    for (std::size_t k = 0; k < len; ++k) t.emplace_back(r, Eigen::Index(c(k)), v(k));
  }
  Sparse S(n, n);
  S.setFromTriplets(t.begin(), t.end());
  return S;
}


using Models = std::map<int, std::shared_ptr<const rom::ComplianceModel>>;

/// The sector equations in x_j (stiffness A, A_next and mass B, B_next):
/// A x_j + A_next x_{j+1} + A_next^T x_{j-1}.
struct SectorEquations {
  std::vector<char> onRight;  // the nodes on the disc's right face
  std::vector<long> xIndex;   // free equation -> its index in x_j (-1 on the right face)
  long nx = 0;
  Sparse A, An, B, Bn;
};
SectorEquations sectorEquations(const mesh::Mesh& mesh, const cyclic::CyclicSector& sector, const fe::DofMap& dofs,
                                const Sparse& K, const Sparse& M) {
  SectorEquations eq;
  auto& onRight = eq.onRight;
  auto& xIndex = eq.xIndex;
  long& nx = eq.nx;
  // x_j: every free DOF of the nodes off the disc's right face; the right face is the
  // neighbour's left face rotated by Q: u = P0 x_j + P1 x_{j+1}.
  onRight.assign(mesh.numNodes(), 0);
  for (auto n : sector.right) onRight[n] = 1;
  xIndex.assign(dofs.numFree(), -1);
  for (mesh::Index node = 0; node < mesh.numNodes(); ++node)
    for (int c = 0; c < 3; ++c)
      if (dofs.equation(node, c) >= 0 && !onRight[node]) xIndex[dofs.equation(node, c)] = nx++;
  std::vector<Eigen::Triplet<double>> t0, t1;
  for (long e = 0; e < dofs.numFree(); ++e)
    if (xIndex[e] >= 0) t0.emplace_back(e, xIndex[e], 1.0);
  const Eigen::Matrix3d Q = sector.rotation();
  for (std::size_t i = 0; i < sector.left.size(); ++i)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        const long er = dofs.equation(sector.right[i], r), ec = dofs.equation(sector.left[i], c);
        if (er >= 0 && ec >= 0 && Q(r, c) != 0) t1.emplace_back(er, xIndex[ec], Q(r, c));
      }
  Sparse P0(dofs.numFree(), nx), P1(dofs.numFree(), nx);
  P0.setFromTriplets(t0.begin(), t0.end());
  P1.setFromTriplets(t1.begin(), t1.end());
  eq.A = Sparse(P0.transpose() * K * P0) + Sparse(P1.transpose() * K * P1), eq.An = P0.transpose() * K * P1;
  eq.B = Sparse(P0.transpose() * M * P0) + Sparse(P1.transpose() * M * P1), eq.Bn = P0.transpose() * M * P1;
  std::printf("sector: %ld unknowns x_j (%lld free physical DOFs)\n", nx, (long long)dofs.numFree());
  return eq;
}

/// Both sides: the sector equations (with the mesh and DOFs they come from, and the
/// retained DOFs' indices in x_j) and the full FE models per nodal diameter.
struct Sides {
  const mesh::Mesh& mesh;
  const fe::DofMap& dofs;
  const SectorEquations& eq;
  const std::vector<long>& retained;
  Models& models;
  const rom::SectorReceptance& receptance;
  int N;
};

/// The worst errors over the phases.
struct PhaseErrors {
  double worst = 0, conjugateGap = 1e300, worstField = 0;
};

/// The whole field under forces at the retained DOFs (what stresses are recovered
/// from): every free DOF off the right face against the sector equations' solution.
double wholeFieldError(const Sides& s, const Eigen::SparseLU<SparseC>& lu, double omega, long phase) {
  const auto& dofs = s.dofs;
  const auto& retained = s.retained;
  const auto& onRight = s.eq.onRight;
  const auto& xIndex = s.eq.xIndex;
  const int N = s.N, n = int(retained.size());
  const auto [kf, sf] = rom::SectorReceptance::nodalDiameter(N, phase);
  const Eigen::VectorXcd F = Eigen::VectorXcd::Random(n);
  Eigen::VectorXcd rhsF = Eigen::VectorXcd::Zero(s.eq.nx);
  for (int j = 0; j < n; ++j) rhsF(retained[j]) += F(j);
  const Eigen::VectorXcd xf = lu.solve(rhsF);
  const auto u = static_cast<const rom::NodalDiameterModel&>(*s.models[kf]).fieldResponse(omega, F, sf);
  double diff = 0;
  for (mesh::Index node = 0; node < s.mesh.numNodes(); ++node)
    for (int c = 0; c < 3; ++c)
      if (dofs.equation(node, c) >= 0 && !onRight[node])
        diff = std::max(diff, std::abs(u[std::size_t(node)](c) - xf(xIndex[dofs.equation(node, c)])));
  const double fieldErr = diff / xf.cwiseAbs().maxCoeff();
  std::printf("phase index %ld: whole field under random forces, largest difference %.2e of the largest motion\n",
              phase, fieldErr);
  return fieldErr;
}

/// Phase index `phase`: the receptance against the sector equations' solution by a sparse
/// complex LU, the other travelling direction (the complex conjugate) and the whole field.
void checkPhase(const Sides& s, double omega, long phase, PhaseErrors& errors) {
  const auto& eq = s.eq;
  const Sparse &A = eq.A, &An = eq.An, &B = eq.B, &Bn = eq.Bn;
  const auto& retained = s.retained;
  const int N = s.N;
  const long nx = eq.nx;
  Timer timer;
  const double a = 2 * M_PI * double(phase) / N;
  const std::complex<double> e(std::cos(a), -std::sin(a));
  const SparseC Z = A.cast<std::complex<double>>() + e * An.cast<std::complex<double>>() +
                    std::conj(e) * Sparse(An.transpose()).cast<std::complex<double>>() -
                    omega * omega * (B.cast<std::complex<double>>() + e * Bn.cast<std::complex<double>>() +
                                     std::conj(e) * Sparse(Bn.transpose()).cast<std::complex<double>>());
  Eigen::SparseLU<SparseC> lu(Z);
  ASSERT_EQ(lu.info(), Eigen::Success);
  const int n = int(retained.size());
  Eigen::MatrixXcd rhs = Eigen::MatrixXcd::Zero(nx, n);
  for (int j = 0; j < n; ++j) rhs(retained[j], j) = 1.0;
  const Eigen::MatrixXcd X = lu.solve(rhs);
  Eigen::MatrixXcd reference(n, n);
  for (int i = 0; i < n; ++i) reference.row(i) = X.row(retained[i]);
  const Eigen::MatrixXcd got = s.receptance.compliance(omega, phase);
  const double fieldErr = wholeFieldError(s, lu, omega, phase);
  errors.worstField = std::max(errors.worstField, fieldErr);
  const double err = (got - reference).norm() / reference.norm();
  const double conj = (got.conjugate() - reference).norm() / reference.norm();
  const auto [k, sign] = rom::SectorReceptance::nodalDiameter(N, phase);
  std::printf("phase index %ld -> ND %d (%+d): error %.2e (the other direction: %.2e), %.2f s\n", phase, k, sign, err,
              conj, timer.seconds());
  errors.worst = std::max(errors.worst, err);
  if (k != 0 && 2 * k != N) errors.conjugateGap = std::min(errors.conjugateGap, conj);
}

/// The mean: nodal diameter 0 at zero frequency, its compliance and its field.
void checkMean(const Sides& s) {
  const auto& eq = s.eq;
  const auto& A = eq.A;
  const auto& An = eq.An;
  const auto& retained = s.retained;
  const auto& dofs = s.dofs;
  const auto& onRight = eq.onRight;
  const auto& xIndex = eq.xIndex;
  const long nx = eq.nx;
  const Sparse K0 = A + An + Sparse(An.transpose());
  Eigen::SparseLU<Sparse> lu0(K0);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(nx, long(retained.size()));
  for (std::size_t j = 0; j < retained.size(); ++j) rhs(retained[j], long(j)) = 1.0;
  const Eigen::MatrixXd X0 = lu0.solve(rhs);
  Eigen::MatrixXd ref0(retained.size(), retained.size());
  for (std::size_t i = 0; i < retained.size(); ++i) ref0.row(long(i)) = X0.row(retained[i]);
  const double meanErr = (s.receptance.meanCompliance() - ref0).norm() / ref0.norm();
  std::printf("mean compliance: error %.2e\n", meanErr);
  {
    // The mean field (harmonic 0: the undamped static solve of ND 0).
    const Eigen::VectorXd F = Eigen::VectorXd::Random(long(retained.size()));
    Eigen::VectorXd rhsF = Eigen::VectorXd::Zero(nx);
    for (std::size_t j = 0; j < retained.size(); ++j) rhsF(retained[j]) += F(long(j));
    const Eigen::VectorXd x0 = lu0.solve(rhsF);
    const auto u = static_cast<const rom::NodalDiameterModel&>(*s.models[0]).fieldResponse(0.0, F.cast<std::complex<double>>(), 1);
    double diff = 0;
    for (mesh::Index node = 0; node < s.mesh.numNodes(); ++node)
      for (int c = 0; c < 3; ++c)
        if (dofs.equation(node, c) >= 0 && !onRight[node])
          diff = std::max(diff, std::abs(u[std::size_t(node)](c) - x0(xIndex[dofs.equation(node, c)])));
    std::printf("mean field: largest difference %.2e of the largest motion\n", diff / x0.cwiseAbs().maxCoeff());
    EXPECT_LT(diff / x0.cwiseAbs().maxCoeff(), 1e-8);
  }
  EXPECT_LT(meanErr, 1e-8);
}

/// Hybrid models of the full FE ones (12 modes, their static correction, loss factor 0.01).
Models hybridModels(const Models& models) {
  Models hybrids;
  for (const auto& [k, m] : models) {
    const auto& full = static_cast<const rom::NodalDiameterModel&>(*m);
    const auto modes = full.modes(12);
    hybrids[k] = std::make_shared<rom::HybridFrfModel>(modes, full.staticCompliance(0.0, modes), 0.01);
  }
  return hybrids;
}

/// The hybrid receptance's Woodbury dynamic stiffness against the inverse of its
/// compliance, for every phase, near and away from a resonance: the worst difference.
double worstWoodburyError(const rom::SectorReceptance& hybrid, Models& hybrids, int N, double omega) {
  double worstZ = 0;
  for (long phase = 0; phase < N; ++phase) {
    const auto [k, sign] = rom::SectorReceptance::nodalDiameter(N, phase);
    const auto& hm = static_cast<const rom::HybridFrfModel&>(*hybrids[k]);
    for (double f : {omega, std::sqrt(hm.modes().eigenvalues[0]), 1.5 * std::sqrt(hm.modes().eigenvalues[0])}) {
      Timer t;
      const Eigen::MatrixXcd Z = hybrid.dynamicStiffness(f, phase);
      const double woodburySeconds = t.seconds();
      t.restart();
      const Eigen::MatrixXcd Zref = hybrid.compliance(f, phase).inverse();
      const double inverseSeconds = t.seconds();
      const double e = (Z - Zref).norm() / Zref.norm();
      worstZ = std::max(worstZ, e);
      std::printf("phase %ld, %.1f Hz: Woodbury vs inverse %.2e (%.1e s against %.1e s)\n", phase, f / (2 * M_PI), e,
                  woodburySeconds, inverseSeconds);
    }
  }
  return worstZ;
}

/// Their modal realizations (what Hill's method uses) give back the compliance for
/// every phase, with a pair's two real-form copies as one travelling-wave mode.
void checkModalRealizations(const rom::SectorReceptance& hybrid, Models& hybrids, int N, double omega) {
  double worstA = 0;
  for (long phase = 0; phase < N; ++phase) {
    const auto [k, sign] = rom::SectorReceptance::nodalDiameter(N, phase);
    const auto& hm = static_cast<const rom::HybridFrfModel&>(*hybrids[k]);
    const auto r = hybrid.modalRealization(phase);
    ASSERT_TRUE(r.has_value());
    const bool pair = k != 0 && 2 * k != N;
    EXPECT_EQ(r->numModes(), pair ? hm.modes().numModes() / 2 : hm.modes().numModes()) << "phase " << phase;
    const std::complex<double> damped(1.0, r->lossFactor);
    for (double f : {omega, 0.9 * std::sqrt(hm.modes().eigenvalues[0]), 1.5 * std::sqrt(hm.modes().eigenvalues[0])}) {
      const Eigen::VectorXcd d = (damped * r->eigenvalues.cast<std::complex<double>>()).array() - f * f;
      const Eigen::MatrixXcd A = r->R / damped + r->U * d.cwiseInverse().asDiagonal() * r->V.transpose();
      const Eigen::MatrixXcd Aref = hybrid.compliance(f, phase);
      worstA = std::max(worstA, (A - Aref).norm() / Aref.norm());
    }
    if (phase == 0) {
      const Eigen::MatrixXcd A0 = r->R + r->U * r->eigenvalues.cwiseInverse().asDiagonal() * r->V.transpose();
      worstA = std::max(worstA, (A0 - hybrid.meanCompliance().cast<std::complex<double>>()).norm() /
                                    hybrid.meanCompliance().norm());
    }
  }
  std::printf("modal realizations vs the hybrid compliance: %.2e\n", worstA);
  EXPECT_LT(worstA, 1e-9);
}

}  // namespace

TEST(SectorReceptance, MatchesTheSectorEquationsForEveryPhase) {
  const auto comm = Tpetra::getDefaultComm();
  mesh::ShroudedSectorParameters p;
  p.sectors = 8;
  p.meshSize = 14.0;
  p.boreRadius = 70.0;
  auto mesh = mesh::generateShroudedSector(p);
  const auto& left = mesh.nodeSet("shroud_contact_left");
  const auto& right = mesh.nodeSet("shroud_contact_right");
  mesh.nodeSets["rom_contact"] = {left.front(), left[left.size() / 2], right.front(), right[right.size() / 2]};
  const auto sector = cyclic::makeCyclicSector(mesh, p.sectors, {}, {"disc_left"}, {"disc_right"});  // cantilever
  const int N = p.sectors;

  // The physical sector: bore fixed, no cyclic constraint.
  fe::DofMap dofs(mesh.numNodes());
  dofs.constrain(mesh.nodeSet("bore"));
  dofs.finalize();
  const fe::Assembler assembler(mesh, dofs, comm);
  rom::NodalDiameterModelProblem problem;
  const Sparse K = toSparse(*assembler.stiffness(problem.material)), M = toSparse(*assembler.mass(problem.material));
  const SectorEquations eq = sectorEquations(mesh, sector, dofs, K, M);

  // The reduced side: the full FE compliance per nodal diameter, undamped.
  problem.retainedNodeSets = {"rom_contact", "mid_blade"};
  problem.fixedNodeSets = {"bore"};
  Models models;
  for (int k = 0; 2 * k <= N; ++k) {
    problem.nodalDiameter = k;
    models[k] = std::make_shared<rom::NodalDiameterModel>(mesh, sector, problem, comm);
  }
  const rom::SectorReceptance receptance(N, models);
  const auto& nodes = static_cast<const rom::NodalDiameterModel&>(*models[0]).retainedNodes();
  ASSERT_EQ(receptance.numDofs(), int(3 * nodes.size()));
  std::vector<long> retained;
  for (auto n : nodes)
    for (int c = 0; c < 3; ++c) retained.push_back(eq.xIndex[dofs.equation(n, c)]);
  const Sides sides{mesh, dofs, eq, retained, models, receptance, N};

  const double omega = 2 * M_PI * 300.0;  // below the first natural frequency of most diameters, not on any
  PhaseErrors errors;
  for (long phase = 0; phase < N; ++phase) ASSERT_NO_FATAL_FAILURE(checkPhase(sides, omega, phase, errors));
  EXPECT_LT(errors.worst, 1e-8);
  EXPECT_LT(errors.worstField, 1e-8);
  EXPECT_GT(errors.conjugateGap, 1e4 * errors.worst);  // the travelling direction matters: the test tells them apart

  checkMean(sides);

  // Hybrid models of the same sector: the Woodbury dynamic stiffness against the inverse
  // of their compliance, for every phase, near and away from a resonance.
  Models hybrids = hybridModels(models);
  const rom::SectorReceptance hybrid(N, hybrids);
  EXPECT_LT(worstWoodburyError(hybrid, hybrids, N, omega), 1e-8);

  checkModalRealizations(hybrid, hybrids, N, omega);
}
