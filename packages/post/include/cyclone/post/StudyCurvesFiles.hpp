#pragma once
// A parameter study's files, one frequency curve per value: every curve on one plot
// (SVG) and a table of their peaks (CSV), gathered as the curves come.
#include <sstream>
#include <string>

#include "cyclone/post/SvgPlot.hpp"
#include "cyclone/response/ForcedResponse.hpp"

namespace cyclone::post {

class StudyCurvesFiles {
public:
  /// `parameter` names the table's first column and the curves' labels ("mu = 0.3").
  StudyCurvesFiles(std::string parameter, const std::string& title, const std::string& yLabel);
  /// The curve traced at `value`: one line per sweep of it (Branch::segmentStarts), in the
  /// next colour, labelled once; its row <parameter>,peak_hz,peak_max_abs,points,finished,seconds.
  void add(double value, const response::ForcedResponseResult& curve, double seconds);
  /// The plot's label of a value: "<parameter> = <value>".
  std::string label(double value) const;
  int curves() const { return curves_; }
  /// Writes both atomically.
  void write(const std::string& svgPath, const std::string& csvPath) const;

private:
  std::string parameter_;
  SvgPlot plot_;
  std::ostringstream table_;
  int curves_ = 0;
};

}  // namespace cyclone::post
