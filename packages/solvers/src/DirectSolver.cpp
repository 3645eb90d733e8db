#include "cyclone/solvers/DirectSolver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>
#include <Eigen/UmfPackSupport>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/PeakMemory.hpp"
#include "cyclone/core/NumberText.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/solvers/SparseCholesky.hpp"

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

// The rows of a distributed problem gathered on rank 0 (no exporter on one rank).
struct RootGather {
  Teuchos::RCP<const linalg::Map> rowMap, rootMap;
  Teuchos::RCP<const Tpetra::Export<>> exporter;  // null on one rank
  bool root = true;

  explicit RootGather(const linalg::Matrix& A) : rowMap(A.getRowMap()) {
    const auto comm = rowMap->getComm();
    const GlobalIndex n = A.getGlobalNumRows();
    root = comm->getRank() == 0;
    if (comm->getSize() > 1) {
      rootMap = Teuchos::rcp(new linalg::Map(n, root ? std::size_t(n) : 0, 0, comm));
      exporter = Teuchos::rcp(new Tpetra::Export<>(rowMap, rootMap));
    }
  }
  SparseMatrix lower(const linalg::Matrix& A) const { return lowerTriangleOnRoot(A, rootMap, exporter); }

  /// The columns of b on rank 0 (n x nv; empty elsewhere).
  Eigen::MatrixXd columns(const linalg::MultiVector& b) const {
    const std::size_t nv = b.getNumVectors();
    Teuchos::RCP<const linalg::MultiVector> bRoot = Teuchos::rcpFromRef(b);
    if (exporter) {
      auto gathered = Teuchos::rcp(new linalg::MultiVector(rootMap, nv));
      gathered->doExport(b, *exporter, Tpetra::INSERT);
      bRoot = gathered;
    }
    if (!root) return {};
    const auto n = Eigen::Index(bRoot->getGlobalLength());
    Eigen::MatrixXd out(n, nv);
    for (std::size_t j = 0; j < nv; ++j) {
      auto col = bRoot->getData(j);
      for (Eigen::Index i = 0; i < n; ++i) out(i, j) = col[i];
    }
    return out;
  }
  /// Scatters columns held on rank 0 into x (x's row map).
  void scatter(const Eigen::MatrixXd& values, linalg::MultiVector& x) const {
    const std::size_t nv = x.getNumVectors();
    Teuchos::RCP<linalg::MultiVector> xRoot = Teuchos::rcpFromRef(x);
    if (exporter) xRoot = Teuchos::rcp(new linalg::MultiVector(rootMap, nv));
    if (root)
      for (std::size_t j = 0; j < nv; ++j) {
        auto col = xRoot->getDataNonConst(j);
        for (Eigen::Index i = 0; i < values.rows(); ++i) col[i] = values(i, j);
      }
    if (exporter) x.doImport(*xRoot, *exporter, Tpetra::INSERT);  // reverse mode: scatter back
  }
};

}  // namespace

// CHOLMOD's own estimate (min/max diagonal of L, squared): a singular matrix
// can factor "successfully" with round-off pivots (e.g. a free body whose
// rigid-body pivots come out 1e-16 positive), which the estimate exposes.
// For LDL^T it is min/max |D|, for LL^T (min/max diag L)^2.
struct CholmodWithConditionEstimate : Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower> {
  double rcond() { return m_cholmodFactor ? cholmod_rcond(m_cholmodFactor, &cholmod()) : 0.0; }
};

using ComplexSparse = Eigen::SparseMatrix<std::complex<double>, Eigen::ColMajor, int>;

namespace {

// The lower triangle of the Hermitian H = P + iQ from the lower triangle of its paired
// real form [[P, -Q], [Q, P]] (pairs (2m, 2m+1)): H(m, n) = A(2m, 2n) + i A(2m+1, 2n),
// both in the real form's lower triangle where m >= n. A's storage is released as it is
// read (the real form's matrix is the largest thing held beside the factor).
ComplexSparse hermitianOfPairs(SparseMatrix&& lower) {
  std::vector<Eigen::Triplet<std::complex<double>, int>> entries;
  entries.reserve(std::size_t(lower.nonZeros() / 4 + lower.cols()));
  for (int col = 0; col < lower.outerSize(); col += 2)
    for (SparseMatrix::InnerIterator it(lower, col); it; ++it)
      entries.emplace_back(it.row() / 2, col / 2,
                           it.row() % 2 == 0 ? std::complex<double>(it.value(), 0) : std::complex<double>(0, it.value()));
  const int n = int(lower.rows() / 2);
  SparseMatrix().swap(lower);
  ComplexSparse H(n, n);
  H.setFromTriplets(entries.begin(), entries.end());
  return H;
}

}  // namespace

struct DirectSolver::Impl {
  explicit Impl(const linalg::Matrix& A) : gather(A) {}
  RootGather gather;
  CholmodWithConditionEstimate cholmod;
  std::unique_ptr<SparseCholesky<std::complex<double>>> paired;  // TravellingWavePairs: the factor of H
  Statistics stats;
  double rcond = 0;
};

DirectSolver::DirectSolver(const linalg::Matrix& A, const linalg::Matrix* B, double sigma,
                           Definiteness definiteness, Structure structure)
    : impl_(std::make_unique<Impl>(A)) {
  auto& I = *impl_;
  Timer timer;
  const auto comm = I.gather.rowMap->getComm();
  const GlobalIndex n = A.getGlobalNumRows();
  SparseMatrix S = I.gather.lower(A);
  if (B && sigma != 0.0) S -= sigma * I.gather.lower(*B);
  I.stats.rows = n;
  I.stats.nonzerosA = S.nonZeros();
  I.stats.gatherSeconds = timer.seconds();

  timer.restart();
  const bool positive = definiteness == Definiteness::Positive;
  if (positive && structure == Structure::TravellingWavePairs) {
    if (n % 2 != 0)
      throw SolverError("travelling-wave solve: an odd number of equations (" + std::to_string(n) + ") cannot pair");
    std::string failure;
    if (I.gather.root) {
      try {
        I.paired = std::make_unique<SparseCholesky<std::complex<double>>>(hermitianOfPairs(std::move(S)));
        I.stats.nonzerosFactor = I.paired->factorNonzeros();
        I.stats.flops = I.paired->factorFlops();
        I.rcond = I.paired->reciprocalCondition();
        // A singular H (a free sector's two-copy nodal diameter holds rigid-body modes)
        // can factor with a last pivot of the rounding's size where the real form's
        // factor fails: refused below 1e-14 of the largest pivot (a held sector's
        // smallest is about 1e-4 of it on the default disc, and falls like the element
        // size squared), so a caller's search for a shift is not misled.
        if (I.rcond < 1e-14) failure = "CHOLMOD: the matrix (" + std::to_string(n) +
                                       " equations) is singular to its rounding (pivots down to " +
                                       std::to_string(I.rcond) + " of the largest): a free body";
      } catch (const SolverError& e) {
        failure = e.what();
      }
    }
    int ok = failure.empty();
    Teuchos::broadcast(*comm, 0, &ok);
    Teuchos::broadcast(*comm, 0, &I.rcond);
    I.stats.factorSeconds = timer.seconds();
    if (!ok)
      throw SolverError(failure.empty() ? "CHOLMOD: the matrix (" + std::to_string(n) +
                                              " equations) is not positive definite"
                                        : failure);
    return;
  }
  int ok = 1;
  std::string shortfall;  // the address space's, said before OpenBLAS would wait for it
  if (I.gather.root) {
    I.cholmod.setMode(positive ? Eigen::CholmodSupernodalLLt : Eigen::CholmodLDLt);
    I.cholmod.cholmod().print = 0;  // failures are reported by SolverError, not on stderr
    I.cholmod.analyzePattern(S);
    try {
      checkFactorAddressSpace(n, double(I.cholmod.cholmod().lnz), int(sizeof(double)), positive);
    } catch (const SolverError& e) {
      shortfall = e.what();
    }
    if (shortfall.empty()) {
      I.cholmod.factorize(S);
      I.rcond = I.cholmod.rcond();
      // min/max pivot of D (LDL^T) or of diag(L)^2 (LL^T): the same measure.
      ok = I.cholmod.info() == Eigen::Success && I.rcond > 1e-24;
      // Out of memory leaves a partial factor, which read as "not positive definite" (a
      // process limited to 700 MB; issue 49 probe): said as what it is.
      if (I.cholmod.cholmod().status == CHOLMOD_OUT_OF_MEMORY) ok = -1;
      if (ok > 0 && positive) noteFactorizationPassed();
    } else {
      ok = -2;
    }
    I.stats.nonzerosFactor = I.cholmod.cholmod().lnz;
    I.stats.flops = I.cholmod.cholmod().fl;
  }
  Teuchos::broadcast(*comm, 0, &ok);
  Teuchos::broadcast(*comm, 0, &I.rcond);
  I.stats.factorSeconds = timer.seconds();
  if (ok == -2)
    throw SolverError(I.gather.root ? shortfall
                                    : "the factorization on rank 0 has no room under its address-space limit (ulimit "
                                      "-v; rank 0 says how much it needs)");
  if (ok < 0) throw SolverError(cholmodOutOfMemory(n));
  if (!ok && positive)
    throw SolverError("CHOLMOD: the matrix (" + std::to_string(n) +
                      " equations) is not positive definite: a free body without enough constraints, "
                      "a shift above the lowest eigenvalue, or an inverted element");
  if (!ok)
    throw SolverError("CHOLMOD LDL^T: the matrix (" + std::to_string(n) +
                      " equations) is singular: a shift on an eigenvalue or a free body at shift 0");
}

DirectSolver::~DirectSolver() = default;

const DirectSolver::Statistics& DirectSolver::statistics() const { return impl_->stats; }
double DirectSolver::reciprocalCondition() const { return impl_->rcond; }

void DirectSolver::solve(const linalg::MultiVector& b, linalg::MultiVector& x) const {
  const auto& I = *impl_;
  const Eigen::MatrixXd rhs = I.gather.columns(b);
  if (!I.gather.root) return I.gather.scatter(Eigen::MatrixXd(), x);
  if (!I.paired) return I.gather.scatter(Eigen::MatrixXd(I.cholmod.solve(rhs)), x);
  // [x_a; x_b] pairs are the real and imaginary parts of H^{-1} (b_a + i b_b).
  const Eigen::Index half = rhs.rows() / 2;
  Eigen::MatrixXcd c(half, rhs.cols());
  for (Eigen::Index m = 0; m < half; ++m)
    for (Eigen::Index j = 0; j < rhs.cols(); ++j) c(m, j) = {rhs(2 * m, j), rhs(2 * m + 1, j)};
  const Eigen::MatrixXcd z = I.paired->solve(c);
  Eigen::MatrixXd out(rhs.rows(), rhs.cols());
  for (Eigen::Index m = 0; m < half; ++m)
    for (Eigen::Index j = 0; j < rhs.cols(); ++j) out(2 * m, j) = z(m, j).real(), out(2 * m + 1, j) = z(m, j).imag();
  I.gather.scatter(out, x);
}

namespace {

// UMFPACK's LU with its transpose solve (UMFPACK_Aat: Z^T x = b, no conjugate) on the same factors.
struct UmfPackWithTransposeSolve : Eigen::UmfPackLU<ComplexSparse> {
  // Why a factorization failed, in UMFPACK's own terms: a zero pivot is a singular
  // matrix, anything else is not (a seed-scale sector's 320k-equation LU ran out of
  // memory and was called singular), with the factor's size UMFPACK estimated.
  bool outOfMemory() const { return m_umfpackInfo(UMFPACK_STATUS) == UMFPACK_ERROR_out_of_memory; }
  std::string failure() const {
    const double status = m_umfpackInfo(UMFPACK_STATUS), unit = m_umfpackInfo(UMFPACK_SIZE_OF_UNIT);
    const double peakGb = m_umfpackInfo(UMFPACK_PEAK_MEMORY_ESTIMATE) * unit / 1e9;
    const std::string estimate =
        peakGb > 0 ? " (UMFPACK's estimate of its peak memory: " + numberText(peakGb, 3) + " GB; available: " +
                         numberText(availableMemoryMb() / 1e3, 3) + " GB)"
                   : "";
    if (status == UMFPACK_WARNING_singular_matrix) return "is singular";
    if (status == UMFPACK_ERROR_out_of_memory) return "could not be factored: out of memory" + estimate;
    return "could not be factored: UMFPACK status " + numberText(status) + estimate;
  }
  Eigen::MatrixXcd solveTransposed(const Eigen::MatrixXcd& b) const {
    Eigen::MatrixXcd x(b.rows(), b.cols());
    for (Eigen::Index j = 0; j < b.cols(); ++j)
      if (Eigen::umfpack_solve(UMFPACK_Aat, mp_matrix.outerIndexPtr(), mp_matrix.innerIndexPtr(), mp_matrix.valuePtr(),
                               x.col(j).data(), b.col(j).data(), m_numeric, m_control.data(), m_umfpackInfo.data()))
        throw SolverError("UMFPACK: the transposed solve failed");
    return x;
  }
};

// Full symmetric matrix from its lower triangle.
SparseMatrix symmetricFromLower(const SparseMatrix& L) {
  const SparseMatrix strictlyLower = L.triangularView<Eigen::StrictlyLower>();
  return L + SparseMatrix(strictlyLower.transpose());
}

// P + iQ of a paired real form [[P, -Q], [Q, P]] (pairs (2m, 2m+1)): the even rows and
// columns give P, the odd rows of the even columns give Q.
ComplexSparse forwardWave(const SparseMatrix& full) {
  std::vector<Eigen::Triplet<std::complex<double>, int>> entries;
  entries.reserve(std::size_t(full.nonZeros() / 2));
  for (int col = 0; col < full.outerSize(); col += 2)
    for (SparseMatrix::InnerIterator it(full, col); it; ++it)
      entries.emplace_back(it.row() / 2, col / 2,
                           it.row() % 2 == 0 ? std::complex<double>(it.value(), 0) : std::complex<double>(0, it.value()));
  ComplexSparse Z(full.rows() / 2, full.cols() / 2);
  Z.setFromTriplets(entries.begin(), entries.end());
  return Z;
}

}  // namespace

struct ComplexDirectSolver::Impl {
  explicit Impl(const linalg::Matrix& A) : gather(A) {}
  RootGather gather;
  bool wave = false;
  ComplexSparse matrix;  // UMFPACK's solve reads the matrix again: it must outlive lu
  UmfPackWithTransposeSolve lu;
};

ComplexDirectSolver::ComplexDirectSolver(const linalg::Matrix& A, std::complex<double> a, const linalg::Matrix& B,
                                         std::complex<double> b, Structure structure)
    : impl_(std::make_unique<Impl>(A)) {
  auto& I = *impl_;
  I.wave = structure == Structure::TravellingWavePairs;
  if (I.wave && A.getGlobalNumRows() % 2 != 0)
    throw SolverError("travelling-wave solve: an odd number of equations (" + std::to_string(A.getGlobalNumRows()) +
                      ") cannot pair");
  int ok = 1, outOfMemory = 0;
  std::string failureText = "could not be factored (on another rank)";
  const SparseMatrix LA = I.gather.lower(A), LB = I.gather.lower(B);
  if (I.gather.root) {
    const SparseMatrix FA = symmetricFromLower(LA), FB = symmetricFromLower(LB);
    I.matrix = I.wave ? ComplexSparse(a * forwardWave(FA) + b * forwardWave(FB))
                      : ComplexSparse(a * FA.cast<std::complex<double>>() + b * FB.cast<std::complex<double>>());
    // The pattern is symmetric: symmetric strategy with a METIS ordering of A + A^T.
    I.lu.umfpackControl()(UMFPACK_STRATEGY) = UMFPACK_STRATEGY_SYMMETRIC;
    I.lu.umfpackControl()(UMFPACK_ORDERING) = UMFPACK_ORDERING_METIS;
    I.lu.umfpackControl()(UMFPACK_IRSTEP) = 0;  // the residual is checked by the caller if needed
    I.lu.compute(I.matrix);
    ok = I.lu.info() == Eigen::Success;
    if (!ok) failureText = I.lu.failure(), outOfMemory = I.lu.outOfMemory() ? 1 : 0;
  }
  Teuchos::broadcast(*I.gather.rowMap->getComm(), 0, &outOfMemory);
  if (outOfMemory)
    throw OutOfMemoryError("UMFPACK: the complex matrix (" + std::to_string(A.getGlobalNumRows()) + " equations) " +
                           failureText);
  Teuchos::broadcast(*I.gather.rowMap->getComm(), 0, &ok);
  if (!ok)
    throw SolverError("UMFPACK: the complex matrix (" + std::to_string(A.getGlobalNumRows()) + " equations) " +
                      failureText);
}

ComplexDirectSolver::~ComplexDirectSolver() = default;

void ComplexDirectSolver::solve(const linalg::MultiVector& rhs, linalg::MultiVector& xReal,
                                linalg::MultiVector& xImag) const {
  const auto& I = *impl_;
  const Eigen::MatrixXd b = I.gather.columns(rhs);
  Eigen::MatrixXcd x;
  if (I.gather.root && !I.wave) {
    const Eigen::MatrixXcd bc = b.cast<std::complex<double>>();
    x = I.lu.solve(bc);
  } else if (I.gather.root) {
    const std::complex<double> i(0, 1);
    const Eigen::MatrixXcd bc = b.cast<std::complex<double>>();
    Eigen::MatrixXcd plus(b.rows() / 2, b.cols()), minus(b.rows() / 2, b.cols());
    for (Eigen::Index m = 0; m < plus.rows(); ++m) {
      plus.row(m) = 0.5 * (bc.row(2 * m) + i * bc.row(2 * m + 1));
      minus.row(m) = 0.5 * (bc.row(2 * m) - i * bc.row(2 * m + 1));
    }
    const Eigen::MatrixXcd up = I.lu.solve(plus), um = I.lu.solveTransposed(minus);
    if (I.lu.info() != Eigen::Success) throw SolverError("UMFPACK: the solve failed");
    x.resize(b.rows(), b.cols());
    for (Eigen::Index m = 0; m < plus.rows(); ++m) {
      x.row(2 * m) = up.row(m) + um.row(m);
      x.row(2 * m + 1) = -i * up.row(m) + i * um.row(m);
    }
  }
  I.gather.scatter(x.real(), xReal);
  I.gather.scatter(x.imag(), xImag);
}

}  // namespace cyclone::solvers
