// Belos CG + MueLu smoothed aggregation. Kept alone in this translation unit:
// the MueLu and Belos headers are the expensive ones to compile.
#include <BelosSolverFactory.hpp>
#include <BelosTpetraAdapter.hpp>
#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <mpi.h>

#include <algorithm>
#include <iomanip>
#include <limits>
#include <sstream>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/solvers/LinearSolver.hpp"
#include "MueLuPreconditioner.hpp"

namespace cyclone::solvers {

double relativeResidual(const linalg::Matrix& K, const linalg::MultiVector& b, const linalg::MultiVector& x);

namespace {

// MueLu 13.2 cannot run on a Teuchos::SerialComm in an MPI build of Trilinos (Debian's). The
// Hierarchy::describe() that HierarchyManager::SetupHierarchy always calls ends, under HAVE_MPI, in
//   rcp_dynamic_cast<const Teuchos::MpiComm<int>>(comm)->getRawMpiComm()   // MueLu_Hierarchy_def.hpp
// without a null check: a SerialComm segfaults there at any verbosity, with any parameters. So a
// matrix on a non-MPI communicator (e.g. an Assembler given a SerialComm) is re-expressed on
// MPI_COMM_SELF, which is equivalent for one process: the same global indices, the local matrix and
// the vectors' data shared, not copied.
Teuchos::RCP<const linalg::Map> onComm(const linalg::Map& map, const linalg::CommPtr& comm) {
  if (map.isContiguous() && map.getMinGlobalIndex() == map.getIndexBase())
    return Teuchos::rcp(
        new linalg::Map(map.getGlobalNumElements(), map.getNodeNumElements(), map.getIndexBase(), comm));
  const auto gids = map.getMyGlobalIndices();
  return Teuchos::rcp(new linalg::Map(map.getGlobalNumElements(),
                                      Teuchos::ArrayView<const linalg::GlobalIndex>(gids.data(), gids.extent(0)),
                                      map.getIndexBase(), comm));
}

/// A view (aliasing v's data) with the same local rows under `map`.
Teuchos::RCP<linalg::MultiVector> viewOn(const linalg::MultiVector& v,
                                         const Teuchos::RCP<const linalg::Map>& map) {
  return Teuchos::rcp(new linalg::MultiVector(v, map, 0));
}

// Smoothed aggregation for elasticity: Chebyshev smoothing, relaxation on the
// coarse level (Debian's KLU2 is wrong on more than one rank).
// Chebyshev needs an upper bound of the spectrum of D^-1 A (the prolongator damping
// reuses it). Ifpack2's default, 10 power iterations, can fall short: on a 12-sector
// cyclic sector (k = 0 and N/2) it gave 4.08 for a true 4.78, more than the 1.1 boost covers,
// so the smoother amplified the top modes and the V-cycle was indefinite
// ((Ke)^T P (Ke) < 0 for some e): LOBPCG stalled and ended in a failed Cholesky.
// 100 iterations (one-off, at set-up) give 4.78 there.
Teuchos::ParameterList smoothedAggregationParameters(int equationsPerNode) {
  Teuchos::ParameterList mueluParams;
  mueluParams.set("verbosity", "none");
  mueluParams.set("multigrid algorithm", "sa");
  mueluParams.set("smoother: type", "CHEBYSHEV");
  mueluParams.sublist("smoother: params").set("chebyshev: degree", 2);
  mueluParams.sublist("smoother: params").set("chebyshev: eigenvalue max iterations", 100);
  mueluParams.set("coarse: type", "RELAXATION");
  mueluParams.sublist("coarse: params").set("relaxation: type", "Symmetric Gauss-Seidel");
  mueluParams.sublist("coarse: params").set("relaxation: sweeps", 4);
  mueluParams.set("coarse: max size", 100);
  mueluParams.set("number of equations", equationsPerNode);
  return mueluParams;
}

}  // namespace

Teuchos::RCP<Tpetra::Operator<>> makeMueLuPreconditioner(const linalg::Matrix& A,
                                                          const Teuchos::RCP<const linalg::MultiVector>& nearNullSpace,
                                                          int equationsPerNode) {
  if (Teuchos::rcp_dynamic_cast<const Teuchos::MpiComm<int>>(A.getComm()).is_null())
    throw SolverError("MueLu preconditioner: the matrix must live on an MPI communicator (MueLu 13.2 needs one)");
  Teuchos::ParameterList params = smoothedAggregationParameters(nearNullSpace.is_null() ? 1 : equationsPerNode);
  if (!nearNullSpace.is_null())
    params.sublist("user data").set("Nullspace", Teuchos::rcp_const_cast<linalg::MultiVector>(nearNullSpace));
  Teuchos::RCP<Tpetra::Operator<>> op = Teuchos::rcp_const_cast<linalg::Matrix>(Teuchos::rcpFromRef(A));
  return MueLu::CreateTpetraPreconditioner(op, params);
}

namespace {
}  // namespace

LinearSolveReport solveIterative(const linalg::Matrix& K, const linalg::MultiVector& b, linalg::MultiVector& x,
                                 const LinearSolveOptions& options) {
  using OP = Tpetra::Operator<>;
  using MV = linalg::MultiVector;
  LinearSolveReport report;
  Timer timer;
  Teuchos::ParameterList mueluParams = smoothedAggregationParameters(options.nearNullSpace.is_null() ? 1 : options.blockSize);
  Teuchos::RCP<const linalg::Matrix> Kmpi = Teuchos::rcpFromRef(K);
  Teuchos::RCP<const MV> bmpi = Teuchos::rcpFromRef(b), nullSpace = options.nearNullSpace;
  Teuchos::RCP<MV> xmpi = Teuchos::rcpFromRef(x);
  if (Teuchos::rcp_dynamic_cast<const Teuchos::MpiComm<int>>(K.getComm()).is_null()) {
    if (K.getComm()->getSize() != 1)
      throw SolverError("iterative solve: the matrix' communicator is neither MPI nor serial");
    int mpiInitialized = 0;
    MPI_Initialized(&mpiInitialized);
    if (!mpiInitialized)
      throw SolverError("iterative solve: MueLu needs MPI to be initialised (Tpetra::ScopeGuard)");
    const linalg::CommPtr self = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
    const auto rowMap = onComm(*K.getRowMap(), self), colMap = onComm(*K.getColMap(), self);
    const auto sameAsRows = [&](const linalg::Map& m) { return m.isSameAs(*K.getRowMap()); };
    const auto domainMap = sameAsRows(*K.getDomainMap()) ? rowMap : onComm(*K.getDomainMap(), self);
    const auto rangeMap = sameAsRows(*K.getRangeMap()) ? rowMap : onComm(*K.getRangeMap(), self);
    Kmpi = Teuchos::rcp(new linalg::Matrix(K.getLocalMatrixDevice(), rowMap, colMap, domainMap, rangeMap));
    bmpi = viewOn(b, rangeMap);
    xmpi = viewOn(x, domainMap);
    if (!nullSpace.is_null()) nullSpace = viewOn(*nullSpace, rowMap);
  }
  if (!nullSpace.is_null())
    mueluParams.sublist("user data").set("Nullspace", Teuchos::rcp_const_cast<MV>(nullSpace));
  Teuchos::RCP<OP> A = Teuchos::rcp_const_cast<linalg::Matrix>(Kmpi);
  Teuchos::RCP<OP> prec = MueLu::CreateTpetraPreconditioner(A, mueluParams);
  report.setupSeconds = timer.seconds();

  timer.restart();
  auto problem = Teuchos::rcp(new Belos::LinearProblem<double, MV, OP>(
      A, xmpi, Teuchos::rcp_const_cast<MV>(bmpi)));
  problem->setRightPrec(prec);
  if (!problem->setProblem()) throw SolverError("Belos rejected the linear problem set-up");
  auto params = Teuchos::rcp(new Teuchos::ParameterList);
  params->set("Convergence Tolerance", options.tolerance);
  params->set("Maximum Iterations", options.maxIterations);
  Belos::SolverFactory<double, MV, OP> factory;
  auto solver = factory.create("CG", params);
  solver->setProblem(problem);
  const auto result = solver->solve();
  report.iterations = solver->getNumIters();
  report.solveSeconds = timer.seconds();
  report.relativeResidual = relativeResidual(K, b, x);
  // Rounding floor: no solver gets ||b - K x|| below about eps ||K|| ||x||, so a
  // tolerance under that is met once the residual reaches it.
  const double floor = 100 * std::numeric_limits<double>::epsilon() * K.getFrobeniusNorm() *
                       x.getVector(0)->norm2() / std::max(b.getVector(0)->norm2(), 1e-300);
  if (result != Belos::Converged || !(report.relativeResidual < std::max(10 * options.tolerance, floor))) {
    std::ostringstream msg;
    msg << "iterative solve (CG + MueLu) did not converge: relative residual " << std::scientific
        << std::setprecision(2) << report.relativeResidual << " (tolerance " << options.tolerance << ") after "
        << report.iterations << " iterations (limit " << options.maxIterations << ")"
        << (result == Belos::Converged ? "" : ", Belos reports no convergence");
    throw SolverError(msg.str());
  }
  return report;
}

}  // namespace cyclone::solvers
