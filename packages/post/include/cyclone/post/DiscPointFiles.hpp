#pragma once
// The files of a disc curve's point (disc::DiscPointStates): the contacts' table, the
// hysteresis loops and the period's response, each as CSV and SVG where a person looks.
#include <string>
#include <vector>

#include "cyclone/disc/DiscPeakInTime.hpp"
#include "cyclone/disc/DiscPointStates.hpp"

namespace cyclone::post {

/// contact,freq_hz,dissipated_energy_per_cycle,mean_normal_force,slip_amplitude per contact.
void writeContactsCsv(const std::string& path, const disc::DiscPointStates& states);

/// The loops as CSV (contact,freq_hz,t_over_T,slip_t1,slip_t2,approach,force_t1,force_t2,force_n)
/// and SVG (each tangential direction's force against its motion about its mean).
void writeHysteresisFiles(const std::string& csvPath, const std::string& svgPath, const std::string& title,
                          const disc::DiscPointStates& states);

/// The output DOFs over one period as CSV (freq_hz,t_over_T,<names>) and SVG.
void writePeriodResponseFiles(const std::string& csvPath, const std::string& svgPath, const std::string& title,
                              const std::vector<std::string>& names, const disc::DiscPointStates& states);

/// The peak's time-domain check (disc::PeakInTime) as CSV (period,amplitude_mm: max |x(t)|
/// of the output DOF per period) and SVG (that against the period, the harmonic balance's
/// periodic amplitude as a dashed line).
void writePeakInTimeFiles(const std::string& csvPath, const std::string& svgPath, const disc::PeakInTime& check);

}  // namespace cyclone::post
