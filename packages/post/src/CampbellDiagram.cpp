#include "cyclone/post/CampbellDiagram.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/post/Mac.hpp"
#include "cyclone/post/SvgPlot.hpp"

namespace cyclone::post {

namespace {

// Shapes of one family (columns): [real; imaginary] parts of its eigenvectors.
Eigen::MatrixXd familyShapes(const cyclic::NodalDiameterModes& hm, int family) {
  const std::size_t nn = hm.shapes.numNodes();
  Eigen::MatrixXd S(6 * nn, hm.copies);
  for (int c = 0; c < hm.copies; ++c) {
    const auto shape = hm.shapes[std::size_t(family * hm.copies + c)];
    for (std::size_t n = 0; n < nn; ++n)
      for (int d = 0; d < 3; ++d) {
        S(3 * n + d, c) = shape.real[n][d];
        S(3 * nn + 3 * n + d, c) = shape.imag[n][d];
      }
  }
  return S;
}

template <class Write>
void writeAtomically(const std::string& path, Write&& write) {
  AtomicFile file(path);
  {
    std::ofstream out(file.tempPath());
    write(out);
    file.check(out);
  }
  file.commit();
}

}  // namespace

Eigen::MatrixXd familyMac(const cyclic::NodalDiameterModes& a, const cyclic::NodalDiameterModes& b) {
  const int fa = int(a.frequenciesHz.size()) / a.copies, fb = int(b.frequenciesHz.size()) / b.copies;
  Eigen::MatrixXd mac(fa, fb);
  // Each family's shapes read once (from the scratch file where the sweep keeps them).
  std::vector<Eigen::MatrixXd> second;
  for (int j = 0; j < fb; ++j) second.push_back(familyShapes(b, j));
  for (int i = 0; i < fa; ++i) {
    const Eigen::MatrixXd first = familyShapes(a, i);
    for (int j = 0; j < fb; ++j) mac(i, j) = subspaceMac(first, second[std::size_t(j)]);
  }
  return mac;
}

std::vector<Branch> trackFamilies(const std::vector<cyclic::SpeedModes>& speeds) {
  std::vector<Branch> branches;
  if (speeds.empty()) return branches;
  const auto& first = speeds.front().nodalDiameters;
  for (std::size_t h = 0; h < first.size(); ++h) {
    const auto& hm0 = first[h];
    const int families = int(hm0.frequenciesHz.size()) / hm0.copies;
    std::vector<Branch> nd(families);
    std::vector<int> current(families);  // family index at the previous speed for each branch
    for (int f = 0; f < families; ++f) {
      nd[f].nd = hm0.nodalDiameter;
      nd[f].family = f + 1;
      nd[f].rpm.push_back(speeds.front().rpm);
      nd[f].freqHz.push_back(hm0.frequenciesHz[f * hm0.copies]);
      current[f] = f;
    }
    for (std::size_t s = 1; s < speeds.size(); ++s) {
      const auto& prev = speeds[s - 1].nodalDiameters.at(h);
      const auto& next = speeds[s].nodalDiameters.at(h);
      if (next.nodalDiameter != hm0.nodalDiameter || next.frequenciesHz.size() != hm0.frequenciesHz.size())
        throw Error("Campbell tracking: speeds have different nodal diameters or mode counts");
      // Subspace MAC between every previous and next family; greedy best-first matching.
      Eigen::MatrixXd mac(families, families);
      for (int a = 0; a < families; ++a)
        for (int b = 0; b < families; ++b)
          mac(a, b) = subspaceMac(familyShapes(prev, current[a]), familyShapes(next, b));
      std::vector<int> assigned(families, -1);
      std::vector<char> taken(families, 0);
      for (int round = 0; round < families; ++round) {
        double best = -1;
        int ba = -1, bb = -1;
        for (int a = 0; a < families; ++a)
          for (int b = 0; b < families; ++b)
            if (assigned[a] < 0 && !taken[b] && mac(a, b) > best) best = mac(a, b), ba = a, bb = b;
        assigned[ba] = bb;
        taken[bb] = 1;
        nd[ba].worstMac = std::min(nd[ba].worstMac, best);
      }
      for (int a = 0; a < families; ++a) {
        current[a] = assigned[a];
        nd[a].rpm.push_back(speeds[s].rpm);
        nd[a].freqHz.push_back(next.frequenciesHz[assigned[a] * next.copies]);
      }
    }
    branches.insert(branches.end(), nd.begin(), nd.end());
  }
  return branches;
}

int foldEngineOrder(int engineOrder, int sectors) {
  int nd = ((engineOrder % sectors) + sectors) % sectors;
  return nd > sectors / 2 ? sectors - nd : nd;
}

std::vector<Resonance> findResonances(const std::vector<Branch>& branches, int sectors,
                                      const std::vector<int>& engineOrders) {
  std::vector<Resonance> out;
  for (int eo : engineOrders) {
    const int nd = foldEngineOrder(eo, sectors);
    for (const auto& b : branches) {
      if (b.nd != nd) continue;
      for (std::size_t s = 0; s + 1 < b.rpm.size(); ++s) {
        // g(rpm) = f(rpm) - EO rpm / 60 changes sign across a crossing.
        const double g0 = b.freqHz[s] - eo * b.rpm[s] / 60, g1 = b.freqHz[s + 1] - eo * b.rpm[s + 1] / 60;
        if (g0 == 0 || (g0 > 0) != (g1 > 0)) {
          const double t = g0 / (g0 - g1);
          const double rpm = b.rpm[s] + t * (b.rpm[s + 1] - b.rpm[s]);
          out.push_back({eo, nd, b.family, rpm, eo * rpm / 60});
        }
      }
    }
  }
  std::sort(out.begin(), out.end(), [](const Resonance& a, const Resonance& b) { return a.rpm < b.rpm; });
  return out;
}

void writeCampbellCsv(const std::string& path, const std::vector<Branch>& branches) {
  writeAtomically(path, [&](std::ostream& out) {
    out.precision(12);
    out << "rpm,nd,family,freq_hz,worst_mac\n";
    for (const auto& b : branches)
      for (std::size_t s = 0; s < b.rpm.size(); ++s)
        out << b.rpm[s] << "," << b.nd << "," << b.family << "," << b.freqHz[s] << "," << b.worstMac << "\n";
  });
}

void writeResonancesCsv(const std::string& path, const std::vector<Resonance>& resonances) {
  writeAtomically(path, [&](std::ostream& out) {
    out.precision(12);
    out << "eo,nd,family,rpm,freq_hz\n";
    for (const auto& r : resonances)
      out << r.engineOrder << "," << r.nd << "," << r.family << "," << r.rpm << "," << r.freqHz << "\n";
  });
}

void writeCampbellSvg(const std::string& path, const std::vector<Branch>& branches,
                      const std::vector<int>& engineOrders, const std::vector<Resonance>& resonances) {
  SvgPlot plot("Campbell diagram (modes tracked by MAC)", "speed (rpm)", "frequency (Hz)");
  double rpmMax = 0, fMax = 0;
  std::map<int, bool> labelled;
  for (const auto& b : branches) {
    rpmMax = std::max(rpmMax, b.rpm.back());
    fMax = std::max(fMax, *std::max_element(b.freqHz.begin(), b.freqHz.end()));
    const bool label = !labelled[b.nd];
    labelled[b.nd] = true;
    plot.addLine(b.rpm, b.freqHz, SvgPlot::palette(b.nd), label ? "ND " + std::to_string(b.nd) : "");
  }
  plot.setXRange(0, rpmMax);
  plot.setYRange(0, fMax * 1.05);
  double lastLabel = -1e300;
  for (int eo : engineOrders) {
    plot.addLine({0, rpmMax}, {0, eo * rpmMax / 60}, "#999", "", true, 1.0);
    // Label where the line leaves the plot, skipping labels that would overlap.
    const double end = eo * rpmMax / 60;
    if (end < fMax * 1.05 && end - lastLabel > 0.03 * fMax) {
      plot.addText(rpmMax * 0.93, end, "EO " + std::to_string(eo), "#666");
      lastLabel = end;
    }
  }
  std::vector<double> rx, ry;
  for (const auto& r : resonances) rx.push_back(r.rpm), ry.push_back(r.freqHz);
  if (!rx.empty()) plot.addMarkers(rx, ry, "#000", "resonance", 4);
  plot.write(path);
}

void writeSafeSvg(const std::string& path, const std::vector<Branch>& branches, int sectors,
                  const std::vector<int>& engineOrders, const std::vector<Resonance>& resonances) {
  SvgPlot plot("SAFE (ZZENF) diagram", "nodal diameter", "frequency (Hz)");
  plot.setIntegerXTicks(true);
  std::map<int, std::vector<const Branch*>> byFamily;
  double rpmMin = 1e300, rpmMax = 0, fMax = 0;
  for (const auto& b : branches) {
    byFamily[b.family].push_back(&b);
    rpmMin = std::min(rpmMin, b.rpm.front());
    rpmMax = std::max(rpmMax, b.rpm.back());
    fMax = std::max(fMax, *std::max_element(b.freqHz.begin(), b.freqHz.end()));
  }
  for (auto& [family, list] : byFamily) {
    std::sort(list.begin(), list.end(), [](const Branch* a, const Branch* b) { return a->nd < b->nd; });
    std::vector<double> nd, lo, hi;
    for (const auto* b : list) nd.push_back(b->nd), lo.push_back(b->freqHz.front()), hi.push_back(b->freqHz.back());
    const auto color = SvgPlot::palette(family - 1);
    plot.addLine(nd, hi, color, "family " + std::to_string(family) + " at " + std::to_string(int(rpmMax)) + " rpm");
    if (rpmMax > rpmMin) plot.addLine(nd, lo, color, "", true, 1.0);
    plot.addMarkers(nd, hi, color, "", 2.5);
  }
  // Engine-order zig-zag at the top speed: EO e excites ND fold(e); consecutive EOs join.
  std::vector<double> zx, zy;
  for (int eo : engineOrders) zx.push_back(foldEngineOrder(eo, sectors)), zy.push_back(eo * rpmMax / 60);
  if (!zx.empty()) plot.addLine(zx, zy, "#999", "EO lines at " + std::to_string(int(rpmMax)) + " rpm", true, 1.0);
  std::vector<double> rx, ry;
  for (const auto& r : resonances) rx.push_back(r.nd), ry.push_back(r.freqHz);
  if (!rx.empty()) plot.addMarkers(rx, ry, "#000", "resonance", 4);
  plot.setXRange(0, sectors / 2);
  plot.setYRange(0, fMax * 1.05);
  plot.write(path);
}

}  // namespace cyclone::post
