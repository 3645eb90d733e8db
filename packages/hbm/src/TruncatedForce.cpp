#include "cyclone/hbm/TruncatedForce.hpp"

#include <fftw3.h>

#include <cmath>
#include <complex>
#include <vector>

#include "cyclone/hbm/ElementStates.hpp"

namespace cyclone::hbm {

TruncatedForce truncatedForce(const HarmonicBalanceSystem& system, const Eigen::VectorXd& x, double omega) {
  TruncatedForce out;
  const int N = system.aft().numSamples(), top = (N - 1) / 2;  // harmonics below the Nyquist one
  const HarmonicSet& kept = system.aft().harmonics();
  // The samples' DFT X_h (FFTW): f = c cos(h t) + s sin(h t) gives X_h = N (c - i s) / 2.
  std::vector<double> samples(N);
  std::vector<std::complex<double>> spectrum(N / 2 + 1);
  const fftw_plan plan = fftw_plan_dft_r2c_1d(N, samples.data(), reinterpret_cast<fftw_complex*>(spectrum.data()),
                                              FFTW_ESTIMATE);
  const auto states = elementStates(system, x, omega);
  Eigen::VectorXd byHarmonic = Eigen::VectorXd::Zero(top + 1);  // sum of c_h^2 + s_h^2
  for (std::size_t e = 0; e < states.size(); ++e) {
    const ElementPeriod period = elementPeriod(system, e, states[e], omega);
    for (Eigen::Index c = 0; c < period.f.cols(); ++c) {
      for (int i = 0; i < N; ++i) samples[i] = period.f(i, c);
      fftw_execute(plan);
      for (int h = 1; h <= top; ++h) byHarmonic(h) += 4 * std::norm(spectrum[h]) / (double(N) * N);
    }
  }
  fftw_destroy_plan(plan);
  double keptSum = 0, droppedSum = 0, largest = 0;
  for (int h = 1; h <= top; ++h) {
    if (kept.contains(h)) {
      keptSum += byHarmonic(h);
    } else {
      droppedSum += byHarmonic(h);
      if (byHarmonic(h) > largest) largest = byHarmonic(h), out.largestDropped = h;
    }
  }
  if (!(keptSum > 0)) return out;
  out.known = true;
  out.kept = std::sqrt(keptSum), out.dropped = std::sqrt(droppedSum);
  out.share = out.dropped / out.kept;
  out.largestDroppedShare = std::sqrt(largest) / out.kept;
  return out;
}

}  // namespace cyclone::hbm
