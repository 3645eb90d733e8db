#include "EigenvaluesNearZero.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cyclone/core/Error.hpp"

// ARPACK-NG's C++ interface (its own translation unit: arpack.hpp brings C's complex.h).
#include <arpack.hpp>

namespace cyclone::hbm {

EigenvaluesNearZero eigenvaluesNearZero(int n, int nev, const InverseAction& applyInverse, double tolerance,
                                        int maxRestarts) {
  using cd = std::complex<double>;
  if (n < 3 || nev < 1 || nev > n - 2)
    throw Error("eigenvaluesNearZero: " + std::to_string(nev) + " eigenvalues of " + std::to_string(n) +
                " (ARPACK needs 1 <= nev <= n - 2)");
  // A Krylov space of about twice the wanted count: ARPACK's advice, few restarts.
  const a_int N = n, NEV = nev, ncv = std::min<a_int>(N, std::max<a_int>(2 * NEV + 1, NEV + 20));
  const a_int lworkl = 3 * ncv * ncv + 5 * ncv;
  std::vector<cd> resid(static_cast<std::size_t>(N)), v(static_cast<std::size_t>(N * ncv)),
      workd(static_cast<std::size_t>(3 * N)), workl(static_cast<std::size_t>(lworkl)),
      workev(static_cast<std::size_t>(2 * ncv)), d(static_cast<std::size_t>(NEV + 1));
  std::vector<double> rwork(static_cast<std::size_t>(ncv));
  std::vector<a_int> select(static_cast<std::size_t>(ncv), 0);
  // A fixed start (info = 1): ARPACK's own random start continues one stream over the
  // whole run, so the same point's exponents would differ at the tolerance with what was
  // computed before it.
  for (a_int i = 0; i < N; ++i) resid[std::size_t(i)] = cd(1.0 + 0.5 * std::sin(0.7 * double(i)), std::cos(1.3 * double(i)));
  a_int iparam[11] = {0}, ipntr[14] = {0};
  iparam[0] = 1;  // exact shifts
  iparam[2] = maxRestarts;
  iparam[6] = 1;  // A x = lambda x with the operator given (here A^{-1})
  a_int ido = 0, info = 1;
  EigenvaluesNearZero out;
  for (;;) {
    arpack::naupd(ido, arpack::bmat::identity, N, arpack::which::largest_magnitude, NEV, tolerance, resid.data(), ncv,
                  v.data(), N, iparam, ipntr, workd.data(), workl.data(), lworkl, rwork.data(), info);
    if (ido != -1 && ido != 1) break;
    applyInverse(&workd[std::size_t(ipntr[0] - 1)], &workd[std::size_t(ipntr[1] - 1)]);
    ++out.operations;
  }
  if (info < 0 || (info != 0 && info != 1))
    throw Error("ARPACK znaupd failed (info " + std::to_string(info) + ") on " + std::to_string(n) + " unknowns");
  const a_int nconv = iparam[4];
  out.converged = info == 0 && nconv >= NEV;
  if (nconv == 0) return out;
  a_int einfo = 0;
  arpack::neupd(0, arpack::howmny::ritz_vectors, select.data(), d.data(), v.data(), N, cd(0), workev.data(),
                arpack::bmat::identity, N, arpack::which::largest_magnitude, NEV, tolerance, resid.data(), ncv,
                v.data(), N, iparam, ipntr, workd.data(), workl.data(), lworkl, rwork.data(), einfo);
  if (einfo != 0) throw Error("ARPACK zneupd failed (info " + std::to_string(einfo) + ")");
  std::vector<cd> mu;
  for (a_int i = 0; i < std::min(nconv, NEV); ++i) mu.push_back(1.0 / d[std::size_t(i)]);
  std::sort(mu.begin(), mu.end(), [](const cd& a, const cd& b) { return std::abs(a) < std::abs(b); });
  out.values = Eigen::Map<Eigen::VectorXcd>(mu.data(), Eigen::Index(mu.size()));
  return out;
}

}  // namespace cyclone::hbm
