#include "cyclone/post/DiscPointFiles.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/post/SvgPlot.hpp"

namespace cyclone::post {

void writeContactsCsv(const std::string& path, const disc::DiscPointStates& states) {
  AtomicFile file(path);
  std::ofstream csv(file.tempPath());
  csv.precision(10);
  csv << "contact,freq_hz,dissipated_energy_per_cycle,mean_normal_force,slip_amplitude\n";
  for (std::size_t e = 0; e < states.contacts.size(); ++e) {
    const auto& c = states.contacts[e];
    csv << e << "," << states.omega / (2 * M_PI) << "," << c.energyPerCycle << "," << c.meanNormalForce << ","
        << c.slipAmplitude << "\n";
  }
  file.check(csv);
  file.commit();
}

void writeHysteresisFiles(const std::string& csvPath, const std::string& svgPath, const std::string& title,
                          const disc::DiscPointStates& states) {
  const double hz = states.omega / (2 * M_PI);
  const std::size_t N = states.phase.size();
  const char* tangential[] = {"t1", "t2"};
  AtomicFile file(csvPath);
  std::ofstream csv(file.tempPath());
  csv.precision(10);
  csv << "contact,freq_hz,t_over_T,slip_t1,slip_t2,approach,force_t1,force_t2,force_n\n";
  // About each direction's mean: the static part differs between directions and would
  // push the loops apart.
  SvgPlot plot(title, "relative tangential displacement about its mean (mm)", "tangential contact force (N)");
  int line = 0;
  double xLow = 0, xHigh = 0;  // the loops' extent: a margin on both sides, none drawn on the frame
  for (const auto& loop : states.loops) {
    const Eigen::MatrixXd &w = loop.period.w, &f = loop.period.f;
    const int d = int(w.cols());
    for (std::size_t i = 0; i < N; ++i) {
      // Tangential columns: d - 1 of them (none for a gap element).
      auto t = [&](const Eigen::MatrixXd& m, int c) { return c < d - 1 ? m(Eigen::Index(i), c) : 0.0; };
      csv << loop.contact << "," << hz << "," << states.phase[i] << "," << t(w, 0) << "," << t(w, 1) << ","
          << w(Eigen::Index(i), d - 1) << "," << t(f, 0) << "," << t(f, 1) << "," << f(Eigen::Index(i), d - 1) << "\n";
    }
    for (int c = 0; c + 1 < d; ++c) {  // closed loops: the first sample repeated at the end
      std::vector<double> x(N + 1), y(N + 1);
      const double mean = w.col(c).mean();
      for (std::size_t i = 0; i <= N; ++i)
        x[i] = w(Eigen::Index(i % N), c) - mean, y[i] = f(Eigen::Index(i % N), c);
      xLow = std::min(xLow, *std::min_element(x.begin(), x.end()));
      xHigh = std::max(xHigh, *std::max_element(x.begin(), x.end()));
      plot.addLine(x, y, SvgPlot::palette(line++), "contact " + std::to_string(loop.contact) + ", " + tangential[c]);
    }
  }
  file.check(csv);
  file.commit();
  if (xHigh > xLow) plot.setXRange(xLow - 0.05 * (xHigh - xLow), xHigh + 0.05 * (xHigh - xLow));
  plot.write(svgPath);
}

void writePeriodResponseFiles(const std::string& csvPath, const std::string& svgPath, const std::string& title,
                              const std::vector<std::string>& names, const disc::DiscPointStates& states) {
  const double hz = states.omega / (2 * M_PI);
  const std::size_t N = states.phase.size();
  const Eigen::MatrixXd& x = states.response;
  AtomicFile file(csvPath);
  std::ofstream csv(file.tempPath());
  csv.precision(10);
  csv << "freq_hz,t_over_T";
  for (const auto& name : names) csv << "," << name;
  csv << "\n";
  SvgPlot plot(title, "t / T", "displacement (mm)");
  std::vector<double> phase(states.phase);
  phase.push_back(1.0);
  for (Eigen::Index k = 0; k < x.cols(); ++k) {
    std::vector<double> y(N + 1);
    for (std::size_t i = 0; i <= N; ++i) y[i] = x(Eigen::Index(i % N), k);
    plot.addLine(phase, y, SvgPlot::palette(int(k)), names[std::size_t(k)]);
  }
  for (std::size_t i = 0; i < N; ++i) {
    csv << hz << "," << states.phase[i];
    for (Eigen::Index k = 0; k < x.cols(); ++k) csv << "," << x(Eigen::Index(i), k);
    csv << "\n";
  }
  file.check(csv);
  file.commit();
  plot.write(svgPath);
}

void writePeakInTimeFiles(const std::string& csvPath, const std::string& svgPath, const disc::PeakInTime& check) {
  AtomicFile file(csvPath);
  std::ofstream csv(file.tempPath());
  csv.precision(10);
  csv << "period,amplitude_mm\n";
  std::vector<double> period(check.amplitudeHistory.size());
  for (std::size_t k = 0; k < period.size(); ++k) {
    period[k] = double(k + 1);
    csv << k + 1 << "," << check.amplitudeHistory[k] << "\n";
  }
  file.check(csv);
  file.commit();
  char title[160];
  std::snprintf(title, sizeof title, "The peak in the time domain at %.2f Hz: max |x(t)| per period", check.hz);
  SvgPlot plot(title, "period", "max |x(t)| over the period (mm)");
  plot.addLine(period, check.amplitudeHistory, SvgPlot::palette(0), "time domain");
  if (!period.empty())
    plot.addLine({period.front(), period.back()}, {check.harmonicBalance, check.harmonicBalance}, SvgPlot::palette(1),
                 "harmonic balance", true);
  plot.write(svgPath);
}

}  // namespace cyclone::post
