#pragma once
// The harmonics retained in a harmonic balance ansatz. Which harmonics are kept
// is a modelling choice (all up to H, odd only for symmetric nonlinearities,
// engine orders...), so the set is any list; the list order fixes where each
// harmonic's coefficients sit in the real coefficient vector of one DOF.
#include <vector>

namespace cyclone::hbm {

/// An ordered set of distinct non-negative harmonic numbers. Per DOF the real
/// coefficients are laid out following the list: harmonic 0 takes one slot
/// (the mean), any other h takes two (cos then sin), e.g. {0, 1, 2} gives
/// [x0, x1c, x1s, x2c, x2s].
class HarmonicSet {
public:
  /// Throws InputError if the list is empty, has a negative or repeated entry.
  explicit HarmonicSet(std::vector<int> harmonics);
  /// 0, 1, ..., maxHarmonic.
  static HarmonicSet upTo(int maxHarmonic);
  /// 1, 3, 5, ... up to maxHarmonic (half-wave symmetric responses).
  static HarmonicSet odd(int maxHarmonic);

  const std::vector<int>& harmonics() const { return harmonics_; }
  int size() const { return static_cast<int>(harmonics_.size()); }
  int maxHarmonic() const { return maxHarmonic_; }
  bool contains(int h) const;
  /// Real coefficients per DOF: 2 per harmonic, 1 for harmonic 0.
  int numCoefficients() const { return numCoefficients_; }
  /// Slot of the cos coefficient of h (the mean for h = 0). InputError if absent.
  int cosIndex(int h) const;
  /// Slot of the sin coefficient of h > 0. InputError if absent or h = 0.
  int sinIndex(int h) const;
  /// Fewest time samples per period that resolve every retained harmonic
  /// without aliasing: 2 maxHarmonic + 1.
  int minimumSamples() const { return 2 * maxHarmonic_ + 1; }
  /// Samples for nonsmooth element laws (contacts, friction: events between samples
  /// shift with the sampling): the power of two from 8 (2 maxHarmonic + 1), so that the
  /// samples grow with the harmonics (16 to 32 per period of the highest).
  int nonsmoothSamples() const;

private:
  std::vector<int> harmonics_;
  std::vector<int> cosSlot_;  // indexed by harmonic number; -1 when absent
  int maxHarmonic_ = 0;
  int numCoefficients_ = 0;
};

}  // namespace cyclone::hbm
