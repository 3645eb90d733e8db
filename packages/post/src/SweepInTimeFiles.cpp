#include "cyclone/post/SweepInTimeFiles.hpp"

#include <cstdio>
#include <fstream>

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/post/SvgPlot.hpp"

namespace cyclone::post {

std::vector<std::string> writeSweepInTimeFiles(const std::string& directory, const std::string& stem,
                                               const disc::PreloadSweepsInTime& sweeps) {
  std::vector<std::string> written;
  const std::string base = directory + "/" + stem;
  {
    AtomicFile file(base + ".csv");
    std::ofstream csv(file.tempPath());
    csv.precision(10);
    csv << "preload_n,frequency_hz,largest_mm,smallest_mm,steady,periods,seconds\n";
    for (const auto& s : sweeps.sweeps)
      for (const auto& p : s.points)
        csv << s.preload << "," << p.hz << "," << p.largest << "," << p.smallest << "," << (p.steady() ? 1 : 0) << ","
            << p.periods << "," << p.seconds << "\n";
    file.check(csv);
    file.commit();
    written.push_back(base + ".csv");
  }
  SvgPlot plot("The ring in time: max |x(t)| per period against the frequency", "frequency (Hz)",
               "max |x(t)| per period (mm)");
  for (std::size_t i = 0; i < sweeps.sweeps.size(); ++i) {
    const auto& s = sweeps.sweeps[i];
    std::vector<double> hz, largest, smallest;
    bool unsteady = false;
    for (const auto& p : s.points) {
      hz.push_back(p.hz), largest.push_back(p.largest), smallest.push_back(p.smallest);
      unsteady = unsteady || !p.steady();
    }
    char label[64];
    std::snprintf(label, sizeof label, "preload %g N", s.preload);
    plot.addLine(hz, largest, SvgPlot::palette(int(i)), label);
    if (unsteady) plot.addLine(hz, smallest, SvgPlot::palette(int(i)), "", true);
  }
  plot.write(base + ".svg");
  written.push_back(base + ".svg");
  if (sweeps.sweeps.size() < 2) return written;

  std::vector<double> preload, largest;
  {
    AtomicFile file(base + "_preload.csv");
    std::ofstream csv(file.tempPath());
    csv.precision(10);
    csv << "preload_n,largest_mm,at_hz,steady,optimum\n";
    for (std::size_t i = 0; i < sweeps.sweeps.size(); ++i) {
      const auto& s = sweeps.sweeps[i];
      const auto& p = s.points[s.largestIndex()];
      preload.push_back(s.preload), largest.push_back(s.largest());
      csv << s.preload << "," << s.largest() << "," << p.hz << "," << (p.steady() ? 1 : 0) << ","
          << (int(i) == sweeps.optimum ? 1 : 0) << "\n";
    }
    file.check(csv);
    file.commit();
    written.push_back(base + "_preload.csv");
  }
  SvgPlot byPreload("The ring in time: the largest amplitude over the band against the preload", "preload (N)",
                    "largest max |x(t)| per period (mm)");
  byPreload.addLine(preload, largest, SvgPlot::palette(0), "time domain");
  byPreload.addMarkers(preload, largest, SvgPlot::palette(0));
  if (sweeps.optimum >= 0) {
    const auto i = std::size_t(sweeps.optimum);
    byPreload.addMarkers({preload[i]}, {largest[i]}, SvgPlot::palette(1),
                         sweeps.optimumInside() ? "the optimum preload" : "the smallest (at the range's end)", 6.0);
  }
  byPreload.write(base + "_preload.svg");
  written.push_back(base + "_preload.svg");
  return written;
}

}  // namespace cyclone::post
