#pragma once
// The eigenvalues of smallest modulus of a complex matrix A, given by the action of its
// inverse: ARPACK's implicitly restarted Arnoldi (znaupd) on A^{-1}, whose largest
// eigenvalues 1 / mu are A's nearest zero (shift-invert at zero). Hill's method wants only
// the Floquet exponents, a strip about the imaginary axis, of the thousands of
// eigenvalues a disc's Hill problem has (ReceptanceHill.cpp).
#include <Eigen/Dense>
#include <complex>
#include <functional>

namespace cyclone::hbm {

struct EigenvaluesNearZero {
  Eigen::VectorXcd values;  ///< the converged eigenvalues of A, by increasing modulus
  bool converged = false;   ///< all nev of them converged
  int operations = 0;       ///< applications of A^{-1}
};

/// y = A^{-1} x for n complex values.
using InverseAction = std::function<void(const std::complex<double>* x, std::complex<double>* y)>;

/// The nev (1 <= nev <= n - 2) eigenvalues of A nearest zero, to `tolerance` relative to
/// each; ARPACK's start vector is fixed (the same answer on every call). Error when
/// ARPACK reports a failure other than running out of restarts (then converged = false
/// and the values are those that did converge).
EigenvaluesNearZero eigenvaluesNearZero(int n, int nev, const InverseAction& applyInverse, double tolerance = 1e-12,
                                        int maxRestarts = 500);

}  // namespace cyclone::hbm
