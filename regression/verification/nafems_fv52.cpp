// Verification: NAFEMS FV52, simply supported thick square plate (NAFEMS R0015).
// 10 m x 10 m x 1 m, E = 200 GPa, nu = 0.3, rho = 8000 kg/m^3, uz = 0 along the
// four bottom edges. Modes 1-3 are in-plane rigid; modes 4-10 (Hz):
// 45.897, 109.44, 109.44, 167.89, 193.59, 206.19, 206.19.
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "BoxMesh.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/fe/Assembler.hpp"
#include "cyclone/solvers/ModalSolver.hpp"

using namespace cyclone;

namespace {

const double kReference[7] = {45.897, 109.44, 109.44, 167.89, 193.59, 206.19, 206.19};

// Frequencies of modes 1-10; inPlaneMode gets the index (among modes 4-10) of the
// mode with the least out-of-plane motion: the in-plane mode 8 of the benchmark,
// found by shape because bending modes cross it as the support softens.
std::vector<double> solveFV52(mesh::ElementType type, int n, int nz, long long& dofsOut, double& seconds,
                              int* inPlaneMode = nullptr) {
  Timer timer;
  auto plate = test_support::makeBoxMesh(10.0, 10.0, 1.0, n, n, nz, type);
  std::vector<mesh::Index> edges;
  for (mesh::Index i = 0; i < plate.numNodes(); ++i) {
    const auto& x = plate.coords[i];
    const bool bottom = std::abs(x[2]) < 1e-9;
    const bool onEdge = std::abs(x[0]) < 1e-9 || std::abs(x[0] - 10) < 1e-9 || std::abs(x[1]) < 1e-9 ||
                        std::abs(x[1] - 10) < 1e-9;
    if (bottom && onEdge) edges.push_back(i);
  }
  fe::DofMap dofs(plate.numNodes());
  dofs.constrain(edges, {false, false, true});
  dofs.finalize();
  fe::Assembler assembler(plate, dofs, Tpetra::getDefaultComm());
  const fe::IsotropicElastic steel{"steel", 200e9, 0.3, 8000};
  auto K = assembler.stiffness(steel);
  auto M = assembler.mass(steel);
  solvers::ModalOptions opt;
  opt.numModes = 10;
  opt.shift = -1.0e4;  // 3 rigid modes: below zero, near the first elastic (2 pi 46)^2 = 8e4
  const auto result = solvers::solveModes(*K, *M, opt);
  dofsOut = dofs.numFree();
  seconds = timer.seconds();
  if (inPlaneMode) {
    double least = 2;
    for (int i = 3; i < 10; ++i) {
      const auto u = assembler.nodalField(*result.modes, i);
      double z = 0, all = 0;
      for (const auto& v : u) z += v[2] * v[2], all += v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
      if (z / all < least) least = z / all, *inPlaneMode = i;
    }
  }
  return result.frequenciesHz;
}

double observedOrder(double coarse, double mid, double fine) {
  return std::log(std::abs((coarse - mid) / (mid - fine))) / std::log(2.0);
}

}  // namespace

// The benchmark's own mesh (4x4x1 HEX20) against NAFEMS' targets and against
// another code's published run of the same mesh (Altair OptiStruct
// verification manual, OS-V 0455: f/f_NAFEMS = 0.9760, 1.0101, 1.0101, 1.0072,
// 1.0017, 1.0022, 1.0022 for modes 4-10).
TEST(NafemsFV52, BenchmarkMeshHex20) {
  const double optistruct[7] = {0.9760, 1.0101, 1.0101, 1.0072, 1.0017, 1.0022, 1.0022};
  long long dofs;
  double seconds;
  const auto f = solveFV52(mesh::ElementType::Hex20, 4, 1, dofs, seconds);
  std::printf("\nNAFEMS FV52, 4x4x1 HEX20 (%lld dofs, %.2f s): f / f_NAFEMS for modes 4-10\n  cyclone   ", dofs,
              seconds);
  for (int i = 0; i < 7; ++i) std::printf(" %.4f", f[3 + i] / kReference[i]);
  std::printf("\n  OptiStruct");
  for (int i = 0; i < 7; ++i) std::printf(" %.4f", optistruct[i]);
  std::printf("\n");
  for (int i = 0; i < 3; ++i) EXPECT_LT(f[i], 1e-3 * f[3]) << "rigid mode " << i + 1;
  for (int i = 0; i < 7; ++i) EXPECT_NEAR(f[3 + i] / kReference[i], optistruct[i], 1.5e-4) << "mode " << 4 + i;
  // Within 1% of NAFEMS' thick-plate targets except modes 4-6, where the 3D line
  // support departs from plate theory (-2.4%, +1.01%; the same in OptiStruct).
  for (int i = 3; i < 7; ++i) EXPECT_NEAR(f[3 + i] / kReference[i], 1.0, 0.01) << "mode " << 4 + i;
  // The mesh is symmetric under a quarter turn: double modes are exact pairs.
  EXPECT_NEAR(f[4] / f[5], 1.0, 1e-9);
  EXPECT_NEAR(f[8] / f[9], 1.0, 1e-9);
}

// Refinement: a 3D solid on line supports has no mesh-converged bending
// frequencies (the support concentrates as h -> 0 and the frequencies keep
// falling), so the ladder is printed, and only mode 8, the support-independent
// in-plane mode (identified by its shape), is checked for convergence to its target at the O(h^4) rate.
TEST(NafemsFV52, RefinementLadder) {
  for (auto type : {mesh::ElementType::Hex20, mesh::ElementType::Tet10}) {
    std::printf("\nNAFEMS FV52 with %s: modes 4-10, relative error to NAFEMS and run time per mesh\n",
                mesh::exodusName(type).c_str());
    std::vector<double> mode8;
    for (auto [n, nz] : {std::pair{4, 1}, std::pair{8, 2}, std::pair{16, 4}}) {
      long long dofs;
      double seconds;
      int inPlane = -1;
      const auto f = solveFV52(type, n, nz, dofs, seconds, &inPlane);
      std::printf("%3dx%-3dx%-2d %7lld dofs %6.2f s |", n, n, nz, dofs, seconds);
      for (int i = 0; i < 7; ++i) std::printf(" %+7.3f%%", 100 * (f[3 + i] / kReference[i] - 1));
      std::printf("\n");
      mode8.push_back(f[inPlane]);
    }
    const double p = observedOrder(mode8[0], mode8[1], mode8[2]);
    std::printf("mode 8: observed order %.2f, error on the finest mesh %.2e\n", p, mode8[2] / kReference[4] - 1);
    EXPECT_NEAR(mode8[2] / kReference[4], 1.0, 1e-3);
    EXPECT_GT(p, 3.0) << mesh::exodusName(type);
  }
}
