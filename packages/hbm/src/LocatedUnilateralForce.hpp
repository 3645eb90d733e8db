#pragma once
// The unilateral law's force samples with its contact instants located between the
// samples (UnilateralSpring, the FrictionContact's normal force).
#include <Eigen/Dense>

namespace cyclone::hbm::detail {

// The force samples of a unilateral law max(g, 0), g given per sample (a spring's
// k (w - gap), a friction contact's N0 + kn n), with the contact instants located between
// the samples. Each interval (i, i + 1) of the period gives half of each end's force, as
// the sampled law does, unless the contact opens or closes inside it: then it gives what
// makes the sum over the samples the exact integral of the force of the linearly
// interpolated motion (a closed part s = g_c / (g_c - g_o) of the interval), split so that
// every sample's force is continuous with a continuous derivative in the motion:
// g_c (2s - s^2) / 2 to the closed end, -g_c s (1 - s) / 2 to the open one. Without an
// instant inside an interval the force is the sampled law's. With the sampled law every
// instant crossing a sample put a kink into the residual, and an impact's kinks folded
// the curve into hairpins no continuation step passed (docs/solvers.md).
// visit(i, j, dfi/dgi, dfi/dgj, dfj/dgi, dfj/dgj) gets each interval's sensitivities.
template <class Visit>
void locatedUnilateralForce(const Eigen::VectorXd& g, Eigen::VectorXd& f, Visit&& visit) {
  const Eigen::Index n = g.size();
  f.setZero(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Index j = (i + 1) % n;
    const double a = g[i], b = g[j];
    if (a > 0 && b > 0) {
      f[i] += a / 2, f[j] += b / 2;
      visit(i, j, 0.5, 0.0, 0.0, 0.5);
    } else if (a > 0 || b > 0) {
      // c the closed end, o the open one (g_o <= 0 < g_c).
      const bool iClosed = a > 0;
      const double gc = iClosed ? a : b, go = iClosed ? b : a, d = gc - go, s = gc / d;
      const double dsdc = -go / (d * d), dsdo = gc / (d * d);
      const double toClosed = gc * (2 * s - s * s) / 2, toOpen = -gc * s * (1 - s) / 2;
      const double cc = (2 * s - s * s) / 2 + gc * (1 - s) * dsdc, co = gc * (1 - s) * dsdo;
      const double oc = -s * (1 - s) / 2 - gc * (1 - 2 * s) / 2 * dsdc, oo = -gc * (1 - 2 * s) / 2 * dsdo;
      if (iClosed) {
        f[i] += toClosed, f[j] += toOpen;
        visit(i, j, cc, co, oc, oo);
      } else {
        f[j] += toClosed, f[i] += toOpen;
        visit(i, j, oo, oc, co, cc);
      }
    }
  }
}

}  // namespace cyclone::hbm::detail
