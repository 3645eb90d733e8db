#include "cyclone/post/SvgPlot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"

namespace cyclone::post {

namespace {

constexpr double kWidth = 900, kHeight = 600, kLeft = 80, kRight = 200, kTop = 50, kBottom = 60;

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else out += c;
  }
  return out;
}

// "Nice" tick spacing: 1, 2 or 5 times a power of ten, about 6 ticks over the range.
double tickStep(double range) {
  const double raw = range / 6;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}

std::string number(double v) {
  std::ostringstream s;
  s << (v == 0 ? 0.0 : v);  // no "-0" tick
  return s.str();
}

}  // namespace

SvgPlot::SvgPlot(std::string title, std::string xLabel, std::string yLabel)
    : title_(std::move(title)), xLabel_(std::move(xLabel)), yLabel_(std::move(yLabel)) {}

void SvgPlot::addLine(const std::vector<double>& x, const std::vector<double>& y, const std::string& color,
                      const std::string& label, bool dashed, double width) {
  series_.push_back({x, y, color, label, false, dashed, width});
}

void SvgPlot::addMarkers(const std::vector<double>& x, const std::vector<double>& y, const std::string& color,
                         const std::string& label, double radius) {
  series_.push_back({x, y, color, label, true, false, radius});
}

void SvgPlot::addText(double x, double y, const std::string& text, const std::string& color) {
  texts_.push_back({x, y, text, color});
}

void SvgPlot::setXRange(double lo, double hi) { xFixed_ = true, x0_ = lo, x1_ = hi; }
void SvgPlot::setYRange(double lo, double hi) { yFixed_ = true, y0_ = lo, y1_ = hi; }

std::string SvgPlot::palette(int i) {
  static const char* colors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                 "#17becf", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22"};
  return colors[((i % 10) + 10) % 10];
}

void SvgPlot::ranges(double& x0, double& x1, double& y0, double& y1) const {
  x0 = x0_, x1 = x1_, y0 = y0_, y1 = y1_;
  if (!xFixed_ || !yFixed_) {
    double ax = std::numeric_limits<double>::max(), bx = -ax, ay = ax, by = -ax;
    for (const auto& s : series_)
      for (std::size_t i = 0; i < s.x.size(); ++i) {
        if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
        ax = std::min(ax, s.x[i]), bx = std::max(bx, s.x[i]), ay = std::min(ay, s.y[i]), by = std::max(by, s.y[i]);
      }
    if (ax > bx) ax = 0, bx = 1, ay = 0, by = 1;
    if (!xFixed_) x0 = ax, x1 = bx > ax ? bx : ax + 1;
    if (!yFixed_) {
      // From zero (amplitudes, frequencies) or below the lowest value, 5 % of the span
      // above the highest (and below the lowest when it is negative): nothing drawn on the frame.
      const double lo = std::min(0.0, ay), span = std::max(by, 0.0) - lo;
      y0 = ay < 0 ? lo - 0.05 * span : 0.0;
      y1 = span > 0 ? std::max(by, 0.0) + 0.05 * span : y0 + 1;
    }
  }
}

void SvgPlot::legend(std::ostream& o, double pw, double ph) const {
  double ly = kTop + 10;
  for (const auto& s : series_) {
    if (s.label.empty()) continue;
    const double lx = kLeft + pw + 15;
    if (s.markers)
      o << "<circle cx=\"" << lx + 10 << "\" cy=\"" << ly << "\" r=\"4\" fill=\"" << s.color << "\"/>\n";
    else
      o << "<line x1=\"" << lx << "\" y1=\"" << ly << "\" x2=\"" << lx + 20 << "\" y2=\"" << ly << "\" stroke=\""
        << s.color << "\" stroke-width=\"2\"" << (s.dashed ? " stroke-dasharray=\"6,4\"" : "") << "/>\n";
    o << "<text x=\"" << lx + 26 << "\" y=\"" << ly + 4 << "\">" << escape(s.label) << "</text>\n";
    ly += 18;
    if (ly > kTop + ph) break;
  }
}

std::string SvgPlot::render() const {
  double x0, x1, y0, y1;
  ranges(x0, x1, y0, y1);
  const double pw = kWidth - kLeft - kRight, ph = kHeight - kTop - kBottom;
  auto X = [&](double x) { return kLeft + (x - x0) / (x1 - x0) * pw; };
  auto Y = [&](double y) { return kTop + ph - (y - y0) / (y1 - y0) * ph; };
  std::ostringstream o;
  o.precision(6);
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << kHeight
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  o << "<defs><clipPath id=\"plot\"><rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\"" << pw << "\" height=\""
    << ph << "\"/></clipPath></defs>\n";
  o << "<text x=\"" << kLeft + pw / 2 << "\" y=\"28\" text-anchor=\"middle\" font-size=\"16\">" << escape(title_)
    << "</text>\n";
  // Grid and ticks.
  const double dx = integerX_ ? std::max(1.0, std::round(tickStep(x1 - x0))) : tickStep(x1 - x0);
  for (double t = std::ceil(x0 / dx) * dx; t <= x1 + 1e-9 * dx; t += dx)
    o << "<line x1=\"" << X(t) << "\" y1=\"" << kTop << "\" x2=\"" << X(t) << "\" y2=\"" << kTop + ph
      << "\" stroke=\"#eee\"/><text x=\"" << X(t) << "\" y=\"" << kTop + ph + 18 << "\" text-anchor=\"middle\">"
      << number(t) << "</text>\n";
  const double dy = tickStep(y1 - y0);
  for (double t = std::ceil(y0 / dy) * dy; t <= y1 + 1e-9 * dy; t += dy)
    o << "<line x1=\"" << kLeft << "\" y1=\"" << Y(t) << "\" x2=\"" << kLeft + pw << "\" y2=\"" << Y(t)
      << "\" stroke=\"#eee\"/><text x=\"" << kLeft - 6 << "\" y=\"" << Y(t) + 4 << "\" text-anchor=\"end\">"
      << number(t) << "</text>\n";
  o << "<rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\"" << pw << "\" height=\"" << ph
    << "\" fill=\"none\" stroke=\"#333\"/>\n";
  o << "<text x=\"" << kLeft + pw / 2 << "\" y=\"" << kHeight - 15 << "\" text-anchor=\"middle\">" << escape(xLabel_)
    << "</text>\n<text transform=\"translate(20," << kTop + ph / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
    << escape(yLabel_) << "</text>\n<g clip-path=\"url(#plot)\">\n";
  for (const auto& s : series_) {
    if (s.markers) {
      for (std::size_t i = 0; i < s.x.size(); ++i)
        if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]))
          o << "<circle cx=\"" << X(s.x[i]) << "\" cy=\"" << Y(s.y[i]) << "\" r=\"" << s.size << "\" fill=\"" << s.color
            << "\"/>\n";
      continue;
    }
    o << "<polyline fill=\"none\" stroke=\"" << s.color << "\" stroke-width=\"" << s.size << "\""
      << (s.dashed ? " stroke-dasharray=\"6,4\"" : "") << " points=\"";
    for (std::size_t i = 0; i < s.x.size(); ++i)
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) o << X(s.x[i]) << "," << Y(s.y[i]) << " ";
    o << "\"/>\n";
  }
  for (const auto& t : texts_)
    o << "<text x=\"" << X(t.x) + 4 << "\" y=\"" << Y(t.y) - 4 << "\" fill=\"" << t.color << "\" font-size=\"10\">"
      << escape(t.text) << "</text>\n";
  o << "</g>\n";
  legend(o, pw, ph);
  o << "</svg>\n";
  return o.str();
}

void SvgPlot::write(const std::string& path) const {
  AtomicFile file(path);
  {
    std::ofstream out(file.tempPath());
    out << render();
    file.check(out);
  }
  file.commit();
}

}  // namespace cyclone::post
