#pragma once
// The files of a band swept in the time domain (disc::PreloadSweepsInTime): a table of
// every frequency at every preload, the amplitude against the frequency per preload, and,
// with several preloads, the largest amplitude against the preload with the optimum marked.
#include <string>
#include <vector>

#include "cyclone/disc/DiscSweepInTime.hpp"

namespace cyclone::post {

/// `<stem>.csv` (preload_n,frequency_hz,largest_mm,smallest_mm,steady,periods,seconds),
/// `<stem>.svg` (max |x(t)| per period against the frequency: each preload's largest as a
/// line, its smallest dashed where the motion did not settle) and, with two preloads or
/// more, `<stem>_preload.csv/.svg` (each preload's largest, the optimum marked). Returns
/// the paths written.
std::vector<std::string> writeSweepInTimeFiles(const std::string& directory, const std::string& stem,
                                               const disc::PreloadSweepsInTime& sweeps);

}  // namespace cyclone::post
