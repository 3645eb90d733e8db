#include "cyclone/solvers/LinearSolver.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include <algorithm>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/solvers/DirectSolver.hpp"

namespace cyclone::solvers {

LinearSolverKind linearSolverKindFromName(const std::string& name, const std::string& where) {
  if (name == "direct") return LinearSolverKind::Direct;
  if (name == "iterative") return LinearSolverKind::Iterative;
  throw InputError(where, "unknown linear solver '" + name + "' (use 'direct' or 'iterative')");
}

double relativeResidual(const linalg::Matrix& K, const linalg::MultiVector& b, const linalg::MultiVector& x) {
  linalg::MultiVector r(b, Teuchos::Copy);
  K.apply(x, r, Teuchos::NO_TRANS, -1.0, 1.0);
  std::vector<double> rn(b.getNumVectors()), bn(b.getNumVectors());
  r.norm2(rn);
  b.norm2(bn);
  double worst = 0;
  for (std::size_t j = 0; j < rn.size(); ++j) worst = std::max(worst, bn[j] > 0 ? rn[j] / bn[j] : rn[j]);
  return worst;
}

LinearSolveReport solveLinear(const linalg::Matrix& K, const linalg::MultiVector& b, linalg::MultiVector& x,
                              const LinearSolveOptions& options) {
  if (options.kind == LinearSolverKind::Iterative) return solveIterative(K, b, x, options);
  LinearSolveReport report;
  Timer timer;
  DirectSolver solver(K);
  report.setupSeconds = timer.seconds();
  timer.restart();
  solver.solve(b, x);
  report.solveSeconds = timer.seconds();
  report.relativeResidual = relativeResidual(K, b, x);
  if (!(report.relativeResidual < 1e-6))
    throw SolverError("direct solve: relative residual " + std::to_string(report.relativeResidual) +
                      " after factorization (matrix nearly singular?)");
  return report;
}

}  // namespace cyclone::solvers
