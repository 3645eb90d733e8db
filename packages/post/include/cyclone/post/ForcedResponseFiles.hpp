#pragma once
// The files of a traced forced-response curve (response::solveForcedResponse's result):
// <name>.csv (per point the frequency, per output DOF the mean, harmonic amplitudes and
// max |x(t)|, stability, flags, sweep), <name>.svg (stable stretches solid, unstable
// dashed), <name>.h5 (every point's coefficients, ResponseCurveFile.hpp) and the
// harmonics check's levels as <name>_harmonics.csv. Each written atomically.
#include <string>
#include <vector>

#include "cyclone/response/ForcedResponse.hpp"

namespace cyclone::post {

/// Writes <outDir>/<name>.csv, .svg and .h5; returns their paths.
std::vector<std::string> writeForcedResponseFiles(const response::ForcedResponseSetup& setup,
                                                  const response::ForcedResponseResult& result,
                                                  const std::string& outDir, const std::string& name);

/// The harmonics check's peak per harmonic truncation, its change from the level before,
/// what each level cost and a note (CSV: max_harmonic, found, peak_max_abs_dof<d>,
/// freq_hz, relative_change, frequency_change, solves, seconds, note).
void writeHarmonicsLevelsCsv(const response::HarmonicsCheck& check, const std::string& path);

}  // namespace cyclone::post
