#pragma once
// A friction harmonic balance with the spectrum of a reduced bladed sector: `nodes`
// nodes of 3 DOFs, M = I and K = Q diag(w_j^2) Q^T with w_j from 1 to 20 (rad/s, scaled
// units), Q a fixed random orthogonal matrix (seed), 0.3 % modal damping; every node but
// the first joined by a 3D friction contact to its partner on the next sector, engine
// order 3 of 24; excited at DOFs 0 and 1 (harmonic 1). The HB benchmark's sector (28
// nodes) and the kept-factors tests' (10 nodes); the continuation problem over its
// frequency with the response of DOF 0 as the measure.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"

namespace cyclone::test_support {

inline std::unique_ptr<hbm::HarmonicBalanceSystem> frictionSector(int nodes, int harmonics, int samples,
                                                                 unsigned seed) {
  const int dofs = 3 * nodes;
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  Eigen::MatrixXd A(dofs, dofs);
  for (int i = 0; i < A.size(); ++i) A.data()[i] = g(rng);
  const Eigen::MatrixXd Q = A.householderQr().householderQ();
  Eigen::VectorXd w2(dofs);
  for (int j = 0; j < dofs; ++j) w2(j) = std::pow(1.0 + 19.0 * j / (dofs - 1), 2);
  const Eigen::MatrixXd K = Q * w2.asDiagonal() * Q.transpose();
  const Eigen::MatrixXd C = Q * (2 * 0.003 * w2.cwiseSqrt()).asDiagonal() * Q.transpose();
  auto s = std::make_unique<hbm::HarmonicBalanceSystem>(Eigen::MatrixXd::Identity(dofs, dofs), C, K,
                                                        hbm::HarmonicSet::upTo(harmonics), samples);
  hbm::CyclicCoupling c;
  c.sectors = 24, c.engineOrder = 3;
  s->setCyclic(c);
  hbm::FrictionContactParameters p;
  p.tangentialDirections = 2, p.kt = 2.0, p.kn = 2.0, p.mu = 0.4, p.preload = 0.02;
  for (int k = 1; k < nodes; ++k) {
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(dofs, 3);
    W.block(3 * k, 0, 3, 3).setIdentity();
    s->addElement(std::make_shared<hbm::FrictionContact>(p), W, -W);
  }
  s->addExcitation(0, 1, 0.05);
  s->addExcitation(1, 1, 0.02);
  return s;
}

inline continuation::ContinuationProblem frictionSectorProblem(const hbm::HarmonicBalanceSystem& s) {
  continuation::ContinuationProblem problem;
  problem.size = s.numUnknowns();
  problem.residual = [&s](const Eigen::VectorXd& X, double p, Eigen::VectorXd& R) { s.residual(X, p, R, nullptr); };
  problem.jacobian = [&s](const Eigen::VectorXd& X, double p, Eigen::MatrixXd& J) {
    Eigen::VectorXd R;
    s.residual(X, p, R, &J);
  };
  problem.measure = [&s](const Eigen::VectorXd& X) { return s.amplitude(X, 0, 1); };
  problem.jacobianOperator = [&s](const Eigen::VectorXd& X, double p) {
    return std::make_shared<continuation::JacobianOperatorOf<hbm::JacobianBlocks>>(s.jacobianBlocks(X, p));
  };
  return problem;
}

/// What a traced curve of the sector is checked by: the largest ||F|| at its points
/// (each must be a solution) and its largest amplitude (DOF 0, harmonic 1).
struct SectorCurve {
  double largestResidual = 0, peak = 0;
};
inline SectorCurve checkSectorCurve(const continuation::ContinuationProblem& problem,
                                    const hbm::HarmonicBalanceSystem& s, const continuation::Branch& b) {
  SectorCurve c;
  Eigen::VectorXd F;
  for (const auto& pt : b.points) {
    problem.residual(pt.x, pt.parameter, F);
    c.largestResidual = std::max(c.largestResidual, F.norm());
    c.peak = std::max(c.peak, s.amplitude(pt.x, 0, 1));
  }
  return c;
}

}  // namespace cyclone::test_support
