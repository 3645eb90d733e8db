// The only translation unit that instantiates Anasazi's solver manager: it is
// expensive to compile (about a minute), so nothing else includes Anasazi.
#include "cyclone/solvers/ModalSolver.hpp"

#include <AnasaziBasicEigenproblem.hpp>
#include <AnasaziBlockKrylovSchurSolMgr.hpp>
#include <AnasaziLOBPCGSolMgr.hpp>
#include <AnasaziTpetraAdapter.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Vector.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/solvers/DirectSolver.hpp"
#include "MueLuPreconditioner.hpp"

namespace cyclone::solvers {

namespace {

using OP = Tpetra::Operator<>;
using MV = linalg::MultiVector;

// Y = (K - sigma M)^{-1} M X
class ShiftInvertOperator : public OP {
public:
  ShiftInvertOperator(const linalg::Matrix& M, const DirectSolver& solver) : M_(M), solver_(solver) {}
  Teuchos::RCP<const linalg::Map> getDomainMap() const override { return M_.getDomainMap(); }
  Teuchos::RCP<const linalg::Map> getRangeMap() const override { return M_.getRangeMap(); }
  void apply(const MV& X, MV& Y, Teuchos::ETransp, double alpha, double beta) const override {
    MV MX(X.getMap(), X.getNumVectors());
    M_.apply(X, MX);
    if (alpha == 1.0 && beta == 0.0) {
      solver_.solve(MX, Y);
    } else {
      MV Z(Y.getMap(), Y.getNumVectors());
      solver_.solve(MX, Z);
      Y.update(alpha, Z, beta);
    }
    applies += int(X.getNumVectors());
  }
  mutable int applies = 0;

private:
  const linalg::Matrix& M_;
  const DirectSolver& solver_;
};

}  // namespace

namespace {

// K factors: no rigid-body modes, shift 0. Otherwise a rough pass with a small
// negative shift (relative to the mean diagonal ratio) locates the first elastic
// eigenvalue; the shift then goes to minus that, where K - sigma M is well conditioned.
double chooseShift(const linalg::Matrix& K, const linalg::Matrix& M, ModalOptions opt, int& rigidModes) {
  rigidModes = 0;
  try {
    DirectSolver probe(K);
    return 0.0;
  } catch (const SolverError&) {
  }
  linalg::Vector dk(K.getRowMap()), dm(M.getRowMap());
  K.getLocalDiagCopy(dk);
  M.getLocalDiagCopy(dm);
  double ratio = 0, count = 0;
  {
    auto k = dk.getData(), m = dm.getData();
    for (decltype(k.size()) i = 0; i < k.size(); ++i)
      if (m[i] > 0) ratio += k[i] / m[i], count += 1;
  }
  double sums[2] = {ratio, count}, global[2];
  Teuchos::reduceAll(*K.getRowMap()->getComm(), Teuchos::REDUCE_SUM, 2, sums, global);
  const double mean = global[0] / std::max(1.0, global[1]);
  opt.shift = -1e-6 * mean;
  opt.tolerance = 1e-6;
  opt.blockSize = std::max(opt.blockSize, 6);
  opt.numModes = std::max(opt.numModes, 7);
  const auto rough = solveModes(K, M, opt);
  const double top = rough.eigenvalues.back();
  double firstElastic = top;
  for (double lam : rough.eigenvalues) {
    if (lam > 1e-6 * top) {
      firstElastic = lam;
      break;
    }
    ++rigidModes;
  }
  return -firstElastic;
}

}  // namespace

// Mass-normalises the modes (Anasazi's are M-orthonormal; make it exact and
// explicit), computes frequencies and normwise backward errors
// ||K x - lambda M x|| / ((||K|| + |lambda| ||M||) ||x||), meaningful for zero
// (rigid-body) eigenvalues too.
static void finishModes(const linalg::Matrix& K, const linalg::Matrix& M, const std::vector<double>& lambda,
                 const std::vector<Teuchos::RCP<const linalg::Vector>>& vectors, ModalResult& result) {
  const int nev = int(lambda.size());
  result.modes = Teuchos::rcp(new MV(K.getRowMap(), nev));
  MV Kx(K.getRowMap(), 1), Mx(K.getRowMap(), 1);
  const double normK = K.getFrobeniusNorm(), normM = M.getFrobeniusNorm();
  for (int i = 0; i < nev; ++i) {
    auto dst = result.modes->getVectorNonConst(i);
    dst->assign(*vectors[i]);
    M.apply(*dst, Mx);
    dst->scale(1.0 / std::sqrt(dst->dot(*Mx.getVector(0))));
    K.apply(*dst, Kx);
    M.apply(*dst, Mx);
    Kx.update(-lambda[i], Mx, 1.0);
    result.eigenvalues.push_back(lambda[i]);
    result.frequenciesHz.push_back(std::sqrt(std::max(lambda[i], 0.0)) / (2 * M_PI));
    result.residuals.push_back(Kx.getVector(0)->norm2() / ((normK + std::abs(lambda[i]) * normM) * dst->norm2()));
  }
}

// LOBPCG needs a preconditioner that resolves the low end of the spectrum; for
// elasticity that means MueLu with the rigid-body near null space, blocked by node.
// With MueLu's default (a constant per scalar unknown) or none, LOBPCG creeps for
// hundreds of iterations until the update of the Ritz vectors outside X is tiny,
// [CX CP]^T M [CX CP] is numerically singular, and Anasazi's full orthogonalisation
// stops with a failed Cholesky (reproduced on cyclic sectors with MueLu's default
// near null space). So the near null space is required unless the unknowns are scalar
// (equationsPerNode = 1, where MueLu's constant is the right one).
static ModalResult solveModesLobpcg(const linalg::Matrix& K, const linalg::Matrix& M, const ModalOptions& opt) {
  const long long n = K.getGlobalNumRows();
  const int nev = opt.numModes;
  if (nev < 1) throw InputError("modes", "number of modes must be at least 1");
  const int bs = std::max(opt.blockSize, nev + 2);  // one block holding all wanted modes and a margin
  if (bs >= n)
    throw InputError("modes", "asked for " + std::to_string(nev) + " modes of a model with only " +
                                  std::to_string(n) + " free degrees of freedom (LOBPCG needs modes + 2 fewer)");
  if (opt.nearNullSpace.is_null() && opt.equationsPerNode != 1)
    throw InputError("LOBPCG", "needs the near null space for its MueLu preconditioner (Assembler::rigidBodyModes()); "
                               "without it the iteration stalls");
  ModalResult result;
  result.shift = 0;  // no shift: LOBPCG works on K and M directly
  Timer timer;
  auto prec = makeMueLuPreconditioner(K, opt.nearNullSpace, opt.equationsPerNode);
  result.factorSeconds = timer.seconds();  // the preconditioner set-up stands in for the factorization
  timer.restart();
  auto X0 = Teuchos::rcp(new MV(K.getRowMap(), bs));
  X0->randomize();
  auto problem = Teuchos::rcp(new Anasazi::BasicEigenproblem<double, MV, OP>(
      Teuchos::rcpFromRef<const OP>(K), Teuchos::rcpFromRef<const OP>(M), X0));
  problem->setHermitian(true);
  problem->setNEV(nev);
  problem->setPrec(prec);
  if (!problem->setProblem()) throw SolverError("Anasazi rejected the LOBPCG set-up");
  const int maxIterations = 2000;
  Teuchos::ParameterList pl;
  pl.set("Which", "SM");
  pl.set("Block Size", bs);
  pl.set("Maximum Iterations", maxIterations);
  pl.set("Convergence Tolerance", std::max(opt.tolerance, 1e-10));
  pl.set("Use Locking", true);
  pl.set("Full Ortho", true);
  pl.set("Verbosity", int(Anasazi::Errors));
  Anasazi::LOBPCGSolMgr<double, MV, OP> manager(problem, pl);
  const auto status = manager.solve();
  const auto& sol = problem->getSolution();
  if (status != Anasazi::Converged || sol.numVecs < nev)
    throw SolverError("LOBPCG: only " + std::to_string(sol.numVecs) + " of " + std::to_string(nev) +
                      " modes converged (at most " + std::to_string(maxIterations) +
                      " iterations; a stall, or a failed Cholesky reported by Anasazi, means a weak or "
                      "indefinite preconditioner: check the near null space)");
  std::vector<int> order(sol.numVecs);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return sol.Evals[a].realpart < sol.Evals[b].realpart; });
  std::vector<double> lambda;
  std::vector<Teuchos::RCP<const linalg::Vector>> vectors;
  for (int i = 0; i < nev; ++i) {
    lambda.push_back(sol.Evals[order[i]].realpart);
    vectors.push_back(sol.Evecs->getVector(order[i]));
  }
  finishModes(K, M, lambda, vectors, result);
  for (int i = 0; i < nev; ++i)
    if (!(result.residuals[i] < 1e-6))
      throw SolverError("LOBPCG: mode " + std::to_string(i + 1) + " has relative residual " +
                        std::to_string(result.residuals[i]));
  result.operatorApplies = manager.getNumIters();
  result.solveSeconds = timer.seconds();
  return result;
}

ModalResult solveModes(const linalg::Matrix& K, const linalg::Matrix& M, const ModalOptions& options) {
  // LOBPCG takes no shift: choosing one would factor K, which that path exists to avoid.
  if (options.method == EigenMethod::Lobpcg) return solveModesLobpcg(K, M, options);
  ModalOptions opt = options;
  int rigidModes = 0;
  if (std::isnan(opt.shift)) {
    opt.shift = chooseShift(K, M, options, rigidModes);
    if (rigidModes > 0) opt.blockSize = std::max(opt.blockSize, std::min(rigidModes, 6));
  }
  ModalResult result;
  result.shift = opt.shift;
  const long long n = K.getGlobalNumRows();
  if (opt.numModes < 1) throw InputError("modes", "number of modes must be at least 1");
  if (opt.numModes >= n)
    throw InputError("modes", "asked for " + std::to_string(opt.numModes) + " modes of a model with only " +
                                  std::to_string(n) + " free degrees of freedom");
  Timer timer;
  std::unique_ptr<DirectSolver> factored;
  try {
    factored = std::make_unique<DirectSolver>(K, &M, opt.shift);
  } catch (const SolverError& e) {
    throw SolverError(std::string(e.what()) + ". For the eigen-solution: K - sigma M with sigma = " +
                      std::to_string(opt.shift) +
                      " must be positive definite; an unconstrained (free) model needs a negative shift "
                      "of the order of its first elastic eigenvalue (2 pi f)^2");
  }
  const DirectSolver& solver = *factored;
  result.factorSeconds = timer.seconds();

  timer.restart();
  auto op = Teuchos::rcp(new ShiftInvertOperator(M, solver));
  const int bs = std::max(2, opt.blockSize);
  const int nev = opt.numModes;
  // A Krylov space of about 3 nev keeps restarts few (each restart costs solves).
  int nb = opt.numBlocks > 0 ? opt.numBlocks : std::max(6, (3 * nev + bs - 1) / bs + 2);
  nb = int(std::min<long long>(nb, std::max<long long>(2, n / bs - 1)));
  auto X0 = Teuchos::rcp(new MV(K.getRowMap(), bs));
  X0->randomize();
  auto problem = Teuchos::rcp(new Anasazi::BasicEigenproblem<double, MV, OP>(op, Teuchos::rcpFromRef(M), X0));
  problem->setHermitian(true);
  problem->setNEV(nev);
  if (!problem->setProblem()) throw SolverError("Anasazi rejected the eigenproblem set-up");

  Teuchos::ParameterList pl;
  pl.set("Which", "LM");  // largest 1/(lambda - sigma): eigenvalues nearest the shift
  pl.set("Block Size", bs);
  pl.set("Num Blocks", nb);
  pl.set("Maximum Restarts", opt.maxRestarts);
  pl.set("Convergence Tolerance", opt.tolerance);
  pl.set("Verbosity", int(Anasazi::Errors));
  Anasazi::BlockKrylovSchurSolMgr<double, MV, OP> manager(problem, pl);
  const auto status = manager.solve();
  const auto& sol = problem->getSolution();
  if (status != Anasazi::Converged || sol.numVecs < nev)
    throw SolverError("eigen-solution: only " + std::to_string(sol.numVecs) + " of " + std::to_string(nev) +
                      " modes converged after " + std::to_string(opt.maxRestarts) +
                      " restarts (raise the restarts or block count, or move the shift)");

  // lambda = sigma + 1/theta, ascending.
  std::vector<int> order(sol.numVecs);
  std::vector<double> lambda(sol.numVecs);
  for (int i = 0; i < sol.numVecs; ++i) lambda[i] = opt.shift + 1.0 / sol.Evals[i].realpart;
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return lambda[a] < lambda[b]; });

  std::vector<double> sorted;
  std::vector<Teuchos::RCP<const linalg::Vector>> vectors;
  for (int i = 0; i < nev; ++i) {
    sorted.push_back(lambda[order[i]]);
    vectors.push_back(sol.Evecs->getVector(order[i]));
  }
  finishModes(K, M, sorted, vectors, result);
  for (int i = 0; i < nev; ++i)
    if (!(result.residuals[i] < 1e-6))
      throw SolverError("eigen-solution: mode " + std::to_string(i + 1) + " has relative residual " +
                        std::to_string(result.residuals[i]) +
                        " (ill-conditioned shift-invert: move the shift closer to the wanted eigenvalues)");
  result.operatorApplies = op->applies;
  result.solveSeconds = timer.seconds();
  return result;
}

}  // namespace cyclone::solvers
