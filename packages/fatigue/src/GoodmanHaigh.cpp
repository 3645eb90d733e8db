#include "cyclone/fatigue/GoodmanHaigh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "cyclone/core/Error.hpp"

namespace cyclone::fatigue {

void FatigueMaterial::validate(const std::string& where) const {
  auto say = [&](const char* key, double v, const std::string& why) {
    std::ostringstream s;
    s << v << ": " << why;
    throw InputError(where + "/" + key, s.str());
  };
  if (!(ultimateStrength > 0) || !std::isfinite(ultimateStrength))
    say("ultimate_strength", ultimateStrength, "must be a positive stress");
  if (!(enduranceLimit > 0) || !std::isfinite(enduranceLimit))
    say("endurance_limit", enduranceLimit, "must be a positive stress");
  if (enduranceLimit >= ultimateStrength)
    say("endurance_limit", enduranceLimit, "must lie below the ultimate strength (the Goodman line needs S_e < S_u)");
  if (yieldStrength != 0 && !(yieldStrength > 0 && yieldStrength <= ultimateStrength))
    say("yield_strength", yieldStrength, "must lie in (0, ultimate_strength], or be left out");
}

FatigueMaterial ti6al4vAnnealed(double stressUnitInMpa) {
  FatigueMaterial m;
  const double u = 1.0 / stressUnitInMpa;
  m.name = "Ti-6Al-4V (grade 5), annealed";
  m.ultimateStrength = 950 * u, m.yieldStrength = 880 * u, m.enduranceLimit = 510 * u;
  m.designCycles = 1e7;
  m.source = "ASM Aerospace Specification Metals data sheet (matweb.com): unnotched (Kt = 1), R = -1, 1e7 cycles";
  return m;
}

double allowableAlternating(double mean, const FatigueMaterial& m) {
  double a = mean >= 0 ? m.enduranceLimit * (1 - mean / m.ultimateStrength) : m.enduranceLimit;
  if (m.yieldStrength > 0) a = std::min(a, m.yieldStrength - std::abs(mean));
  return std::max(a, 0.0);
}

double goodmanSafetyFactor(double mean, double alternating, const FatigueMaterial& m) {
  if (!(alternating >= 0)) throw InputError("Goodman", "the alternating stress must be >= 0");
  const double allowed = allowableAlternating(mean, m);
  if (alternating == 0) return allowed > 0 ? std::numeric_limits<double>::infinity() : 0.0;
  return allowed / alternating;
}

}  // namespace cyclone::fatigue
