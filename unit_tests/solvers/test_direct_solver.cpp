// The direct and iterative solvers against a dense LAPACK-grade solve (Eigen
// LLT) of the same assembled stiffness.
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <gtest/gtest.h>

#include <cstdio>

#include <Eigen/Eigenvalues>
#include <complex>

#include "BoxMesh.hpp"
#include "cyclone/fe/Assembler.hpp"
#include "cyclone/solvers/DirectSolver.hpp"
#include "cyclone/solvers/LinearSolver.hpp"

using namespace cyclone;

namespace {

Eigen::MatrixXd toDense(const linalg::Matrix& A) {
  const int n = int(A.getGlobalNumRows());
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, n);
  linalg::Matrix::global_inds_host_view_type cols;
  linalg::Matrix::values_host_view_type vals;
  for (int r = 0; r < n; ++r) {
    std::size_t len = A.getNumEntriesInGlobalRow(r);
    linalg::Matrix::nonconst_global_inds_host_view_type c("c", len);
    linalg::Matrix::nonconst_values_host_view_type v("v", len);
    A.getGlobalRowCopy(r, c, v, len);
    for (std::size_t k = 0; k < len; ++k) D(r, c(k)) = v(k);
  }
  return D;
}

struct Cantilever {
  mesh::Mesh mesh = test_support::makeBoxMesh(4.0, 1.0, 1.0, 4, 1, 1, mesh::ElementType::Tet10);
  fe::IsotropicElastic steel{"steel", 2.1e5, 0.3, 7.85e-9};
  fe::DofMap dofs{mesh.numNodes()};
  std::unique_ptr<fe::Assembler> assembler;
  Cantilever() {
    dofs.constrain(mesh.nodeSet("x0"));
    dofs.finalize();
    assembler = std::make_unique<fe::Assembler>(mesh, dofs, Teuchos::rcp(new Teuchos::SerialComm<int>));
  }
};

}  // namespace

TEST(DirectSolver, MatchesDenseCholeskyOnAssembledStiffness) {
  Cantilever c;
  auto K = c.assembler->stiffness(c.steel);
  linalg::MultiVector b(c.assembler->map(), 3), x(c.assembler->map(), 3);
  b.randomize();
  solvers::DirectSolver solver(*K);
  solver.solve(b, x);

  const Eigen::MatrixXd D = toDense(*K);
  ASSERT_LT((D - D.transpose()).norm(), 1e-12 * D.norm()) << "assembled stiffness is not symmetric";
  Eigen::MatrixXd B(D.rows(), 3), X(D.rows(), 3);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < D.rows(); ++i) B(i, j) = b.getData(j)[i], X(i, j) = x.getData(j)[i];
  const Eigen::MatrixXd reference = D.llt().solve(B);
  EXPECT_LT((X - reference).norm() / reference.norm(), 1e-10);
  EXPECT_GT(solver.statistics().nonzerosFactor, 0);
}

TEST(DirectSolver, ShiftedFactorizationSolvesKMinusSigmaM) {
  Cantilever c;
  auto K = c.assembler->stiffness(c.steel);
  auto M = c.assembler->mass(c.steel);
  const double sigma = -1.0e6;
  linalg::MultiVector b(c.assembler->map(), 1), x(c.assembler->map(), 1);
  b.randomize();
  solvers::DirectSolver solver(*K, M.get(), sigma);
  solver.solve(b, x);
  const Eigen::MatrixXd A = toDense(*K) - sigma * toDense(*M);
  Eigen::VectorXd B(A.rows()), X(A.rows());
  for (int i = 0; i < A.rows(); ++i) B(i) = b.getData(0)[i], X(i) = x.getData(0)[i];
  EXPECT_LT((A * X - B).norm() / B.norm(), 1e-10);
}

TEST(DirectSolver, IndefiniteShiftBetweenEigenvalues) {
  Cantilever c;
  auto K = c.assembler->stiffness(c.steel);
  auto M = c.assembler->mass(c.steel);
  const Eigen::MatrixXd Kd = toDense(*K), Md = toDense(*M);
  const Eigen::VectorXd lambda = Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(Kd, Md).eigenvalues();
  const double sigma = 0.5 * (lambda(2) + lambda(3));  // three negative pivots
  EXPECT_THROW(solvers::DirectSolver(*K, M.get(), sigma), SolverError);
  solvers::DirectSolver solver(*K, M.get(), sigma, solvers::DirectSolver::Definiteness::Indefinite);
  linalg::MultiVector b(c.assembler->map(), 2), x(c.assembler->map(), 2);
  b.randomize();
  solver.solve(b, x);
  const Eigen::MatrixXd A = Kd - sigma * Md;
  Eigen::MatrixXd B(A.rows(), 2), X(A.rows(), 2);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < A.rows(); ++i) B(i, j) = b.getData(j)[i], X(i, j) = x.getData(j)[i];
  const Eigen::MatrixXd reference = A.lu().solve(B);
  EXPECT_LT((X - reference).norm() / reference.norm(), 1e-9);
}

TEST(ComplexDirectSolver, MatchesDenseComplexLu) {
  Cantilever c;
  auto K = c.assembler->stiffness(c.steel);
  auto M = c.assembler->mass(c.steel);
  const Eigen::MatrixXd Kd = toDense(*K), Md = toDense(*M);
  const double lambda1 = Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(Kd, Md).eigenvalues()(0);
  const std::complex<double> a(1.0, 0.01), b(-1.001 * lambda1, 0.0);  // just above the first resonance
  solvers::ComplexDirectSolver solver(*K, a, *M, b);
  linalg::MultiVector f(c.assembler->map(), 3), xr(c.assembler->map(), 3), xi(c.assembler->map(), 3);
  f.randomize();
  solver.solve(f, xr, xi);
  const Eigen::MatrixXcd A = a * Kd.cast<std::complex<double>>() + b * Md.cast<std::complex<double>>();
  Eigen::MatrixXcd F(A.rows(), 3), X(A.rows(), 3);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < A.rows(); ++i)
      F(i, j) = f.getData(j)[i], X(i, j) = {xr.getData(j)[i], xi.getData(j)[i]};
  const Eigen::MatrixXcd reference = A.partialPivLu().solve(F);
  EXPECT_LT((X - reference).norm() / reference.norm(), 1e-9);
}

namespace {

// A Tpetra matrix of a dense one's nonzeros.
Teuchos::RCP<linalg::Matrix> sparseOf(const Eigen::MatrixXd& dense, const Teuchos::RCP<const linalg::Comm>& comm) {
  const Eigen::Index n = dense.rows();
  auto map = Teuchos::rcp(new linalg::Map(n, 0, comm));
  auto A = Teuchos::rcp(new linalg::Matrix(map, std::size_t(n)));
  for (Eigen::Index r = 0; r < n; ++r)
    for (Eigen::Index c = 0; c < n; ++c)
      if (dense(r, c) != 0) A->insertGlobalValues(r, Teuchos::tuple<linalg::GlobalIndex>(c), Teuchos::tuple(dense(r, c)));
  A->fillComplete();
  return A;
}

// A cyclic real form [[P, -Q], [Q, P]] with interleaved pairs (2m, 2m+1) = (a, b):
// P symmetric (the cantilever's matrix), Q antisymmetric on P's pattern.
Teuchos::RCP<linalg::Matrix> pairedRealForm(const Eigen::MatrixXd& P, double q,
                                            const Teuchos::RCP<const linalg::Comm>& comm, Eigen::MatrixXd& dense) {
  const Eigen::Index n = P.rows();
  Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = i + 1; j < n; ++j) Q(i, j) = q * P(i, j) * (1 + 0.1 * double((i + 3 * j) % 7)), Q(j, i) = -Q(i, j);
  dense.setZero(2 * n, 2 * n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) {
      dense(2 * i, 2 * j) = dense(2 * i + 1, 2 * j + 1) = P(i, j);
      dense(2 * i + 1, 2 * j) = Q(i, j);
      dense(2 * i, 2 * j + 1) = -Q(i, j);
    }
  return sparseOf(dense, comm);
}

// The paired real form of U P U^H, U = diag(exp(i theta_m)): Hermitian with P's
// eigenvalues (P positive definite: so is it), P's pattern, and an imaginary part
// sin(theta_m - theta_n) P(m, n) that is not small.
Teuchos::RCP<linalg::Matrix> rotatedPairedRealForm(const Eigen::MatrixXd& P, const Teuchos::RCP<const linalg::Comm>& comm,
                                                   Eigen::MatrixXd& dense) {
  const Eigen::Index n = P.rows();
  dense.setZero(2 * n, 2 * n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) {
      const double t = 0.7 * double(i % 5) - 0.4 * double(j % 3) - (0.7 * double(j % 5) - 0.4 * double(i % 3));
      const double re = std::cos(t) * P(i, j), im = std::sin(t) * P(i, j);
      dense(2 * i, 2 * j) = dense(2 * i + 1, 2 * j + 1) = re;
      dense(2 * i + 1, 2 * j) = im;
      dense(2 * i, 2 * j + 1) = -im;
    }
  return sparseOf(dense, comm);
}

}  // namespace

// The forward/backward travelling-wave split (one half-size LU and its transpose
// solve) against a dense complex LU of the whole real form.
TEST(ComplexDirectSolver, TravellingWavePairsMatchDenseComplexLuOfTheRealForm) {
  Cantilever c;
  const Eigen::MatrixXd Kd = toDense(*c.assembler->stiffness(c.steel)), Md = toDense(*c.assembler->mass(c.steel));
  const auto comm = Teuchos::rcp(new Teuchos::SerialComm<int>);
  Eigen::MatrixXd Kr, Mr;
  const auto K = pairedRealForm(Kd, 0.3, comm, Kr);
  const auto M = pairedRealForm(Md, 0.2, comm, Mr);
  const double lambda1 = Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(Kr, Mr).eigenvalues()(0);
  const std::complex<double> a(1.0, 0.01), b(-1.001 * lambda1, 0.0);
  const solvers::ComplexDirectSolver wave(*K, a, *M, b, solvers::ComplexDirectSolver::Structure::TravellingWavePairs);
  linalg::MultiVector f(K->getRowMap(), 3), xr(K->getRowMap(), 3), xi(K->getRowMap(), 3);
  f.randomize();
  wave.solve(f, xr, xi);
  const Eigen::MatrixXcd A = a * Kr.cast<std::complex<double>>() + b * Mr.cast<std::complex<double>>();
  Eigen::MatrixXcd F(A.rows(), 3), X(A.rows(), 3);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < A.rows(); ++i) F(i, j) = f.getData(j)[i], X(i, j) = {xr.getData(j)[i], xi.getData(j)[i]};
  const Eigen::MatrixXcd reference = A.partialPivLu().solve(F);
  EXPECT_LT((X - reference).norm() / reference.norm(), 1e-9);
  // An odd count cannot pair.
  auto map3 = Teuchos::rcp(new linalg::Map(3, 0, comm));
  auto I3 = Teuchos::rcp(new linalg::Matrix(map3, 1));
  for (int r = 0; r < 3; ++r) I3->insertGlobalValues(r, Teuchos::tuple<linalg::GlobalIndex>(r), Teuchos::tuple(1.0));
  I3->fillComplete();
  EXPECT_THROW(solvers::ComplexDirectSolver(*I3, a, *I3, b, solvers::ComplexDirectSolver::Structure::TravellingWavePairs),
               SolverError);
}

// The real solve of a paired real form by the Hermitian half's complex Cholesky
// (DirectSolver::Structure::TravellingWavePairs) against a dense solve of the real form,
// with a shift; a quarter of the real form factor's entries (complex: half its memory).
// The matrices are the real forms of U P U^H (the cantilever's K and M). Not positive
// definite (a shift above the first eigenvalue): refused like the real LL^T.
TEST(DirectSolver, TravellingWavePairsFactorTheHermitianHalf) {
  Cantilever c;
  const Eigen::MatrixXd Kd = toDense(*c.assembler->stiffness(c.steel)), Md = toDense(*c.assembler->mass(c.steel));
  const auto comm = Teuchos::rcp(new Teuchos::SerialComm<int>);
  Eigen::MatrixXd Kr, Mr;
  const auto K = rotatedPairedRealForm(Kd, comm, Kr);
  const auto M = rotatedPairedRealForm(Md, comm, Mr);
  const double lambda1 = Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(Kr, Mr).eigenvalues()(0);
  const double sigma = -0.5 * lambda1;
  const solvers::DirectSolver real(*K, M.get(), sigma);
  const solvers::DirectSolver wave(*K, M.get(), sigma, solvers::DirectSolver::Definiteness::Positive,
                                   solvers::DirectSolver::Structure::TravellingWavePairs);
  linalg::MultiVector f(K->getRowMap(), 3), x(K->getRowMap(), 3), y(K->getRowMap(), 3);
  f.randomize();
  wave.solve(f, x);
  real.solve(f, y);
  const Eigen::MatrixXd A = Kr - sigma * Mr;
  Eigen::MatrixXd F(A.rows(), 3), X(A.rows(), 3), Y(A.rows(), 3);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < A.rows(); ++i) F(i, j) = f.getData(j)[i], X(i, j) = x.getData(j)[i], Y(i, j) = y.getData(j)[i];
  const Eigen::MatrixXd reference = A.ldlt().solve(F);
  const double error = (X - reference).norm() / reference.norm();
  EXPECT_LT(error, 1e-10);
  EXPECT_LT((Y - reference).norm() / reference.norm(), 1e-10);
  std::printf("paired %.1e, real %.1e from the dense solve; factor entries %.0f complex against %.0f real\n", error,
              (Y - reference).norm() / reference.norm(), wave.statistics().nonzerosFactor,
              real.statistics().nonzerosFactor);
  EXPECT_LT(wave.statistics().nonzerosFactor, 0.5 * real.statistics().nonzerosFactor);
  EXPECT_THROW(solvers::DirectSolver(*K, M.get(), 1.5 * lambda1, solvers::DirectSolver::Definiteness::Positive,
                                     solvers::DirectSolver::Structure::TravellingWavePairs),
               SolverError);
}

TEST(DirectSolver, UnconstrainedStiffnessIsReportedNotPositiveDefinite) {
  auto mesh = test_support::makeBoxMesh(1.0, 1.0, 1.0, 1, 1, 1, mesh::ElementType::Hex8);
  fe::DofMap dofs(mesh.numNodes());
  dofs.finalize();
  fe::Assembler assembler(mesh, dofs, Teuchos::rcp(new Teuchos::SerialComm<int>));
  auto K = assembler.stiffness(fe::IsotropicElastic{});
  EXPECT_THROW(solvers::DirectSolver solver(*K), SolverError);
}

// The same free body as the travelling-wave pairs' real form (the Hermitian form of a
// free sector's two-copy nodal diameter has its rigid-body modes): refused as the real
// form is, not factored with a pivot of the rounding's size (the modal solver's
// automatic shift then stayed at 0 and its vectors did not span the eigenvalues).
TEST(DirectSolver, UnconstrainedTravellingWavePairsAreReportedNotPositiveDefinite) {
  auto mesh = test_support::makeBoxMesh(1.0, 1.0, 2.0, 4, 4, 8, mesh::ElementType::Hex8);
  fe::DofMap dofs(mesh.numNodes());
  dofs.finalize();
  fe::Assembler assembler(mesh, dofs, Teuchos::rcp(new Teuchos::SerialComm<int>));
  const Eigen::MatrixXd Kd = toDense(*assembler.stiffness(fe::IsotropicElastic{}));
  const auto comm = Teuchos::rcp(new Teuchos::SerialComm<int>);
  Eigen::MatrixXd Kr;
  const auto K = rotatedPairedRealForm(Kd, comm, Kr);
  EXPECT_THROW(solvers::DirectSolver real(*K), SolverError);
  EXPECT_THROW(solvers::DirectSolver wave(*K, nullptr, 0.0, solvers::DirectSolver::Definiteness::Positive,
                                          solvers::DirectSolver::Structure::TravellingWavePairs),
               SolverError);
}

// A Hermitian form whose smallest pivot is of the rounding's size (a rigid-body mode
// left by rounding) is refused by the paired path's condition bound (1e-14), which CHOLMOD
// alone passes; a well-conditioned one is factored.
TEST(DirectSolver, TravellingWavePairsSingularToRoundingAreRefused) {
  const auto comm = Teuchos::rcp(new Teuchos::SerialComm<int>);
  Eigen::MatrixXd P = Eigen::MatrixXd::Identity(6, 6), Pr;
  P(5, 5) = 1e-17;
  const auto nearlySingular = rotatedPairedRealForm(P, comm, Pr);
  EXPECT_THROW(solvers::DirectSolver wave(*nearlySingular, nullptr, 0.0, solvers::DirectSolver::Definiteness::Positive,
                                          solvers::DirectSolver::Structure::TravellingWavePairs),
               SolverError);
  P(5, 5) = 1e-6;
  const auto conditioned = rotatedPairedRealForm(P, comm, Pr);
  const solvers::DirectSolver wave(*conditioned, nullptr, 0.0, solvers::DirectSolver::Definiteness::Positive,
                                   solvers::DirectSolver::Structure::TravellingWavePairs);
  EXPECT_NEAR(wave.reciprocalCondition(), 1e-6, 1e-12);
}

TEST(IterativeSolver, AgreesWithDirectSolve) {
  Cantilever c;
  auto K = c.assembler->stiffness(c.steel);
  linalg::MultiVector b(c.assembler->map(), 1), xd(c.assembler->map(), 1), xi(c.assembler->map(), 1);
  b.randomize();
  solvers::LinearSolveOptions direct;
  solvers::solveLinear(*K, b, xd, direct);
  solvers::LinearSolveOptions iterative;
  iterative.kind = solvers::LinearSolverKind::Iterative;
  iterative.tolerance = 1e-12;
  iterative.nearNullSpace = c.assembler->rigidBodyModes();
  const auto report = solvers::solveLinear(*K, b, xi, iterative);
  EXPECT_GT(report.iterations, 0);
  xi.update(-1.0, xd, 1.0);
  EXPECT_LT(xi.getVector(0)->norm2() / xd.getVector(0)->norm2(), 1e-8);
}

