#pragma once
// A small x-y line and marker plot written as SVG: enough for Campbell and
// SAFE diagrams and convergence plots, readable in any browser, no plotting
// library or interpreter needed at run time.
#include <ostream>
#include <string>
#include <vector>

namespace cyclone::post {

class SvgPlot {
public:
  SvgPlot(std::string title, std::string xLabel, std::string yLabel);

  /// A polyline; dashed for reference lines (engine orders); label shown in the legend if not empty.
  void addLine(const std::vector<double>& x, const std::vector<double>& y, const std::string& color,
               const std::string& label = "", bool dashed = false, double width = 1.5);
  /// Markers (circles) at the points.
  void addMarkers(const std::vector<double>& x, const std::vector<double>& y, const std::string& color,
                  const std::string& label = "", double radius = 3.0);
  /// A short text at a data point.
  void addText(double x, double y, const std::string& text, const std::string& color = "#333");
  /// Fixes the axis ranges (default: the data's bounds with a margin).
  void setXRange(double lo, double hi);
  void setYRange(double lo, double hi);
  /// Ticks at integers only (nodal diameters).
  void setIntegerXTicks(bool on) { integerX_ = on; }

  /// Writes atomically (temporary file, then rename).
  void write(const std::string& path) const;
  std::string render() const;

  /// A distinct colour for series i.
  static std::string palette(int i);

private:
  /// The axes' ranges: the fixed ones, else from the data (frames nothing is drawn on).
  void ranges(double& x0, double& x1, double& y0, double& y1) const;
  /// The labelled series' legend right of the plot area (pw x ph).
  void legend(std::ostream& o, double pw, double ph) const;
  struct Series {
    std::vector<double> x, y;
    std::string color, label;
    bool markers, dashed;
    double size;
  };
  struct Text {
    double x, y;
    std::string text, color;
  };
  std::string title_, xLabel_, yLabel_;
  std::vector<Series> series_;
  std::vector<Text> texts_;
  bool xFixed_ = false, yFixed_ = false, integerX_ = false;
  double x0_ = 0, x1_ = 1, y0_ = 0, y1_ = 1;
};

}  // namespace cyclone::post
