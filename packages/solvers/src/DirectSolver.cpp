#include "cyclone/solvers/DirectSolver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Timer.hpp"

namespace cyclone::solvers {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using linalg::GlobalIndex;

namespace {

// All rows of a distributed matrix on rank 0 (others get an empty matrix):
// lower triangle only, in Eigen's compressed format.
SparseMatrix lowerTriangleOnRoot(const linalg::Matrix& A, const Teuchos::RCP<const linalg::Map>& rootMap,
                                 const Teuchos::RCP<const Tpetra::Export<>>& exporter) {
  Teuchos::RCP<const linalg::Matrix> rooted = Teuchos::rcpFromRef(A);
  if (exporter) {
    auto R = Teuchos::rcp(new linalg::Matrix(rootMap, 0));
    R->doExport(A, *exporter, Tpetra::ADD);
    R->fillComplete(A.getDomainMap(), rootMap);
    rooted = R;
  }
  const GlobalIndex n = A.getGlobalNumRows();
  if (A.getRowMap()->getComm()->getRank() != 0) return SparseMatrix(int(n), int(n));
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(rooted->getNodeNumEntries() / 2 + n);
  const auto rowMap = rooted->getRowMap();
  const auto colMap = rooted->getColMap();
  linalg::Matrix::local_inds_host_view_type cols;
  linalg::Matrix::values_host_view_type vals;
  for (std::size_t r = 0; r < rooted->getNodeNumRows(); ++r) {
    const GlobalIndex gr = rowMap->getGlobalElement(r);
    rooted->getLocalRowView(r, cols, vals);
    for (std::size_t k = 0; k < cols.extent(0); ++k) {
      const GlobalIndex gc = colMap->getGlobalElement(cols(k));
      if (gc >= gr) entries.emplace_back(int(gc), int(gr), vals(k));  // (row >= col): lower
    }
  }
  SparseMatrix L{static_cast<int>(n), static_cast<int>(n)};
  L.setFromTriplets(entries.begin(), entries.end());
  return L;
}

}  // namespace

// CHOLMOD's own estimate (min/max diagonal of L, squared): a singular matrix
// can factor "successfully" with round-off pivots (e.g. a free body whose
// rigid-body pivots come out 1e-16 positive), which the estimate exposes.
struct CholmodWithConditionEstimate : Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> {
  double rcond() { return m_cholmodFactor ? cholmod_rcond(m_cholmodFactor, &cholmod()) : 0.0; }
};

struct DirectSolver::Impl {
  Teuchos::RCP<const linalg::Map> rowMap, rootMap;
  Teuchos::RCP<const Tpetra::Export<>> exporter;  // null on one rank
  CholmodWithConditionEstimate cholmod;
  Statistics stats;
  bool root = true;
};

DirectSolver::DirectSolver(const linalg::Matrix& A, const linalg::Matrix* B, double sigma)
    : impl_(std::make_unique<Impl>()) {
  auto& I = *impl_;
  Timer timer;
  I.rowMap = A.getRowMap();
  const auto comm = I.rowMap->getComm();
  const GlobalIndex n = A.getGlobalNumRows();
  I.root = comm->getRank() == 0;
  if (comm->getSize() > 1) {
    I.rootMap = Teuchos::rcp(new linalg::Map(n, I.root ? std::size_t(n) : 0, 0, comm));
    I.exporter = Teuchos::rcp(new Tpetra::Export<>(I.rowMap, I.rootMap));
  }
  SparseMatrix S = lowerTriangleOnRoot(A, I.rootMap, I.exporter);
  if (B && sigma != 0.0) S -= sigma * lowerTriangleOnRoot(*B, I.rootMap, I.exporter);
  I.stats.rows = n;
  I.stats.nonzerosA = S.nonZeros();
  I.stats.gatherSeconds = timer.seconds();

  timer.restart();
  int ok = 1;
  if (I.root) {
    I.cholmod.cholmod().supernodal = CHOLMOD_SUPERNODAL;
    I.cholmod.cholmod().print = 0;  // failures are reported by SolverError, not on stderr
    I.cholmod.compute(S);
    ok = I.cholmod.info() == Eigen::Success && I.cholmod.rcond() > 1e-24;
    I.stats.nonzerosFactor = I.cholmod.cholmod().lnz;
    I.stats.flops = I.cholmod.cholmod().fl;
  }
  Teuchos::broadcast(*comm, 0, &ok);
  I.stats.factorSeconds = timer.seconds();
  if (!ok)
    throw SolverError("CHOLMOD: the matrix (" + std::to_string(n) +
                      " equations) is not positive definite: a free body without enough constraints, "
                      "a shift above the lowest eigenvalue, or an inverted element");
}

DirectSolver::~DirectSolver() = default;

const DirectSolver::Statistics& DirectSolver::statistics() const { return impl_->stats; }

void DirectSolver::solve(const linalg::MultiVector& b, linalg::MultiVector& x) const {
  const auto& I = *impl_;
  const std::size_t nv = b.getNumVectors();
  Teuchos::RCP<const linalg::MultiVector> bRoot = Teuchos::rcpFromRef(b);
  Teuchos::RCP<linalg::MultiVector> xRoot = Teuchos::rcpFromRef(x);
  if (I.exporter) {
    auto gathered = Teuchos::rcp(new linalg::MultiVector(I.rootMap, nv));
    gathered->doExport(b, *I.exporter, Tpetra::INSERT);
    bRoot = gathered;
    xRoot = Teuchos::rcp(new linalg::MultiVector(I.rootMap, nv));
  }
  if (I.root) {
    const int n = int(I.stats.rows);
    Eigen::MatrixXd rhs(n, nv);
    for (std::size_t j = 0; j < nv; ++j) {
      auto col = bRoot->getData(j);
      for (int i = 0; i < n; ++i) rhs(i, j) = col[i];
    }
    const Eigen::MatrixXd sol = I.cholmod.solve(rhs);
    for (std::size_t j = 0; j < nv; ++j) {
      auto col = xRoot->getDataNonConst(j);
      for (int i = 0; i < n; ++i) col[i] = sol(i, j);
    }
  }
  if (I.exporter) x.doImport(*xRoot, *I.exporter, Tpetra::INSERT);  // reverse mode: scatter back
}

}  // namespace cyclone::solvers
