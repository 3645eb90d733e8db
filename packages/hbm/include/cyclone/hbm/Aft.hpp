#pragma once
// Alternating frequency-time transforms: nonlinear forces are evaluated on time
// samples of one period and projected back onto the retained harmonics. Plans
// and buffers are made once here because a harmonic balance solve calls the
// transforms for every element at every Newton iteration.
#include "cyclone/hbm/HarmonicSet.hpp"

#include <Eigen/Dense>

struct fftw_plan_s;  // FFTW's opaque plan; fftw3.h stays out of public headers

namespace cyclone::hbm {

/// Transforms between the real coefficients of one DOF (HarmonicSet layout) and
/// N equidistant samples over one period, tau_n = 2 pi n / N:
///   x(tau_n) = x0 + sum_h (c_h cos(h tau_n) + s_h sin(h tau_n)).
/// Not thread-safe: the transforms share the object's work buffers (use one
/// Aft per thread).
class Aft {
public:
  /// InputError unless samples >= harmonics.minimumSamples() (no aliasing).
  Aft(HarmonicSet harmonics, int samples);
  ~Aft();
  Aft(const Aft&) = delete;  // owns FFTW plans bound to its own buffers
  Aft& operator=(const Aft&) = delete;

  const HarmonicSet& harmonics() const { return harmonics_; }
  int numSamples() const { return n_; }
  int numCoefficients() const { return harmonics_.numCoefficients(); }

  /// coefficients[numCoefficients()] -> samples[numSamples()]. No allocation.
  void toTime(const double* coefficients, double* samples) const;
  /// samples -> coefficients of the retained harmonics (least-squares
  /// projection; the exact inverse of toTime for band-limited signals).
  void toFrequency(const double* samples, double* coefficients) const;

  /// coefficients = P samples for k sampled signals at once (samples N x k, coefficients
  /// nc x k; any outer strides): one FFT per column, N log N where the dense product
  /// costs N nc. The contacts' coefficient Jacobians are such projections of their
  /// sampled force sensitivities, one column per coefficient of the motion: at tens of
  /// harmonics the dense product was most of a Jacobian's time. No allocation.
  void toFrequencyColumns(const Eigen::Ref<const Eigen::MatrixXd>& samples,
                          Eigen::Ref<Eigen::MatrixXd> coefficients) const;

  /// Allocating conveniences.
  Eigen::VectorXd toTime(const Eigen::VectorXd& coefficients) const;
  Eigen::VectorXd toFrequency(const Eigen::VectorXd& samples) const;

  /// E (N x nc): samples = E * coefficients. For Jacobians dF/dX = P (df/dx) E.
  const Eigen::MatrixXd& timeFromCoefficients() const { return e_; }
  /// P (nc x N): coefficients = P * samples; P E = I.
  const Eigen::MatrixXd& coefficientsFromTime() const { return p_; }
  /// D (nc x nc): coefficients of d/dtau; c_h -> h s_h in the cos slot and
  /// s_h -> -h c_h in the sin slot. Multiply by omega for d/dt.
  const Eigen::MatrixXd& derivativeMatrix() const { return d_; }

private:
  void release();  // frees plans and buffers; safe on a half-built object

  HarmonicSet harmonics_;
  int n_;
  double* real_ = nullptr;      // N samples (FFTW-aligned)
  double* spectrum_ = nullptr;  // N/2+1 complex values, interleaved re/im
  fftw_plan_s* forward_ = nullptr;   // r2c: real_ -> spectrum_
  fftw_plan_s* backward_ = nullptr;  // c2r: spectrum_ -> real_ (destroys spectrum_)
  Eigen::MatrixXd e_, p_, d_;
};

}  // namespace cyclone::hbm
