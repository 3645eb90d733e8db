// The only translation unit that instantiates Anasazi's solver manager: it is
// expensive to compile (about a minute), so nothing else includes Anasazi.
#include "cyclone/solvers/ModalSolver.hpp"

#include <AnasaziBasicEigenproblem.hpp>
#include <AnasaziBlockKrylovSchurSolMgr.hpp>
#include <AnasaziLOBPCGSolMgr.hpp>
#include <AnasaziTpetraAdapter.hpp>
#include <Eigen/Eigenvalues>
#include <Teuchos_SerialDenseMatrix.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultSerialComm.hpp>
#include <Tpetra_Vector.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>
#include <random>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/solvers/DirectSolver.hpp"
#include "MueLuPreconditioner.hpp"

namespace cyclone::solvers {

namespace {

using OP = Tpetra::Operator<>;
using MV = linalg::MultiVector;

// The eigen-solver's start block from its rows' global indices and a fixed seed: the
// same on any number of processes and whatever was solved before. Tpetra's randomize
// draws from a pool shared by every solve of the run, so a nodal diameter's modes (and
// the reduced models built from them) differed at the solver's tolerance with the set
// of diameters built before it, and a friction curve sensitive at that level was
// traced whole with one set and not with another (docs/decisions.md, 2026-11-26).
Teuchos::RCP<MV> seededStartBlock(const Teuchos::RCP<const linalg::Map>& map, int columns) {
  auto X0 = Teuchos::rcp(new MV(map, columns));
  for (int j = 0; j < columns; ++j) {
    auto col = X0->getDataNonConst(j);
    for (std::size_t i = 0; i < std::size_t(col.size()); ++i) {
      // splitmix64 of (seed, column, global row): uniform in [-1, 1).
      std::uint64_t z = 20261126ULL + 0x9E3779B97F4A7C15ULL * (std::uint64_t(j) * 0x100000000ULL +
                                                              std::uint64_t(map->getGlobalElement(long(i))));
      z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
      z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
      z ^= z >> 31;
      col[i] = 2.0 * double(z >> 11) * 0x1.0p-53 - 1.0;
    }
  }
  return X0;
}

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
// When K factors, that factorization is the one the solve uses (handed back in `factored`).
double chooseShift(const linalg::Matrix& K, const linalg::Matrix& M, ModalOptions opt, int& rigidModes,
                   std::unique_ptr<DirectSolver>& factored) {
  rigidModes = 0;
  try {
    factored = std::make_unique<DirectSolver>(K, nullptr, 0.0, DirectSolver::Definiteness::Positive, opt.structure);
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
static void finishModes(const OP& K, const OP& M, double normK, double normM, const std::vector<double>& lambda,
                        const std::vector<Teuchos::RCP<const linalg::Vector>>& vectors, ModalResult& result) {
  const int nev = int(lambda.size());
  result.modes = Teuchos::rcp(new MV(K.getRangeMap(), nev));
  MV Kx(K.getRangeMap(), 1), Mx(K.getRangeMap(), 1);
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

static void finishModes(const linalg::Matrix& K, const linalg::Matrix& M, const std::vector<double>& lambda,
                        const std::vector<Teuchos::RCP<const linalg::Vector>>& vectors, ModalResult& result) {
  finishModes(K, M, K.getFrobeniusNorm(), M.getFrobeniusNorm(), lambda, vectors, result);
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
  auto X0 = seededStartBlock(K.getRowMap(), bs);
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

namespace {

// Anasazi's block Krylov-Schur on a shift-inverted operator (M-symmetric), the nev
// eigenvalues nearest the shift: lambda = sigma + 1/theta, ascending, with their vectors.
struct ShiftInvertedModes {
  std::vector<double> lambda;
  std::vector<Teuchos::RCP<const linalg::Vector>> vectors;
};

// Rayleigh-Ritz of K, M on span(V) (+ span(partner V)): the eigenpairs as the
// subspace gives them, each value with its own vector.
//
// Anasazi's solution pairs values and vectors itself, and when the converged Ritz
// pairs are not the leading ones (a travelling-wave pair of which one member
// converged first) the 13.2 solver manager can hand back vectors of other
// eigenvalues than the values listed (seen on a 24-sector disc, ND 7: the second
// vector of each pair belonged to the next pair; the backward error with Frobenius
// norms did not notice). Anasazi's vectors are used as a subspace only; with
// `partner` (i on a travelling-wave real form) it is completed so that every pair's
// plane is in it. The caller checks the values against Anasazi's: a subspace that
// misses an eigenvector would skip its value.
ShiftInvertedModes rayleighRitz(const OP& K, const OP& M, const OP* partner, const MV& V, int nev) {
  using MVT = Anasazi::MultiVecTraits<double, MV>;
  using Dense = Teuchos::SerialDenseMatrix<int, double>;
  const int found = int(V.getNumVectors());
  const int m = partner ? 2 * found : found;
  // The basis B = [V, JV] with a partner J, and M B: M commutes with J, so
  // M [V, JV] = [MV, J MV] (one product per vector of V instead of two).
  auto withPartner = [&](const MV& X) {
    auto out = Teuchos::rcp(new MV(V.getMap(), m));
    std::vector<int> columns(found);
    std::iota(columns.begin(), columns.end(), 0);
    MVT::SetBlock(X, columns, *out);
    if (partner) {
      MV turned(V.getMap(), found);
      partner->apply(X, turned);
      for (int& c : columns) c += found;
      MVT::SetBlock(turned, columns, *out);
    }
    return out;
  };
  auto timesV = [&](const OP& A) {
    MV AV(V.getMap(), found);
    A.apply(V, AV);
    return withPartner(AV);
  };
  const auto basis = withPartner(V);
  auto toEigen = [](const Dense& d) {
    Eigen::MatrixXd e(d.numRows(), d.numCols());
    for (int i = 0; i < d.numRows(); ++i)
      for (int j = 0; j < d.numCols(); ++j) e(i, j) = d(i, j);
    return Eigen::MatrixXd(0.5 * (e + e.transpose()));
  };
  // An M-orthonormal basis W = B toW of the span, without the directions the partner repeats.
  // The Gram matrix of the basis scaled to unit M-norm columns: the vectors of a standard
  // form (P^T L^{-H} y) differ in length by (lambda - sigma) / (lambda_0 - sigma), which
  // for a free sector's rigid-body modes at a small shift exceeded 1e10, and an unscaled
  // Gram matrix's relative cutoff dropped every other mode.
  Dense gram(m, m);
  MVT::MvTransMv(1.0, *basis, *timesV(M), gram);
  const Eigen::MatrixXd gramE = toEigen(gram);
  const Eigen::VectorXd length = gramE.diagonal().cwiseMax(0.0).cwiseSqrt();
  Eigen::VectorXd inverseLength(m);
  for (int i = 0; i < m; ++i) inverseLength(i) = length(i) > 0 ? 1.0 / length(i) : 0.0;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> gramEigen(inverseLength.asDiagonal() * gramE *
                                                           inverseLength.asDiagonal());
  const double largest = gramEigen.eigenvalues().maxCoeff();
  std::vector<int> kept;
  for (int i = 0; i < m; ++i)
    if (gramEigen.eigenvalues()(i) > 1e-10 * largest) kept.push_back(i);
  const int w = int(kept.size());
  if (w < nev)
    throw SolverError("eigen-solution: the converged subspace holds " + std::to_string(w) + " of " +
                      std::to_string(nev) + " modes");
  Dense toW(m, w);
  for (int j = 0; j < w; ++j)
    for (int i = 0; i < m; ++i)
      toW(i, j) = inverseLength(i) * gramEigen.eigenvectors()(i, kept[j]) / std::sqrt(gramEigen.eigenvalues()(kept[j]));
  // K on W itself, not W^T K W = toW^T (B^T K B) toW: with the partner B is nearly
  // dependent (a pair's two members and their turns), toW is large, and B^T K B's rounding
  // grew with it (a reduced model's modal realization moved by 1e-9).
  MV W(V.getMap(), w), KW(V.getMap(), w);
  MVT::MvTimesMatAddMv(1.0, *basis, toW, 0.0, W);
  K.apply(W, KW);
  Dense projected(w, w);
  MVT::MvTransMv(1.0, W, KW, projected);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ritz(toEigen(projected));
  // Ascending: the shift lies below the spectrum, so the lowest are the nearest to it.
  Dense Y(w, nev);
  std::vector<double> lambda(nev);
  for (int j = 0; j < nev; ++j) {
    for (int i = 0; i < w; ++i) Y(i, j) = ritz.eigenvectors()(i, j);
    lambda[j] = ritz.eigenvalues()(j);
  }
  auto X = Teuchos::rcp(new MV(V.getMap(), nev));
  MVT::MvTimesMatAddMv(1.0, W, Y, 0.0, *X);
  ShiftInvertedModes out;
  out.lambda = lambda;
  for (int j = 0; j < nev; ++j) out.vectors.push_back(X->getVector(j));
  return out;
}

// `op` is (K - sigma M)^{-1} M with the M inner product (standardForm null), or the
// standard form L^{-1} P M P^T L^{-H} of the factor P (K - sigma M) P^T = L L^H with the
// plain inner product (no M applies in Anasazi's orthogonalizations), whose vectors
// `standardForm` (P^T L^{-H}) takes back to the pencil's.
ShiftInvertedModes blockKrylovSchur(const OP& K, const Teuchos::RCP<OP>& op, const Teuchos::RCP<const OP>& M,
                                    const Teuchos::RCP<MV>& X0, long long n, const ModalOptions& opt,
                                    const OP* partner = nullptr, const OP* standardForm = nullptr,
                                    double normRatio = 0) {
  const int bs = int(X0->getNumVectors());
  const int nev = opt.numModes;
  // A Krylov space of about 3 nev keeps restarts few (each restart costs solves).
  int nb = opt.numBlocks > 0 ? opt.numBlocks : std::max(6, (3 * nev + bs - 1) / bs + 2);
  nb = int(std::min<long long>(nb, std::max<long long>(2, n / bs - 1)));
  auto problem = standardForm ? Teuchos::rcp(new Anasazi::BasicEigenproblem<double, MV, OP>(op, X0))
                              : Teuchos::rcp(new Anasazi::BasicEigenproblem<double, MV, OP>(op, M, X0));
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
  std::vector<double> listed;
  for (int i = 0; i < sol.numVecs; ++i) listed.push_back(opt.shift + 1.0 / sol.Evals[i].realpart);
  std::sort(listed.begin(), listed.end());
  Teuchos::RCP<const MV> vectors = sol.Evecs;
  if (standardForm) {
    auto pencil = Teuchos::rcp(new MV(sol.Evecs->getMap(), sol.Evecs->getNumVectors()));
    standardForm->apply(*sol.Evecs, *pencil);
    vectors = pencil;
  }
  auto modes = rayleighRitz(K, *M, partner, *vectors, nev);
  // Relative to the eigenvalue and the shift, and to ||K|| / ||M|| (normRatio, where
  // known) for eigenvalues near zero, which a backward-stable solve gives to about
  // eps ||K|| / ||M|| only (a free sector's rigid-body modes: 4e-5 listed, -1.4e-4 in
  // the span, of a sector whose elastic modes start at 3e7).
  for (int i = 0; i < nev; ++i)
    if (!(std::abs(modes.lambda[i] - listed[i]) <=
          1e-6 * (std::abs(listed[i]) + std::abs(opt.shift)) + 1e-12 * normRatio))
      throw SolverError("eigen-solution: Anasazi's vectors do not span its eigenvalues (mode " + std::to_string(i + 1) +
                        ": " + std::to_string(listed[i]) + " listed, " + std::to_string(modes.lambda[i]) +
                        " in the span of the vectors)");
  return modes;
}

void checkResiduals(const ModalResult& result) {
  for (std::size_t i = 0; i < result.residuals.size(); ++i)
    if (!(result.residuals[i] < 1e-6))
      throw SolverError("eigen-solution: mode " + std::to_string(i + 1) + " has relative residual " +
                        std::to_string(result.residuals[i]) +
                        " (ill-conditioned shift-invert: move the shift closer to the wanted eigenvalues)");
}

// A Tpetra operator from a function on blocks of columns (one process): what the
// Eigen-held operators of ShiftInvertedProblem look like to Anasazi.
class BlockFunctionOperator : public OP {
public:
  using Function = std::function<void(const Eigen::MatrixXd&, Eigen::MatrixXd&)>;
  BlockFunctionOperator(Teuchos::RCP<const linalg::Map> map, Function f) : map_(std::move(map)), f_(std::move(f)) {}
  Teuchos::RCP<const linalg::Map> getDomainMap() const override { return map_; }
  Teuchos::RCP<const linalg::Map> getRangeMap() const override { return map_; }
  // Blocks of at most kChunk columns: the final Rayleigh-Ritz applies the operators to
  // 10-20 vectors at once, and a solve's block is copied several times on its way
  // through the factor (permutations, CHOLMOD's result), which made the eigen-solution's
  // memory peak; a pair [w, Jw] stays whole (kChunk is even).
  void apply(const MV& X, MV& Y, Teuchos::ETransp, double alpha, double beta) const override {
    constexpr std::size_t kChunk = 4;
    const std::size_t nv = X.getNumVectors();
    const Eigen::Index n = Eigen::Index(X.getLocalLength());
    for (std::size_t first = 0; first < nv; first += kChunk) {
      const std::size_t count = std::min(kChunk, nv - first);
      Eigen::MatrixXd x(n, Eigen::Index(count)), y;
      for (std::size_t j = 0; j < count; ++j) {
        const auto col = X.getData(first + j);
        for (Eigen::Index i = 0; i < n; ++i) x(i, Eigen::Index(j)) = col[i];
      }
      f_(x, y);
      if (y.rows() != n || y.cols() != Eigen::Index(count))
        throw SolverError("eigen-solution: an operator returned a " + std::to_string(y.rows()) + " x " +
                          std::to_string(y.cols()) + " block for " + std::to_string(n) + " x " +
                          std::to_string(count));
      for (std::size_t j = 0; j < count; ++j) {
        auto col = Y.getDataNonConst(first + j);
        for (Eigen::Index i = 0; i < n; ++i)
          col[i] = alpha * y(i, Eigen::Index(j)) + (beta == 0.0 ? 0.0 : beta * col[i]);
      }
    }
    applies += int(nv);
  }
  mutable int applies = 0;

private:
  Teuchos::RCP<const linalg::Map> map_;
  Function f_;
};

}  // namespace

ModalResult solveModes(const linalg::Matrix& K, const linalg::Matrix& M, const ModalOptions& options) {
  // LOBPCG takes no shift: choosing one would factor K, which that path exists to avoid.
  if (options.method == EigenMethod::Lobpcg) return solveModesLobpcg(K, M, options);
  ModalOptions opt = options;
  int rigidModes = 0;
  Timer timer;
  std::unique_ptr<DirectSolver> factored;
  if (std::isnan(opt.shift)) {
    opt.shift = chooseShift(K, M, options, rigidModes, factored);
    if (rigidModes > 0) opt.blockSize = std::max(opt.blockSize, std::min(rigidModes, 6));
  }
  ModalResult result;
  result.shift = opt.shift;
  const long long n = K.getGlobalNumRows();
  if (opt.numModes < 1) throw InputError("modes", "number of modes must be at least 1");
  if (opt.numModes >= n)
    throw InputError("modes", "asked for " + std::to_string(opt.numModes) + " modes of a model with only " +
                                  std::to_string(n) + " free degrees of freedom");
  if (!factored) try {
      factored = std::make_unique<DirectSolver>(K, &M, opt.shift, DirectSolver::Definiteness::Positive, opt.structure);
    } catch (const SolverError& e) {
      throw SolverError(std::string(e.what()) + ". For the eigen-solution: K - sigma M with sigma = " +
                        std::to_string(opt.shift) +
                        " must be positive definite; an unconstrained (free) model needs a negative shift "
                        "of the order of its first elastic eigenvalue (2 pi f)^2");
    }
  result.factorSeconds = timer.seconds();

  timer.restart();
  auto op = Teuchos::rcp(new ShiftInvertOperator(M, *factored));
  auto X0 = seededStartBlock(K.getRowMap(), std::max(2, opt.blockSize));
  const auto modes = blockKrylovSchur(K, op, Teuchos::rcpFromRef(M), X0, n, opt);
  finishModes(K, M, modes.lambda, modes.vectors, result);
  checkResiduals(result);
  result.operatorApplies = op->applies;
  result.solveSeconds = timer.seconds();
  return result;
}

using BlockApply = std::function<void(const Eigen::MatrixXd& x, Eigen::MatrixXd& y)>;

// An operator A that commutes with the partner J (J^2 = -1), on blocks of 2.
// Started from [v, Jv], every block of Anasazi's Krylov space stays [w, +-Jw] to
// rounding: orthogonalizing against a J-invariant basis commutes with J, and w is
// orthogonal to Jw in any inner product J is skew for. Then A [w, +-Jw] =
// [Aw, +-J Aw]: one solve instead of two. A block that is not so (beyond 1e-12)
// is applied column by column as given.
BlockApply pairedApply(BlockApply apply, BlockApply partner) {
  return [apply = std::move(apply), partner = std::move(partner)](const Eigen::MatrixXd& x, Eigen::MatrixXd& y) {
    if (x.cols() == 2) {
      Eigen::MatrixXd first = x.col(0), turned, image, turnedImage;
      partner(first, turned);
      const double scale = first.norm();
      for (double sign : {1.0, -1.0})
        if ((x.col(1) - sign * turned).norm() <= 1e-12 * scale) {
          apply(first, image);
          partner(image, turnedImage);
          y.resize(x.rows(), 2);
          y.col(0) = image;
          y.col(1) = sign * turnedImage;
          return;
        }
    }
    apply(x, y);
  };
}

ModalResult solveModes(const ShiftInvertedProblem& problem, const ModalOptions& options) {
  ModalOptions opt = options;
  opt.shift = problem.shift;
  const long long n = problem.size;
  if (opt.numModes < 1) throw InputError("modes", "number of modes must be at least 1");
  if (opt.numModes >= n)
    throw InputError("modes", "asked for " + std::to_string(opt.numModes) + " modes of a model with only " +
                                  std::to_string(n) + " free degrees of freedom");
  Timer timer;
  const auto map = Teuchos::rcp(new linalg::Map(n, 0, Teuchos::rcp(new Teuchos::SerialComm<int>())));
  auto K = Teuchos::rcp(new BlockFunctionOperator(map, problem.applyK));
  auto M = Teuchos::rcp(
      new BlockFunctionOperator(map, problem.partner ? pairedApply(problem.applyM, problem.partner) : problem.applyM));
  const bool standard = problem.solveLower && problem.solveUpper;
  int solved = 0;  // right-hand sides through the factor
  const BlockApply shiftInverted = [&](const Eigen::MatrixXd& x, Eigen::MatrixXd& y) {
    solved += int(x.cols());
    Eigen::MatrixXd u(x.rows(), x.cols()), mu(x.rows(), x.cols());
    if (!standard) {
      problem.applyM(x, mu);
      problem.solveShifted(mu, y);
      return;
    }
    problem.solveUpper(x, u);
    problem.applyM(u, mu);
    problem.solveLower(mu, y);
  };
  auto op = Teuchos::rcp(new BlockFunctionOperator(
      map, problem.partner ? pairedApply(shiftInverted, problem.partner) : shiftInverted));
  Teuchos::RCP<BlockFunctionOperator> toPencil;
  if (standard) toPencil = Teuchos::rcp(new BlockFunctionOperator(map, problem.solveUpper));
  // A seeded start block: the same on any process and whatever was solved before.
  const int bs = std::max(2, opt.blockSize);
  auto X0 = Teuchos::rcp(new MV(map, bs));
  std::mt19937_64 random(20261124);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int j = 0; j < bs; ++j) {
    auto col = X0->getDataNonConst(j);
    for (long long i = 0; i < n; ++i) col[i] = uniform(random);
  }
  ModalResult result;
  result.shift = opt.shift;
  Teuchos::RCP<BlockFunctionOperator> partner;
  if (problem.partner) partner = Teuchos::rcp(new BlockFunctionOperator(map, problem.partner));
  if (problem.partner && bs == 2) {
    // The start block [v, Jv]: see pairedApply.
    Eigen::MatrixXd v(n, 1), jv;
    const auto first = X0->getData(0);
    for (long long i = 0; i < n; ++i) v(i, 0) = first[i];
    problem.partner(v, jv);
    auto second = X0->getDataNonConst(1);
    for (long long i = 0; i < n; ++i) second[i] = jv(i, 0);
  }
  const double normRatio = problem.normM > 0 ? problem.normK / problem.normM : 0.0;
  ShiftInvertedModes modes;
  try {
    modes = blockKrylovSchur(*K, op, M, X0, n, opt, partner.get(), toPencil.get(), normRatio);
  } catch (const SolverError& e) {
    if (!(problem.partner && bs == 2)) throw;
    // The paired start [v, Jv] can lose a mode (the default disc at 10 000 rpm, ND 4:
    // Anasazi listed 2406 Hz, its vectors spanned 4086 Hz): the solve again from two
    // independent random vectors, each block then two solves instead of one.
    log::info(std::string("eigen-solution: the paired start failed (") + e.what() +
              "); solved again from an unpaired start block");
    std::mt19937_64 again(20261125);
    for (int j = 0; j < bs; ++j) {
      auto col = X0->getDataNonConst(j);
      for (long long i = 0; i < n; ++i) col[i] = uniform(again);
    }
    modes = blockKrylovSchur(*K, op, M, X0, n, opt, partner.get(), toPencil.get(), normRatio);
  }
  finishModes(*K, *M, problem.normK, problem.normM, modes.lambda, modes.vectors, result);
  checkResiduals(result);
  result.operatorApplies = solved;
  result.solveSeconds = timer.seconds();
  return result;
}

}  // namespace cyclone::solvers
