#include "cyclone/continuation/NewtonSolve.hpp"

#include <Eigen/LU>

#include "cyclone/continuation/DenseLu.hpp"
#include "cyclone/continuation/KrylovSolve.hpp"

namespace cyclone::continuation {

NewtonResult solveNewton(const ContinuationProblem& problem, Eigen::VectorXd& x, double p, double tolerance,
                         int maxIterations, DenseLu* lastFactors, ContinuationOptions::LinearSolver linearSolver) {
  NewtonResult r;
  Eigen::VectorXd F, Ft;
  Eigen::MatrixXd J;
  ContinuationOptions choice;
  choice.linearSolver = linearSolver;
  const bool krylov = useKrylov(problem, choice);
  try {
    problem.residual(x, p, F);
    for (; r.iterations < maxIterations; ++r.iterations) {
      if (F.norm() <= tolerance) break;
      Eigen::VectorXd dx;
      if (krylov) {
        // GMRES on the operator; a step it cannot solve ends Newton (not converged).
        const std::shared_ptr<JacobianOperator> op = problem.jacobianOperator(x, p);
        op->preparePreconditioner();
        const Eigen::VectorXd minusF = -F;
        const KrylovResult k = solveKrylov([&op](const Eigen::VectorXd& v, Eigen::VectorXd& y) { op->apply(v, y); },
                                           [&op](const Eigen::VectorXd& v, Eigen::VectorXd& y) { op->precondition(v, y); },
                                           minusF, dx, choice.krylov);
        r.krylovIterations += k.iterations;
        if (!k.converged) break;
      } else {
        problem.jacobian(x, p, J);
        // Partial pivoting (LAPACK, several times faster than full pivoting at the
        // harmonic balance's sizes); full pivoting only when J is singular to it.
        DenseLu local;
        DenseLu& lu = lastFactors ? *lastFactors : local;
        lu.compute(J);
        dx = lu.solve(-F);
        if (!dx.allFinite()) dx = J.fullPivLu().solve(-F);
      }
      double step = 1.0;
      for (int k = 0;; ++k, step *= 0.5) {  // backtracking: accept the first sufficient decrease
        problem.residual(x + step * dx, p, Ft);
        if (Ft.allFinite() && Ft.norm() < (1 - 1e-4 * step) * F.norm()) break;
        if (k == 30) {  // stagnation (e.g. a spurious minimum of ||F|| at the kinks of a nonsmooth
          r.residualNorm = F.norm();  // system): more iterations would not leave it
          return r;
        }
      }
      x += step * dx;
      F = Ft;
    }
  } catch (...) {
    r.residualNorm = F.size() ? F.norm() : 0.0;
    return r;
  }
  r.residualNorm = F.norm();
  r.converged = r.residualNorm <= tolerance;
  return r;
}

}  // namespace cyclone::continuation
