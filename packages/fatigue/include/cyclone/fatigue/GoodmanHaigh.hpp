#pragma once
// The high-cycle-fatigue margin of one point in the Goodman-Haigh diagram
// (Scalvini 2021, sec. 2.1.5): the alternating stress the material carries at the point's
// mean stress, over the alternating stress it carries. The mean is held: a
// blade's mean stress is the centrifugal one (and the harmonic-0 part of the
// vibration), which does not grow when the vibration does, so the margin is
// measured along the alternating axis (the usual HCF margin of turbomachinery
// blades), not along a proportional load line.
//   allowable alternating  S_a(s_m) = S_e (1 - s_m / S_u)   for s_m >= 0 (Goodman line),
//                          S_a(s_m) = S_e                    for s_m < 0 (no credit for a
//                                                            compressive mean),
//   and, when a yield strength is given, at most S_y - |s_m| (Langer's first-cycle
//   yield line: the "modified Goodman" diagram).
//   safety factor  n = S_a(s_m) / s_a  (infinite without alternating stress; 0 when the
//   mean alone reaches the line).
// S_e is the endurance limit at the design life for fully reversed stress
// (R = -1), the component's: surface, size and notch factors are the user's to
// apply to the specimen value.
#include <string>

namespace cyclone::fatigue {

struct FatigueMaterial {
  std::string name;
  double ultimateStrength = 0;  ///< S_u
  double enduranceLimit = 0;    ///< S_e at the design life, R = -1
  double yieldStrength = 0;     ///< S_y; 0: no Langer line
  double designCycles = 0;      ///< the life S_e belongs to (for the report; 0: not stated)
  std::string source;           ///< where the values come from
  /// InputError naming `where` and the value: S_u, S_e > 0, S_e < S_u, S_y in (0, S_u] or 0.
  void validate(const std::string& where) const;
};

/// Ti-6Al-4V (grade 5), annealed, in MPa: S_u 950, S_y 880, S_e 510 at 1e7 cycles,
/// unnotched (K_t = 1), R = -1; from ASM Aerospace Specification Metals' data sheet
/// (matweb.com, "Titanium Ti-6Al-4V (Grade 5), Annealed"), Young's modulus 113.8 GPa.
/// `stressUnit`: the scene's stress unit in MPa (1 for mm-N-s-t, 1e-6 for SI in Pa).
FatigueMaterial ti6al4vAnnealed(double stressUnitInMpa = 1.0);

/// The Goodman-Haigh safety factor n (see the file comment) of a point with mean stress
/// `mean` (signed) and alternating stress `alternating` >= 0.
double goodmanSafetyFactor(double mean, double alternating, const FatigueMaterial& material);

/// The allowable alternating stress at a mean stress: the diagram's limit line.
double allowableAlternating(double mean, const FatigueMaterial& material);

}  // namespace cyclone::fatigue
