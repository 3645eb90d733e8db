#include "cyclone/fatigue/StressCycle.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "cyclone/core/Error.hpp"

namespace cyclone::fatigue {

double vonMises(const Voigt& s) {
  const double a = s(0) - s(1), b = s(1) - s(2), c = s(2) - s(0);
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (s(3) * s(3) + s(4) * s(4) + s(5) * s(5)));
}

double largestPrincipal(const Voigt& s) {
  Eigen::Matrix3d m;
  m << s(0), s(5), s(4), s(5), s(1), s(3), s(4), s(3), s(2);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(m, Eigen::EigenvaluesOnly);
  const Eigen::Vector3d l = eig.eigenvalues();
  return std::abs(l(0)) > std::abs(l(2)) ? l(0) : l(2);
}

Voigt stressAt(const Voigt& mean, const std::vector<HarmonicStress>& harmonics, double theta) {
  Voigt s = mean;
  for (const auto& h : harmonics) {
    const std::complex<double> e(std::cos(h.harmonic * theta), std::sin(h.harmonic * theta));
    for (int k = 0; k < 6; ++k) s(k) += (h.amplitude(k) * e).real();
  }
  return s;
}

namespace {

// The largest value of a smooth periodic g over [0, 2 pi): the best of n samples, then
// golden section on the bracket of its two neighbours.
double periodicMaximum(const std::function<double(double)>& g, int n) {
  const double dt = 2 * M_PI / n;
  int best = 0;
  double top = -1e300;
  for (int i = 0; i < n; ++i) {
    const double v = g(i * dt);
    if (v > top) top = v, best = i;
  }
  double a = (best - 1) * dt, b = (best + 1) * dt;
  const double r = 0.5 * (std::sqrt(5.0) - 1);
  double x1 = b - r * (b - a), x2 = a + r * (b - a), f1 = g(x1), f2 = g(x2);
  for (int it = 0; it < 40; ++it) {
    if (f1 > f2) b = x2, x2 = x1, f2 = f1, x1 = b - r * (b - a), f1 = g(x1);
    else a = x1, x1 = x2, f1 = f2, x2 = a + r * (b - a), f2 = g(x2);
  }
  return std::max({top, f1, f2});
}

}  // namespace

CycleMeasures measureCycle(const Voigt& mean, const std::vector<HarmonicStress>& harmonics, int samples) {
  if (samples < 4) throw InputError("stress cycle", "needs at least 4 samples per period");
  int highest = 1;
  for (const auto& h : harmonics) {
    if (h.harmonic < 1) throw InputError("stress cycle", "harmonic " + std::to_string(h.harmonic) + " (the mean goes apart)");
    highest = std::max(highest, h.harmonic);
  }
  const int n = std::max(samples, 16 * highest);
  CycleMeasures out;
  const double vm = vonMises(mean);
  out.meanVonMises = largestPrincipal(mean) < 0 ? -vm : vm;
  const Voigt zero = Voigt::Zero();
  out.alternatingVonMises = periodicMaximum([&](double t) { return vonMises(stressAt(zero, harmonics, t)); }, n);
  out.alternatingPrincipal =
      periodicMaximum([&](double t) { return std::abs(largestPrincipal(stressAt(zero, harmonics, t))); }, n);
  out.maxVonMises = periodicMaximum([&](double t) { return vonMises(stressAt(mean, harmonics, t)); }, n);
  return out;
}

}  // namespace cyclone::fatigue
