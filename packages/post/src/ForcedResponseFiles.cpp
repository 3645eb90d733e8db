#include "cyclone/post/ForcedResponseFiles.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"
#include "cyclone/io/ResponseCurveFile.hpp"
#include "cyclone/post/SvgPlot.hpp"

namespace cyclone::post {

namespace {

// A free-text note as one CSV cell (the report's table splits at commas).
std::string csvCell(std::string text) {
  for (char& c : text)
    if (c == ',') c = ';';
  return text;
}

}  // namespace

void writeHarmonicsLevelsCsv(const response::HarmonicsCheck& check, const std::string& path) {
  const auto& levels = check.levels;
  const int dof = check.dof;
  AtomicFile file(path);
  std::ofstream out(file.tempPath());
  out.precision(10);
  out << "max_harmonic,found,peak_max_abs_dof" << dof
      << ",freq_hz,relative_change,frequency_change,force_beyond_h,solves,seconds,note\n";
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const auto& l = levels[i];
    out << l.maxHarmonic << "," << (l.peak.found ? 1 : 0) << ",";
    if (l.peak.x.size() == 0) {  // no solution at all: nothing to compare
      out << ",,,,," << l.peak.solves << "," << l.seconds << "," << csvCell(l.peak.reason) << "\n";
      continue;
    }
    out << l.peak.value << "," << l.peak.parameter << ",";
    if (i > 0) {
      const auto& b = levels[i - 1].peak;
      out << std::abs(l.peak.value / b.value - 1) << "," << std::abs(l.peak.parameter / b.parameter - 1);
    } else {
      out << ",";
    }
    out << ",";
    if (l.truncated.known) out << l.truncated.share;
    std::string note = l.peak.reason;
    if (i > 0 && l.startHz != levels[i - 1].peak.parameter) {
      std::ostringstream from;
      from << "started on the flank at " << l.startHz << " Hz" << (note.empty() ? "" : "; ");
      note = from.str() + note;
    }
    out << "," << l.peak.solves << "," << l.seconds << "," << csvCell(note) << "\n";
  }
  file.check(out);
  file.commit();
}

namespace {

void writeCurveCsv(const response::ForcedResponseSetup& setup, const response::ForcedResponseResult& result,
                   const std::string& path) {
  const auto& hb = *setup.system;
  const auto& harmonics = hb.aft().harmonics();
  const bool byOmega = setup.parameter == response::ForcedResponseSetup::Parameter::Omega;
  AtomicFile file(path);
  std::ofstream csv(file.tempPath());
  csv.precision(12);
  csv << "point,omega_rad_s,freq_hz" << (byOmega ? "" : "," + setup.parameterName());
  for (int d : setup.outputDofs) {
    const std::string& name = setup.dofNames[d];
    csv << "," << name << "_h0";
    for (int h : harmonics.harmonics())
      if (h > 0) csv << "," << name << "_amp_h" << h;
    csv << "," << name << "_max";
  }
  csv << ",stable,max_floquet_real,bifurcation,segment\n";
  const int nc = hb.numCoefficients();
  for (std::size_t i = 0; i < result.branch.points.size(); ++i) {
    const auto& pt = result.branch.points[i];
    const double w = result.omega[i];
    csv << i << "," << w << "," << w / (2 * M_PI);
    if (!byOmega) csv << "," << pt.parameter;
    for (int d : setup.outputDofs) {
      csv << "," << (harmonics.contains(0) ? pt.x(d * nc + harmonics.cosIndex(0)) : 0.0);
      for (int h : harmonics.harmonics())
        if (h > 0) csv << "," << hb.amplitude(pt.x, d, h);
      csv << "," << hbm::peakMagnitude(harmonics, Eigen::VectorXd(pt.x.segment(d * nc, nc)));
    }
    if (result.stabilityComputed) {
      csv << "," << result.stable[i] << ",";
      if (result.leadingExponent[i]) csv << result.leadingExponent[i]->real();
    } else {
      csv << ",,";
    }
    csv << "," << result.flags[i] << "," << result.segment[i] << "\n";
  }
  file.check(csv);
  file.commit();
}

// Stable stretches solid, unstable ones dashed (each stretch shares its end points; no
// line across two sweeps; undetermined points drawn with the stable ones).
void writeCurveSvg(const response::ForcedResponseSetup& setup, const response::ForcedResponseResult& result,
                   const std::string& path) {
  const bool byOmega = setup.parameter == response::ForcedResponseSetup::Parameter::Omega;
  std::vector<double> x;
  for (std::size_t i = 0; i < result.branch.points.size(); ++i)
    x.push_back(byOmega ? result.omega[i] / (2 * M_PI) : result.branch.points[i].parameter);
  const auto& y = result.measure;
  const auto stablePoint = [&](std::size_t i) { return !result.stabilityComputed || result.stable[i] != 0; };
  SvgPlot plot("Forced response (harmonic balance, arclength continuation)",
               byOmega ? "frequency (Hz)" : setup.parameterName(),
               "max |x(t)| of " + setup.dofNames[setup.outputDofs.front()]);
  bool labelled[2] = {false, false};
  const int H = setup.system->aft().harmonics().maxHarmonic();
  for (std::size_t i = 0; i + 1 < x.size();) {
    if (result.segment[i + 1] != result.segment[i]) {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j + 1 < x.size() && result.segment[j + 1] == result.segment[i] && stablePoint(j) == stablePoint(i)) ++j;
    const bool stablePart = stablePoint(i);
    std::string label;
    if (!labelled[stablePart]) {
      label = (result.stabilityComputed ? std::string(stablePart ? "stable" : "unstable") + ", " : std::string()) +
              "H = " + std::to_string(H);
      labelled[stablePart] = true;
    }
    plot.addLine(std::vector<double>(x.begin() + i, x.begin() + j + 1),
                 std::vector<double>(y.begin() + i, y.begin() + j + 1), SvgPlot::palette(0), label, !stablePart);
    i = j;
  }
  // The harmonics check's peaks at the other harmonic counts (each a peak search, not a
  // traced curve): how far the traced curve's H is from converged, where it is seen.
  if (byOmega) {
    int colour = 1;
    for (const auto& level : result.harmonicsCheck.levels)
      if (level.peak.found && level.maxHarmonic != H)
        plot.addMarkers({level.peak.parameter}, {level.peak.value}, SvgPlot::palette(colour++),
                        "peak with H = " + std::to_string(level.maxHarmonic) + " (search)", 4.0);
  }
  plot.write(path);
}

}  // namespace

std::vector<std::string> writeForcedResponseFiles(const response::ForcedResponseSetup& setup,
                                                  const response::ForcedResponseResult& result,
                                                  const std::string& outDir, const std::string& name) {
  const std::string base = outDir + "/" + name;
  writeCurveCsv(setup, result, base + ".csv");
  if (!setup.outputDofs.empty()) writeCurveSvg(setup, result, base + ".svg");
  // The full coefficient vectors, for post-processing and restarts.
  const auto& hb = *setup.system;
  io::ResponseCurve curve;
  curve.numDofs = hb.numDofs();
  curve.numCoefficients = hb.numCoefficients();
  curve.samples = hb.aft().numSamples();
  curve.harmonics = hb.aft().harmonics().harmonics();
  for (std::size_t i = 0; i < result.branch.points.size(); ++i) {
    curve.omega.push_back(result.omega[i]);
    curve.parameter.push_back(result.branch.points[i].parameter);
    curve.coefficients.push_back(result.branch.points[i].x);
    curve.stable.push_back(result.stabilityComputed ? result.stable[i] : -1);
    curve.segment.push_back(result.segment[i]);
  }
  io::writeResponseCurveHdf5(base + ".h5", curve);
  return {base + ".h5", base + ".csv", base + ".svg"};
}

}  // namespace cyclone::post
