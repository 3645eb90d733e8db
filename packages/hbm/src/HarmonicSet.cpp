#include "cyclone/hbm/HarmonicSet.hpp"

#include "cyclone/core/Error.hpp"

#include <algorithm>
#include <string>

namespace cyclone::hbm {

HarmonicSet::HarmonicSet(std::vector<int> harmonics) : harmonics_(std::move(harmonics)) {
  if (harmonics_.empty()) throw InputError("HarmonicSet", "the list of harmonics is empty");
  for (int h : harmonics_)
    if (h < 0) throw InputError("HarmonicSet", "harmonic " + std::to_string(h) + " is negative");
  maxHarmonic_ = *std::max_element(harmonics_.begin(), harmonics_.end());
  cosSlot_.assign(maxHarmonic_ + 1, -1);
  for (int h : harmonics_) {
    if (cosSlot_[h] >= 0) throw InputError("HarmonicSet", "harmonic " + std::to_string(h) + " is listed twice");
    cosSlot_[h] = numCoefficients_;
    numCoefficients_ += h == 0 ? 1 : 2;
  }
}

HarmonicSet HarmonicSet::upTo(int maxHarmonic) {
  if (maxHarmonic < 0)
    throw InputError("HarmonicSet", "highest harmonic " + std::to_string(maxHarmonic) + " is negative");
  std::vector<int> list(maxHarmonic + 1);
  for (int h = 0; h <= maxHarmonic; ++h) list[h] = h;
  return HarmonicSet(list);
}

HarmonicSet HarmonicSet::odd(int maxHarmonic) {
  std::vector<int> list;
  for (int h = 1; h <= maxHarmonic; h += 2) list.push_back(h);
  if (list.empty())
    throw InputError("HarmonicSet", "no odd harmonic up to " + std::to_string(maxHarmonic));
  return HarmonicSet(list);
}

bool HarmonicSet::contains(int h) const {
  return h >= 0 && h <= maxHarmonic_ && cosSlot_[h] >= 0;
}

int HarmonicSet::cosIndex(int h) const {
  if (!contains(h)) throw InputError("HarmonicSet", "harmonic " + std::to_string(h) + " is not in the set");
  return cosSlot_[h];
}

int HarmonicSet::sinIndex(int h) const {
  if (h == 0) throw InputError("HarmonicSet", "harmonic 0 has no sin coefficient");
  return cosIndex(h) + 1;
}

int HarmonicSet::nonsmoothSamples() const {
  int n = 1;
  while (n < 8 * minimumSamples()) n *= 2;
  return n;
}

}  // namespace cyclone::hbm
