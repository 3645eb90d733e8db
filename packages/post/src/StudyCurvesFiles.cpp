#include "cyclone/post/StudyCurvesFiles.hpp"

#include <cmath>

#include "cyclone/core/AtomicFile.hpp"

namespace cyclone::post {

StudyCurvesFiles::StudyCurvesFiles(std::string parameter, const std::string& title, const std::string& yLabel)
    : parameter_(std::move(parameter)), plot_(title, "frequency (Hz)", yLabel) {
  table_.precision(10);
  table_ << parameter_ << ",peak_hz,peak_max_abs,points,finished,seconds\n";
}

std::string StudyCurvesFiles::label(double value) const {
  std::ostringstream label;
  label << parameter_ << " = " << value;
  return label.str();
}

void StudyCurvesFiles::add(double value, const response::ForcedResponseResult& r, double seconds) {
  const auto bounds = response::segmentBounds(r.branch);
  for (std::size_t k = 0; k + 1 < bounds.size(); ++k) {  // one line per sweep, labelled once
    std::vector<double> hz;
    for (std::size_t i = bounds[k]; i < bounds[k + 1]; ++i) hz.push_back(r.omega[i] / (2 * M_PI));
    plot_.addLine(hz, std::vector<double>(r.measure.begin() + long(bounds[k]), r.measure.begin() + long(bounds[k + 1])),
                  SvgPlot::palette(curves_), k == 0 ? label(value) : std::string());
  }
  table_ << value << "," << r.peakOmega / (2 * M_PI) << "," << r.peak << "," << r.branch.points.size() << ","
         << (r.branch.finished ? 1 : 0) << "," << seconds << "\n";
  ++curves_;
}

void StudyCurvesFiles::write(const std::string& svgPath, const std::string& csvPath) const {
  plot_.write(svgPath);
  AtomicFile file(csvPath);
  const std::string table = table_.str();
  file.write(table.data(), table.size());
  file.commit();
}

}  // namespace cyclone::post
