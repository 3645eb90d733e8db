// Verification: the same problem on the MPI ranks of this run (distributed
// assembly, owned + shared rows) and on one rank (a serial communicator, in the
// same process) gives the same answer: static (direct and iterative) and modal.
// ctest runs it with mpirun -np 2.
#include <Teuchos_DefaultSerialComm.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <gtest/gtest.h>

#include <cmath>

#include "BoxMesh.hpp"
#include "cyclone/analysis/StaticAnalysis.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/solvers/ModalSolver.hpp"

using namespace cyclone;

namespace {

analysis::StaticProblem cantileverProblem(solvers::LinearSolverKind kind) {
  analysis::StaticProblem p;
  p.material = fe::IsotropicElastic{"steel", 2.1e5, 0.3, 7.85e-9};
  p.fixedNodeSets = {"x0"};
  p.speedRpm = 3000;
  p.axis.point = Eigen::Vector3d(0, -50, 0);
  p.axis.direction = Eigen::Vector3d(0, 0, 1);
  p.nodalForces.push_back({"x1", Eigen::Vector3d(0, 0, -1.0)});
  p.solver.kind = kind;
  p.solver.tolerance = 1e-10;
  return p;
}

double maxDifference(const std::vector<std::array<double, 3>>& a, const std::vector<std::array<double, 3>>& b) {
  double diff = 0, scale = 0;
  for (std::size_t n = 0; n < a.size(); ++n)
    for (int d = 0; d < 3; ++d) {
      diff = std::max(diff, std::abs(a[n][d] - b[n][d]));
      scale = std::max(scale, std::abs(b[n][d]));
    }
  return diff / scale;
}

}  // namespace

TEST(StaticMpi, DistributedEqualsSerial) {
  log::setQuiet(true);
  auto world = Tpetra::getDefaultComm();
  auto serial = Teuchos::rcp(new Teuchos::SerialComm<int>);
  auto mesh = test_support::makeBoxMesh(100.0, 10.0, 10.0, 12, 2, 2, mesh::ElementType::Tet10);
  std::printf("rank %d of %d\n", world->getRank(), world->getSize());
  for (auto kind : {solvers::LinearSolverKind::Direct, solvers::LinearSolverKind::Iterative}) {
    const auto problem = cantileverProblem(kind);
    const auto distributed = analysis::solveStatic(mesh, problem, world);
    const auto reference = analysis::solveStatic(mesh, cantileverProblem(solvers::LinearSolverKind::Direct), serial);
    const double diff = maxDifference(distributed.displacement, reference.displacement);
    std::printf("%s solve on %d ranks vs 1 rank: max relative difference %.2e\n",
                kind == solvers::LinearSolverKind::Direct ? "direct" : "iterative", world->getSize(), diff);
    EXPECT_LT(diff, kind == solvers::LinearSolverKind::Direct ? 1e-11 : 1e-8);
    for (std::size_t e = 0; e < distributed.stress.elementVonMises.size(); ++e)
      ASSERT_NEAR(distributed.stress.elementVonMises[e], reference.stress.elementVonMises[e],
                  1e-6 * reference.maxVonMises);
  }
}

TEST(StaticMpi, DistributedModesEqualSerial) {
  auto world = Tpetra::getDefaultComm();
  auto serial = Teuchos::rcp(new Teuchos::SerialComm<int>);
  auto mesh = test_support::makeBoxMesh(100.0, 10.0, 10.0, 12, 2, 2, mesh::ElementType::Tet10);
  const fe::IsotropicElastic steel{"steel", 2.1e5, 0.3, 7.85e-9};
  std::vector<double> f[2];
  int i = 0;
  for (auto comm : {world, Teuchos::RCP<const Teuchos::Comm<int>>(serial)}) {
    fe::DofMap dofs(mesh.numNodes());
    dofs.constrain(mesh.nodeSet("x0"));
    dofs.finalize();
    fe::Assembler assembler(mesh, dofs, comm);
    auto K = assembler.stiffness(steel);
    auto M = assembler.mass(steel);
    solvers::ModalOptions opt;
    opt.numModes = 6;
    f[i++] = solvers::solveModes(*K, *M, opt).frequenciesHz;
  }
  for (int m = 0; m < 6; ++m) EXPECT_NEAR(f[0][m] / f[1][m], 1.0, 1e-10) << "mode " << m + 1;
}
