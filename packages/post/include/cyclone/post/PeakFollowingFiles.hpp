#pragma once
// A followed peak's files (disc::DiscPeakFollowing): every peak's whole solution in the
// response-curve schema (HDF5), the table (CSV) and the plot against the parameter (SVG).
#include <string>
#include <vector>

#include "cyclone/disc/DiscPeakFollowing.hpp"

namespace cyclone::post {

/// <outDir>/peak_<name>.h5 (/parameter, /omega at each peak, /coefficients; no stability),
/// peak_<name>.csv (<name>,peak_hz,peak_max_abs,jump,optimum,force_beyond_h) and
/// peak_<name>.svg (log10 of the parameter, linear for the clearance and the speed; the
/// optimum marked; `curvePeaks`, the frequency curves' tops at some values, beside it).
/// `unit` follows the parameter's name on the axis (" / N"). Returns the paths written.
std::vector<std::string> writePeakFollowingFiles(const std::string& outDir, const std::string& name,
                                                 const std::string& unit, const disc::DiscPeakFollowing& following,
                                                 const std::vector<continuation::KnownPeak>& curvePeaks);

}  // namespace cyclone::post
