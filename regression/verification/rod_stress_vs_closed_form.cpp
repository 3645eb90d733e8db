// Verification: the vibratory stress chain (fatigue::recoverSectorVibration: the
// whole field from forces at retained DOFs by the cyclic sector's complex FE
// solve, small-strain stresses averaged to the nodes, the cycle's alternating von
// Mises) against the closed form of a rod under a harmonic end force. The rod
// (hex8, nu = 0, so the stress is uniaxial) lies inside a 24-sector wedge without
// touching its faces, held at its root; its tip carries F cos(w t) along the rod.
// With structural damping E* = E (1 + i eta) and k = w sqrt(rho / E*):
//   u(x) = F sin(k x) / (E* A k cos(k L)),  elastic stress E u'(0) = (E / E*) F / (A cos(k L)).
// The root node's stress is its element's mean, (1/h) int_0^h sigma dx: the error falls
// like h^2, printed per mesh with the run time.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>

#include "cyclone/core/Timer.hpp"
#include "cyclone/fatigue/SectorVibration.hpp"

using namespace cyclone;

namespace {

constexpr double kLength = 100, kSide = 2, kRoot = 50;

mesh::Mesh rod(int elements) {
  mesh::Mesh m;
  m.source = "rod";
  for (int i = 0; i <= elements; ++i)
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        m.coords.push_back({kRoot + kLength * i / elements, kSide * (j - 0.5), kSide * (k - 0.5)});
  mesh::ElementBlock b;
  b.name = "rod", b.type = mesh::ElementType::Hex8;
  auto node = [](int i, int j, int k) { return mesh::Index(4 * i + 2 * k + j); };
  for (int i = 0; i < elements; ++i)
    for (int k = 0; k < 2; ++k)
      for (auto [a, c] : {std::pair{i, 0}, {i + 1, 0}, {i + 1, 1}, {i, 1}}) b.connectivity.push_back(node(a, c, k));
  m.blocks.push_back(b);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j) {
      m.nodeSets["root"].push_back(node(0, j, k));
      m.nodeSets["tip"].push_back(node(elements, j, k));
    }
  m.assignDefaultIds();
  mesh::checkConsistency(m);
  return m;
}

}  // namespace

TEST(RodStress, AlternatingStressAtTheRootAgainstTheClosedForm) {
  const auto comm = Tpetra::getDefaultComm();
  fe::IsotropicElastic steel;
  steel.E = 2.0e5, steel.nu = 0.0, steel.rho = 7.85e-9;
  const double eta = 0.02, force = 100, area = kSide * kSide;
  const double omega = 1.2 * std::sqrt(steel.E / steel.rho) / kLength;  // k L = 1.2 (first axial resonance at pi/2)
  const std::complex<double> Estar = steel.E * std::complex<double>(1, eta);
  const std::complex<double> k = omega * std::sqrt(steel.rho / Estar);
  const double exact = std::abs(steel.E / Estar * force / (area * std::cos(k * kLength)));

  cyclic::CyclicSector sector;
  sector.sectors = 24;  // the rod touches neither side face: every nodal diameter is the same rod
  double previous = 0;
  for (int elements : {10, 20, 40}) {
    Timer timer;
    const auto m = rod(elements);
    rom::NodalDiameterModelProblem problem;
    problem.material = steel;
    problem.fixedNodeSets = {"root"};
    problem.retainedNodeSets = {"tip"};
    problem.lossFactor = eta;
    hbm::HarmonicLoad load;
    load.harmonic = 1, load.phaseIndex = 0;
    load.force = Eigen::VectorXcd::Zero(12);
    for (int n = 0; n < 4; ++n) load.force(3 * n) = force / 4;  // along x at each tip node
    const auto v = fatigue::recoverSectorVibration(m, sector, problem, {load}, omega, comm);
    double worst = 0;
    for (auto n : m.nodeSet("root")) {
      const auto cycle = fatigue::measureCycle(v.meanStress(std::size_t(n)), v.alternatingStress(std::size_t(n)));
      worst = std::max(worst, std::abs(cycle.alternatingVonMises / exact - 1));
      EXPECT_NEAR(cycle.alternatingPrincipal, cycle.alternatingVonMises, 1e-9 * exact);  // uniaxial
      EXPECT_NEAR(cycle.meanVonMises, 0.0, 1e-9 * exact);
    }
    std::printf("rod, %d hex8 along it: root alternating stress error %.3e (closed form %.6g MPa), %.2f s\n", elements,
                worst, exact, timer.seconds());
    if (previous > 0) {
      EXPECT_LT(worst, 0.3 * previous) << "the error falls like h^2";
    }
    previous = worst;
  }
  EXPECT_LT(previous, 1e-3);
}
