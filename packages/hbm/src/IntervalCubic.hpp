#pragma once
// Cubics over one interval between two time samples, tau in [0, 1]: the Hermite
// interpolant of the samples' values and slopes, and the first instant a cubic
// crosses to a side (the located contact laws, LocatedFrictionForce).
#include <algorithm>
#include <array>
#include <cmath>

namespace cyclone::hbm::detail {

inline constexpr double pi = 3.14159265358979323846;

// A cubic in an interval's coordinate tau in [0, 1]: c0 + c1 tau + c2 tau^2 + c3 tau^3.
struct Cubic {
  std::array<double, 4> c{};
  double operator()(double t) const { return ((c[3] * t + c[2]) * t + c[1]) * t + c[0]; }
  double slope(double t) const { return (3 * c[3] * t + 2 * c[2]) * t + c[1]; }
  Cubic derivative() const { return {{c[1], 2 * c[2], 3 * c[3], 0}}; }
};

inline Cubic combine(double a, const Cubic& p, double b, const Cubic& q, double constant) {
  Cubic r;
  for (int k = 0; k < 4; ++k) r.c[k] = a * p.c[k] + b * q.c[k];
  r.c[0] += constant;
  return r;
}

// The Hermite basis on [0, 1]: the weights of an interval's end values and slopes
// (a0, b0, a1, b1) in its interpolant at t.
inline std::array<double, 4> hermite(double t) {
  const double t2 = t * t, t3 = t2 * t;
  return {2 * t3 - 3 * t2 + 1, t3 - 2 * t2 + t, -2 * t3 + 3 * t2, t3 - t2};
}

inline Cubic hermiteCubic(double a0, double b0, double a1, double b1) {
  return {{a0, b0, -3 * a0 - 2 * b0 + 3 * a1 - b1, 2 * a0 + b0 - 2 * a1 + b1}};
}

// The first instant after `from` (up to 1) where q passes to its event side
// (side * q > 0), or 2 when it does not: q is cut at its turning points so that each
// piece is monotone, and the first piece that ends on the event side from the other
// holds the crossing, found by bisection. A piece that starts on the event side
// (rounding just after the instant that began the phase) is not an instant.
inline double firstCrossing(const Cubic& q, double side, double from) {
  std::array<double, 4> cuts{};
  int n = 0;
  cuts[n++] = from;
  const double A = 3 * q.c[3], B = 2 * q.c[2], C = q.c[1];  // q' = A t^2 + B t + C
  std::array<double, 2> turns{2, 2};
  if (A != 0) {
    const double disc = B * B - 4 * A * C;
    if (disc > 0) {
      const double r = -(B + std::copysign(std::sqrt(disc), B)) / 2;  // no cancellation
      turns = {r / A, r != 0 ? C / r : 2};
    }
  } else if (B != 0) {
    turns[0] = -C / B;
  }
  std::sort(turns.begin(), turns.end());
  for (double t : turns)
    if (t > from && t < 1) cuts[n++] = t;
  cuts[n++] = 1;
  for (int k = 0; k + 1 < n; ++k) {
    double lo = cuts[k], hi = cuts[k + 1];
    if (!(side * q(hi) > 0) || side * q(lo) > 0) continue;
    for (int it = 0; it < 64 && hi - lo > 1e-16; ++it) {
      const double mid = 0.5 * (lo + hi);
      (side * q(mid) > 0 ? hi : lo) = mid;
    }
    return hi;
  }
  return 2;
}


}  // namespace cyclone::hbm::detail
