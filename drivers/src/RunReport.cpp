// The report a person reads after a run: Markdown next to the figures.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "SceneStages.hpp"
#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"

namespace cyclone::scenes {

namespace {

bool exists(const std::string& dir, const std::string& name) { return std::filesystem::exists(dir + "/" + name); }

// A CSV file as a Markdown table (at most `rows` data rows).
std::string csvTable(const std::string& path, std::size_t rows) {
  std::ifstream in(path);
  std::ostringstream out;
  std::string line;
  std::size_t row = 0;
  while (std::getline(in, line)) {
    if (row > rows) {
      out << "| ... |\n";
      break;
    }
    std::string cell;
    std::stringstream cells(line);
    std::size_t columns = 0;
    out << "|";
    while (std::getline(cells, cell, ',')) out << " " << cell << " |", ++columns;
    out << "\n";
    if (row == 0) {
      out << "|";
      for (std::size_t c = 0; c < columns; ++c) out << "---|";
      out << "\n";
    }
    ++row;
  }
  return out.str();
}

// The modal and reduced-model sections: Campbell and SAFE diagrams, resonances, the
// reduced model's check.
void modalSections(std::ostringstream& r, const std::string& outDir) {
  if (exists(outDir, "campbell.svg") || exists(outDir, "safe.svg")) {
    r << "## Modes: Campbell and SAFE diagrams\n\nPrestressed modes of every nodal diameter (`frequencies.csv`, "
         "`modes_<rpm>rpm.exo`).\n\n";
    if (exists(outDir, "campbell.svg")) r << "![Campbell diagram](campbell.svg)\n\n";
    if (exists(outDir, "safe.svg")) r << "![SAFE diagram](safe.svg)\n\n";
    if (exists(outDir, "resonances.csv"))
      r << "Engine-order resonances in the speed range (`resonances.csv`):\n\n" << csvTable(outDir + "/resonances.csv", 20)
        << "\n";
  }
  if (exists(outDir, "rom_check.svg")) {
    r << "## Reduced model against the full FE model\n\nThe reduced model's compliance at the excitation DOF against "
         "the full FE model's (a complex solve per frequency), at the engine order's nodal diameter "
         "(`rom_check.csv`).\n\n![reduced model check](rom_check.svg)\n\n";
  }
}

// A forced-response curve with its harmonics check and contacts, the time domain at the
// peak, and the stress and fatigue margin there.
void responseSections(std::ostringstream& r, const std::string& outDir) {
  for (const char* frc : {"disc_frc", "frc"})
    if (exists(outDir, std::string(frc) + ".svg")) {
      r << "## Forced response\n\nHarmonic balance (AFT) traced by pseudo-arclength continuation (`" << frc
        << ".csv`: amplitudes per harmonic, max |x(t)|, bifurcation flags; `" << frc
        << ".h5`: every coefficient).\n\n![forced response](" << frc << ".svg)\n\n";
      if (exists(outDir, std::string(frc) + "_harmonics.csv"))
        r << "The peak by harmonic truncation (`" << frc << "_harmonics.csv`: each level's peak found by a search at "
          << "fixed frequencies from the level below's, its change from that level, and its cost):\n\n"
          << csvTable(outDir + "/" + frc + "_harmonics.csv", 20) << "\n";
      if (exists(outDir, std::string(frc) + "_contacts.csv"))
        r << "Contacts at the peak (`" << frc << "_contacts.csv`):\n\n"
          << csvTable(outDir + "/" + frc + "_contacts.csv", 60) << "\n";
    }
  if (exists(outDir, "disc_hysteresis.svg"))
    r << "### Time domain at the peak\n\nTangential contact force against relative tangential displacement over one "
         "period, from the sampled contact law (`disc_hysteresis.csv`; the loop's area is the energy per cycle; "
         "`disc_response/hysteresis_contacts` chooses the contacts, default the one dissipating most):\n\n"
         "![hysteresis loops](disc_hysteresis.svg)\n\n";
  if (exists(outDir, "disc_time_response.svg"))
    r << "The response DOFs over one period (`disc_time_response.csv`):\n\n"
         "![time response](disc_time_response.svg)\n\n";
  if (exists(outDir, "disc_goodman.svg")) {
    r << "## Vibratory stress and fatigue margin at the peak\n\nThe whole sector solved with the forces the "
         "harmonic balance solution puts on the reduced model (a full FE solve per harmonic), its stresses, and "
         "per node the alternating von Mises stress (the largest excursion from the mean over the period) against "
         "the signed von Mises mean stress (prestress + harmonic 0) in the Goodman-Haigh diagram; the safety factor "
         "is the allowable alternating stress at the node's mean over its alternating stress "
         "(`disc_peak_response.exo`: per harmonic displacement, stresses, safety factor; "
         "`disc_peak_vibration.exo`: one period as time steps for ParaView).\n\n"
         "![Goodman-Haigh diagram](disc_goodman.svg)\n\nThe worst nodes (`disc_peak_stress.csv`):\n\n"
      << csvTable(outDir + "/disc_peak_stress.csv", 8) << "\n";
  }
}

// The time domain (disc_response/time_domain_check, time_domain_sweep): this run's files
// only, as the studies'.
void timeDomainSections(std::ostringstream& r, const std::string& outDir, const SceneSummary& summary) {
  const auto wrote = [&summary](const std::string& name) {
    for (const auto& path : summary.written)
      if (std::filesystem::path(path).filename() == name) return true;
    return false;
  };
  if (wrote("disc_peak_in_time.svg"))
    r << "## The peak in the time domain\n\nThe ring of reduced sectors integrated in time at the curve's largest "
         "point, started from its periodic state (`disc_peak_in_time.csv`: max |x(t)| per period; dashed, the "
         "harmonic balance's periodic amplitude):\n\n![the peak in time](disc_peak_in_time.svg)\n\n";
  if (!wrote("disc_time_sweep.svg")) return;
  r << "## The band swept in time\n\nThe ring of reduced sectors integrated at each frequency of the band, upwards, "
       "each from the last one's end (`disc_time_sweep.csv`: per preload and frequency the largest and smallest "
       "max |x(t)| per period over the end of the run, and whether it settled; dashed, the smallest where it did "
       "not):\n\n![the band swept in time](disc_time_sweep.svg)\n\n";
  if (wrote("disc_time_sweep_preload.svg"))
    r << "Per preload the largest amplitude over the band, the optimum preload (the smallest) marked "
         "(`disc_time_sweep_preload.csv`):\n\n![the largest amplitude against the preload]"
         "(disc_time_sweep_preload.svg)\n\n"
      << csvTable(outDir + "/disc_time_sweep_preload.csv", 50) << "\n";
}

// The value-list studies' figures and tables, and the peaks followed over a parameter:
// this run's only (an earlier run's study_* files in the same directory made a section of
// a run that had no studies).
void studySections(std::ostringstream& r, const std::string& outDir, const SceneSummary& summary) {
  bool studies = false;
  for (const auto& path : summary.written) {
    const std::filesystem::path entry(path);
    const auto name = entry.filename().string();
    if (name.rfind("study_", 0) != 0 || entry.extension() != ".svg") continue;
    const std::string base = name.substr(0, name.size() - 4);
    if (exists(outDir, base + ".h5")) continue;  // one curve of a study (its points): the study's figure shows it
    if (!studies) r << "## Parameter studies\n\n", studies = true;
    r << "### " << base.substr(6) << "\n\n![" << base << "](" << name << ")\n\n";
    if (exists(outDir, base + ".csv")) r << csvTable(outDir + "/" + base + ".csv", 50) << "\n";
  }
  // The peaks followed over a parameter (disc_response/peak_studies), this run's only.
  for (const auto& path : summary.written) {
    const auto name = std::filesystem::path(path).filename().string();
    if (name.rfind("peak_", 0) != 0 || std::filesystem::path(path).extension() != ".svg") continue;
    const std::string base = name.substr(0, name.size() - 4);
    if (!studies) r << "## Parameter studies\n\n", studies = true;
    const std::string parameter = base.substr(5);
    const auto& byLoca = summary.continuedPeakStudies;
    const bool continued = std::find(byLoca.begin(), byLoca.end(), parameter) != byLoca.end();
    r << "### " << parameter << ": the peak followed\n\n"
      << (continued ? "The reference curve's peak continued over the range by one LOCA continuation"
                    : "One peak search per value from the reference curve's peak")
      << " (`" << base << ".csv`; the optimum, the smallest peak, is marked; the frequency curves' peaks of the "
      << "study at the same values beside it):\n\n![" << base << "](" << name << ")\n\n";
    if (exists(outDir, base + ".csv")) r << csvTable(outDir + "/" + base + ".csv", 50) << "\n";
  }
}

}  // namespace

void writeRunReport(const std::string& outDir, const std::string& source, const SceneSummary& summary) {
  std::ostringstream r;
  r << "# Cyclone run report\n\nScene: `" << source << "`. Every figure below is a file in this directory.\n\n";
  r << "## Summary\n\n";
  for (const auto& line : summary.computed) r << "- " << line << "\n";
  r << "\n";
  if (!summary.stages.empty()) {
    r << "## Error estimate against run time, per stage\n\n| stage | run time [s] | error estimate |\n|---|---|---|\n";
    for (const auto& s : summary.stages) r << "| " << s.stage << " | " << s.seconds << " | " << s.errorEstimate << " |\n";
    r << "\n";
  }
  modalSections(r, outDir);
  responseSections(r, outDir);
  timeDomainSections(r, outDir, summary);
  studySections(r, outDir, summary);
  r << "## Files\n\n";
  for (const auto& f : summary.written) r << "- `" << std::filesystem::path(f).filename().string() << "`\n";
  AtomicFile file(outDir + "/report.md");
  std::ofstream out(file.tempPath());
  out << r.str();
  file.check(out);
  file.commit();
}

}  // namespace cyclone::scenes
