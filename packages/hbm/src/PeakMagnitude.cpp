#include "cyclone/hbm/PeakMagnitude.hpp"

#include <cmath>

#include "cyclone/core/Error.hpp"

namespace cyclone::hbm {

double peakMagnitude(const HarmonicSet& H, const Eigen::VectorXd& X) {
  if (X.size() != H.numCoefficients()) throw InputError("peakMagnitude", "coefficient vector of the wrong size");
  // x(t) and its first two derivatives.
  auto eval = [&](double t, double& d1, double& d2) {
    double x = 0;
    d1 = d2 = 0;
    for (int h : H.harmonics()) {
      const int c = H.cosIndex(h);
      if (h == 0) {
        x += X(c);
        continue;
      }
      const double ch = std::cos(h * t), sh = std::sin(h * t), a = X(c), b = X(c + 1);
      x += a * ch + b * sh;
      d1 += h * (-a * sh + b * ch);
      d2 -= h * h * (a * ch + b * sh);
    }
    return x;
  };
  const int grid = std::max(256, 32 * H.maxHarmonic());
  double best = 0, bestT = 0, d1, d2;
  for (int i = 0; i < grid; ++i) {
    const double t = 2 * M_PI * i / grid, v = std::abs(eval(t, d1, d2));
    if (v > best) best = v, bestT = t;
  }
  // Newton on x'(t) = 0 from the best grid point; keep it only if it improves.
  double t = bestT;
  for (int it = 0; it < 8; ++it) {
    eval(t, d1, d2);
    if (d2 == 0) break;
    const double step = d1 / d2;
    if (std::abs(step) > 2 * M_PI / grid) break;  // left the grid cell: keep the grid value
    t -= step;
  }
  return std::max(best, std::abs(eval(t, d1, d2)));
}

}  // namespace cyclone::hbm
