// Benchmark (not a test): sparse direct (CHOLMOD) and iterative (CG + MueLu)
// solves of tet10 elasticity on structured cantilever boxes, printing assembly,
// factorization and solve times, nnz(L), flops and peak memory per size.
// Usage: solver_benchmark [cells_per_edge ...]   (default: 8 16; 16 ~ 1e5 DOF, 27 ~ 5e5 DOF)
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>

#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

#include "BoxMesh.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/fe/Assembler.hpp"
#include "cyclone/solvers/DirectSolver.hpp"
#include "cyclone/solvers/LinearSolver.hpp"

using namespace cyclone;

static double peakRssGb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0 / 1024.0;
}

int main(int argc, char** argv) {
  Tpetra::ScopeGuard mpi(&argc, &argv);
  std::vector<int> sizes;
  for (int i = 1; i < argc; ++i) sizes.push_back(std::atoi(argv[i]));
  if (sizes.empty()) sizes = {8, 16};
  const fe::IsotropicElastic titanium;
  std::printf("%6s %9s %11s %9s %9s %9s %11s %10s %9s %9s %7s %8s\n", "cells", "dofs", "nnz(K)", "assembly",
              "factor", "solve", "nnz(L)", "Gflop", "cg_setup", "cg_solve", "cg_it", "rss(GB)");
  for (int n : sizes) {
    Timer timer;
    auto box = test_support::makeBoxMesh(n, n, n, n, n, n, mesh::ElementType::Tet10);
    fe::DofMap dofs(box.numNodes());
    dofs.constrain(box.nodeSet("x0"));
    dofs.finalize();
    fe::Assembler assembler(box, dofs, Tpetra::getDefaultComm());
    auto K = assembler.stiffness(titanium);
    auto f = assembler.bodyLoad(Eigen::Vector3d(0, 0, -1));
    const double assembly = timer.seconds();

    solvers::DirectSolver direct(*K);
    linalg::MultiVector x(assembler.map(), 1), xi(assembler.map(), 1);
    timer.restart();
    direct.solve(*f, x);
    const double solve = timer.seconds();
    const auto& s = direct.statistics();

    solvers::LinearSolveOptions it;
    it.kind = solvers::LinearSolverKind::Iterative;
    it.tolerance = 1e-8;
    it.nearNullSpace = assembler.rigidBodyModes();
    const auto report = solvers::solveLinear(*K, *f, xi, it);
    std::printf("%6d %9lld %11zu %9.2f %9.2f %9.3f %11.3e %10.1f %9.2f %9.2f %7d %8.2f\n", n, s.rows,
                std::size_t(K->getGlobalNumEntries()), assembly, s.factorSeconds, solve, s.nonzerosFactor,
                s.flops / 1e9, report.setupSeconds, report.solveSeconds, report.iterations, peakRssGb());
    std::fflush(stdout);
  }
  return 0;
}
