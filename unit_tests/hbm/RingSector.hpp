#pragma once
// A small cyclic sector shared by the harmonic balance tests: 3 DOFs, M, C, K and a
// coupling to the next sector that is not symmetric (A_next^T couples the other way),
// and its nonlinear elements: a 3D friction contact between neighbouring tips, a
// Jenkins element to ground, a cubic spring.
#include <Eigen/Dense>
#include <memory>

#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/hbm/JenkinsElement.hpp"

namespace cyclone::test_support {

struct RingMatrices {
  Eigen::MatrixXd M, C, K, Mn, Cn, Kn;
};

inline RingMatrices ringMatrices() {
  RingMatrices m;
  m.M = Eigen::Vector3d(1.2, 0.4, 0.4).asDiagonal();
  m.K.resize(3, 3);
  m.K << 13.0, -1.0, -0.5, -1.0, 3.0, 0.2, -0.5, 0.2, 4.0;
  m.Kn = Eigen::MatrixXd::Zero(3, 3);
  m.Kn(0, 0) = -2.0, m.Kn(1, 0) = -0.3;  // not symmetric: A_next^T couples the other way
  m.C = 0.01 * m.K, m.Cn = 0.01 * m.Kn;
  m.Mn = Eigen::MatrixXd::Zero(3, 3);
  m.Mn(0, 0) = 0.05;
  return m;
}

inline void addRingElements(hbm::HarmonicBalanceSystem& s) {
  hbm::FrictionContactParameters p;
  p.tangentialDirections = 2, p.kt = 5.0, p.kn = 6.0, p.mu = 0.3, p.preload = 0.5;
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(3, 3), Wn = Eigen::MatrixXd::Zero(3, 3);
  W(1, 0) = 1, W(0, 1) = 0.3, W(2, 2) = 1;
  Wn(1, 0) = -1, Wn(0, 1) = -0.3, Wn(2, 2) = -1;
  s.addElement(std::make_shared<hbm::FrictionContact>(p), W, Wn);
  s.addElement(std::make_shared<hbm::JenkinsElement>(3.0, 0.2), Eigen::Vector3d(1, 0, 0));
  s.addElement(std::make_shared<hbm::CubicSpring>(0.5), Eigen::Vector3d(0, 1, -1));
}

}  // namespace cyclone::test_support
