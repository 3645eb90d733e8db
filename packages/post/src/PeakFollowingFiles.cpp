#include "cyclone/post/PeakFollowingFiles.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/io/ResponseCurveFile.hpp"
#include "cyclone/post/SvgPlot.hpp"

namespace cyclone::post {

std::vector<std::string> writePeakFollowingFiles(const std::string& outDir, const std::string& name,
                                                 const std::string& unit, const disc::DiscPeakFollowing& following,
                                                 const std::vector<continuation::KnownPeak>& curvePeaks) {
  const auto& curve = following.curve;
  const auto& hb = *following.setup.system;
  const bool continued = following.continued;
  const std::string base = outDir + "/peak_" + name;
  {
    // Every peak's whole solution, for post-processing.
    io::ResponseCurve h5;
    h5.numDofs = hb.numDofs();
    h5.numCoefficients = hb.numCoefficients();
    h5.samples = hb.aft().numSamples();
    h5.harmonics = hb.aft().harmonics().harmonics();
    for (const auto& p : curve.points) {
      h5.omega.push_back(p.frequency);
      h5.parameter.push_back(p.parameter);
      h5.coefficients.push_back(p.x);
      h5.stable.push_back(-1);
    }
    io::writeResponseCurveHdf5(base + ".h5", h5);
  }
  {
    AtomicFile file(base + ".csv");
    std::ofstream out(file.tempPath());
    out.precision(10);
    // force_beyond_h: the contact forces' harmonics above the study's H over those kept at
    // each peak (empty: not known), what the truncation leaves out there.
    out << name << ",peak_hz,peak_max_abs,jump,optimum,force_beyond_h\n";
    for (std::size_t i = 0; i < curve.points.size(); ++i) {
      const auto& p = curve.points[i];
      out << p.parameter << "," << p.frequency / (2 * M_PI) << "," << p.measure << "," << (p.jump ? 1 : 0) << ","
          << (int(i) == curve.optimum ? 1 : 0) << ",";
      if (i < following.forceBeyond.size() && following.forceBeyond[i] >= 0) out << following.forceBeyond[i];
      out << "\n";
    }
    file.check(out);
    file.commit();
  }
  // The clearance on a linear axis (zero and interference are values of it), the speed
  // too (0 rpm is one); the others in log.
  const bool linear = name == "clearance" || name == "speed";
  auto axis = [linear](double v) { return linear ? v : std::log10(v); };
  SvgPlot plot("Resonance peak against the " + name + (continued ? " (one LOCA continuation)" : " (followed)"),
               linear ? name + unit : "log10(" + name + unit + ")", "peak max |x(t)|");
  std::vector<double> x, y;
  for (const auto& p : curve.points) x.push_back(axis(p.parameter)), y.push_back(p.measure);
  plot.addLine(x, y, SvgPlot::palette(0), continued ? "continued peak" : "followed peak");
  if (!curvePeaks.empty()) {
    std::vector<double> lx, ly;
    for (const auto& s : curvePeaks) lx.push_back(axis(s.parameter)), ly.push_back(s.peak.measure);
    plot.addMarkers(lx, ly, SvgPlot::palette(2), "frequency curves (studies)");
  }
  if (curve.optimum >= 0) {
    const auto& o = curve.points[std::size_t(curve.optimum)];
    plot.addMarkers({axis(o.parameter)}, {o.measure}, "#000000", "optimum", 5.0);
    std::ostringstream text;
    text.precision(4);
    text << "optimum " << o.parameter;
    plot.addText(axis(o.parameter), o.measure, text.str());
  }
  plot.write(base + ".svg");
  return {base + ".h5", base + ".csv", base + ".svg"};
}

}  // namespace cyclone::post
