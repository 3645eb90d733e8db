#pragma once
// Small dense K, M systems for the rom unit tests, and the references they are
// measured against, all computed here by plain dense Eigen and independently of
// the rom package: the exact receptance ((1 + i eta) K - w^2 M)^{-1} by an LU,
// the full model's modes by the generalized eigensolver, the static compliance,
// and the textbook Guyan / Craig-Bampton reduction (Psi^T K Psi, Psi^T M Psi as
// full triple products rather than the library's boundary-rows shortcut).
// Convention: the retained (boundary) DOFs are the leading nb of the system;
// reordered() puts chosen DOFs there.
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "cyclone/rom/BoundaryReduction.hpp"
#include "cyclone/rom/HybridFrfModel.hpp"

namespace rom_test {

using cd = std::complex<double>;
using Eigen::Index;

struct DenseSystem {
  Eigen::MatrixXd K, M;
  Index size() const { return K.rows(); }
};

// Fixed-free chain: mass i hangs on spring k(i) from mass i - 1 (mass 0 from the ground).
inline DenseSystem chain(const Eigen::VectorXd& k, const Eigen::VectorXd& m) {
  const Index n = m.size();
  DenseSystem s{Eigen::MatrixXd::Zero(n, n), Eigen::MatrixXd(m.asDiagonal())};
  for (Index i = 0; i < n; ++i) {
    s.K(i, i) += k(i);
    if (i == 0) continue;
    s.K(i - 1, i - 1) += k(i);
    s.K(i - 1, i) -= k(i);
    s.K(i, i - 1) -= k(i);
  }
  return s;
}

inline DenseSystem uniformChain(int n, double k, double m) {
  return chain(Eigen::VectorXd::Constant(n, k), Eigen::VectorXd::Constant(n, m));
}

// Springs and masses that vary along the chain, so that no mode has a node at a
// retained DOF by symmetry and all natural frequencies are well apart. Not grounded:
// free-free, with one rigid-body mode.
inline DenseSystem gradedChain(int n, bool grounded = true) {
  Eigen::VectorXd k(n), m(n);
  for (int i = 0; i < n; ++i) {
    k(i) = 1.0e4 * (1.0 + 0.4 * std::sin(1.3 * i));
    m(i) = 0.5 + 0.07 * i + 0.1 * std::cos(2.1 * i);
  }
  if (!grounded) k(0) = 0;
  return chain(k, m);
}

// K = B B^T + n I (symmetric positive definite, fully coupled), M diagonal in [0.5, 1.5].
inline DenseSystem randomSpd(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(0.5, 1.5);
  Eigen::MatrixXd B(n, n);
  for (Index i = 0; i < B.size(); ++i) B.data()[i] = g(rng);
  DenseSystem s{1.0e3 * (B * B.transpose() + n * Eigen::MatrixXd::Identity(n, n)), Eigen::MatrixXd::Zero(n, n)};
  for (int i = 0; i < n; ++i) s.M(i, i) = u(rng);
  return s;
}

// The same system with `retained` moved to the front (in that order), the other DOFs after, ascending.
inline DenseSystem reordered(const DenseSystem& s, const std::vector<int>& retained) {
  std::vector<int> order = retained;
  for (int i = 0; i < int(s.size()); ++i)
    if (std::find(retained.begin(), retained.end(), i) == retained.end()) order.push_back(i);
  Eigen::PermutationMatrix<Eigen::Dynamic> P(Index(order.size()));
  for (std::size_t j = 0; j < order.size(); ++j) P.indices()(order[j]) = int(j);  // new position of old DOF
  return {P * s.K * P.transpose(), P * s.M * P.transpose()};
}

// ((1 + i eta) K - w^2 M)^{-1} F by a dense LU: the exact response to loads F.
inline Eigen::MatrixXcd exactResponse(const DenseSystem& s, const Eigen::MatrixXcd& F, double omega, double eta) {
  const Eigen::MatrixXcd Z = cd(1.0, eta) * s.K.cast<cd>() - omega * omega * s.M.cast<cd>();
  return Z.partialPivLu().solve(F);
}

// The exact receptance at the leading nb DOFs (its nb x nb block).
inline Eigen::MatrixXcd exactReceptance(const DenseSystem& s, Index nb, double omega, double eta) {
  return exactResponse(s, Eigen::MatrixXcd::Identity(s.size(), nb), omega, eta).topRows(nb);
}

// All modes of the full system: eigenvalues ascending, shapes mass-normalised.
struct FullModes {
  Eigen::VectorXd eigenvalues;
  Eigen::MatrixXd shapes;
  double omega(int j) const { return std::sqrt(eigenvalues(j)); }
};

inline FullModes fullModes(const DenseSystem& s) {
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(s.K, s.M);
  return {es.eigenvalues(), es.eigenvectors()};
}

// The lowest m full modes as the rom package takes them: shapes at the leading nb
// DOFs and, for load patterns F (n x p, may be empty), the modal loads phi_j^T F.
inline cyclone::rom::RetainedModes retainedModes(const FullModes& f, Index nb, int m, int copies = 1,
                                                 const Eigen::MatrixXd& F = {}) {
  cyclone::rom::RetainedModes out;
  out.copies = copies;
  out.eigenvalues.assign(f.eigenvalues.data(), f.eigenvalues.data() + m);
  out.shapes = f.shapes.topLeftCorner(nb, m);
  if (F.size()) out.loads = f.shapes.leftCols(m).transpose() * F;
  return out;
}

// (K - w0^2 M)^{-1} at the leading nb DOFs by a dense LU, and the loads' static response there.
inline cyclone::rom::StaticCompliance staticCompliance(const DenseSystem& s, Index nb, double omega0,
                                                       const Eigen::MatrixXd& F = {}) {
  cyclone::rom::StaticCompliance out;
  out.omega0 = omega0;
  out.shift = omega0 * omega0;
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(s.K - out.shift * s.M);
  out.matrix = lu.solve(Eigen::MatrixXd::Identity(s.size(), nb)).topRows(nb);
  out.matrix = 0.5 * (out.matrix + out.matrix.transpose()).eval();
  if (F.size()) out.loadResponse = lu.solve(F).topRows(nb);
  return out;
}

// The Guyan / Craig-Bampton reduction onto the leading nb DOFs, the textbook way:
// Psi = [I; -K_ii^{-1} K_ib], K_g = Psi^T K Psi, M_g = Psi^T M Psi, all fixed-interface
// modes phi of (K_ii, M_ii) mass-normalised, M_bm = Psi^T M [0; phi].
inline cyclone::rom::BoundaryReduction boundaryReduction(const DenseSystem& s, Index nb, int copies = 1) {
  const Index n = s.size(), ni = n - nb;
  Eigen::MatrixXd Psi(n, nb);
  Psi.topRows(nb).setIdentity();
  Psi.bottomRows(ni) = -s.K.bottomRightCorner(ni, ni).llt().solve(s.K.bottomLeftCorner(ni, nb));
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(s.K.bottomRightCorner(ni, ni),
                                                               s.M.bottomRightCorner(ni, ni));
  Eigen::MatrixXd Phi = Eigen::MatrixXd::Zero(n, ni);
  Phi.bottomRows(ni) = es.eigenvectors();
  cyclone::rom::BoundaryReduction r;
  r.copies = copies;
  r.stiffness = Psi.transpose() * s.K * Psi;
  r.mass = Psi.transpose() * s.M * Psi;
  r.stiffness = 0.5 * (r.stiffness + r.stiffness.transpose()).eval();
  r.mass = 0.5 * (r.mass + r.mass.transpose()).eval();
  r.interfaceEigenvalues.assign(es.eigenvalues().data(), es.eigenvalues().data() + ni);
  r.massCoupling = Psi.transpose() * s.M * Phi;
  r.interiorEquations = ni;
  return r;
}

// |got - reference|_F / |reference|_F.
template <class A, class B>
double relativeError(const A& got, const B& reference) {
  return (got - reference).norm() / reference.norm();
}

}  // namespace rom_test
