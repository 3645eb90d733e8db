#include "cyclone/hbm/Aft.hpp"

#include <sstream>

#include "cyclone/core/Error.hpp"

#include <fftw3.h>

#include <cmath>
#include <string>

namespace cyclone::hbm {

namespace {
fftw_complex* asComplex(double* p) { return reinterpret_cast<fftw_complex*>(p); }
}  // namespace

Aft::Aft(HarmonicSet harmonics, int samples) : harmonics_(std::move(harmonics)), n_(samples) {
  if (n_ < harmonics_.minimumSamples())
    throw InputError("Aft", std::to_string(n_) + " samples per period cannot resolve harmonic " +
                                std::to_string(harmonics_.maxHarmonic()) + " (need at least " +
                                std::to_string(harmonics_.minimumSamples()) + ")");
  // The dense maps between coefficients and samples (E, P, D) are held for the
  // elements' Jacobians: a harmonic count and sample count that make them larger than
  // a workstation's memory are refused before anything is allocated.
  {
    constexpr double kMaxGigabytes = 8;
    const double nc = harmonics_.numCoefficients();
    const double gigabytes = 8.0 * (2.0 * n_ * nc + nc * nc) / 1e9;
    if (gigabytes > kMaxGigabytes) {
      std::ostringstream why;
      why.precision(3);
      why << harmonics_.size() << " harmonics (up to " << harmonics_.maxHarmonic() << ") at " << n_
          << " samples per period: the transform's dense matrices would take " << gigabytes << " GB (at most "
          << kMaxGigabytes << "); use fewer harmonics or samples";
      throw InputError("harmonics and samples", why.str());
    }
  }
  real_ = static_cast<double*>(fftw_malloc(sizeof(double) * n_));
  spectrum_ = static_cast<double*>(fftw_malloc(sizeof(fftw_complex) * (n_ / 2 + 1)));
  // ESTIMATE: deterministic plans, and planning does not touch the buffers.
  forward_ = fftw_plan_dft_r2c_1d(n_, real_, asComplex(spectrum_), FFTW_ESTIMATE);
  backward_ = fftw_plan_dft_c2r_1d(n_, asComplex(spectrum_), real_, FFTW_ESTIMATE);
  if (!real_ || !spectrum_ || !forward_ || !backward_) {
    release();
    throw Error("Aft: FFTW could not plan transforms of " + std::to_string(n_) + " samples");
  }

  const int nc = harmonics_.numCoefficients();
  e_.setZero(n_, nc);
  p_.setZero(nc, n_);
  d_.setZero(nc, nc);
  const double twoPi = 6.283185307179586476925286766559;
  for (int h : harmonics_.harmonics()) {
    const int c = harmonics_.cosIndex(h);
    for (int i = 0; i < n_; ++i) {
      // (h i) mod N keeps the argument small so large h and N lose no digits.
      const double tau = twoPi * static_cast<double>((static_cast<long>(h) * i) % n_) / n_;
      if (h == 0) {
        e_(i, c) = 1.0;
        p_(c, i) = 1.0 / n_;
      } else {
        e_(i, c) = std::cos(tau);
        e_(i, c + 1) = std::sin(tau);
        p_(c, i) = 2.0 / n_ * std::cos(tau);
        p_(c + 1, i) = 2.0 / n_ * std::sin(tau);
      }
    }
    if (h > 0) {
      d_(c, c + 1) = h;
      d_(c + 1, c) = -h;
    }
  }
}

Aft::~Aft() { release(); }

void Aft::release() {
  if (forward_) fftw_destroy_plan(forward_);
  if (backward_) fftw_destroy_plan(backward_);
  fftw_free(real_);
  fftw_free(spectrum_);
  forward_ = backward_ = nullptr;
  real_ = spectrum_ = nullptr;
}

void Aft::toTime(const double* coefficients, double* samples) const {
  // c2r computes x_n = sum_k Y_k e^{+i 2 pi k n / N} over the Hermitian
  // extension, so Y_h = (c_h - i s_h) / 2 and Y_0 = x0. Every h < N/2 (no
  // Nyquist bin) because N >= 2 maxH + 1.
  fftw_complex* y = asComplex(spectrum_);
  for (int k = 0; k <= n_ / 2; ++k) y[k][0] = y[k][1] = 0.0;
  for (int h : harmonics_.harmonics()) {
    const int c = harmonics_.cosIndex(h);
    if (h == 0) {
      y[0][0] = coefficients[c];
    } else {
      y[h][0] = 0.5 * coefficients[c];
      y[h][1] = -0.5 * coefficients[c + 1];
    }
  }
  fftw_execute(backward_);  // destroys spectrum_, which we own
  for (int i = 0; i < n_; ++i) samples[i] = real_[i];
}

void Aft::toFrequency(const double* samples, double* coefficients) const {
  for (int i = 0; i < n_; ++i) real_[i] = samples[i];
  fftw_execute(forward_);  // Y_k = sum_n x_n e^{-i 2 pi k n / N}
  const fftw_complex* y = asComplex(spectrum_);
  for (int h : harmonics_.harmonics()) {
    const int c = harmonics_.cosIndex(h);
    if (h == 0) {
      coefficients[c] = y[0][0] / n_;
    } else {
      coefficients[c] = 2.0 * y[h][0] / n_;
      coefficients[c + 1] = -2.0 * y[h][1] / n_;
    }
  }
}

void Aft::toFrequencyColumns(const Eigen::Ref<const Eigen::MatrixXd>& samples,
                             Eigen::Ref<Eigen::MatrixXd> coefficients) const {
  if (samples.rows() != n_ || coefficients.rows() != numCoefficients() || coefficients.cols() != samples.cols())
    throw Error("Aft::toFrequencyColumns: " + std::to_string(samples.rows()) + " x " + std::to_string(samples.cols()) +
                " samples onto " + std::to_string(coefficients.rows()) + " x " + std::to_string(coefficients.cols()) +
                " coefficients (expected " + std::to_string(n_) + " and " + std::to_string(numCoefficients()) + " rows)");
  // Columns of a Ref are contiguous (inner stride 1): each is one transform's input and output.
  for (Eigen::Index j = 0; j < samples.cols(); ++j) toFrequency(samples.col(j).data(), coefficients.col(j).data());
}

Eigen::VectorXd Aft::toTime(const Eigen::VectorXd& coefficients) const {
  if (coefficients.size() != numCoefficients())
    throw InputError("Aft::toTime", "expected " + std::to_string(numCoefficients()) + " coefficients, got " +
                                        std::to_string(coefficients.size()));
  Eigen::VectorXd samples(n_);
  toTime(coefficients.data(), samples.data());
  return samples;
}

Eigen::VectorXd Aft::toFrequency(const Eigen::VectorXd& samples) const {
  if (samples.size() != n_)
    throw InputError("Aft::toFrequency",
                     "expected " + std::to_string(n_) + " samples, got " + std::to_string(samples.size()));
  Eigen::VectorXd coefficients(numCoefficients());
  toFrequency(samples.data(), coefficients.data());
  return coefficients;
}

}  // namespace cyclone::hbm
