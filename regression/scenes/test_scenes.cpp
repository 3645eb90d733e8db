// Scenes through the library entry point: the demo's products exist and are
// physically sane; bad scenes give errors naming the file and key and leave no
// product behind.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/file.h>
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <cerrno>
#include <iostream>
#include <iterator>
#include <filesystem>
#include <fstream>
#include <map>
#include <algorithm>
#include <regex>
#include <sstream>

#include "cyclone/core/Error.hpp"
#include "cyclone/disc/DiscParameterStudy.hpp"
#include "cyclone/disc/DiscPeakFollowing.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/mesh/ExodusIO.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/mesh/AbaqusIO.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"
#include "cyclone/io/ReducedModelFile.hpp"
#include "cyclone/io/ResponseCurveFile.hpp"
#include "cyclone/io/TraceCheckpointDirectory.hpp"
#include "cyclone/scenes/ForcedResponseScene.hpp"
#include "cyclone/scenes/SceneRunner.hpp"

using namespace cyclone;
namespace fs = std::filesystem;

namespace {

fs::path freshDir(const std::string& name) {
  const auto dir = fs::temp_directory_path() / ("cyclone_scene_test_" + name);
  fs::remove_all(dir);
  return dir;
}

std::string smallScene(const std::string& extra = "", const std::string& sectorExtra = "") {
  return "cyclone:\n"
         "  analysis: static\n"
         "  mesh:\n"
         "    source: shrouded_sector\n"
         "    shrouded_sector:\n"
         "      mesh_size: 10.0\n" +
         sectorExtra +
         "  constraints:\n"
         "    fixed_node_sets: [bore]\n"
         "  loads:\n"
         "    speed_rpm: 10000.0\n" +
         extra;
}

// Runs a scene that must fail; returns the message.
std::string failure(const std::string& yaml, const fs::path& dir) {
  scenes::SceneOverrides o;
  o.outputDirectory = dir.string();
  try {
    scenes::runSceneText(yaml, "bad.yaml", o, Tpetra::getDefaultComm());
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "scene did not fail";
  return "";
}

// The Duffing scene with one value replaced (a regex on its text).
std::string duffingSceneWith(const std::string& pattern, const std::string& replacement) {
  std::ifstream in(CYCLONE_SCENE_DIR "/duffing.yaml");
  std::stringstream text;
  text << in.rdbuf();
  return std::regex_replace(text.str(), std::regex(pattern), replacement);
}

// frequencies.csv as (rpm, nd) -> frequencies in mode order; checks the header.
std::map<std::pair<double, int>, std::vector<double>> readFrequencies(const fs::path& dir) {
  std::map<std::pair<double, int>, std::vector<double>> f;
  std::ifstream csv(dir / "frequencies.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "rpm,nd,mode,freq_hz");
  while (std::getline(csv, line)) {
    double rpm, hz;
    int nd, mode;
    EXPECT_EQ(std::sscanf(line.c_str(), "%lf,%d,%d,%lf", &rpm, &nd, &mode, &hz), 4) << line;
    f[{rpm, nd}].push_back(hz);
  }
  return f;
}


// Hill's verdicts along every disc curve in a directory (reduced models: the
// modal realization): computed at every point (1, 0, or 2 undetermined), and no
// point strictly inside a backward stretch of the frequency between two folds
// (the middle branch of an overhang: a saddle, from the path alone) is called
// stable. Returns how many such points were checked.
int expectNoStableMiddleBranch(const fs::path& dir) {
  int checked = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (e.path().extension() != ".csv" || !(name.rfind("disc_frc", 0) == 0 || name.rfind("study_", 0) == 0)) continue;
    std::ifstream csv(e.path());
    std::string header;
    std::getline(csv, header);
    std::vector<std::string> names;
    std::stringstream hs(header);
    for (std::string c; std::getline(hs, c, ',');) names.push_back(c);
    const auto col = [&](const std::string& n) { return std::find(names.begin(), names.end(), n) - names.begin(); };
    const long f = col("freq_hz"), st = col("stable");
    if (f == long(names.size()) || st == long(names.size())) continue;  // a study's table, not a curve
    const long fl = col("bifurcation"), sg = col("segment");
    EXPECT_LT(sg, long(names.size())) << name << ": no segment column";
    std::vector<double> hz;
    std::vector<std::string> verdict, flag, segment;
    for (std::string line; std::getline(csv, line);) {
      std::vector<std::string> cells;
      std::stringstream ls(line);
      for (std::string c; std::getline(ls, c, ',');) cells.push_back(c);
      if (line.back() == ',') cells.push_back("");
      hz.push_back(std::stod(cells.at(f)));
      verdict.push_back(cells.at(st));
      flag.push_back(fl < long(cells.size()) ? cells[fl] : "");
      segment.push_back(sg < long(cells.size()) ? cells[sg] : "");
    }
    // A curve whose system is too large for Hill's method by default (stability: auto,
    // n nc > 1500: the demo's H = 6 curves) has no verdict at any point; otherwise every
    // point has one.
    if (std::all_of(verdict.begin(), verdict.end(), [](const std::string& v) { return v.empty(); })) continue;
    for (std::size_t i = 0; i < hz.size(); ++i)
      EXPECT_TRUE(verdict[i] == "0" || verdict[i] == "1" || verdict[i] == "2") << name << " point " << i << ": '" << verdict[i] << "'";
    // Backward: against the sweep's direction, within one sweep (the first sweeps up; a
    // second one, from the range's end, sweeps down).
    const auto back = [&](std::size_t j, std::size_t k) {  // the step j -> k (neighbours)
      return segment[j] == segment[k] && (segment[j] == "0" ? hz[k] < hz[j] : hz[k] > hz[j]);
    };
    for (std::size_t i = 1; i + 1 < hz.size(); ++i) {
      if (!back(i - 1, i) || !back(i, i + 1)) continue;
      std::size_t a = i, b = i;  // the backward stretch's ends
      while (a > 0 && back(a - 1, a)) --a;
      while (b + 1 < hz.size() && back(b, b + 1)) ++b;
      if (flag[a] != "fold" || flag[b] != "fold") continue;
      ++checked;
      EXPECT_NE(verdict[i], "1") << name << ": point " << i << " at " << hz[i] << " Hz lies between two folds";
    }
  }
  return checked;
}

}  // namespace

// The demo's products: those of the suite's `cyclone demo` run (cyclone_demo_runs, the
// README's first command, at the shipped mesh size) when CYCLONE_DEMO_OUTPUT names its
// directory, so the suite runs the demo once; else the demo run here at mesh size 12.
// The summary's lines are read back from report.md, the files from run_manifest.txt.
struct DemoRun {
  fs::path dir;
  scenes::SceneSummary summary;
};

DemoRun demoProducts() {
  DemoRun run;
  if (const char* given = std::getenv("CYCLONE_DEMO_OUTPUT")) {
    run.dir = given;
    std::ifstream report(run.dir / "report.md");
    std::string line;
    bool inSummary = false;
    while (std::getline(report, line)) {
      if (line.rfind("## ", 0) == 0) inSummary = line == "## Summary";
      else if (inSummary && line.rfind("- ", 0) == 0) run.summary.computed.push_back(line.substr(2));
    }
    std::ifstream manifest(run.dir / "run_manifest.txt");
    while (std::getline(manifest, line))
      if (line.rfind("  - ", 0) == 0) run.summary.written.push_back((run.dir / line.substr(4)).string());
    return run;
  }
  run.dir = freshDir("demo");
  scenes::SceneOverrides o;
  o.outputDirectory = run.dir.string();
  o.meshSize = 12.0;
  run.summary = scenes::runSceneText(scenes::demoScene(), "demo", o, Tpetra::getDefaultComm());
  return run;
}

namespace {

// The demo's checks, one product each (DemoSceneWritesSaneProducts runs them in turn).
void checkFollowedPeaks(const fs::path& dir) {
  // The peak continued over the preload (peak_studies, one LOCA continuation): at the
  // value-list study's preloads (the range's ends and the scene's preload, points of the
  // continuation) it meets the peaks of the frequency curves traced there, to what those
  // curves resolve of their flat, friction-damped tops (a curve's largest point, which a
  // study reports: up to 2.3e-3 on the 12 mm disc of earlier demos at 50 N, whose curve
  // stepped 1.35 Hz across its top; tops of micro-folds 1.1e-3 deep at 300 N).
  {
    auto rows = [&](const char* name) {
      std::ifstream in(dir / name);
      std::string line;
      std::getline(in, line);
      std::vector<std::vector<double>> out;
      while (std::getline(in, line)) {
        std::stringstream cells(line);
        std::vector<double> row;
        for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
        out.push_back(row);
      }
      return out;
    };
    const auto followed = rows("peak_preload.csv"), swept = rows("study_preload.csv");
    ASSERT_GE(followed.size(), 5u);  // LOCA's points, the range's ends and the scene's preload among them
    int optima = 0, compared = 0;
    for (std::size_t i = 0; i < followed.size(); ++i) {
      optima += followed[i][4] == 1;
      if (i > 0) {
        EXPECT_GT(followed[i][0], followed[i - 1][0]);
      }
    }
    EXPECT_EQ(optima, 1);
    // peak_preload.h5: every peak's whole solution, its max |x(t)| the CSV's.
    const auto h5 = io::readResponseCurveHdf5((dir / "peak_preload.h5").string());
    ASSERT_EQ(h5.parameter.size(), followed.size());
    const auto& H = h5.harmonics;
    for (std::size_t i = 0; i < followed.size(); ++i) {
      EXPECT_NEAR(h5.parameter[i] / followed[i][0], 1.0, 1e-9);  // the CSV has 10 digits
      const Eigen::VectorXd dof0 = h5.coefficients[i].head(h5.numCoefficients);
      EXPECT_NEAR(hbm::peakMagnitude(hbm::HarmonicSet(H), dof0) / followed[i][2], 1.0, 1e-9) << i;
    }
    for (const auto& s : swept) {
      if (s[4] != 1) continue;  // a study curve left incomplete: its peak is not a reference
      for (const auto& f : followed)
        if (std::abs(f[0] - s[0]) <= 1e-9 * s[0]) {
          ++compared;
          EXPECT_NEAR(f[2] / s[2], 1.0, 5e-3) << "preload " << s[0];
          EXPECT_NEAR(f[1] / s[1], 1.0, 1e-3) << "preload " << s[0];
        }
    }
    EXPECT_GE(compared, 3);
  }
}

void checkReportSections(const fs::path& dir) {
  {
    std::ifstream report(dir / "report.md");
    const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
    for (const char* section : {"## Error estimate against run time", "![SAFE diagram](safe.svg)",
                                "![reduced model check](rom_check.svg)", "![forced response](disc_frc.svg)",
                                "### preload", "The peak by harmonic truncation (`disc_frc_harmonics.csv`",
                                "### preload: the peak followed", "![peak_preload](peak_preload.svg)"})
      EXPECT_NE(text.find(section), std::string::npos) << section;
  }
}

void checkHarmonicsLevelsAndHeadline(const fs::path& dir) {
  // The harmonics check's peaks (harmonics: auto up to 7): the H = 1 level, found by the
  // search from the H = 1 curve's largest point, lies at or just above that point (the
  // curve samples the continuous peak); the levels above are there, found or with a
  // reason. Where the target is met, disc_frc is the curve traced again with the last
  // level's harmonics: that level's peak then lies at or just above its largest point.
  {
    std::ifstream curve(dir / "disc_frc.csv");
    std::string line, header;
    std::getline(curve, header);
    const std::string maxColumn = header.substr(0, header.find("_max,"));  // up to the first DOF's max
    const int column = int(std::count(maxColumn.begin(), maxColumn.end(), ','));
    double traced = 0;
    while (std::getline(curve, line)) {
      std::stringstream cells(line);
      std::string cell;
      for (int c = 0; c <= column; ++c) std::getline(cells, cell, ',');
      traced = std::max(traced, std::stod(cell));
    }
    std::ifstream levels(dir / "disc_frc_harmonics.csv");
    std::getline(levels, line);
    std::vector<std::string> rows;
    while (std::getline(levels, line)) rows.push_back(line);
    ASSERT_GE(rows.size(), 2u);  // a level not found ends the list
    ASSERT_LE(rows.size(), 7u);
    int H = 0, found = 0;
    double peak = 0, hz = 0;
    ASSERT_EQ(std::sscanf(rows[0].c_str(), "%d,%d,%lf,%lf", &H, &found, &peak, &hz), 4) << rows[0];
    EXPECT_EQ(H, 1);
    EXPECT_EQ(found, 1);
    {  // the target met (each of the last two changes at most 1 %): the curve is the last level's
      double c1 = -1, c2 = -1;
      const bool lastFound = std::sscanf(rows.back().c_str(), "%*d,%d,%*f,%*f,%lf", &found, &c1) == 2 && found == 1;
      const bool beforeFound = rows.size() >= 3 &&
                               std::sscanf(rows[rows.size() - 2].c_str(), "%*d,%d,%*f,%*f,%lf", &found, &c2) == 2 &&
                               found == 1;
      if (lastFound && beforeFound && c1 <= 1e-2 && c2 <= 1e-2) {
        ASSERT_EQ(std::sscanf(rows.back().c_str(), "%d,%d,%lf,%lf", &H, &found, &peak, &hz), 4) << rows.back();
      }
    }
    std::printf("demo peak: traced %.6e, searched %.6e at %.2f Hz\n", traced, peak, hz);
    // The search's peak is a local maximum, so no point of the curve lies above it by
    // more than what the solves leave: both are solutions to a residual of 1e-8 of the
    // forces (the disc's Newton tolerance), which near a resonance of quality Q is an
    // error of up to about Q x 1e-8 in the response (3.4e-6 measured, Q ~ 300).
    EXPECT_GE(peak, traced * (1 - 1e-5));
    EXPECT_LE(peak, 1.05 * traced);
    for (std::size_t i = 1; i < rows.size(); ++i) {
      ASSERT_EQ(std::sscanf(rows[i].c_str(), "%d,%d", &H, &found), 2) << rows[i];
      EXPECT_EQ(std::count(rows[i].begin(), rows[i].end(), ','), 9) << "10 cells, the note's commas escaped: " << rows[i];
      EXPECT_EQ(H, int(i) + 1);
      if (!found) {
        EXPECT_EQ(i + 1, rows.size()) << "a level not found ends the list";
        EXPECT_GT(rows[i].size(), 20u) << "a level not found says why: " << rows[i];
      }
    }
    // The report's headline is the highest level found, with its change from the level
    // below: converged (to 1 %) or labelled an estimate.
    int lastH = 0, notFoundH = -1;
    double lastPeak = 0, lastHz = 0, lastChange = -1, changeBefore = -1;
    for (const auto& row : rows) {
      int h = 0, f = 0;
      double v = 0, z = 0, c = -1;
      const int cells = std::sscanf(row.c_str(), "%d,%d,%lf,%lf,%lf", &h, &f, &v, &z, &c);
      if (cells >= 4 && f == 1) changeBefore = lastChange, lastH = h, lastPeak = v, lastHz = z, lastChange = c;
      if (cells >= 2 && f == 0) notFoundH = h;
    }
    std::ifstream report(dir / "report.md");
    const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
    const auto at = text.find("- friction-damped peak: max|x(t)| ");
    ASSERT_NE(at, std::string::npos) << "the report states the headline peak";
    double value = 0, headHz = 0;
    int headH = 0;
    ASSERT_EQ(std::sscanf(text.c_str() + at, "- friction-damped peak: max|x(t)| %lf at %lf Hz with harmonics 0..%d",
                          &value, &headHz, &headH),
              3);
    EXPECT_EQ(headH, lastH);
    EXPECT_NEAR(value, lastPeak, 1e-5 * lastPeak);
    EXPECT_NEAR(headHz, lastHz, 1e-5 * lastHz);
    const std::string headline = text.substr(at, text.find('\n', at) - at);
    std::printf("%s\n", headline.c_str());
    // The demo asks for harmonics by an error target (1 %): converged when each of the
    // last two raises changed the peak by at most that, and the curve is then the one
    // traced whole with those harmonics.
    const bool met = lastChange >= 0 && lastChange <= 1e-2 && changeBefore >= 0 && changeBefore <= 1e-2;
    EXPECT_NE(headline.find(met ? "converged in the harmonics to 1 %" : "an estimate"), std::string::npos) << headline;
    if (met) {
      EXPECT_NE(headline.find("the curve traced whole with H = " + std::to_string(lastH)), std::string::npos) << headline;
    }
    // A level tried above the headline's and not found is said: the last change then
    // does not bound the error.
    if (notFoundH >= 0)
      EXPECT_NE(headline.find("H = " + std::to_string(notFoundH) + " was tried and its peak not found"),
                std::string::npos)
          << headline;
    else
      EXPECT_EQ(headline.find("was tried"), std::string::npos) << headline;
  }
}

void checkContactEnergies(const fs::path& dir, std::map<int, double>& energies) {
  // Friction dissipates: every contact's energy per cycle at the peak is >= 0, some > 0.
  {
    std::ifstream csv(dir / "disc_frc_contacts.csv");
    std::string line;
    std::getline(csv, line);
    double total = 0;
    while (std::getline(csv, line)) {
      double e = 0;
      int contact = -1;
      ASSERT_EQ(std::sscanf(line.c_str(), "%d,%*f,%lf", &contact, &e), 2) << line;
      EXPECT_GE(e, -1e-12) << line;
      total += e, energies[contact] = e;
    }
    EXPECT_GT(total, 0.0);
  }
}

void checkHysteresisLoop(const fs::path& dir, const std::map<int, double>& energies) {
  // The hysteresis loop of the contact dissipating most (the default choice):
  // every sample obeys Coulomb's law |f_t| <= mu f_n (mu = 0.4 in the demo),
  // and the loop's area (trapezoidal rule over the samples) is the energy per
  // cycle that the contacts CSV computed from the harmonics.
  {
    std::ifstream csv(dir / "disc_hysteresis.csv");
    std::string line;
    std::getline(csv, line);
    std::vector<std::array<double, 6>> s;
    int contact = -1;
    while (std::getline(csv, line)) {
      std::array<double, 6> v{};
      ASSERT_EQ(std::sscanf(line.c_str(), "%d,%*f,%*f,%lf,%lf,%*f,%lf,%lf,%lf", &contact, &v[0], &v[1], &v[2], &v[3],
                            &v[4]), 6) << line;
      s.push_back(v);
    }
    ASSERT_GE(s.size(), 64u);
    double area = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const auto &a = s[i], &b = s[(i + 1) % s.size()];
      EXPECT_LE(std::hypot(a[2], a[3]), 0.4 * a[4] * (1 + 1e-9) + 1e-12) << "sample " << i;
      area += 0.5 * (a[2] + b[2]) * (b[0] - a[0]) + 0.5 * (a[3] + b[3]) * (b[1] - a[1]);
    }
    double largest = 0;
    for (const auto& [c, e] : energies) largest = std::max(largest, e);
    EXPECT_EQ(energies.at(contact), largest);
    std::printf("hysteresis loop of contact %d: area %.6e, energy from the harmonics %.6e\n", contact, area, largest);
    EXPECT_NEAR(area, largest, 0.02 * largest);
  }

}

void checkPeakStress(const fs::path& dir, const scenes::SceneSummary& summary, double& safetyFactor) {
  // The sector's vibration at the peak: the full FE field at the retained DOFs against the
  // harmonic balance solution (the reduced model's error); the headline's safety factor is
  // the worst node's, and the Goodman closed form of its own mean and alternating stress.
    for (const char* f : {"disc_peak_response.exo", "disc_peak_vibration.exo", "disc_peak_stress.csv", "disc_goodman.svg"})
      EXPECT_TRUE(fs::exists(dir / f)) << f;
    double fieldError = -1;
    for (const auto& line : summary.computed)
      if (const auto at = line.find("differs from the harmonic balance solution by "); at != std::string::npos)
        fieldError = std::stod(line.substr(at + 46));
    std::printf("whole field at the retained DOFs against the harmonic balance solution: %.2e\n", fieldError);
    EXPECT_GE(fieldError, 0.0);
    EXPECT_LT(fieldError, 1e-3);  // the hybrid model with 20 modes per ND: a few 1e-6 on the default mesh
    std::ifstream csv(dir / "disc_peak_stress.csv");
    std::string line;
    std::getline(csv, line);
    std::getline(csv, line);
    long node = 0;
    double x, y, z, mean, alt, principal, top, factor;
    ASSERT_EQ(std::sscanf(line.c_str(), "%ld,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &node, &x, &y, &z, &mean, &alt,
                          &principal, &top, &factor), 9) << line;
    // Ti-6Al-4V: S_e (1 - s_m / S_u), at most S_y - |s_m| (tensile mean here).
    const double allowed = std::min(510 * (1 - std::max(mean, 0.0) / 950), 880 - std::abs(mean));
    EXPECT_NEAR(factor, allowed / alt, 1e-6 * factor);
    EXPECT_GT(alt, 0.0);
    EXPECT_GE(principal, alt / std::sqrt(3.0));  // von Mises is at most sqrt(3) times the largest principal
    std::ifstream report(dir / "report.md");
    const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("![Goodman-Haigh diagram](disc_goodman.svg)"), std::string::npos);
    const auto at = text.find("- fatigue margin at ");
    ASSERT_NE(at, std::string::npos) << "the report states the margin";
    const std::string headline = text.substr(at, text.find('\n', at) - at);
    std::printf("%s\n", headline.c_str());
    EXPECT_NE(headline.find("critical node " + std::to_string(node) + " "), std::string::npos) << headline;
    const auto sf = headline.find("safety factor ");
    ASSERT_NE(sf, std::string::npos);
    EXPECT_NEAR(std::stod(headline.substr(sf + 14)), factor, 1e-3 * factor);
    safetyFactor = factor;
}

void checkPeakAnimation(const fs::path& dir) {
    // The animation's first step (t = 0) is the sum of the harmonics' real parts.
    const auto fields = mesh::readExodusResults((dir / "disc_peak_response.exo").string());
    const auto period = mesh::readExodusResults((dir / "disc_peak_vibration.exo").string());
    ASSERT_EQ(period.steps.size(), 32u);
    ASSERT_EQ(period.nodalNames[0], "u_x");
    double worst = 0, largest = 0;
    for (std::size_t n = 0; n < period.steps[0].nodal[0].size(); ++n) {
      double sum = 0;
      for (std::size_t v = 0; v < fields.nodalNames.size(); ++v) {
        const auto& name = fields.nodalNames[v];
        if (name == "u_h0_x" || (name.rfind("u_h", 0) == 0 && name.size() > 8 && name.substr(name.size() - 5) == "_re_x"))
          sum += fields.steps[0].nodal[v][n];
      }
      worst = std::max(worst, std::abs(sum - period.steps[0].nodal[0][n]));
      largest = std::max(largest, std::abs(sum));
    }
    EXPECT_LT(worst, 1e-12 + 1e-12 * largest);
    EXPECT_GT(largest, 0.0);
}

void checkExodusWithMeshio(const fs::path& dir, double factor) {
    // A reader other than ours opens both files and sees the fields (python3-meshio, Debian).
    const std::string script =
        "import meshio, sys\n"
        "m = meshio.read(sys.argv[1])\n"
        "need = ['u_h1_re_x', 'u_h1_im_z', 'u_h0_x', 'sigma_alt_vm', 'sigma_mean_vm_signed', 'safety_factor']\n"
        "missing = [k for k in need if k not in m.point_data]\n"
        "assert not missing, missing\n"
        "assert abs(m.point_data['safety_factor'].min() - float(sys.argv[3])) <= 1e-6 * float(sys.argv[3])\n"
        "v = meshio.read(sys.argv[2])\n"
        "assert 'u_x' in v.point_data and 'sigma_vm' in v.point_data, list(v.point_data)\n"
        "print('meshio reads', len(m.points), 'nodes,', len(m.point_data), 'fields')\n";
    {
      std::ofstream py(dir / "check_exodus.py");
      py << script;
    }
    std::ostringstream cmd;
    cmd.precision(12);
    cmd << "/usr/bin/python3 " << (dir / "check_exodus.py") << " " << (dir / "disc_peak_response.exo") << " "
        << (dir / "disc_peak_vibration.exo") << " " << factor;
    EXPECT_EQ(std::system(cmd.str().c_str()), 0) << cmd.str();
    fs::remove(dir / "check_exodus.py");
}

void checkStaticProducts(const fs::path& dir) {
  const auto mesh = mesh::readExodus((dir / "static.exo").string());
  const auto results = mesh::readExodusResults((dir / "static.exo").string());
  ASSERT_EQ(results.steps.size(), 1u);
  ASSERT_EQ(results.nodalNames.size(), 4u);
  const auto& u = results.steps[0].nodal;
  // The bore is fixed; the shroud moves outward under the centrifugal load.
  for (auto n : mesh.nodeSet("bore"))
    for (int d = 0; d < 3; ++d) EXPECT_EQ(u[d][n], 0.0);
  double radial = 0;
  for (auto n : mesh.nodeSet("shroud_left")) {
    const auto& x = mesh.coords[n];
    radial += (x[0] * u[0][n] + x[1] * u[1][n]) / std::hypot(x[0], x[1]);
  }
  EXPECT_GT(radial, 0.0);
  std::printf("middle-branch points (between folds) checked unstable: %d\n", expectNoStableMiddleBranch(dir));
  // No temporary files left behind.
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
}

}  // namespace

TEST(Scenes, DemoSceneWritesSaneProducts) {
  log::setQuiet(true);
  const auto run = demoProducts();
  const auto& dir = run.dir;
  const auto& summary = run.summary;
  ASSERT_FALSE(summary.written.empty()) << "no files listed for the demo in " << dir;
  ASSERT_FALSE(summary.computed.empty()) << "no summary for the demo in " << dir;
  for (const auto& p : summary.written) EXPECT_TRUE(fs::exists(p)) << p;
  for (const char* f : {"mesh.exo", "mesh.inp", "static.exo", "frequencies.csv", "modes_10000rpm.exo",
                        "campbell.svg", "safe.svg", "resonances.csv", "rom_check.svg", "disc_frc.csv",
                        "disc_frc_contacts.csv", "disc_hysteresis.csv", "disc_hysteresis.svg",
                        "disc_time_response.svg", "study_preload.svg", "study_preload.csv", "report.md",
                        "disc_frc_harmonics.csv", "peak_preload.csv", "peak_preload.svg"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  checkFollowedPeaks(dir);
  if (HasFatalFailure()) return;
  checkReportSections(dir);
  checkHarmonicsLevelsAndHeadline(dir);
  if (HasFatalFailure()) return;
  std::map<int, double> energies;
  checkContactEnergies(dir, energies);
  if (HasFatalFailure()) return;
  checkHysteresisLoop(dir, energies);
  if (HasFatalFailure()) return;
  double factor = 0;
  checkPeakStress(dir, summary, factor);
  if (HasFatalFailure()) return;
  checkPeakAnimation(dir);
  if (HasFatalFailure()) return;
  checkExodusWithMeshio(dir, factor);
  checkStaticProducts(dir);
}

// A small 8-sector disc (thin ring) with the bore held.
std::string discScene(const std::string& analysis) {
  return "cyclone:\n"
         "  analysis: " + analysis + "\n"
         "  mesh:\n"
         "    source: shrouded_sector\n"
         "    shrouded_sector:\n"
         "      sectors: 8\n"
         "      bore_radius: 70.0\n"
         "      mesh_size: 14.0\n"
         "  constraints:\n"
         "    fixed_node_sets: [bore]\n";
}

// The forced response of that disc at 10 000 rpm, EO 3, harmonic 1, 5 N preload, 20 N;
// a test appends keys of disc_response.
std::string discResponseScene() {
  return discScene("disc_response") +
         "  loads:\n"
         "    speed_rpm: 10000.0\n"
         "  reduced_model:\n"
         "    prestress: linear\n"
         "    check_frequencies: 0\n"
         "  disc_response:\n"
         "    engine_order: 3\n"
         "    harmonics: 1\n"
         "    contact:\n"
         "      law: per_pair\n"
         "      preload: 5.0\n"
         "    excitation:\n"
         "      amplitude: 20.0\n";
}

// Reduced models: built once, reused while the inputs match, rebuilt when one changes.
TEST(Scenes, ReducedModelsAreReusedWhileTheirInputsMatch) {
  log::setQuiet(true);
  const auto dir = freshDir("rom_cache");
  auto scene = [](int modes, const std::string& nds) {
    return discScene("reduced_model") +
           "  loads:\n"
           "    speed_rpm: 10000.0\n"
           "  reduced_model:\n"
           "    prestress: linear\n"
           "    modes: " + std::to_string(modes) + "\n"
           "    nodal_diameters: " + nds + "\n";
  };
  scenes::SceneOverrides o;
  o.outputDirectory = dir.string();
  auto line = [](const scenes::SceneSummary& s) {
    for (const auto& l : s.computed)
      if (l.rfind("reduced models", 0) == 0) return l;
    return std::string();
  };
  const auto first = scenes::runSceneText(scene(6, "[2]"), "rom.yaml", o, Tpetra::getDefaultComm());
  EXPECT_NE(line(first).find("1 built, 0 reused"), std::string::npos) << line(first);
  const auto second = scenes::runSceneText(scene(6, "[2]"), "rom.yaml", o, Tpetra::getDefaultComm());
  EXPECT_NE(line(second).find("0 built, 1 reused"), std::string::npos) << line(second);

  const auto third = scenes::runSceneText(scene(7, "[2]"), "rom.yaml", o, Tpetra::getDefaultComm());
  EXPECT_NE(line(third).find("1 built, 0 reused"), std::string::npos) << line(third);
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir / "reduced_models")) files += e.path().extension() == ".h5";
  EXPECT_EQ(files, 2);
  // A nodal diameter outside 0..N/2 is named.
  const auto msg = failure(scene(6, "[5]"), dir);
  EXPECT_NE(msg.find("5"), std::string::npos) << msg;
}

// A disc scene on a mesh with its own set names (issue 20: the reduced models demanded
// the built-in sector's disc_left/disc_right and ignored cyclic's keys): the built-in
// sector written as .inp with its sets renamed, the cyclic faces, the bore and the
// retained nodes named by the scene, builds the same reduced model (its eigenvalues
// equal the built-in names' to the eigen-solver's tolerance); the built-in names, absent there,
// are named in the error.
TEST(Scenes, ADiscSceneTakesTheMeshsOwnSetNames) {
  log::setQuiet(true);
  const auto dir = freshDir("own_sets");
  scenes::SceneOverrides o;
  o.outputDirectory = (dir / "builtin").string();
  const std::string rom = "  loads:\n    speed_rpm: 10000.0\n  reduced_model:\n    prestress: linear\n"
                          "    modes: 6\n    nodal_diameters: [2]\n";
  const std::string builtin = discScene("reduced_model");
  const std::string withInp = builtin.substr(0, builtin.find("  constraints:")) + "    write: [inp]\n" +
                              builtin.substr(builtin.find("  constraints:")) + rom;
  scenes::runSceneText(withInp, "builtin.yaml", o, Tpetra::getDefaultComm());
  std::ifstream in(dir / "builtin" / "mesh.inp");
  std::string inp((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"disc_left", "hub_l"}, {"disc_right", "hub_r"}, {"shroud_contact_left", "patch_l"},
           {"shroud_contact_right", "patch_r"}, {"mid_blade", "gauge"}, {"NSET=bore", "NSET=inner"}}) {
    for (std::size_t at = inp.find(from); at != std::string::npos; at = inp.find(from, at + to.size()))
      inp.replace(at, from.size(), to);
  }
  std::ofstream(dir / "own.inp") << inp;
  auto own = [&](const std::string& cyclicKeys) {
    return "cyclone:\n  analysis: reduced_model\n  mesh:\n    source: " + (dir / "own.inp").string() +
           "\n  constraints:\n    fixed_node_sets: [inner]\n  cyclic:\n    sectors: 8\n" + cyclicKeys + rom +
           "    retained_node_sets: [patch_l, patch_r, gauge]\n";
  };
  const auto missing = failure(own(""), dir / "missing");
  EXPECT_NE(missing.find("disc_left"), std::string::npos) << missing;
  o.outputDirectory = (dir / "own").string();
  scenes::runSceneText(own("    disc_left_node_sets: [hub_l]\n    disc_right_node_sets: [hub_r]\n"), "own.yaml", o,
                       Tpetra::getDefaultComm());
  auto eigenvalues = [](const fs::path& d) {
    for (const auto& e : fs::directory_iterator(d / "reduced_models"))
      if (e.path().extension() == ".h5") return io::readReducedModelHdf5(e.path().string()).modes.eigenvalues;
    return std::vector<double>();
  };
  const auto a = eigenvalues(dir / "builtin"), b = eigenvalues(dir / "own");
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  double largest = 0;
  for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, std::abs(b[i] / a[i] - 1));
  std::printf("own set names: %zu eigenvalues, largest relative difference from the built-in names' %.1e\n", a.size(),
              largest);
  // The .inp keeps 16 significant digits (CalculiX's field width): the coordinates
  // move by up to 1e-16 and the eigen-solver (whose random start vectors also depend
  // on what ran before in the process) stops at other iterates inside its tolerance
  // (1e-10 relative residual): 8e-11 .. 1.0e-10 measured. With the shroud's faces
  // cyclic too (the wrong faces for a reduced model) the lowest is 15 times larger.
  EXPECT_LT(largest, 1e-9);
}

// (Also: bad peak studies are named before any work.)
TEST(Scenes, DiscResponseEngineOrderFoldingIsExplained) {
  log::setQuiet(true);
  const auto dir = freshDir("disc_eo");
  auto scene = [](int eo, bool excitation = true) {
    return discScene("disc_response") +
           "  disc_response:\n" +
           (excitation ? "    excitation: {node_set: mid_blade, amplitude: 1.0}\n" : "") +
           "    engine_order: " + std::to_string(eo) + "\n";
  };
  EXPECT_NE(failure(scene(0), dir).find("no travelling excitation"), std::string::npos);
  const auto folded = failure(scene(11), dir);
  EXPECT_NE(folded.find("exactly as engine order 3"), std::string::npos) << folded;
  EXPECT_NE(failure(scene(8), dir).find("folds to 0"), std::string::npos);
  // Peak studies checked before any work (the reference preload is 0 here).
  auto peakStudy = [&](const std::string& entry) {
    return failure(scene(3) + "    contact:\n      preload: 5.0\n    peak_studies:\n" + entry, dir);
  };
  auto msg = peakStudy("      preload: {range: [10.0, 200.0]}\n");
  EXPECT_NE(msg.find("peak_studies/preload/range"), std::string::npos) << msg;
  EXPECT_NE(msg.find("must contain the scene's preload"), std::string::npos) << msg;
  msg = peakStudy("      preload: {range: [1.0, 0.5]}\n");
  EXPECT_NE(msg.find("0 < from < to"), std::string::npos) << msg;
  msg = peakStudy("      mu: {range: [0.1, 0.8], values: 2}\n");
  EXPECT_NE(msg.find("peak_studies/mu/values"), std::string::npos) << msg;
  msg = peakStudy("      preload: {range: [1.0, 200.0], method: bisection}\n");
  EXPECT_NE(msg.find("peak_studies/preload/method"), std::string::npos) << msg;
  EXPECT_NE(msg.find("must be peak_search"), std::string::npos) << msg;
  msg = peakStudy("      preload: {range: [1.0, 200.0], values: 8, method: continuation}\n");
  EXPECT_NE(msg.find("peak_studies/preload/values"), std::string::npos) << msg;
  EXPECT_NE(msg.find("is not used by method continuation"), std::string::npos) << msg;
  msg = peakStudy("      loss_factor: {range: [0.001, 0.05], method: continuation}\n");
  EXPECT_NE(msg.find("peak_studies/loss_factor/method"), std::string::npos) << msg;
  EXPECT_NE(msg.find("use peak_search"), std::string::npos) << msg;
  msg = peakStudy("      stiffness: {range: [1.0, 2.0]}\n");
  EXPECT_NE(msg.find("stiffness"), std::string::npos) << msg;
  // The contact stiffness is followed as kn = kt: a scene with kn != kt is refused.
  msg = failure(scene(3) + "    contact:\n      preload: 5.0\n      kn: 1.0e4\n      kt: 2.0e4\n    peak_studies:\n"
                           "      contact_stiffness: {range: [1.0e3, 1.0e5]}\n",
                dir);
  EXPECT_NE(msg.find("peak_studies/contact_stiffness/range"), std::string::npos) << msg;
  EXPECT_NE(msg.find("kn and kt must be equal"), std::string::npos) << msg;
  msg = failure(scene(3) + "    contact:\n      preload: 5.0\n      kn: 1.0e4\n      kt: 1.0e4\n    peak_studies:\n"
                           "      contact_stiffness: {range: [2.0e4, 1.0e5]}\n",
                dir);
  EXPECT_NE(msg.find("must contain the scene's contact_stiffness"), std::string::npos) << msg;
  // The loss factor's reference is the reduced models' (reduced_model/loss_factor, 0.006 by default).
  msg = peakStudy("      loss_factor: {range: [0.01, 0.05]}\n");
  EXPECT_NE(msg.find("peak_studies/loss_factor/range"), std::string::npos) << msg;
  EXPECT_NE(msg.find("must contain the scene's loss_factor (0.006"), std::string::npos) << msg;
  // The speed's reference is the reduced models' (reduced_model/speed_rpm, or loads/speed_rpm; 0 here).
  msg = peakStudy("      speed: {range: [-100.0, 12000.0]}\n");
  EXPECT_NE(msg.find("peak_studies/speed/range"), std::string::npos) << msg;
  EXPECT_NE(msg.find("0 <= from < to"), std::string::npos) << msg;
  msg = peakStudy("      speed: {range: [1000.0, 5000.0]}\n");
  EXPECT_NE(msg.find("must contain the scene's speed (0"), std::string::npos) << msg;
  // The sweep's keys too before the reduced models are built (they took 33 s on the
  // default disc before a misspelt stability was named).
  const auto early = freshDir("disc_eo_early");
  msg = failure(scene(3) + "    stability: never\n", early);
  EXPECT_NE(msg.find("disc_response/stability"), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(early / "reduced_models")) << "models built before the key was read";
  // A continuation tolerance of 0 (Newton could never meet it) before the models too.
  msg = failure(scene(3) + "    continuation:\n      tolerance: 0.0\n", early);
  EXPECT_NE(msg.find("disc_response/continuation/tolerance"), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(early / "reduced_models")) << "models built before the tolerance was read";
  // The contact law's key, and contact faces that do not pair, before the models too.
  msg = failure(scene(3) + "    contact:\n      law: per_node\n", early);
  EXPECT_NE(msg.find("disc_response/contact/law"), std::string::npos) << msg;
  EXPECT_NE(msg.find("per_area"), std::string::npos) << msg;
  msg = failure(scene(3) + "    contact:\n      right_node_set: disc_right\n", early);
  EXPECT_NE(msg.find("disc_response/contact"), std::string::npos) << msg;
  EXPECT_NE(msg.find("do not pair"), std::string::npos) << msg;
  // Issue 49's list: friction and excitation values, node sets named.
  msg = failure(scene(3) + "    contact:\n      mu: -0.1\n", early);
  EXPECT_NE(msg.find("disc_response/contact"), std::string::npos) << msg;
  msg = failure(scene(3) + "    contact:\n      kt: 0.0\n", early);
  EXPECT_NE(msg.find("disc_response/contact"), std::string::npos) << msg;
  msg = failure(scene(3, false) + "    excitation:\n      direction: [0.0, 0.0, 0.0]\n", early);
  EXPECT_NE(msg.find("disc_response/excitation/direction"), std::string::npos) << msg;
  msg = failure(scene(3, false) + "    excitation:\n      node_set: no_such_set\n", early);
  EXPECT_NE(msg.find("no_such_set"), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(early / "reduced_models")) << "models built before the contact was checked";
}

namespace {

// A curve's points between two folds on a stretch traced against its sweep's direction
// (the middle branch of an S) are not stable by Hill's method; returns how many were checked.
// The points next to a fold are not checked: on a friction curve (piecewise smooth at the
// AFT samples' resolution) the turn in frequency and the real exponent's zero crossing
// coincide only to within a step (the thin disc: the exponent crossed between the first
// and the second point after a turn at 581.0 Hz, the next four points unstable).
int expectNoStableMiddleBranch(const response::ForcedResponseResult& c) {
  const std::size_t n = c.omega.size();
  const auto back = [&](std::size_t j, std::size_t k) {  // the step j -> k against its sweep
    return c.segment[j] == c.segment[k] && (c.segment[j] == 0 ? c.omega[k] < c.omega[j] : c.omega[k] > c.omega[j]);
  };
  int checked = 0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (!back(i - 1, i) || !back(i, i + 1)) continue;
    std::size_t a = i, b = i;
    while (a > 0 && back(a - 1, a)) --a;
    while (b + 1 < n && back(b, b + 1)) ++b;
    if (c.flags[a] != "fold" || c.flags[b] != "fold" || i == a + 1 || i + 1 == b) continue;
    ++checked;
    EXPECT_NE(c.stable[i], 1) << "point " << i << " at " << c.omega[i] / (2 * M_PI)
                              << " Hz lies between two folds (points " << a << ".." << b << ", "
                              << c.omega[a] / (2 * M_PI) << ".." << c.omega[b] / (2 * M_PI) << " Hz; leading exponent "
                              << (c.leadingExponent[i] ? *c.leadingExponent[i] : std::nan("")) << ")";
  }
  return checked;
}

}  // namespace

// The thin 8-sector disc of discResponseScene through the library: its reduced models at
// 10 000 rpm (linear prestress), EO 3, H = 1, 5 N preload, 20 N, and its reference curve
// (no harmonics check).
struct ThinDisc {
  mesh::Mesh mesh;
  disc::DiscResponseSpec spec;
  disc::DiscReducedModels reduced;
  disc::DiscSweepOptions sweep;
  disc::DiscForcedResponse reference;
  ThinDisc() {
    mesh::ShroudedSectorParameters sector;
    sector.sectors = 8, sector.boreRadius = 70.0, sector.meshSize = 14.0;
    mesh = mesh::generateShroudedSector(sector);
    disc::DiscModelSpec models;
    models.sectors = 8, models.rpm = 10000.0, models.prestress = cyclic::PrestressKind::Linear;
    spec.engineOrder = 3, spec.harmonics = {0, 1}, spec.contact.preload = 5.0, spec.excitation.amplitude = 20.0;
    spec.contact.law = disc::ShroudContactSpec::Law::PerPair, spec.contact.kn = spec.contact.kt = 1e4;
    reduced = disc::buildDiscReducedModels(mesh, models, disc::nodalDiametersFor(8, 3, {0, 1}), "",
                                           Tpetra::getDefaultComm());
    sweep.harmonicsCheckTo = -1;
    reference = disc::solveDiscForcedResponse(mesh, reduced, spec, sweep);
  }
};

// Studies other than the demo's preload, by the library's values (disc::studyDisc on the
// thin 8-sector disc of discResponseScene): more damping lowers the peak, more force
// raises it; the modes study runs on fewer modes of the same models.
TEST(Scenes, DiscStudiesMoveThePeakTheWayTheoryPredicts) {
  log::setQuiet(true);
  const ThinDisc disc;
  const auto& [mesh, spec, reduced, sweep, reference] = disc;
  // The reference curve covers the sweep (its first sweep folds back to the start at about
  // 346 Hz; a second sweep from the range's end traces the rest).
  ASSERT_FALSE(reference.curve.omega.empty());
  const auto [lo, hi] = std::minmax_element(reference.curve.omega.begin(), reference.curve.omega.end());
  EXPECT_NEAR(*lo / (2 * M_PI), reference.fromHz, 1e-6 * reference.toHz);
  EXPECT_NEAR(*hi / (2 * M_PI), reference.toHz, 1e-6 * reference.toHz);
  auto studyPeak = [&](disc::DiscStudyParameter q, double value) {
    const auto curves = disc::studyDisc(mesh, reduced, spec, reference, q, {value}, sweep);
    EXPECT_EQ(curves.size(), 1u);
    EXPECT_GT(curves.front().curve.omega.size(), 10u);
    return curves.front().curve.peak;
  };
  const double damped = studyPeak(disc::DiscStudyParameter::LossFactor, 0.012),
               forced = studyPeak(disc::DiscStudyParameter::Force, 2.0),
               fewer = studyPeak(disc::DiscStudyParameter::Modes, 10);
  const double peak = reference.curve.peak;
  std::printf("peaks: reference %.4e, loss factor x2 %.4e, force x2 %.4e, 10 modes %.4e\n", peak, damped, forced,
              fewer);
  EXPECT_LT(damped, peak);
  EXPECT_GT(forced, peak);
  // Fewer modes: no bound from theory on a friction curve (7 % here on this thin test disc); the
  // study must run and give a finite peak.
  EXPECT_TRUE(std::isfinite(fewer) && fewer > 0);
  std::printf("middle-branch points (between folds) checked unstable: %d\n", expectNoStableMiddleBranch(reference.curve));
}

namespace {

// A swept curve's largest point within 2 % of `hz`, and whether it has points within
// 1 Hz on each side (a curve that jumped over the top has not).
// A followed peak's frequency against a swept curve's top: to 2e-3 (relative); the curve
// must resolve its top as finely.
constexpr double kTopFrequencyTolerance = 2e-3;

// The swept curve's largest point within 2 % of hz; resolved where the points before and
// after it along the curve lie within kTopFrequencyTolerance of it (a trace that steps
// over a top has neighbours far apart: 602.9 and 596.0 Hz about a top at 600.7 Hz; a top
// at a fold has no point above it in frequency, but close neighbours along the path).
struct SweptTop {
  double measure = 0, hz = 0, beforeHz = 0, afterHz = 0;
  bool resolved = false;
};
SweptTop sweptTopNear(const response::ForcedResponseResult& c, double hz) {
  SweptTop top;
  std::size_t at = c.measure.size();
  for (std::size_t i = 0; i < c.measure.size(); ++i) {
    const double f = c.omega[i] / (2 * M_PI);
    if (std::abs(f / hz - 1) <= 0.02 && c.measure[i] > top.measure) top.measure = c.measure[i], top.hz = f, at = i;
  }
  if (at == 0 || at + 1 >= c.measure.size()) return top;
  top.beforeHz = c.omega[at - 1] / (2 * M_PI), top.afterHz = c.omega[at + 1] / (2 * M_PI);
  top.resolved = c.segment[at - 1] == c.segment[at] && c.segment[at + 1] == c.segment[at] &&
                 std::abs(top.beforeHz / top.hz - 1) <= kTopFrequencyTolerance &&
                 std::abs(top.afterHz / top.hz - 1) <= kTopFrequencyTolerance;
  return top;
}

// A followed peak against a swept curve's top near it: the measure to what the curve
// resolves of its top (5e-3, as the demo's preload check), the frequency to 2e-3, and a
// peak search maximises, so not below the sampled top by more than its resolution.
void expectMeetsSweptTop(const std::string& what, const continuation::FollowedPeak& p, const SweptTop& top) {
  const double hz = p.frequency / (2 * M_PI);
  std::printf("  %s: followed %.6e at %.3f Hz; swept %.6e at %.3f Hz near it (%.1e, %.1e)\n", what.c_str(), p.measure,
              hz, top.measure, top.hz, p.measure / top.measure - 1, hz / top.hz - 1);
  ASSERT_GT(top.measure, 0) << what << ": the swept curve has no point within 2 % of the followed peak's " << hz
                            << " Hz";
  EXPECT_NEAR(p.measure / top.measure, 1.0, 5e-3) << what;
  EXPECT_NEAR(hz / top.hz, 1.0, kTopFrequencyTolerance) << what;
  EXPECT_GT(p.measure, top.measure * (1 - 1e-3)) << what;
}

// The thin disc's reference peak followed over `parameter` from `from` to `to` (5 values
// in log, the reference value and `swept` added), timed into `seconds`.
disc::DiscPeakFollowing followOnThinDisc(const ThinDisc& d, disc::DiscStudyParameter parameter, double from, double to,
                                         const std::vector<double>& swept, double& seconds) {
  disc::DiscPeakFollowingSpec following;
  following.parameter = parameter;
  following.from = from, following.to = to, following.values = 5, following.extraValues = swept;
  Timer timer;
  auto followed = disc::followDiscPeak(d.mesh, d.reduced, d.spec, d.reference.setup, d.reference.curve,
                                       d.reference.fromHz, d.reference.toHz, following);
  seconds = timer.seconds();
  return followed;
}

// The followed peak at `value` of the grid (none when the grid does not hold it).
const continuation::FollowedPeak* followedAt(const continuation::FollowedPeakCurve& curve, double value) {
  for (const auto& p : curve.points)
    if (std::abs(p.parameter / value - 1) <= 1e-12) return &p;
  return nullptr;
}

// The followed peak at a swept curve's value, checked as the largest: the swept curve is
// whole, the grid holds its value, and the curve's largest anywhere is not above the
// followed peak by more than what the curve resolves of its top (5e-3). Null where a
// check failed (reported).
const continuation::FollowedPeak* followedPeakOverSwept(const continuation::FollowedPeakCurve& followed,
                                                        const disc::DiscStudyCurve& c) {
  EXPECT_TRUE(c.curve.branch.finished) << c.value << ": " << c.curve.branch.stopReason;
  const continuation::FollowedPeak* match = followedAt(followed, c.value);
  EXPECT_NE(match, nullptr) << c.value;
  if (!c.curve.branch.finished || !match) return nullptr;
  EXPECT_LT(c.curve.peak, match->measure * (1 + 5e-3)) << c.value;
  return match;
}

}  // namespace

// The peak followed over the contact stiffness (kn = kt together, disc::followDiscPeak)
// against frequency curves traced independently at three stiffnesses of its grid
// (disc::studyDisc over the reference band), on the thin 8-sector disc: where the
// followed peak lies in the band it must meet the swept curve's top there to what the
// curve resolves of it (5e-3, as the demo's preload check), and no swept curve may rise
// above the followed (largest) peak.
TEST(Scenes, DiscPeakFollowedOverContactStiffnessMeetsSweptPeaks) {
  log::setQuiet(true);
  const ThinDisc disc;
  const auto& [mesh, spec, reduced, sweep, reference] = disc;
  // Two values below the scene's 1e4 N/mm, where the followed peak stays in the reference
  // band, and one above, where it leaves it: at 2e4 the followed (largest) peak is the
  // one near 1037 Hz, above the band's 998 Hz, while the curve over the band has its
  // largest near 604 Hz, 0.4 % lower (measured; the stiffer contact lifts the stuck peak).
  const std::vector<double> swept = {3.0e3, 6.0e3, 2.0e4};
  double followSeconds = 0;
  const auto followed = followOnThinDisc(disc, disc::DiscStudyParameter::ContactStiffness, 2.0e3, 5.0e4, swept,
                                         followSeconds);
  Timer timer;
  EXPECT_DOUBLE_EQ(followed.referenceValue, spec.contact.kt);
  const auto curves = disc::studyDisc(mesh, reduced, spec, reference, disc::DiscStudyParameter::ContactStiffness, swept, sweep);
  std::printf("followed over kn = kt: %zu peaks in %.1f s; %zu swept curves (%.1f..%.1f Hz) in %.1f s\n",
              followed.curve.points.size(), followSeconds, curves.size(), reference.fromHz, reference.toHz,
              timer.seconds());
  for (const auto& p : followed.curve.points)
    std::printf("  followed: kn = kt = %9.1f  %.6e at %8.3f Hz%s\n", p.parameter, p.measure,
                p.frequency / (2 * M_PI), p.jump ? " (jump)" : "");
  ASSERT_EQ(curves.size(), swept.size());
  int compared = 0;
  for (const auto& c : curves) {
    const continuation::FollowedPeak* match = followedPeakOverSwept(followed.curve, c);
    ASSERT_NE(match, nullptr) << c.value;
    const double hz = match->frequency / (2 * M_PI);
    if (hz > reference.toHz || hz < reference.fromHz) {
      std::printf("  kn = kt = %g: followed %.6e at %.3f Hz, outside the swept band; the swept curve's largest "
                  "%.6e at %.3f Hz\n", c.value, match->measure, hz, c.curve.peak, c.curve.peakOmega / (2 * M_PI));
      continue;
    }
    expectMeetsSweptTop("kn = kt = " + std::to_string(c.value), *match, sweptTopNear(c.curve, hz));
    ++compared;
  }
  EXPECT_GE(compared, 2);
  // A stiffer contact holds more: the followed peak moves up in frequency.
  EXPECT_GT(followed.curve.points.back().frequency, followed.curve.points.front().frequency);
}

// The peak followed over the reduced models' loss factor (disc::followDiscPeak, the system
// made again from the models per value) against frequency curves traced independently at
// two loss factors of its grid (disc::studyDisc, whose models are built with that loss
// factor), on the thin 8-sector disc: the followed peak meets each swept curve's top to
// what the curve resolves of it, and more structural damping lowers the peak at every
// step of the grid (a damping added to the friction's cannot raise the resonance).
TEST(Scenes, DiscPeakFollowedOverLossFactorMeetsSweptPeaks) {
  log::setQuiet(true);
  const ThinDisc disc;
  const auto& [mesh, spec, reduced, sweep, reference] = disc;
  // Two loss factors whose swept curves resolve their tops (at 0.012 the default trace
  // jumps over the top: the resolution check below would fail, docs/decisions.md; at
  // 0.003 too, from 600.78 to 603.36 Hz, once the mid-blade node became a mesh node).
  const std::vector<double> swept = {0.009, 0.02};
  double followSeconds = 0;
  const auto followed = followOnThinDisc(disc, disc::DiscStudyParameter::LossFactor, 0.002, 0.03, swept, followSeconds);
  Timer timer;
  EXPECT_DOUBLE_EQ(followed.referenceValue, 0.006);  // DiscModelSpec's default, the fixture's
  const auto curves = disc::studyDisc(mesh, reduced, spec, reference, disc::DiscStudyParameter::LossFactor, swept, sweep);
  std::printf("followed over the loss factor: %zu peaks in %.1f s; %zu swept curves in %.1f s\n",
              followed.curve.points.size(), followSeconds, curves.size(), timer.seconds());
  for (const auto& p : followed.curve.points)
    std::printf("  followed: loss factor %.4f  %.6e at %8.3f Hz%s\n", p.parameter, p.measure, p.frequency / (2 * M_PI),
                p.jump ? " (jump)" : "");
  ASSERT_TRUE(followed.curve.complete) << followed.curve.stopReason;
  for (std::size_t i = 1; i < followed.curve.points.size(); ++i)
    EXPECT_LT(followed.curve.points[i].measure, followed.curve.points[i - 1].measure)
        << "loss factor " << followed.curve.points[i].parameter;
  ASSERT_EQ(curves.size(), swept.size());
  for (const auto& c : curves) {
    const continuation::FollowedPeak* match = followedPeakOverSwept(followed.curve, c);
    ASSERT_NE(match, nullptr) << c.value;
    const double hz = match->frequency / (2 * M_PI);
    // The swept curve must resolve the top it is compared with: its neighbours along the
    // curve within the comparison's frequency tolerance (at 0.012 the curve's default
    // trace jumps from 602.9 to 596.0 Hz over the peak at 600.7 Hz: docs/decisions.md,
    // 2026-11-26).
    const SweptTop top = sweptTopNear(c.curve, hz);
    EXPECT_TRUE(top.resolved) << "loss factor " << c.value << ": the swept curve's top at " << top.hz
                              << " Hz has its neighbours along the curve at " << top.beforeHz << " and "
                              << top.afterHz << " Hz";
    expectMeetsSweptTop("loss factor " + std::to_string(c.value), *match, top);
  }
}

// Gap elements at a shroud pair (seed 8.6), on the thin disc around its friction peak.
// Closed forms: the gap's normal force at every sample of the peak's period is the
// unilateral spring's kn max(0, approach - clearance) (the clearance's size and sign reach
// the element), and it dissipates nothing over a cycle (conservative; against the
// friction contacts' energies); its tangential columns are zero. A clearance study traces
// each value (a trace key of the residual at rest alone read the 0.005 mm curve back from
// the 0.002 mm trace: a gap open at rest does not show its clearance there), both curves
// whole with their peaks inside the band, the wider clearance's peak lower (less contact
// stiffness). The peak followed over the clearance (peak_studies, issue 21: a peak search
// per value on a linear grid) meets both curves' tops. Bad gap input is named. (Until
// 2026-11-26 this test compared an incomplete
// curve's top with the far end of the range, under an interference whose 100 N at one node
// pair overloads the 5 N friction contacts: docs/decisions.md.)
TEST(Scenes, DiscGapClearanceStudyTracesEachValue) {
  log::setQuiet(true);
  const auto dir = freshDir("disc_gap");
  constexpr double kn = 1.0e4, clearance = 0.002, wider = 0.005, fromHz = 560, toHz = 660;
  auto scene = [&](const std::string& pairs) {
    return std::regex_replace(discResponseScene(), std::regex("    harmonics: 1\n"),
                              "    harmonics: 1\n    frequency_range_hz: [560.0, 660.0]\n") +
           "    gap:\n"
           "      pairs: " + pairs + "\n"
           "      kn: 1.0e4\n"
           "      clearance: 0.002\n"
           "    hysteresis_contacts: [0, 1]\n"
           "    stability: false\n"  // not what is tested here: Hill's method on ~800 points a curve
           "    studies:\n"
           "      clearance: [0.002, 0.005]\n"
           "    peak_studies:\n"
           "      clearance: {range: [-0.001, 0.005], values: 4}\n";
  };
  scenes::SceneOverrides o;
  o.outputDirectory = dir.string();
  scenes::runSceneText(scene("[0]"), "gap.yaml", o, Tpetra::getDefaultComm());
  std::ifstream csv(dir / "study_clearance.csv");
  std::string line;
  std::getline(csv, line);
  std::vector<double> values, hz, peak;
  while (std::getline(csv, line)) {
    double value, f, amplitude;
    int points, finished;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%d,%d", &value, &f, &amplitude, &points, &finished), 5) << line;
    EXPECT_EQ(finished, 1) << line;
    EXPECT_GT(f, fromHz + 1) << line;  // a peak inside the band, not at its ends
    EXPECT_LT(f, toHz - 1) << line;
    values.push_back(value), hz.push_back(f), peak.push_back(amplitude);
  }
  ASSERT_EQ(hz.size(), 2u);
  EXPECT_EQ(values[0], clearance);
  EXPECT_EQ(values[1], wider);
  std::printf("gap at pair 0: peak %.6g mm at %.3f Hz with %.3f mm clearance, %.6g mm at %.3f Hz with %.3f mm\n",
              peak[0], hz[0], clearance, peak[1], hz[1], wider);
  EXPECT_NE(peak[1], peak[0]);  // traced, not the other clearance's curve read back
  EXPECT_LT(hz[1], hz[0]);
  {  // the followed peak at the study's values: the curves' tops (to what a curve resolves, 5e-3)
    std::ifstream followed(dir / "peak_clearance.csv");
    ASSERT_TRUE(followed.good());
    std::getline(followed, line);
    int rows = 0, met = 0;
    double lowest = 1e300;
    while (std::getline(followed, line)) {
      double value, f, amplitude;
      ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf", &value, &f, &amplitude), 3) << line;
      ++rows;
      lowest = std::min(lowest, value);
      for (std::size_t i = 0; i < values.size(); ++i)
        if (std::abs(value - values[i]) <= 1e-12) {
          ++met;
          std::printf("  followed at %.3f mm: %.6g mm at %.3f Hz (swept %.6g at %.3f Hz)\n", value, amplitude, f,
                      peak[i], hz[i]);
          EXPECT_NEAR(amplitude / peak[i], 1.0, 5e-3) << value;
          EXPECT_NEAR(f / hz[i], 1.0, 1e-3) << value;
        }
    }
    EXPECT_EQ(rows, 5);  // -0.001, 0.001, 0.003, 0.005 and the scene's 0.002
    EXPECT_EQ(met, 2);
    EXPECT_NEAR(lowest, -0.001, 1e-12);  // an interference followed too (a linear grid through zero)
  }
  {  // the gap's rows at the peak: no tangential motion or force, the spring's normal force
    std::ifstream loops(dir / "disc_hysteresis.csv");
    std::getline(loops, line);
    int gapRows = 0, closed = 0;
    double worst = 0, largest = 0;
    while (std::getline(loops, line)) {
      int contact = -1;
      double slip1, slip2, approach, f1, f2, fn;
      ASSERT_EQ(std::sscanf(line.c_str(), "%d,%*f,%*f,%lf,%lf,%lf,%lf,%lf,%lf", &contact, &slip1, &slip2, &approach,
                            &f1, &f2, &fn),
                7);
      if (contact != 0) continue;
      ++gapRows;
      EXPECT_EQ(std::abs(slip1) + std::abs(slip2) + std::abs(f1) + std::abs(f2), 0.0) << line;
      worst = std::max(worst, std::abs(fn - kn * std::max(0.0, approach - clearance)));
      largest = std::max(largest, std::abs(fn));
      closed += approach > clearance;
    }
    EXPECT_GT(gapRows, 0);
    EXPECT_GT(closed, 0);  // the gap closes over part of the period: the law is exercised
    EXPECT_LT(closed, gapRows);
    EXPECT_LE(worst, 1e-6 * largest) << "largest gap force " << largest;
  }
  {  // a gap dissipates nothing over a cycle; the friction contacts do
    std::ifstream contacts(dir / "disc_frc_contacts.csv");
    std::getline(contacts, line);
    double gapEnergy = std::nan(""), frictionEnergy = 0;
    while (std::getline(contacts, line)) {
      int contact = -1;
      double energy;
      ASSERT_EQ(std::sscanf(line.c_str(), "%d,%*f,%lf", &contact, &energy), 2) << line;
      if (contact == 0) gapEnergy = energy;
      else frictionEnergy = std::max(frictionEnergy, energy);
    }
    EXPECT_GT(frictionEnergy, 0);
    ASSERT_TRUE(std::isfinite(gapEnergy)) << "no row for the gap (contact 0)";
    EXPECT_LT(std::abs(gapEnergy), 1e-3 * frictionEnergy);
  }
  const auto msg = failure(scene("[100000]"), dir);
  EXPECT_NE(msg.find("gap/pairs"), std::string::npos) << msg;
  EXPECT_NE(failure(scene("[0, 0]"), dir).find("twice"), std::string::npos);
  // A followed range that leaves out the scene's clearance, or runs backwards, is named.
  for (const std::string range : {"[0.003, 0.008]", "[0.005, -0.001]"}) {
    const auto bad = failure(std::regex_replace(scene("[0]"), std::regex("\\[-0.001, 0.005\\]"), range), dir);
    EXPECT_NE(bad.find("peak_studies/clearance/range"), std::string::npos) << range << ": " << bad;
  }
}

TEST(Scenes, UnknownKeyIsNamedWithItsPath) {
  const auto dir = freshDir("unknown");
  const auto msg = failure(smallScene("", "      sectorz: 12\n"), dir);
  EXPECT_NE(msg.find("bad.yaml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("cyclone/mesh/shrouded_sector/sectorz"), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(dir / "static.exo"));
}

// An empty analysis list built the mesh and ended "complete" with exit 0 (issue 49).
TEST(Scenes, AnEmptyAnalysisListIsRefused) {
  const auto dir = freshDir("no_analysis");
  const auto msg = failure("cyclone:\n  analysis: []\n", dir);
  EXPECT_NE(msg.find("cyclone/analysis"), std::string::npos) << msg;
  EXPECT_NE(msg.find("lists no analysis"), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(dir / "mesh.exo"));
}

TEST(Scenes, WrongTypeAndImpossibleGeometryAreReported) {
  const auto dir = freshDir("types");
  auto msg = failure(smallScene("", "      sectors: many\n"), dir);
  EXPECT_NE(msg.find("sectors"), std::string::npos) << msg;
  msg = failure(smallScene("", "      sectors: 90\n"), dir);  // blade wider than the sector
  EXPECT_NE(msg.find("blade_chord"), std::string::npos) << msg;
  msg = failure(smallScene("", "      rim_radius: 30.0\n"), dir);
  EXPECT_NE(msg.find("rim_radius"), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(dir / "static.exo"));
}

// A built-in sector meshed so finely that its stiffness matrix alone would not fit in
// memory is refused before gmsh meshes it (issue 20's limits), with the key and the
// estimate (gmsh would mesh for hours first: the test would time out).
TEST(Scenes, AMeshTooFineForMemoryIsRefusedBeforeMeshing) {
  const auto dir = freshDir("too_fine");
  const std::string yaml = "cyclone:\n  analysis: mesh\n  mesh:\n    source: shrouded_sector\n    write: []\n"
                           "    shrouded_sector:\n      mesh_size: 0.1\n";
  const auto msg = failure(yaml, dir);
  EXPECT_NE(msg.find("mesh_size"), std::string::npos) << msg;
  EXPECT_NE(msg.find("unknowns in the sector"), std::string::npos) << msg;
}

TEST(Scenes, MissingNodeSetAndMissingConstraintsAreReported) {
  const auto dir = freshDir("sets");
  std::string yaml = smallScene();
  yaml = std::regex_replace(yaml, std::regex("\\[bore\\]"), "[hub]");
  auto msg = failure(yaml, dir);
  EXPECT_NE(msg.find("hub"), std::string::npos) << msg;
  EXPECT_NE(msg.find("bore"), std::string::npos) << "the message should list the sets that exist: " << msg;
  yaml = std::regex_replace(smallScene(), std::regex("    fixed_node_sets: \\[bore\\]\n"), "");
  msg = failure(yaml, dir);
  EXPECT_NE(msg.find("fixed_node_sets"), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(dir / "static.exo"));
}

TEST(Scenes, MissingMeshFileIsNamed) {
  const auto dir = freshDir("file");
  const std::string yaml = "cyclone:\n  analysis: mesh\n  mesh:\n    source: no_such_mesh.inp\n";
  const auto msg = failure(yaml, dir);
  EXPECT_NE(msg.find("no_such_mesh.inp"), std::string::npos) << msg;
  // A built-in sector block left beside a file source (issue 20: "unknown key (known
  // here: )"): the block is named and why it does not apply.
  const auto both = failure(yaml + "    shrouded_sector:\n      sectors: 24\n", dir);
  EXPECT_NE(both.find("mesh/shrouded_sector"), std::string::npos) << both;
  EXPECT_NE(both.find("applies to source: shrouded_sector only"), std::string::npos) << both;
}

// An empty YAML list means none (Teuchos cannot type `[]`; issue 18): a mesh scene with
// `write: []` runs and writes no mesh file.
TEST(Scenes, AnEmptyListMeansNone) {
  log::setQuiet(true);
  const auto dir = freshDir("empty_list");
  scenes::SceneOverrides o;
  o.outputDirectory = dir.string();
  const std::string yaml = "cyclone:\n  analysis: mesh\n  mesh:\n    source: shrouded_sector\n    write: []   # none\n"
                           "    shrouded_sector:\n      mesh_size: 12.0\n";
  scenes::runSceneText(yaml, "empty.yaml", o, Tpetra::getDefaultComm());
  EXPECT_FALSE(fs::exists(dir / "mesh.exo"));
  EXPECT_FALSE(fs::exists(dir / "mesh.inp"));
}

// The run's mark in its output directory (issue 20): a second run into a directory whose
// lock is held is refused, naming the other run; a run that died leaves "running",
// which the next run reports; a finished run says "complete" with its files, a failed
// one "failed" with the reason.
TEST(Scenes, ARunMarksItsDirectoryAndAConcurrentRunIsRefused) {
  log::setQuiet(true);
  const auto dir = freshDir("manifest");
  fs::create_directories(dir);
  auto manifest = [&] {
    std::ifstream in(dir / "run_manifest.txt");
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  {
    std::ofstream m(dir / "run_manifest.txt");
    m << "status: running\nscene: other.yaml\npid: 4242\nstarted: 2026-11-25T10:00:00Z\n";
  }
  const int fd = ::open((dir / ".cyclone_run.lock").c_str(), O_CREAT | O_RDWR, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  const auto busy = failure(smallScene(), dir);
  EXPECT_NE(busy.find("another cyclone run is writing into this output directory"), std::string::npos) << busy;
  EXPECT_NE(busy.find("4242"), std::string::npos) << busy;
  EXPECT_NE(manifest().find("scene: other.yaml"), std::string::npos) << "the refused run left the manifest alone";
  ::close(fd);  // the other run "dies": its manifest still says running
  scenes::SceneOverrides o;
  o.outputDirectory = dir.string();
  const auto summary = scenes::runSceneText(smallScene(), "small.yaml", o, Tpetra::getDefaultComm());
  bool warned = false;
  for (const auto& line : summary.computed) warned = warned || line.find("stopped without finishing") != std::string::npos;
  EXPECT_TRUE(warned);
  const auto done = manifest();
  EXPECT_NE(done.find("status: complete"), std::string::npos) << done;
  EXPECT_NE(done.find("static.exo"), std::string::npos) << done;
  failure(smallScene("    nonsense_key: 1\n"), dir);
  EXPECT_NE(manifest().find("status: failed"), std::string::npos) << manifest();
}

// A run killed with SIGKILL in the middle of its curve and run again with --resume
// (issue 20): the killed run's directory says "running" and holds the trace saved
// so far; the resumed run continues from it (the log says from how many points) and
// its curve is an uninterrupted run's, point for point; the checkpoints go once the
// run completes. A friction scene whose corrector steps over a wall at a fixed
// parameter after the resume point. Stopped by SIGTERM (issue 49), the same, its
// manifest saying "interrupted".
void stopMidCurveAndResume(int signal, const std::string& manifestStatus) {
  const std::string scene = std::string(CYCLONE_SCENE_DIR) + "/friction3d_rotating.yaml";
  const std::string tag = signal == SIGKILL ? "killed" : "terminated";
  const auto whole = freshDir("resume_whole_" + tag), killed = freshDir("resume_" + tag);
  fs::create_directories(killed);
  auto cyclone = [&](const fs::path& out, const std::string& extra, const fs::path& log) {
    const std::string cmd = std::string(CYCLONE_EXE) + " run " + scene + " --output " + out.string() + " " + extra +
                            " > " + log.string() + " 2>&1";
    return std::system(cmd.c_str());
  };
  ASSERT_EQ(cyclone(whole, "", whole.string() + ".log"), 0);

  // The run to kill, saving at every step.
  const std::string logPath = killed.string() + "_first.log";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  const std::string out = killed.string();
  std::vector<std::string> args{CYCLONE_EXE, "run", scene, "--output", out, "--checkpoint-seconds", "0"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, CYCLONE_EXE, &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  const fs::path checkpoints = killed / "checkpoints";
  io::TraceCheckpointDirectory store(checkpoints.string(), true);
  auto savedTrace = [&]() -> std::optional<continuation::TraceState> {
    if (!fs::exists(checkpoints)) return std::nullopt;
    for (const auto& f : fs::directory_iterator(checkpoints)) {
      const std::string name = f.path().filename().string();
      if (name.rfind("trace_", 0) != 0 || f.path().extension() != ".h5") continue;
      return store.load(name.substr(6, name.size() - 9));
    }
    return std::nullopt;
  };
  bool killedMidCurve = false;
  for (int i = 0; i < 3000 && !killedMidCurve; ++i) {  // up to a minute
    ::usleep(20000);
    const auto s = savedTrace();
    if (s && !s->complete && s->branch.points.size() >= 10) {
      ::kill(pid, signal);
      killedMidCurve = true;
    }
    int status = 0;
    if (!killedMidCurve && ::waitpid(pid, &status, WNOHANG) == pid) break;  // ended by itself: the test fails below
  }
  int status = 0;
  if (killedMidCurve) ::waitpid(pid, &status, 0);
  ASSERT_TRUE(killedMidCurve) << "the run ended before its curve had 10 saved points (" << logPath << ")";
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal);
  {
    std::ifstream m(killed / "run_manifest.txt");
    const std::string text((std::istreambuf_iterator<char>(m)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("status: " + manifestStatus), std::string::npos) << text;
  }
  EXPECT_FALSE(fs::exists(killed / "frc.h5"));
  const auto atKill = savedTrace();
  ASSERT_TRUE(atKill && !atKill->complete);
  const std::size_t savedPoints = atKill->branch.points.size();

  const fs::path resumeLog = killed.string() + "_resume.log";
  ASSERT_EQ(cyclone(killed, "--resume", resumeLog), 0);
  std::ifstream in(resumeLog);
  const std::string log((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(log.find("resumed from its checkpoint (" + std::to_string(savedPoints) + " points"), std::string::npos)
      << log;
  EXPECT_FALSE(fs::exists(checkpoints)) << "the checkpoints outlived the completed run";

  const auto a = io::readResponseCurveHdf5((whole / "frc.h5").string());
  const auto b = io::readResponseCurveHdf5((killed / "frc.h5").string());
  ASSERT_EQ(a.omega.size(), b.omega.size());
  ASSERT_GT(a.omega.size(), savedPoints);
  double largest = 0;
  for (std::size_t i = 0; i < a.omega.size(); ++i) {
    EXPECT_EQ(a.omega[i], b.omega[i]) << "point " << i;
    largest = std::max(largest, (a.coefficients[i] - b.coefficients[i]).cwiseAbs().maxCoeff());
  }
  EXPECT_EQ(largest, 0.0);
  std::printf("%s at %zu saved points of %zu; the resumed curve equals the uninterrupted one (largest "
              "difference %g)\n", tag.c_str(), savedPoints, a.omega.size(), largest);
}

TEST(Scenes, AKilledRunResumesItsCurveWhereItStopped) { stopMidCurveAndResume(SIGKILL, "running"); }

TEST(Scenes, ATerminatedRunSaysInterruptedAndResumes) { stopMidCurveAndResume(SIGTERM, "interrupted"); }

// Scenes the YAML parser would spend minutes on (issue 20: 10 000 nested flow maps, a
// 10 MB list) are refused first, with the line or the size.
TEST(Scenes, DeepOrHugeScenesAreRefusedBeforeParsing) {
  const auto dir = freshDir("limits");
  std::string nested = "cyclone: ";
  for (int i = 0; i < 10000; ++i) nested += "{a: ";
  nested += "1" + std::string(10000, '}') + "\n";
  const auto deep = failure(nested, dir);
  EXPECT_NE(deep.find("nested more than 32 levels"), std::string::npos) << deep;
  EXPECT_NE(deep.find("line 1"), std::string::npos) << deep;
  std::string block = "cyclone:\n";
  for (int i = 1; i < 40; ++i) block += std::string(2 * i, ' ') + "a" + std::to_string(i) + ":\n";
  const auto indented = failure(block + std::string(80, ' ') + "x: 1\n", dir);
  EXPECT_NE(indented.find("nested more than 32 levels"), std::string::npos) << indented;
  std::string huge = "cyclone:\n  analysis: static\n  list: [";
  for (int i = 0; i < 400000; ++i) huge += "1.0, ";
  const auto big = failure(huge + "1.0]\n", dir);
  EXPECT_NE(big.find("limited to 1 MB"), std::string::npos) << big;
}

// A margin asked for without fatigue data names both keys before any FE work; a
// known material in units E does not tell is refused with the reason.
TEST(Scenes, AFatigueMarginNeedsFatigueData) {
  const auto dir = freshDir("fatigue");
  auto scene = [](int steps) {
    return "cyclone:\n  analysis: disc_response\n  mesh:\n    source: shrouded_sector\n"
           "  constraints:\n    fixed_node_sets: [bore]\n  disc_response:\n    excitation: {node_set: mid_blade, amplitude: 1.0}\n    engine_order: 3\n    peak_stress:\n      animation_steps: " +
           std::to_string(steps) + "\n";
  };
  const std::string disc = scene(16);
  const auto missing = failure(disc, dir);
  EXPECT_NE(missing.find("material/fatigue"), std::string::npos) << missing;
  EXPECT_NE(missing.find("peak_stress"), std::string::npos) << missing;
  const std::string inPsi = disc + "  material:\n    E: 16.8e6\n    fatigue:\n      data: Ti-6Al-4V\n";
  const auto units = failure(inPsi, dir);
  EXPECT_NE(units.find("material/fatigue/data"), std::string::npos) << units;
  EXPECT_NE(units.find("stress unit"), std::string::npos) << units;
  const auto bad = failure(disc + "  material:\n    fatigue:\n      ultimate_strength: 900\n      endurance_limit: 950\n", dir);
  EXPECT_NE(bad.find("endurance_limit"), std::string::npos) << bad;
  const auto steps = failure(scene(2), dir);
  EXPECT_NE(steps.find("animation_steps"), std::string::npos) << steps;
  const auto at = failure(disc + "      at_hz: -5\n", dir);
  EXPECT_NE(at.find("at_hz"), std::string::npos) << at;
  const auto yes = failure(disc + "      margin: yes\n", dir);
  EXPECT_NE(yes.find("margin"), std::string::npos) << yes;
}

// A message the library gives with the entry only ("excitation: DOF 5 out of range") names
// the scene file too (issue 20).
TEST(Scenes, LibraryMessagesNameTheSceneFile) {
  const auto dir = freshDir("library_message");
  const std::string scene = "cyclone:\n  analysis: forced_response\n  system:\n    dofs: 1\n    M: [1.0]\n    C: [0.05]\n"
                            "    K: [1.0]\n  excitation:\n    force:\n      dof: 5\n      harmonic: 1\n      cos: 0.18\n"
                            "  harmonics: [1]\n  continuation:\n    parameter: omega\n    from: 0.5\n    to: 2.0\n";
  const auto msg = failure(scene, dir);
  EXPECT_EQ(msg.rfind("bad.yaml", 0), 0u) << msg;
  EXPECT_NE(msg.find("DOF 5"), std::string::npos) << msg;
}

// A node in no element is named before any solve (issue 20: CHOLMOD's "not positive
// definite" named nothing); writing the mesh alone still works.
TEST(Scenes, ANodeInNoElementIsNamed) {
  log::setQuiet(true);
  const auto dir = freshDir("orphan");
  fs::create_directories(dir);
  mesh::ShroudedSectorParameters p;
  p.meshSize = 12.0;
  auto m = mesh::generateShroudedSector(p);
  m.assignDefaultIds();
  m.coords.push_back({500.0, 0.0, 0.0});
  m.nodeIds.push_back(987654);
  mesh::writeAbaqusInp((dir / "deck.inp").string(), m);
  const std::string scene = "cyclone:\n  analysis: static\n  mesh:\n    source: " + (dir / "deck.inp").string() +
                            "\n  constraints:\n    fixed_node_sets: [bore]\n";
  const auto msg = failure(scene, dir / "out");
  EXPECT_NE(msg.find("deck.inp"), std::string::npos) << msg;
  EXPECT_NE(msg.find("1 node in no element (id 987654)"), std::string::npos) << msg;
  scenes::SceneOverrides o;
  o.outputDirectory = (dir / "mesh_only").string();
  const std::string meshOnly = "cyclone:\n  analysis: mesh\n  mesh:\n    source: " + (dir / "deck.inp").string() + "\n";
  EXPECT_NO_THROW(scenes::runSceneText(meshOnly, "mesh.yaml", o, Tpetra::getDefaultComm()));
}

TEST(Scenes, ModalSceneWritesFrequenciesPerNodalDiameter) {
  log::setQuiet(true);
  const auto dir = freshDir("modal");
  const std::string yaml =
      "cyclone:\n  analysis: modal\n  mesh:\n    shrouded_sector:\n      sectors: 12\n      mesh_size: 12.0\n"
      "  constraints:\n    fixed_node_sets: [bore]\n  cyclic:\n    configuration: cantilever\n"
      "  modal:\n    nodal_diameters: [0, 3, 6]\n    modes_per_nd: 2\n    speeds_rpm: [0, 12000]\n";
  scenes::SceneOverrides o;
  o.outputDirectory = dir.string();
  const auto summary = scenes::runSceneText(yaml, "modal.yaml", o, Tpetra::getDefaultComm());
  for (const auto& p : summary.written) EXPECT_TRUE(fs::exists(p)) << p;
  // Rows: per speed, ND 0 and 6 (= N/2) single (2 modes), ND 3 pairs (4 modes).
  auto f = readFrequencies(dir);
  auto at = [&](double rpm, int nd) { return f[std::make_pair(rpm, nd)]; };
  EXPECT_EQ(f.size(), 6u);
  EXPECT_EQ(at(0.0, 0).size(), 2u);
  EXPECT_EQ(at(0.0, 3).size(), 4u);
  EXPECT_EQ(at(0.0, 6).size(), 2u);
  EXPECT_NEAR(at(0.0, 3)[0] / at(0.0, 3)[1], 1.0, 1e-8);  // a travelling-wave pair
  // Centrifugal stiffening raises the first blade-dominated frequency of each ND.
  for (int nd : {0, 3, 6}) EXPECT_GT(at(12000.0, nd)[0], at(0.0, nd)[0]) << "ND " << nd;
}

// eigen_solver: lobpcg (LOBPCG + MueLu, no factorization) gives the shift-invert
// frequencies of the same scene (1e-8: see regression/verification/cyclic_lobpcg.cpp).
TEST(Scenes, ModalSceneByLobpcgMatchesShiftInvert) {
  log::setQuiet(true);
  const std::string yaml =
      "cyclone:\n  analysis: modal\n  mesh:\n    shrouded_sector:\n      sectors: 12\n      mesh_size: 12.0\n"
      "  constraints:\n    fixed_node_sets: [bore]\n"
      "  modal:\n    nodal_diameters: [0, 6]\n    modes_per_nd: 2\n    prestress: none\n";
  std::map<std::pair<double, int>, std::vector<double>> f[2];
  for (int i = 0; i < 2; ++i) {
    const auto dir = freshDir(i ? "lobpcg" : "shift_invert");
    scenes::SceneOverrides o;
    o.outputDirectory = dir.string();
    scenes::runSceneText(yaml + (i ? "    eigen_solver: lobpcg\n" : "    eigen_solver: shift_invert\n"), "modal.yaml", o,
                         Tpetra::getDefaultComm());
    f[i] = readFrequencies(dir);
  }
  ASSERT_EQ(f[0].size(), 2u);
  for (const auto& [key, reference] : f[0]) {
    ASSERT_EQ(f[1][key].size(), reference.size()) << "ND " << key.second;
    for (std::size_t m = 0; m < reference.size(); ++m)
      EXPECT_NEAR(f[1][key][m] / reference[m], 1.0, 1e-8) << "ND " << key.second << " mode " << m + 1;
  }
}

TEST(Scenes, ModalBadNodalDiameterAndConfigurationAreNamed) {
  const auto dir = freshDir("modalbad");
  const std::string base =
      "cyclone:\n  analysis: modal\n  mesh:\n    shrouded_sector:\n      sectors: 12\n      mesh_size: 12.0\n"
      "  constraints:\n    fixed_node_sets: [bore]\n";
  auto msg = failure(base + "  modal:\n    nodal_diameters: [7]\n", dir);
  EXPECT_NE(msg.find("nodal_diameters"), std::string::npos) << msg;
  EXPECT_NE(msg.find("0..6"), std::string::npos) << msg;
  msg = failure(base + "  modal:\n    modes_per_nd: 100000\n", dir);
  EXPECT_NE(msg.find("modal/modes_per_nd"), std::string::npos) << msg;
  EXPECT_NE(msg.find("more than half the sector's"), std::string::npos) << msg;
  msg = failure(base + "  modal:\n    nodal_diameters: [1, 3, 1]\n", dir);
  EXPECT_NE(msg.find("modal/nodal_diameters"), std::string::npos) << msg;
  EXPECT_NE(msg.find("nodal diameter 1 is listed twice"), std::string::npos) << msg;
  msg = failure(base + "  modal:\n    eigen_solver: arpack\n", dir);
  EXPECT_NE(msg.find("eigen_solver"), std::string::npos) << msg;
  EXPECT_NE(msg.find("lobpcg"), std::string::npos) << msg;
  msg = failure(base + "  modal:\n    eigen_solver: lobpcg\n    shift: -1.0\n", dir);
  EXPECT_NE(msg.find("shift_invert only"), std::string::npos) << msg;
  for (const char* threads : {"0", "-2", "many", "2.5", "2000"}) {
    msg = failure(base + "  modal:\n    threads: " + threads + "\n", dir);
    EXPECT_NE(msg.find("modal/threads"), std::string::npos) << threads << ": " << msg;
    EXPECT_NE(msg.find("auto or a count of threads from 1 to 1024"), std::string::npos) << threads << ": " << msg;
  }
  msg = failure(base + "  cyclic:\n    configuration: glued\n", dir);
  EXPECT_NE(msg.find("configuration"), std::string::npos) << msg;
  msg = failure(base + "  cyclic:\n    sectors: 1\n", dir);
  EXPECT_NE(msg.find("at least 2 sectors"), std::string::npos) << msg;
  msg = failure(base + "  cyclic:\n    sectors: 13\n", dir);  // faces do not match a 13-sector rotation
  EXPECT_NE(msg.find("do not match"), std::string::npos) << msg;
  // A zero density (issue 20: the eigen-solver spun for minutes): rejected before any work.
  msg = failure(base + "  material:\n    rho: 0.0\n", dir);
  EXPECT_NE(msg.find("material/rho"), std::string::npos) << msg;
  EXPECT_NE(msg.find("must be positive for modes"), std::string::npos) << msg;
  msg = failure(base + "  material:\n    mass_quadrature: lumped\n", dir);
  EXPECT_NE(msg.find("material/mass_quadrature"), std::string::npos) << msg;
  EXPECT_NE(msg.find("exact (the default) or stiffness_rule"), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(dir / "frequencies.csv"));
}

TEST(Scenes, ModalWithoutConstraintsReportsRigidBodyModes) {
  // A free sector: k = 0 keeps the rotation about the axis and the axial
  // translation, k = 1 the in-plane translations and the two tilts (a pair each).
  log::setQuiet(true);
  const auto dir = freshDir("free");
  const std::string yaml =
      "cyclone:\n  analysis: modal\n  mesh:\n    shrouded_sector:\n      sectors: 12\n      mesh_size: 12.0\n"
      "  cyclic:\n    configuration: fixed_shroud\n"
      "  modal:\n    nodal_diameters: [0, 1, 2]\n    modes_per_nd: 3\n    prestress: none\n";
  scenes::SceneOverrides o;
  o.outputDirectory = dir.string();
  const auto summary = scenes::runSceneText(yaml, "free.yaml", o, Tpetra::getDefaultComm());
  std::string all;
  for (const auto& line : summary.computed) all += line + "\n";
  EXPECT_NE(all.find("rigid-body modes ND 0: 2, ND 1: 4"), std::string::npos) << all;
}

TEST(Scenes, DuffingForcedResponseSceneMatchesTheReferencePeak) {
  log::setQuiet(true);
  const auto dir = freshDir("duffing");
  scenes::SceneOverrides o;
  o.outputDirectory = dir.string();
  scenes::runSceneFile(CYCLONE_SCENE_DIR "/duffing.yaml", o, Tpetra::getDefaultComm());
  std::ifstream csv(dir / "frc.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line.rfind("point,omega_rad_s,freq_hz,dof0_h0,dof0_amp_h1,", 0), 0u) << line;
  double best = 0, bestW = 0;
  int rows = 0;
  std::vector<int> stability;
  std::vector<double> folds;
  while (std::getline(csv, line)) {
    std::vector<double> v;
    std::stringstream ss(line);
    std::string cell;
    for (int c = 0; c < 14 && std::getline(ss, cell, ','); ++c) v.push_back(std::stod(cell));
    ASSERT_EQ(v.size(), 14u);
    std::getline(ss, cell, ',');  // the bifurcation column: empty or a kind
    if (cell == "fold") folds.push_back(v[1]);
    else EXPECT_EQ(cell, "") << line;
    std::getline(ss, cell);  // the segment: one sweep
    EXPECT_EQ(cell, "0") << line;
    if (v[4] > best) best = v[4], bestW = v[1];
    stability.push_back(int(v[12]));
    ++rows;
  }
  // The two folds of the H = 7 curve, flagged where the parameter turns.
  ASSERT_EQ(folds.size(), 2u);
  EXPECT_NEAR(folds[0], 1.2696, 1e-3);
  EXPECT_NEAR(folds[1], 1.1157, 1e-3);
  // Hill's method: stable, then one unstable stretch (the middle branch between the
  // two folds), then stable again.
  int changes = 0;
  for (std::size_t i = 1; i < stability.size(); ++i) changes += stability[i] != stability[i - 1];
  EXPECT_EQ(changes, 2);
  EXPECT_EQ(stability.front(), 1);
  EXPECT_EQ(stability.back(), 1);
  // The default steps trace the curve whole in the issue's budget for a smooth
  // resonance (at most about 300 points), and its peak is one of the rows.
  EXPECT_GT(rows, 20);
  EXPECT_LE(rows, 300);
  EXPECT_NEAR(best, 2.8302, 2e-4);  // reference H = 7 peak (the sampled branch)
  EXPECT_NEAR(bestW, 1.2688, 2e-3);
  EXPECT_TRUE(fs::exists(dir / "frc.svg"));
  // The HDF5 curve: read back, the same points and coefficients as the CSV's amplitudes;
  // and a real HDF5 client (h5dump) reads it.
  const auto curve = io::readResponseCurveHdf5((dir / "frc.h5").string());
  ASSERT_EQ(int(curve.omega.size()), rows);
  EXPECT_EQ(curve.segment, std::vector<int>(std::size_t(rows), 0));  // one sweep
  EXPECT_EQ(curve.numDofs, 1);
  EXPECT_EQ(curve.harmonics, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
  double h5best = 0;
  for (const auto& X : curve.coefficients) h5best = std::max(h5best, std::hypot(X(1), X(2)));
  EXPECT_NEAR(h5best, best, 1e-9 * best);
  const std::string dump = "h5dump -H '" + (dir / "frc.h5").string() + "' > '" + (dir / "h5dump.txt").string() + "' 2>&1";
  ASSERT_EQ(std::system(dump.c_str()), 0) << "h5dump could not read frc.h5";
  std::ifstream header(dir / "h5dump.txt");
  const std::string text((std::istreambuf_iterator<char>(header)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("DATASET \"coefficients\""), std::string::npos) << text;
  EXPECT_NE(text.find("DATASET \"omega\""), std::string::npos) << text;
}

// A scene whose curve has no point (issue 20: Duffing with k3 = 1e300 exited 0 with a
// header-only frc.csv): the run fails with the reason, and writes none of the curve's files.
TEST(Scenes, ACurveWithoutAnyPointFailsTheRun) {
  log::setQuiet(true);
  const auto dir = freshDir("nopoint");
  const std::string yaml = duffingSceneWith("k3: [-+.0-9eE]+", "k3: 1.0e300");
  ASSERT_NE(yaml.find("k3: 1.0e300"), std::string::npos);
  scenes::SceneOverrides o;
  o.outputDirectory = dir.string();
  std::string msg;
  // LOCA (the fallback engine here) printed "Step size reached minimum step size bound"
  // on the error stream four times (issue 20): the stop reason says it, nothing else.
  std::ostringstream captured;
  auto* out = std::cout.rdbuf(captured.rdbuf());
  auto* err = std::cerr.rdbuf(captured.rdbuf());
  try {
    scenes::runSceneText(yaml, "stiff.yaml", o, Tpetra::getDefaultComm());
  } catch (const SolverError& e) {
    msg = e.what();
  }
  std::cout.rdbuf(out), std::cerr.rdbuf(err);
  EXPECT_EQ(captured.str().find("Step size reached"), std::string::npos) << captured.str();
  EXPECT_NE(msg.find("frc: no point of the curve was computed"), std::string::npos) << msg;
  EXPECT_NE(msg.find("no converged start"), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(dir / "frc.csv"));
  EXPECT_FALSE(fs::exists(dir / "frc.h5"));
}

// A force so small that the response underflows (issue 49: Duffing at 1.8e-201 traced
// 34 points of zeros, "end of the parameter range reached", exit 0, and a samples check
// "changes the peak by nan"): refused after the first point with the cause, nothing written.
TEST(Scenes, AForceTooSmallToTraceIsRefused) {
  log::setQuiet(true);
  const auto dir = freshDir("tiny_force");
  const std::string yaml = duffingSceneWith("cos: 0.18", "cos: 1.8e-201");
  ASSERT_NE(yaml.find("cos: 1.8e-201"), std::string::npos);
  const auto msg = failure(yaml, dir);
  EXPECT_NE(msg.find("excitation"), std::string::npos) << msg;
  EXPECT_NE(msg.find("too small to trace"), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(dir / "frc.csv"));
  // The same force at 1.8e-140 is traced whole (its peak, measured, 3.6e-139: the linear
  // oscillator's F / (c w) at w = 1, the cubic term nothing at that size).
  const std::string small = duffingSceneWith("cos: 0.18", "cos: 1.8e-140");
  scenes::SceneOverrides o;
  o.outputDirectory = dir.string();
  EXPECT_NO_THROW(scenes::runSceneText(small, "small.yaml", o, Tpetra::getDefaultComm()));
  EXPECT_TRUE(fs::exists(dir / "frc.csv"));
}

// An engine order beyond N/2 folds onto a nodal diameter (issue 20: 100 on 24 sectors
// was accepted without a word). The ring of 12 sectors driven at engine order 27 = 3 +
// 2 x 12 is the same travelling wave as at 3: the summary says which nodal diameter,
// and the two curves' peaks agree to the solver's tolerance.
TEST(Scenes, AnEngineOrderBeyondHalfTheSectorsFoldsAndIsSaid) {
  log::setQuiet(true);
  std::ifstream in(CYCLONE_SCENE_DIR "/cyclic_friction_ring.yaml");
  std::stringstream text;
  text << in.rdbuf();
  auto peakOf = [](const fs::path& dir) {
    std::ifstream csv(dir / "frc.csv");
    std::string line;
    std::getline(csv, line);
    const auto header = line;
    int column = 0;
    {
      std::stringstream h(header);
      std::string cell;
      for (int c = 0; std::getline(h, cell, ','); ++c)
        if (cell.size() > 4 && cell.compare(cell.size() - 4, 4, "_max") == 0) {
          column = c;
          break;
        }
    }
    double best = 0;
    while (std::getline(csv, line)) {
      std::stringstream row(line);
      std::string cell;
      for (int c = 0; std::getline(row, cell, ','); ++c)
        if (c == column) best = std::max(best, std::stod(cell));
    }
    return best;
  };
  scenes::SceneOverrides o;
  const auto dir3 = freshDir("eo3"), dir27 = freshDir("eo27");
  o.outputDirectory = dir3.string();
  const auto s3 = scenes::runSceneText(text.str(), "eo3.yaml", o, Tpetra::getDefaultComm());
  const std::string folded = std::regex_replace(text.str(), std::regex("engine_order: 3"), "engine_order: 27");
  ASSERT_NE(folded.find("engine_order: 27"), std::string::npos);
  o.outputDirectory = dir27.string();
  const auto s27 = scenes::runSceneText(folded, "eo27.yaml", o, Tpetra::getDefaultComm());
  std::string all;
  for (const auto& line : s27.computed) all += line + "\n";
  EXPECT_NE(all.find("engine order 27 on 12 sectors excites nodal diameter 3"), std::string::npos) << all;
  for (const auto& line : s3.computed) EXPECT_EQ(line.find("folds"), std::string::npos) << line;
  const double p3 = peakOf(dir3), p27 = peakOf(dir27);
  std::printf("ring peak max|x(t)|: engine order 3 %.12g, engine order 27 %.12g\n", p3, p27);
  ASSERT_GT(p3, 0.0);
  EXPECT_NEAR(p27 / p3, 1.0, 1e-9);
}

TEST(Scenes, ForcedResponseBadInputIsNamed) {
  const auto dir = freshDir("frcbad");
  const std::string base = "cyclone:\n  analysis: forced_response\n  system:\n    dofs: 2\n";
  auto msg = failure(base + "    M: [1.0, 0.0, 0.0]\n    K: [1.0, 0.0, 0.0, 1.0]\n", dir);
  EXPECT_NE(msg.find("cyclone/system/M"), std::string::npos) << msg;
  EXPECT_NE(msg.find("needs 4 numbers"), std::string::npos) << msg;
  msg = failure(base + "    M: [1.0, 0.0, 0.0, 1.0]\n    K: [1.0, 0.0, 0.0, 1.0]\n"
                       "  nonlinear_elements:\n    e:\n      type: magic\n      direction: [1.0, 0.0]\n",
                dir);
  EXPECT_NE(msg.find("unknown element type 'magic'"), std::string::npos) << msg;
  msg = failure(base + "    M: [1.0, 0.0, 0.0, 1.0]\n    K: [1.0, 0.0, 0.0, 1.0]\n"
                       "  excitation:\n    f:\n      dof: 0\n      cos: 1.0\n  continuation:\n    from: 0.5\n",
                dir);
  EXPECT_NE(msg.find("continuation/to"), std::string::npos) << msg;
  msg = failure(base + "    M: [1.0, 0.0, 0.0, 1.0]\n    K: [1.0, 0.0, 0.0, 1.0]\n"
                       "  excitation:\n    f:\n      dof: 0\n      cos: 1.0\n  continuation:\n    from: 0.5\n"
                       "    to: 1.5\n    line_search: wolfe\n",
                dir);
  EXPECT_NE(msg.find("continuation/line_search"), std::string::npos) << msg;
  EXPECT_NE(msg.find("full_step, backtrack or polynomial"), std::string::npos) << msg;
  msg = failure(base + "    M: [1.0, 0.0, 0.0, 1.0]\n    K: [1.0, 0.0, 0.0, 1.0]\n"
                       "  excitation:\n    f:\n      dof: 0\n      cos: 1.0\n  continuation:\n    from: 0.5\n"
                       "    to: 1.5\n    engine: arclength\n",
                dir);
  EXPECT_NE(msg.find("continuation/engine"), std::string::npos) << msg;
  EXPECT_NE(msg.find("predictor_corrector or loca"), std::string::npos) << msg;
  // Nonsense accepted before (issue 20): a range of one point, a huge sample count, a
  // negative mass, damping that generates energy.
  const std::string aForce = "  excitation:\n    f:\n      dof: 0\n      cos: 1.0\n";
  const std::string range = "  continuation:\n    from: 0.5\n    to: 1.5\n";
  msg = failure(base + "    M: [1.0, 0.0, 0.0, 1.0]\n    K: [1.0, 0.0, 0.0, 1.0]\n" + aForce +
                    "  continuation:\n    from: 0.5\n    to: 0.5\n",
                dir);
  EXPECT_NE(msg.find("continuation/to"), std::string::npos) << msg;
  EXPECT_NE(msg.find("equals from"), std::string::npos) << msg;
  msg = failure(base + "    M: [1.0, 0.0, 0.0, 1.0]\n    K: [1.0, 0.0, 0.0, 1.0]\n" + aForce + range +
                    "  samples: 2000000\n",
                dir);
  EXPECT_NE(msg.find("cyclone/samples"), std::string::npos) << msg;
  EXPECT_NE(msg.find("must lie in 15..65536 time samples per period (2 H + 1 resolve harmonic H = 7"), std::string::npos) << msg;
  msg = failure(base + "    M: [1.0, 0.0, 0.0, -1.0]\n    K: [1.0, 0.0, 0.0, 1.0]\n" + aForce + range, dir);
  EXPECT_NE(msg.find("cyclone/system/M"), std::string::npos) << msg;
  EXPECT_NE(msg.find("positive definite"), std::string::npos) << msg;
  msg = failure(base + "    M: [1.0, 0.0, 0.0, 1.0]\n    K: [1.0, 0.0, 0.0, 1.0]\n    C: [0.1, 0.0, 0.0, -0.01]\n" +
                    aForce + range,
                dir);
  EXPECT_NE(msg.find("cyclone/system"), std::string::npos) << msg;
  EXPECT_NE(msg.find("generates energy"), std::string::npos) << msg;
  // A gyroscopic (skew) C dissipates nothing and is accepted: only its symmetric part counts.
  {
    scenes::SceneOverrides o;
    o.outputDirectory = freshDir("frcgyro").string();
    log::setQuiet(true);
    EXPECT_NO_THROW(scenes::runSceneText(base + "    M: [1.0, 0.0, 0.0, 1.0]\n    K: [1.0, 0.0, 0.0, 1.0]\n"
                                                "    C: [0.02, 0.1, -0.1, 0.02]\n" + aForce + range,
                                         "gyro.yaml", o, Tpetra::getDefaultComm()));
  }
  msg = failure(base + "    M: [1.0, 0.0, 0.0, 1.0]\n    K: [1.0, 0.0, 0.0, 1.0]\n"
                       "  excitation:\n    f:\n      dof: 0\n      cos: 1.0\n  continuation:\n    from: 0.5\n"
                       "    to: 1.5\n    min_step: 0.1\n    max_step: 0.01\n",
                dir);
  EXPECT_NE(msg.find("continuation/max_step"), std::string::npos) << msg;
  EXPECT_NE(msg.find("at least min_step"), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(dir / "frc.csv"));
}

// Friction and cyclic keys: the element's parameter, W_next without a ring, a cyclic
// system without (or with two different) engine orders, a harmonics check below H.
TEST(Scenes, ForcedResponseBadElementAndCyclicKeysAreNamed) {
  const auto dir = freshDir("frcbad2");
  const std::string base = "cyclone:\n  analysis: forced_response\n  system:\n    dofs: 2\n";
  std::string msg;
  const std::string mk = "    M: [1.0, 0.0, 0.0, 1.0]\n    K: [1.0, 0.0, 0.0, 1.0]\n";
  const std::string force = "  excitation:\n    f:\n      dof: 0\n      cos: 1.0\n";
  msg = failure(base + mk + "  nonlinear_elements:\n    c:\n      type: friction2d\n      W: [1.0, 0.0, 0.0, 1.0]\n"
                       "      kt: -5.0\n      mu: 0.3\n      kn: 1.0\n" + force,
                dir);
  EXPECT_NE(msg.find("nonlinear_elements/c"), std::string::npos) << msg;
  EXPECT_NE(msg.find("kt must be positive"), std::string::npos) << msg;
  msg = failure(base + mk + "  nonlinear_elements:\n    c:\n      type: friction2d\n      W: [1.0, 0.0]\n"
                       "      kt: 5.0\n      mu: 0.3\n      kn: 1.0\n" + force,
                dir);
  EXPECT_NE(msg.find("needs 4 numbers"), std::string::npos) << msg;
  msg = failure(base + mk + "  nonlinear_elements:\n    c:\n      type: cubic\n      direction: [1.0, 0.0]\n"
                       "      W_next: [-1.0, 0.0]\n      k3: 1.0\n" + force,
                dir);
  EXPECT_NE(msg.find("W_next"), std::string::npos) << msg;
  EXPECT_NE(msg.find("must be cyclic"), std::string::npos) << msg;
  msg = failure(base + "    sectors: 6\n" + mk + force, dir);
  EXPECT_NE(msg.find("engine_order"), std::string::npos) << msg;
  msg = failure(base + "    sectors: 6\n" + mk + force + "      engine_order: 2\n    g:\n      dof: 1\n"
                       "      cos: 1.0\n      engine_order: 3\n",
                dir);
  EXPECT_NE(msg.find("one travelling wave"), std::string::npos) << msg;
  msg = failure(base + mk + force + "  harmonics: [2]\n  continuation:\n    from: 0.5\n    to: 1.5\n"
                       "  output:\n    harmonics_check_to: 2\n",
                dir);
  EXPECT_NE(msg.find("output/harmonics_check_to"), std::string::npos) << msg;
  EXPECT_NE(msg.find("must exceed the curve's highest harmonic 2"), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(dir / "frc.csv"));
}

namespace {
// Columns of a frc.csv as numbers (header skipped).
std::vector<std::vector<double>> readCsv(const fs::path& path) {
  std::ifstream csv(path);
  std::string line;
  std::getline(csv, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(csv, line)) {
    std::vector<double> v;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) {  // text cells (the bifurcation kind) as NaN
      char* end = nullptr;
      const double x = std::strtod(cell.c_str(), &end);
      v.push_back(cell.empty() || *end != '\0' ? NAN : x);
    }
    rows.push_back(v);
  }
  return rows;
}
// Values of column `value` where column `parameter` crosses `at` (linear interpolation).
std::vector<double> crossings(const std::vector<std::vector<double>>& rows, int parameter, int value, double at) {
  std::vector<double> out;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const double a = rows[i - 1][parameter] - at, b = rows[i][parameter] - at;
    if ((a < 0) != (b < 0)) out.push_back(rows[i - 1][value] + a / (a - b) * (rows[i][value] - rows[i - 1][value]));
  }
  std::sort(out.begin(), out.end());
  return out;
}
}  // namespace

TEST(Scenes, ForceLevelContinuationFoldsAndMeetsTheFrequencySweep) {
  log::setQuiet(true);
  const auto dirF = freshDir("dforce"), dirW = freshDir("dfreq");
  scenes::SceneOverrides o;
  o.outputDirectory = dirF.string();
  // The comparison below interpolates linearly between neighbouring points of each
  // curve: both are traced with steps of at most 0.05 (the default, 0.2, leaves an
  // interpolation error of about 1 % at the crossings).
  auto finer = [](const std::string& name) {
    std::ifstream in(std::string(CYCLONE_SCENE_DIR) + "/" + name);
    std::stringstream text;
    text << in.rdbuf();
    std::string yaml = text.str();
    const auto at = yaml.find("  continuation:\n");
    yaml.insert(at + std::string("  continuation:\n").size(), "    max_step: 0.05\n");
    return yaml;
  };
  scenes::runSceneText(finer("duffing_force.yaml"), "duffing_force.yaml", o, Tpetra::getDefaultComm());
  o.outputDirectory = dirW.string();
  scenes::runSceneText(finer("duffing.yaml"), "duffing.yaml", o, Tpetra::getDefaultComm());
  const auto force = readCsv(dirF / "frc.csv"), freq = readCsv(dirW / "frc.csv");
  // Columns: force scan  point, omega, freq, scale, h0, amp_h1..h7, max, stable, max_re
  //          frequency   point, omega, freq,        h0, amp_h1..h7, max, stable, max_re
  std::vector<double> folds;
  int stabilityChanges = 0;
  for (std::size_t i = 2; i < force.size(); ++i) {
    const double d1 = force[i - 1][3] - force[i - 2][3], d2 = force[i][3] - force[i - 1][3];
    if (i + 1 < force.size() && (d1 > 0) != (d2 > 0)) folds.push_back(force[i - 1][3]);
    stabilityChanges += force[i][13] != force[i - 1][13];
  }
  ASSERT_EQ(folds.size(), 2u);
  EXPECT_EQ(stabilityChanges, 2);
  // Single-term closed form of the folds: s = 2.33 and 0.805 (H = 7 moves them by < 2%).
  EXPECT_NEAR(folds[0] / 2.33, 1.0, 0.02);
  EXPECT_NEAR(folds[1] / 0.805, 1.0, 0.02);
  // At s = 1 the force scan passes the frequency sweep's three solutions at W = 1.2.
  const auto a = crossings(force, 3, 5, 1.0), b = crossings(freq, 1, 4, 1.2);
  ASSERT_EQ(a.size(), 3u);
  ASSERT_EQ(b.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i] / b[i], 1.0, 2e-3) << "solution " << i;
  const auto curve = io::readResponseCurveHdf5((dirF / "frc.h5").string());
  ASSERT_EQ(curve.parameter.size(), force.size());
  EXPECT_DOUBLE_EQ(curve.parameter.back(), force.back()[3]);
}

// The harmonics check of a frequency curve compares peaks, each found by the peak
// search at fixed frequencies (PeakSearch.hpp), from H up to harmonics_check_to:
// here the Duffing oscillator x'' + 0.05 x' + x + 0.1 x^3 = 0.18 cos(W t) from
// H = 1 to 3. References: H = 1 is the single-term closed form (s = c^2 / 2m); H = 2
// adds nothing to an odd oscillator without a static load (the same peak); H = 3 is
// the largest point of an independent arclength trace with H = 3 and small steps
// (the search finds the continuous maximum, so it may exceed the sampled one only by
// what the sampling misses), and the same search started from that trace's own
// largest point.
TEST(Scenes, HarmonicsCheckComparesPeaksFoundBySearchWithTheReferences) {
  log::setQuiet(true);
  auto scene = [](const std::string& harmonics, const std::string& extra) {
    return std::string("cyclone:\n  analysis: forced_response\n"
                       "  system:\n    dofs: 1\n    M: [1.0]\n    C: [0.05]\n    K: [1.0]\n"
                       "  nonlinear_elements:\n    hardening:\n      type: cubic\n      direction: [1.0]\n"
                       "      k3: 0.1\n"
                       "  excitation:\n    force:\n      dof: 0\n      harmonic: 1\n      cos: 0.18\n"
                       "  harmonics: [") +
           harmonics +
           "]\n  samples: 64\n"
           "  continuation:\n    parameter: omega\n    from: 0.9\n    to: 1.4\n    initial_step: 0.002\n"
           "    max_step: 0.002\n"
           "  output:\n    dofs: [0]\n    stability: false\n" +
           extra;
  };
  const auto dirLow = freshDir("harmonics_check_low"), dirH3 = freshDir("harmonics_check_h3");
  scenes::SceneOverrides o;
  o.outputDirectory = dirLow.string();
  const auto summary = scenes::runSceneText(scene("1", "    harmonics_check_to: 3\n"), "h1.yaml", o,
                                            Tpetra::getDefaultComm());
  o.outputDirectory = dirH3.string();
  scenes::runSceneText(scene("3", ""), "h3.yaml", o, Tpetra::getDefaultComm());
  // Columns: max_harmonic, found, peak, freq_hz, relative_change, frequency_change, force_beyond_h, solves,
  // seconds, note
  const auto levels = readCsv(dirLow / "frc_harmonics.csv"), own = readCsv(dirH3 / "frc_harmonics.csv");
  ASSERT_EQ(levels.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(levels[i][0], i + 1);
    EXPECT_EQ(levels[i][1], 1) << "H = " << i + 1 << " peak not found";
  }
  const double m = 1, c = 0.05, k = 1, g = 0.1, P = 0.18, sPeak = c * c / (2 * m);
  double Wpeak = 1.2, Apeak = 0;
  for (int i = 0; i < 500; ++i) {
    Apeak = P / std::sqrt(sPeak * sPeak + c * c * Wpeak * Wpeak);
    Wpeak = std::sqrt((k + 0.75 * g * Apeak * Apeak - sPeak) / m);
  }
  const double W = 2 * M_PI;
  // The searches stop at brackets 1e-5 of the frequency wide: near the flat top that
  // leaves about 1e-8 of the peak value (0.5 A''/A df^2).
  EXPECT_NEAR(levels[0][2] / Apeak, 1.0, 1e-7);
  EXPECT_NEAR(levels[0][3] * W / Wpeak, 1.0, 1e-4);
  EXPECT_NEAR(levels[1][2] / levels[0][2], 1.0, 1e-7);
  EXPECT_NEAR(levels[1][3] / levels[0][3], 1.0, 1e-4);
  // H = 3 against the traced H = 3 curve (columns: point, omega, freq, h0, amp_h1..h3, max, ...).
  const auto curve = readCsv(dirH3 / "frc.csv");
  double traced = 0, tracedW = 0;
  for (const auto& row : curve)
    if (row[7] > traced) traced = row[7], tracedW = row[1];
  std::printf("Duffing peaks: H = 1 %.9f at %.6f (closed form %.9f at %.6f); H = 2 %.9f; H = 3 %.9f at %.6f, "
              "traced %.9f at %.6f, from the trace's own point %.9f\n",
              levels[0][2], levels[0][3] * W, Apeak, Wpeak, levels[1][2], levels[2][2], levels[2][3] * W, traced,
              tracedW, own[0][2]);
  EXPECT_GE(levels[2][2], traced * (1 - 1e-9));
  EXPECT_NEAR(levels[2][2] / traced, 1.0, 1e-4);
  EXPECT_NEAR(levels[2][3] * W / tracedW, 1.0, 2e-3);
  ASSERT_FALSE(own.empty());
  EXPECT_EQ(own[0][0], 3);
  EXPECT_NEAR(own[0][2] / levels[2][2], 1.0, 1e-7);
  // The summary says what changed from H = 2 to 3.
  bool said = false;
  for (const auto& line : summary.computed)
    if (line.find("H 2 -> 3 changes the peak by") != std::string::npos) {
      said = true;
      EXPECT_EQ(line.find("not found"), std::string::npos) << line;  // every level was found
      EXPECT_NE(line.find("H 3 2.87634"), std::string::npos) << line;
    }
  EXPECT_TRUE(said);
}

// harmonics: auto (harmonics by an error target): the Duffing oscillator from H = 1 up
// until each of the peak's last two raises of H changed it by at most the tolerance (two:
// its even harmonics are zero, so H = 1 -> 2 changes nothing), then the curve traced
// again whole with that H. Its peak must lie within the tolerance of a curve traced
// independently with two harmonics more.
TEST(Scenes, HarmonicsByAnErrorTargetMeetACurveTracedWithTwoMore) {
  log::setQuiet(true);
  const auto dir = freshDir("harmonics_auto");
  fs::create_directories(dir);
  auto load = [&](const std::string& harmonics, const std::string& extra, const std::string& parameter = "omega") {
    const std::string text =
        "cyclone:\n  analysis: forced_response\n"
        "  system:\n    dofs: 1\n    M: [1.0]\n    C: [0.05]\n    K: [1.0]\n"
        "  nonlinear_elements:\n    hardening:\n      type: cubic\n      direction: [1.0]\n      k3: 0.1\n"
        "  excitation:\n    force:\n      dof: 0\n      harmonic: 1\n      cos: 0.18\n"
        "  harmonics: " + harmonics + "\n" + extra +
        "  continuation:\n    parameter: " + parameter + "\n    from: 0.9\n    to: 1.4\n"
        "  output:\n    dofs: [0]\n    stability: false\n";
    const auto path = dir / "scene.yaml";
    std::ofstream(path) << text;
    return scenes::loadForcedResponseScene(path.string());
  };
  const double tolerance = 1e-3;
  Timer timer;
  auto setup = load("auto", "  harmonics_tolerance: 0.001\n");
  const auto result = response::solveForcedResponse(setup);
  const double autoSeconds = timer.seconds();
  const auto& target = result.harmonicsTarget;
  ASSERT_TRUE(target.retraced) << target.text;
  EXPECT_EQ(target.tracedHarmonic, 1);
  EXPECT_GE(target.reached, 3);
  EXPECT_LE(target.change, tolerance);
  EXPECT_EQ(setup.system->aft().harmonics().maxHarmonic(), target.reached);
  EXPECT_TRUE(result.branch.finished) << result.branch.stopReason;
  timer.restart();
  auto reference = load("[" + std::to_string(target.reached + 2) + "]", "");
  reference.harmonicsCheckTo = -1;
  const auto two = response::solveForcedResponse(reference);
  std::printf("harmonics: auto to %.0e: H = %d reached (change %.2e), peak %.9f at %.6f, %zu points, %.2f s in all; "
              "H = %d traced alone: %.9f at %.6f, %.2f s; relative difference %.2e\n%s\n",
              tolerance, target.reached, target.change, result.peak, result.peakOmega, result.branch.points.size(),
              autoSeconds, target.reached + 2, two.peak, two.peakOmega, timer.seconds(), result.peak / two.peak - 1,
              target.text.c_str());
  EXPECT_NEAR(result.peak / two.peak, 1.0, tolerance);
  // The search's peak at the level reached and the retraced curve's largest point agree to
  // what the curve's points resolve of its top.
  EXPECT_NEAR(result.peak / result.harmonicsCheck.levels.back().peak.value, 1.0, 1e-4);

  // Bad combinations are named.
  auto refused = [&](const std::string& harmonics, const std::string& extra, const std::string& parameter) {
    try {
      load(harmonics, extra, parameter);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  auto msg = refused("auto", "  harmonics_tolerance: 0.0\n", "omega");
  EXPECT_NE(msg.find("harmonics_tolerance"), std::string::npos) << msg;
  msg = refused("auto", "  harmonics_max: 2\n", "omega");
  EXPECT_NE(msg.find("harmonics_max"), std::string::npos) << msg;
  msg = refused("[3]", "  harmonics_tolerance: 0.01\n", "omega");
  EXPECT_NE(msg.find("applies to harmonics: auto only"), std::string::npos) << msg;
  msg = refused("auto", "", "force_scale\n    omega: 1.2");
  EXPECT_NE(msg.find("continuation parameter omega"), std::string::npos) << msg;
  msg = refused("auto", "  harmonics_tolerance: nan\n", "omega");
  EXPECT_NE(msg.find("harmonics_tolerance"), std::string::npos) << msg;
}

// A force given by amplitude and phase is the same force as its cos/sin form:
// A cos(w t + phi) = A cos(phi) cos(w t) - A sin(phi) sin(w t).
// A matrix scene's harmonics_tolerance and harmonics_max are taken by `cyclone run` (the
// runner's check of the scene's top-level keys once refused them as unknown while the
// library's loader read them), and nonsense in them is still refused naming the key.
TEST(Scenes, MatrixSceneHarmonicsTargetKeysRunThroughTheRunner) {
  const fs::path dir = fs::temp_directory_path() / "cyclone_matrix_harmonics_target";
  fs::remove_all(dir);
  auto scene = [](const std::string& extra) {
    return "cyclone:\n  analysis: forced_response\n"
           "  system:\n    dofs: 1\n    M: [1.0]\n    C: [0.05]\n    K: [1.0]\n"
           "  nonlinear_elements:\n    hardening:\n      type: cubic\n      direction: [1.0]\n      k3: 0.1\n"
           "  excitation:\n    force:\n      dof: 0\n      harmonic: 1\n      cos: 0.18\n"
           "  harmonics: auto\n" + extra +
           "  continuation:\n    from: 0.9\n    to: 1.4\n"
           "  output:\n    dofs: [0]\n    stability: false\n";
  };
  scenes::SceneOverrides o;
  o.outputDirectory = dir.string();
  // A tolerance no raise meets: the check goes on to harmonics_max (the default would be 7).
  const auto summary = scenes::runSceneText(scene("  harmonics_tolerance: 1e-9\n  harmonics_max: 4\n"), "auto.yaml", o,
                                            Tpetra::getDefaultComm());
  std::string computed;
  for (const auto& line : summary.computed) computed += line + "\n";
  EXPECT_NE(computed.find("; H 4 "), std::string::npos) << computed;
  EXPECT_EQ(computed.find("; H 5 "), std::string::npos) << computed;
  const std::string msg = failure(scene("  harmonics_max: 99\n"), dir);
  EXPECT_NE(msg.find("harmonics_max"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("unknown key"), std::string::npos) << msg;
  fs::remove_all(dir);
}

TEST(Scenes, ExcitationByAmplitudeAndPhase) {
  const auto dir = freshDir("amplitude_phase");
  fs::create_directories(dir);
  auto scene = [&](const std::string& name, const std::string& force) {
    const auto path = dir / name;
    std::ofstream(path) << "cyclone:\n  analysis: forced_response\n  system:\n    dofs: 1\n    M: [1.0]\n    K: [1.0]\n"
                           "  excitation:\n    f: {dof: 0, " + force + "}\n  continuation:\n    from: 0.5\n    to: 1.5\n";
    return scenes::loadForcedResponseScene(path.string());
  };
  const double A = 0.7, phi = 0.4;
  const auto a = scene("a.yaml", "amplitude: 0.7, phase: 0.4");
  const auto b = scene("b.yaml", "cos: " + std::to_string(A * std::cos(phi)) + ", sin: " + std::to_string(-A * std::sin(phi)));
  EXPECT_LT((a.system->excitation() - b.system->excitation()).norm(), 1e-6);
  EXPECT_NEAR(a.system->amplitude(a.system->excitation(), 0, 1), A, 1e-15);
}

// A sparse matrix (triplets) is the same matrix as its dense form; DOF names
// label the outputs.
// Harmonic balances too large for this machine's memory are refused with the keys
// before anything large is allocated (issue 20's limits): 20000 harmonics at 65536
// samples (the transform's dense matrices, 54.7 GB); 2200 DOFs with harmonics 0..40
// (178 200 unknowns: the Krylov solver's blocks per harmonic and GMRES's basis, 12.9 GB).
TEST(Scenes, HarmonicBalancesTooLargeForMemoryAreRefused) {
  const auto dir = freshDir("hb_limits");
  const std::string oneDof = "cyclone:\n  analysis: forced_response\n  system:\n    dofs: 1\n    M: [1.0]\n"
                             "    C: [0.01]\n    K: [1.0]\n  harmonics: 20000\n  samples: 65536\n"
                             "  excitation:\n    f: {dof: 0, cos: 1.0}\n  continuation:\n    from: 0.5\n    to: 1.5\n";
  const auto aft = failure(oneDof, dir);
  EXPECT_NE(aft.find("harmonics and samples"), std::string::npos) << aft;
  EXPECT_NE(aft.find("54.7 GB"), std::string::npos) << aft;
  std::ostringstream diagonal;
  diagonal << "{rows: [";
  for (int i = 0; i < 2200; ++i) diagonal << (i ? ", " : "") << i;
  diagonal << "], cols: [";
  for (int i = 0; i < 2200; ++i) diagonal << (i ? ", " : "") << i;
  diagonal << "], values: [";
  for (int i = 0; i < 2200; ++i) diagonal << (i ? ", " : "") << "1.0";
  diagonal << "]}";
  const std::string many = "cyclone:\n  analysis: forced_response\n  system:\n    dofs: 2200\n    M: " + diagonal.str() +
                           "\n    K: " + diagonal.str() + "\n  harmonics: 40\n  samples: 128\n"
                           "  excitation:\n    f: {dof: 0, cos: 1.0}\n  continuation:\n    from: 0.5\n    to: 1.5\n";
  // Krylov's Newton steps (from 1000 unknowns) hold per harmonic the linear block over
  // the DOFs (2 x 2200 square) and its LU: 41 x 2 x 4400^2 doubles, with GMRES's basis
  // (160 vectors of 178 200), 12.9 GB.
  const auto jacobian = failure(many, dir);
  EXPECT_NE(jacobian.find("harmonics: 41 harmonics (up to 40) on 2200 DOFs make 178200 unknowns"), std::string::npos)
      << jacobian;
  EXPECT_NE(jacobian.find("Jacobian's blocks and GMRES's basis would take 12.9 GB"), std::string::npos) << jacobian;
  // Within memory but not within time (issue 49: harmonics 0..5000 on the Duffing DOF
  // spent minutes on its first Jacobian, silently): the cubic spring's Jacobian, its
  // 20001 samples' sensitivities projected onto 10001 coefficients, 4e12 flops a Newton
  // iteration. Refused at once with the estimate.
  Timer timer;
  const auto slow = failure(duffingSceneWith("  harmonics: \\[7\\]\n  samples: 64\n", "  harmonics: 5000\n"), dir);
  EXPECT_NE(slow.find("the elements' Jacobians alone take about"), std::string::npos) << slow;
  EXPECT_NE(slow.find("use fewer harmonics"), std::string::npos) << slow;
  EXPECT_LT(timer.seconds(), 30.0);
}

TEST(Scenes, SparseMatricesAndDofNames) {
  const auto dir = freshDir("sparse");
  fs::create_directories(dir);
  auto scene = [&](const std::string& name, const std::string& K) {
    const auto path = dir / name;
    std::ofstream(path) << "cyclone:\n  analysis: forced_response\n  system:\n    dofs: 2\n"
                           "    M: [1.0, 0.0, 0.0, 1.0]\n    K: " + K + "\n    dof_names: [disc, tip]\n"
                           "  excitation:\n    f: {dof: 0, cos: 1.0}\n  continuation:\n    from: 0.5\n    to: 1.5\n";
    return scenes::loadForcedResponseScene(path.string());
  };
  const auto dense = scene("dense.yaml", "[3.0, -1.0, -1.0, 2.0]");
  const auto sparse = scene("sparse.yaml", "{rows: [0, 0, 1, 1, 1], cols: [0, 1, 0, 1, 1], values: [3.0, -1.0, -1.0, 1.5, 0.5]}");
  EXPECT_EQ((dense.system->K() - sparse.system->K()).norm(), 0.0);
  EXPECT_EQ(sparse.dofNames, (std::vector<std::string>{"disc", "tip"}));
  try {
    scene("bad.yaml", "{rows: [0, 2], cols: [0, 0], values: [1.0, 1.0]}");
    ADD_FAILURE() << "an entry outside the matrix was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("outside 2 x 2"), std::string::npos) << e.what();
  }
}

// max_points is the curve's budget (issue 49: the Duffing curve with max_points 2 came out
// with 508 points: its first sweep stopped at 2, then the sweep from the range's end and
// the other engine each had the whole budget again). The curve ends there, and says so.
TEST(Scenes, MaxPointsIsTheCurvesBudget) {
  log::setQuiet(true);
  for (const int budget : {2, 20}) {
    const auto dir = freshDir("max_points_" + std::to_string(budget));
    const std::string yaml = duffingSceneWith("    to: 2.0", "    to: 2.0\n    max_points: " + std::to_string(budget));
    ASSERT_NE(yaml.find("max_points"), std::string::npos);
    scenes::SceneOverrides o;
    o.outputDirectory = dir.string();
    const auto summary = scenes::runSceneText(yaml, "budget.yaml", o, Tpetra::getDefaultComm());
    const auto rows = readCsv(dir / "frc.csv");
    EXPECT_EQ(int(rows.size()), budget);
    bool said = false;
    for (const auto& line : summary.computed) said = said || line.find("max_points " + std::to_string(budget)) != std::string::npos;
    EXPECT_TRUE(said) << "the summary does not say the curve stopped at its budget";
  }
}

namespace {
// A matrix scene curve's largest point of DOF 0, (max|x(t)|, omega in rad/s), from frc.csv.
std::pair<double, double> largestPoint(const fs::path& dir) {
  double top = 0, at = 0;
  for (const auto& r : readCsv(dir / "frc.csv"))
    if (r.size() > 11 && r[11] > top) top = r[11], at = r[1];  // dof0_max, omega_rad_s
  return {top, at};
}
}  // namespace

// A frequency range of twelve decades (issue 49: the Duffing scene over 1e-6..1e6 rad/s
// stepped from 0.327 to 1000.3 in one step at a fixed parameter, missed the resonance at
// 1.27 and reported the range finished): the steps land on the linear resonance (1 rad/s,
// ContinuationOptions::parameterMarks) instead of passing it, and the curve's largest
// point is the one the scene's own range (0.5..2) gives. The same for a step as long as
// the range.
TEST(Scenes, AWideRangeOrALongStepDoesNotStepOverTheResonance) {
  log::setQuiet(true);
  const auto narrowDir = freshDir("duffing_narrow"), wideDir = freshDir("duffing_wide");
  scenes::SceneOverrides o;
  o.outputDirectory = narrowDir.string();
  scenes::runSceneText(duffingSceneWith("cos: 0.18", "cos: 0.18"), "narrow.yaml", o, Tpetra::getDefaultComm());
  const std::string wide = duffingSceneWith("from: 0.5", "from: 1.0e-6");
  ASSERT_NE(wide.find("from: 1.0e-6"), std::string::npos);
  const std::string wider = std::regex_replace(wide, std::regex("to: 2.0"), "to: 1.0e6");
  ASSERT_NE(wider.find("to: 1.0e6"), std::string::npos);
  o.outputDirectory = wideDir.string();
  scenes::runSceneText(wider, "wide.yaml", o, Tpetra::getDefaultComm());
  {
    std::ifstream header(wideDir / "frc.csv");
    std::string line, column;
    std::getline(header, line);
    std::stringstream columns(line);
    for (int i = 0; i <= 11; ++i) std::getline(columns, column, ',');
    ASSERT_EQ(column, "dof0_max") << line;
  }
  const auto [narrowPeak, narrowAt] = largestPoint(narrowDir);
  const auto [widePeak, wideAt] = largestPoint(wideDir);
  std::printf("largest point: %.6f at %.5f rad/s over 0.5..2, %.6f at %.5f over 1e-6..1e6\n", narrowPeak, narrowAt,
              widePeak, wideAt);
  ASSERT_GT(narrowPeak, 2.8);  // the scene's resonance (its reference 2.83 for |x_1| at 1.2688)
  EXPECT_NEAR(widePeak / narrowPeak, 1.0, 1e-6);  // each curve's largest point is located on its path
  EXPECT_NEAR(wideAt / narrowAt, 1.0, 1e-5);
  // A step as long as the whole range (initial_step and max_step 1000 went from 0.5 to
  // the range's end at 2 in one step, over the resonance, and said the range finished,
  // exit 0): the step lands on the linear resonance first; a step longer than the scaled
  // range is refused.
  const auto longDir = freshDir("duffing_long_steps");
  const std::string longSteps = duffingSceneWith("to: 2.0", "to: 2.0\n    initial_step: 1.0\n    max_step: 1.0");
  ASSERT_NE(longSteps.find("max_step: 1.0"), std::string::npos);
  o.outputDirectory = longDir.string();
  scenes::runSceneText(longSteps, "long.yaml", o, Tpetra::getDefaultComm());
  const auto [longPeak, longAt] = largestPoint(longDir);
  std::printf("largest point: %.6f at %.5f rad/s by steps of 1\n", longPeak, longAt);
  EXPECT_NEAR(longPeak / narrowPeak, 1.0, 1e-6);
  EXPECT_NEAR(longAt / narrowAt, 1.0, 1e-5);
  const std::string msg =
      failure(duffingSceneWith("to: 2.0", "to: 2.0\n    initial_step: 1000.0\n    max_step: 1000.0"), longDir);
  EXPECT_NE(msg.find("continuation/initial_step"), std::string::npos) << msg;
  EXPECT_NE(msg.find("at most 1"), std::string::npos) << msg;
}

// Sections no analysis listed reads (issue 49: `modal: {modes_per_ndd: 3}` in a matrix
// scene was ignored, exit 0). A section of the other kind of scene is refused before any
// work, naming it; a matrix system's response listed with a mesh analysis too (the mesh
// stages would not run). A section of the same kind that the analyses listed do not read
// (reduced_model in a mesh-only scene) runs, with a warning in the summary.
TEST(Scenes, SectionsNoAnalysisReadsAreRefusedOrSaid) {
  log::setQuiet(true);
  const auto dir = freshDir("unread_sections");
  const std::string withModal = duffingSceneWith("  samples: 64", "  samples: 64\n  modal: {modes_per_ndd: 3}");
  ASSERT_NE(withModal.find("modes_per_ndd"), std::string::npos);
  std::string msg = failure(withModal, dir);
  EXPECT_NE(msg.find("cyclone/modal"), std::string::npos) << msg;
  EXPECT_NE(msg.find("is not read by"), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(dir / "frc.csv"));
  const std::string mixed = duffingSceneWith("analysis: forced_response", "analysis: [forced_response, static]");
  ASSERT_NE(mixed.find("[forced_response, static]"), std::string::npos);
  msg = failure(mixed, dir);
  EXPECT_NE(msg.find("runs alone"), std::string::npos) << msg;
  const std::string meshOnly = "cyclone:\n  analysis: [mesh]\n  mesh: {source: shrouded_sector, shrouded_sector: "
                               "{mesh_size: 12.0}}\n";
  msg = failure(meshOnly + "  samples: 64\n", dir);
  EXPECT_NE(msg.find("cyclone/samples"), std::string::npos) << msg;
  scenes::SceneOverrides o;
  o.outputDirectory = dir.string();
  const auto summary =
      scenes::runSceneText(meshOnly + "  reduced_model: {modez: 3}\n", "mesh_only.yaml", o, Tpetra::getDefaultComm());
  bool said = false;
  for (const auto& line : summary.computed) said = said || line.find("'reduced_model' was not read") != std::string::npos;
  EXPECT_TRUE(said) << "no warning for the unread section";
}

// Every section is read and checked before the first FE solve (issue 49: a misspelt key
// in disc_response was refused after the static, modal and reduced-model stages had run
// and written their products; an unknown key in a section no listed analysis reads, or in
// loads, which the disc chain reads only for its speed, passed silently). Each scene
// below, the demo's on its coarsest mesh, must be refused naming the key, before the
// static stage writes anything, in well under the seconds the stages would take.
// A matrix scene's zero excitation (a curve of zeros, "end of the parameter range
// reached", exit 0), an element whose direction is zero (never acting: the linear curve,
// exit 0) and too few samples for its harmonics (refused by the AFT naming no
// key): refused naming the key.
TEST(Scenes, AZeroForceAndTooFewSamplesAreRefused) {
  log::setQuiet(true);
  const auto dir = freshDir("zero_force");
  for (const auto& [pattern, replacement, what] :
       {std::tuple<std::string, std::string, std::string>{"cos: 0.18", "cos: 0.0", "excitation: is zero"},
        {"samples: 64", "samples: 3", "'cyclone/samples': 3: must lie in 15.."},
        {"direction: \\[1.0\\]", "direction: [0.0]", "coordinate 0 of the element is zero on every DOF"}}) {
    const std::string msg = failure(duffingSceneWith(pattern, replacement), dir);
    EXPECT_NE(msg.find(what), std::string::npos) << msg;
  }
}

// The report is this run's: an earlier run's study figure and table in the same output
// directory made a "Parameter studies" section of a run that had none.
TEST(Scenes, TheReportShowsOnlyThisRunsStudies) {
  log::setQuiet(true);
  const auto dir = freshDir("stale_study");
  fs::create_directories(dir);
  std::ofstream(dir / "study_preload.svg") << "<svg xmlns='http://www.w3.org/2000/svg'/>";
  std::ofstream(dir / "study_preload.csv") << "preload,peak_hz,peak\n1,2,3\n";
  scenes::SceneOverrides o;
  o.outputDirectory = dir.string();
  scenes::runSceneText(duffingSceneWith("output_directory: duffing_out", "output_directory: x"), "duffing.yaml", o,
                       Tpetra::getDefaultComm());
  std::ifstream in(dir / "report.md");
  std::stringstream report;
  report << in.rdbuf();
  EXPECT_NE(report.str().find("# Cyclone run report"), std::string::npos);
  EXPECT_EQ(report.str().find("Parameter studies"), std::string::npos) << report.str();
}

TEST(Scenes, EveryKeyIsCheckedBeforeAnyWork) {
  log::setQuiet(true);
  const auto dir = freshDir("keys_before_work");
  auto demoWith = [](const std::string& analyses, const std::string& from, const std::string& to) {
    std::string text = scenes::demoScene();
    auto replace = [&text](const std::string& a, const std::string& b) {
      const auto at = text.find(a);
      EXPECT_NE(at, std::string::npos) << a;
      if (at != std::string::npos) text.replace(at, a.size(), b);
    };
    replace("mesh_size: 6.0", "mesh_size: 12.0");
    replace("analysis: [static, modal, disc_response]", "analysis: " + analyses);
    replace(from, to);
    return text;
  };
  const struct {
    std::string analyses, from, to, key;
  } cases[] = {
      {"[static, modal, disc_response]", "    engine_order: 3\n", "    engine_order: 3\n    harmonicz: 1\n",
       "cyclone/disc_response/harmonicz"},
      {"[static, modal, disc_response]", "    studies:", "    studiez:", "cyclone/disc_response/studiez"},
      {"[static, modal, disc_response]", "      preload: [16000.0,", "      preloadd: [16000.0,",
       "cyclone/disc_response/studies/preloadd"},
      {"[static]", "modes_per_nd: 3", "modes_per_ndd: 3", "cyclone/modal/modes_per_ndd"},
      {"[static]", "    modes: 20\n", "    modez: 20\n", "cyclone/reduced_model/modez"},
      {"[static, disc_response]", "engine_orders: [1,", "engine_orderz: [1,", "cyclone/diagrams/engine_orderz"},
      {"[disc_response]", "speed_rpm: 10000.0", "speed_rmp: 10000.0", "cyclone/loads/speed_rmp"},
      {"[modal]", "    type: direct\n", "    typee: direct\n", "cyclone/solver/typee"},
  };
  for (const auto& c : cases) {
    Timer timer;
    const std::string msg = failure(demoWith(c.analyses, c.from, c.to), dir);
    EXPECT_NE(msg.find("'" + c.key + "': unknown key"), std::string::npos) << c.key << ": " << msg;
    EXPECT_LT(timer.seconds(), 10.0) << c.key;  // the mesh alone; the stages take minutes
    EXPECT_FALSE(fs::exists(dir / "static.exo")) << c.key << ": the static stage ran";
    EXPECT_FALSE(fs::exists(dir / "frequencies.csv")) << c.key << ": the modal stage ran";
  }
  // A value too, before the work: modes that cannot fit the sector (10000 reached Anasazi
  // and came back as its "Num Blocks must be strictly positive").
  {
    Timer timer;
    const std::string msg =
        failure(demoWith("[static, modal, disc_response]", "    modes: 20\n", "    modes: 10000\n"), dir);
    EXPECT_NE(msg.find("'cyclone/reduced_model/modes': 10000 is more than half the sector's"), std::string::npos)
        << msg;
    EXPECT_LT(timer.seconds(), 10.0);
    EXPECT_FALSE(fs::exists(dir / "static.exo"));
  }
  // Contact patches: more than the face's pairs, and beside gap elements (which name
  // pairs), refused with the key before the work.
  for (const auto& [patches, gap, key, what] :
       {std::tuple<int, bool, std::string, std::string>{400, false, "cyclone/disc_response/contact/patches",
                                                        "must lie in 0.."},
        {4, true, "cyclone/disc_response/gap/pairs", "names node pairs, which contact/patches groups"}}) {
    Timer timer;
    std::string scene = demoWith("[static, modal, disc_response]", "      mu: 0.4\n",
                                 "      mu: 0.4\n      patches: " + std::to_string(patches) + "\n");
    if (gap) scene = std::regex_replace(scene, std::regex("\n    excitation:\n"), "\n    gap: {pairs: [0]}\n    excitation:\n");
    const std::string msg = failure(scene, dir);
    EXPECT_NE(msg.find("'" + key + "': " + what), std::string::npos) << msg;
    EXPECT_LT(timer.seconds(), 10.0);
    EXPECT_FALSE(fs::exists(dir / "static.exo"));
  }
  // Values, each refused naming its key before the work (a probe of the shipped build
  // found these refused only after the reduced models or the reference curve, or not at
  // all: check_frequencies -1 skipped the check, a study of 50 modes used the models' 20).
  const struct {
    std::string from, to, key, what;
  } values[] = {
      {"    engine_order: 3\n", "    engine_order: 3\n    samples: 1\n", "cyclone/disc_response/samples",
       "1: must lie in 3.."},
      {"      preload: [16000.0,", "      mu: [0.2, -1.0]\n      preload: [16000.0,",
       "cyclone/disc_response/studies/mu", "the value -1: contact"},
      {"      preload: [16000.0,", "      modes: [50]\n      preload: [16000.0,",
       "cyclone/disc_response/studies/modes", "the value 50: must be a whole number of modes from 1 to the reduced "
                                              "models' 20"},
      {"      preload: [16000.0,", "      force: [0.0]\n      preload: [16000.0,",
       "cyclone/disc_response/studies/force", "the value 0: excitation/amplitude: must be finite and not zero"},
      {"      amplitude: 20.0\n", "      amplitude: 0.0\n", "cyclone/disc_response/excitation/amplitude",
       "must be finite and not zero"},
      {"      mu: 0.4\n", "      mu: 0.4\n      normal: [1.0, 0.0, 0.0]\n      tangent: [1.0, 0.0, 0.0]\n",
       "cyclone/disc_response/contact/normal, contact/tangent", "contact frame not orthonormal"},
      {"    modes: 20\n", "    modes: 20\n    check_frequencies: -1\n", "cyclone/reduced_model/check_frequencies",
       "-1: must be >= 0"},
      // Refused only after the reduced models were built, or late in the stage, or under
      // another key (a second probe of the shipped build).
      {"    engine_order: 3\n", "    engine_order: 3\n    family: 99\n", "cyclone/disc_response/family",
       "99: must lie in 1..20"},
      {"    engine_order: 3\n", "    engine_order: 3\n    response_node_sets: [bore]\n",
       "cyclone/reduced_model/retained_node_sets", "does not retain node set 'bore'"},
      {"    modes: 20\n", "    modes: 20\n    retained_node_sets: []\n", "cyclone/reduced_model/retained_node_sets",
       "is empty"},
      {"    engine_order: 3\n", "    engine_order: 3\n    frequency_range_hz: [1400.0, 1700.0]\n",
       "cyclone/disc_response/peak_stress/at_hz", "2000.000000 Hz lies outside"},
      {"    rho: 4.507e-9\n", "    rho: 1.0e300\n", "cyclone/loads/speed_rpm", "10000 rpm: rho (Omega r)^2"},
      {"speed_rpm: 10000.0", "speed_rpm: -100.0", "cyclone/loads/speed_rpm", "-100.000000: must be >= 0"},
      {"mesh_size: 12.0", "mesh_size: 1.0e300", "cyclone/mesh/shrouded_sector",
       "parameter 'mesh_size' must be at most"},
      {"    excitation:\n      node_set: mid_blade\n      direction: [0.0, 0.0, 1.0]\n      amplitude: 20.0\n", "",
       "cyclone/disc_response/excitation", "is required"},
  };
  for (const auto& c : values) {
    Timer timer;
    std::string scene = demoWith("[static, modal, disc_response]", c.from, c.to);
    if (c.key.find("at_hz") != std::string::npos)
      scene = std::regex_replace(scene, std::regex("animation_steps: 32"), "animation_steps: 32\n      at_hz: 2000.0");
    const std::string msg = failure(scene, dir);
    EXPECT_NE(msg.find("'" + c.key + "': " + c.what), std::string::npos) << c.key << ": " << msg;
    EXPECT_LT(timer.seconds(), 10.0) << c.key;
    EXPECT_FALSE(fs::exists(dir / "static.exo")) << c.key;
  }
  {  // the fatigue data checked without peak_stress too (a wrong name passed silently)
    std::string scene = std::regex_replace(demoWith("[static, modal, disc_response]", "data: Ti-6Al-4V", "data: Nonsense"),
                                           std::regex("\n    peak_stress:[^\n]*\n      animation_steps:[^\n]*"), "");
    ASSERT_EQ(scene.find("    peak_stress:"), std::string::npos);
    const std::string msg = failure(scene, dir);
    EXPECT_NE(msg.find("'cyclone/material/fatigue/data': 'Nonsense' is not known"), std::string::npos) << msg;
    EXPECT_FALSE(fs::exists(dir / "static.exo"));
  }
  {  // harmonics 500: the friction solve's cost known from the contact pairs (it was refused
     // only after the reduced models were built)
    Timer timer;
    const std::string scene = std::regex_replace(
        demoWith("[static, modal, disc_response]", "harmonics: auto ", "harmonics: 500 "),
        std::regex("\n    harmonics_(tolerance|max):[^\n]*"), "");
    ASSERT_EQ(scene.find("harmonics_max"), std::string::npos);
    const std::string msg = failure(scene, dir);
    EXPECT_NE(msg.find("'cyclone/disc_response/harmonics': harmonics up to 500 on"), std::string::npos) << msg;
    EXPECT_NE(msg.find("the elements' Jacobians alone take about"), std::string::npos) << msg;
    EXPECT_LT(timer.seconds(), 10.0);
    EXPECT_FALSE(fs::exists(dir / "static.exo"));
  }
  // A section no listed analysis reads, whose reader needs another section the scene
  // lacks (reduced_model's needs the constraints), cannot be checked: said, not refused.
  scenes::SceneOverrides o;
  o.outputDirectory = dir.string();
  const auto summary = scenes::runSceneText("cyclone:\n  analysis: [mesh]\n  mesh: {source: shrouded_sector, "
                                            "shrouded_sector: {mesh_size: 12.0}}\n  reduced_model: {modes: 3}\n",
                                            "mesh_only.yaml", o, Tpetra::getDefaultComm());
  bool said = false;
  for (const auto& line : summary.computed)
    said = said || line.find("'reduced_model' was not read by the analyses listed (mesh): its keys could not be "
                             "checked") != std::string::npos;
  EXPECT_TRUE(said) << "no warning for the unread section";
}

// What Teuchos' YAML reader does not take (issue 49: each gave a parser state number): a
// UTF-8 byte-order mark and a block list whose dashes stand at its key's indentation are
// valid YAML and read as the same scene (the Duffing curve's peak to the last digit); an
// anchor or alias is refused naming its line; a directory given as the scene is named as
// one.
TEST(Scenes, YamlTeuchosDoesNotTakeIsReadOrRefusedPlainly) {
  log::setQuiet(true);
  auto peakOf = [](const std::string& yaml, const std::string& name) {
    scenes::SceneOverrides o;
    o.outputDirectory = freshDir("yaml_" + name).string();
    scenes::runSceneText(yaml, name + ".yaml", o, Tpetra::getDefaultComm());
    std::ifstream csv(fs::path(*o.outputDirectory) / "frc.csv");
    auto cells = [](const std::string& line) {
      std::vector<std::string> out;
      std::stringstream row(line);
      for (std::string cell; std::getline(row, cell, ',');) out.push_back(cell);
      return out;
    };
    std::string line;
    std::getline(csv, line);
    const auto header = cells(line);
    const auto column = std::find(header.begin(), header.end(), "dof0_max") - header.begin();
    EXPECT_LT(std::size_t(column), header.size()) << line;
    double peak = 0;
    while (std::getline(csv, line)) peak = std::max(peak, std::stod(cells(line).at(std::size_t(column))));
    return peak;
  };
  const std::string plain = duffingSceneWith("cos: 0.18", "cos: 0.18");
  const double reference = peakOf(plain, "plain");
  EXPECT_GT(reference, 1.0);
  EXPECT_EQ(peakOf("\xEF\xBB\xBF" + plain, "bom"), reference);
  const std::string dashes = duffingSceneWith("    dofs: \\[0\\]", "    dofs:\n    - 0");
  ASSERT_NE(dashes.find("    dofs:\n    - 0"), std::string::npos);
  const std::string harmonics = std::regex_replace(dashes, std::regex("  harmonics: \\[7\\]"), "  harmonics:\n  - 7");
  ASSERT_NE(harmonics.find("  harmonics:\n  - 7"), std::string::npos);
  EXPECT_EQ(peakOf(harmonics, "dashes"), reference);
  const auto dir = freshDir("yaml_refused");
  std::string msg = failure(duffingSceneWith("  samples: 64", "  samples: &s 64"), dir);
  EXPECT_NE(msg.find("anchors and aliases"), std::string::npos) << msg;
  EXPECT_TRUE(std::regex_search(msg, std::regex("bad.yaml: line [0-9]+"))) << msg;
  // A key given twice, an empty or comment-only scene, a list for a scene: said as such
  // (the parser said "Parser failure at line 15 column 6", "Could not tokenize this").
  msg = failure(duffingSceneWith("    K: \\[1.0\\]", "    K: [1.0]\n    K: [2.0]"), dir);
  EXPECT_NE(msg.find("the key 'K' is given twice in the same section (first at line"), std::string::npos) << msg;
  for (const std::string empty : {"", "\n\n", "# only a comment\n  # another\n"}) {
    msg = failure(empty, dir);
    EXPECT_NE(msg.find("the scene is empty"), std::string::npos) << msg;
  }
  msg = failure("- cyclone:\n    analysis: static\n", dir);
  EXPECT_NE(msg.find("the scene is a list; it must be a mapping"), std::string::npos) << msg;
  // The same key in two list items, or in sibling sections, is not twice.
  {
    scenes::SceneOverrides o;
    o.outputDirectory = freshDir("yaml_siblings").string();
    const std::string siblings = std::regex_replace(plain, std::regex("      k3: 0.1"), "      k3: 0.1\n  # dof: here\n");
    EXPECT_NO_THROW(scenes::runSceneText(siblings, "siblings.yaml", o, Tpetra::getDefaultComm()));
  }
  fs::create_directories(dir);
  try {
    scenes::runSceneFile(dir.string(), {}, Tpetra::getDefaultComm());
    ADD_FAILURE() << "a directory was run as a scene";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory, not a scene"), std::string::npos) << e.what();
  }
}

// Stability by Hill's method needs an invertible mass matrix (issue 49: a singular one was
// refused only after the curve was traced, writing nothing). A two-DOF system whose second
// mass is 1e-20: asked for, refused before the trace, no file written; by default the
// curve is traced and says why it has no stability.
TEST(Scenes, ASingularMassMatrixIsSaidBeforeTheTrace) {
  log::setQuiet(true);
  std::string yaml = duffingSceneWith("    dofs: 1\n    M: \\[1.0\\]\n    C: \\[0.05\\]\n    K: \\[1.0\\]",
                                      "    dofs: 2\n    M: [1.0, 0.0, 0.0, 1.0e-20]\n    C: [0.05, 0.0, 0.0, 0.05]\n"
                                      "    K: [2.0, -1.0, -1.0, 1.0]");
  yaml = std::regex_replace(yaml, std::regex("      direction: \\[1.0\\]"), "      direction: [1.0, 0.0]");
  ASSERT_NE(yaml.find("1.0e-20"), std::string::npos);
  const auto dir = freshDir("singular_mass");
  const std::string asked = std::regex_replace(yaml, std::regex("    dofs: \\[0\\]"), "    dofs: [0]\n    stability: true");
  ASSERT_NE(asked.find("stability: true"), std::string::npos);
  const std::string msg = failure(asked, dir);
  EXPECT_NE(msg.find("invertible mass matrix"), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(dir / "frc.csv"));
  scenes::SceneOverrides o;
  o.outputDirectory = dir.string();
  const auto summary = scenes::runSceneText(yaml, "singular.yaml", o, Tpetra::getDefaultComm());
  bool said = false;
  for (const auto& line : summary.computed) said = said || line.find("the mass matrix is singular") != std::string::npos;
  EXPECT_TRUE(said) << "the curve does not say why it has no stability";
  EXPECT_TRUE(fs::exists(dir / "frc.csv"));
}

// A full disk (issue 49: a 12-36 kB filesystem crashed the program in HDF5's close at
// exit, the manifest left "running"; at 40 kB frc.h5 was left in place cut short). The
// Duffing scene into a tmpfs of each size from 8 to 64 kB: every run ends with exit 0 or
// 1, never a signal; a failed one names the file and "No space left on device", and its
// manifest says failed; every file left is whole (frc.h5 read back with the curve's
// points, text files ending in a newline) and no temporary is left. Needs the right to
// mount a tmpfs (root, as this project's machine runs the suite): skipped, saying so,
// where it is not given.
// A read-only output directory (issue 49 probe: "cannot create the run's lock file",
// no reason): the system's reason is said. A tmpfs mounted read-only (root ignores a
// directory's mode); skipped where it cannot be mounted.
TEST(Scenes, AReadOnlyOutputDirectoryIsSaidWithTheReason) {
  log::setQuiet(true);
  ::umount2((fs::temp_directory_path() / "cyclone_scene_test_read_only").c_str(), MNT_DETACH);
  const auto disk = freshDir("read_only");
  fs::create_directories(disk);
  if (::mount("tmpfs", disk.c_str(), "tmpfs", 0, "size=64k") != 0)
    GTEST_SKIP() << "cannot mount a tmpfs here (" << std::strerror(errno) << "): the test needs root";
  fs::create_directories(disk / "o");
  ASSERT_EQ(::mount("tmpfs", disk.c_str(), "tmpfs", MS_REMOUNT | MS_RDONLY, "size=64k"), 0) << std::strerror(errno);
  const std::string msg = failure(duffingSceneWith("cos: 0.18", "cos: 0.18"), disk / "o");
  ::umount2(disk.c_str(), MNT_DETACH);
  EXPECT_NE(msg.find("cannot create the run's lock file"), std::string::npos) << msg;
  EXPECT_NE(msg.find("Read-only file system"), std::string::npos) << msg;
}

TEST(Scenes, AFullDiskIsSaidAndLeavesNoHalfFile) {
  // A run of this test killed while its tmpfs was mounted leaves the mount: taken away first.
  ::umount2((fs::temp_directory_path() / "cyclone_scene_test_full_disk").c_str(), MNT_DETACH);
  const auto disk = freshDir("full_disk");
  fs::create_directories(disk);
  if (::mount("tmpfs", disk.c_str(), "tmpfs", 0, "size=8k") != 0)
    GTEST_SKIP() << "cannot mount a tmpfs here (" << std::strerror(errno) << "): the test needs root";
  ::umount2(disk.c_str(), MNT_DETACH);
  const std::string scene = std::string(CYCLONE_SCENE_DIR) + "/duffing.yaml";
  int failed = 0, completed = 0;
  for (int kb = 8; kb <= 64; kb += 8) {
    const std::string size = "size=" + std::to_string(kb) + "k";
    ASSERT_EQ(::mount("tmpfs", disk.c_str(), "tmpfs", 0, size.c_str()), 0) << std::strerror(errno);
    const fs::path out = disk / "o", log = freshDir("full_disk_log").string() + std::to_string(kb) + ".log";
    const int status = std::system((std::string(CYCLONE_EXE) + " run " + scene + " --output " + out.string() + " > " +
                                    log.string() + " 2>&1").c_str());
    std::ifstream logFile(log);
    const std::string text((std::istreambuf_iterator<char>(logFile)), std::istreambuf_iterator<char>());
    ASSERT_TRUE(WIFEXITED(status)) << kb << " kB: killed by a signal\n" << text;
    const int code = WEXITSTATUS(status);
    EXPECT_TRUE(code == 0 || code == 1) << kb << " kB: exit " << code << "\n" << text;
    std::ifstream manifestFile(out / "run_manifest.txt");
    const std::string manifest((std::istreambuf_iterator<char>(manifestFile)), std::istreambuf_iterator<char>());
    if (code == 1) {
      ++failed;
      const std::regex said("cannot write " + out.string() + "/[a-z0-9_.]+: No space left on device");
      EXPECT_TRUE(std::regex_search(text, said)) << kb << " kB:\n" << text;
      EXPECT_EQ(manifest.rfind("status: failed", 0), 0u) << kb << " kB:\n" << manifest;
    } else {
      ++completed;
      EXPECT_EQ(manifest.rfind("status: complete", 0), 0u) << kb << " kB:\n" << manifest;
    }
    for (const auto& entry : fs::directory_iterator(out)) {
      const std::string name = entry.path().filename().string();
      EXPECT_TRUE(name[0] != '.' || name == ".cyclone_run.lock") << kb << " kB: left " << name;
      if (name == "frc.h5") {
        const auto curve = io::readResponseCurveHdf5(entry.path().string());
        std::ifstream csv(out / "frc.csv");
        const long rows = std::count(std::istreambuf_iterator<char>(csv), std::istreambuf_iterator<char>(), '\n') - 1;
        EXPECT_EQ(long(curve.omega.size()), rows) << kb << " kB";
      } else if (entry.path().extension() == ".csv" || entry.path().extension() == ".md") {
        std::ifstream f(entry.path(), std::ios::binary | std::ios::ate);
        ASSERT_GT(f.tellg(), 0) << kb << " kB: " << name;
        f.seekg(-1, std::ios::end);
        EXPECT_EQ(f.get(), '\n') << kb << " kB: " << name << " cut short";
      }
    }
    ASSERT_EQ(::umount2(disk.c_str(), MNT_DETACH), 0) << std::strerror(errno);
  }
  EXPECT_GT(failed, 0);     // the disk filled at the small sizes
  EXPECT_GT(completed, 0);  // and the scene completes where it fits
  // The reduced-model cache on a disk that takes the first model (ND 0, 160 kB on the
  // coarsest demo disc) but not the checked one (ND 3, 620 kB): its check file was written
  // before the model and stayed behind alone (issue 49). Neither may be left without the other.
  std::string demo = std::regex_replace(scenes::demoScene(), std::regex("mesh_size: 6.0"), "mesh_size: 12.0");
  demo = std::regex_replace(demo, std::regex("analysis: \\[static, modal, disc_response\\]"), "analysis: [disc_response]");
  demo = std::regex_replace(demo, std::regex("\n    write: \\[exodus, inp\\]"), "");
  ASSERT_NE(demo.find("analysis: [disc_response]"), std::string::npos);
  const fs::path discScene = freshDir("full_disk_disc").string() + ".yaml";
  std::ofstream(discScene) << demo;
  ASSERT_EQ(::mount("tmpfs", disk.c_str(), "tmpfs", 0, "size=400k"), 0) << std::strerror(errno);
  const fs::path out = disk / "o", log = freshDir("full_disk_log").string() + "disc.log";
  const int status = std::system((std::string(CYCLONE_EXE) + " run " + discScene.string() + " --output " +
                                  out.string() + " > " + log.string() + " 2>&1").c_str());
  std::ifstream logFile(log);
  const std::string text((std::istreambuf_iterator<char>(logFile)), std::istreambuf_iterator<char>());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << text;
  EXPECT_NE(text.find("No space left on device"), std::string::npos) << text;
  int models = 0;
  for (const auto& entry : fs::directory_iterator(out / "reduced_models")) {
    const std::string name = entry.path().filename().string();
    EXPECT_NE(name[0], '.') << "left " << name;
    if (entry.path().extension() == ".h5") ++models;
    if (name.size() > 10 && name.substr(name.size() - 10) == ".check.csv")
      EXPECT_TRUE(fs::exists(out / "reduced_models" / name.substr(0, name.size() - 10))) << name << " without its model";
  }
  EXPECT_GE(models, 1) << "the disk did not take the first model: the case is not the one meant";
  ASSERT_EQ(::umount2(disk.c_str(), MNT_DETACH), 0) << std::strerror(errno);
}

// A run killed outright (SIGKILL) in the middle of a write leaves its temporary file
// (issue 49: the next run did not remove it). The next run into the directory, holding its
// lock, removes every such file, in the subdirectories Cyclone writes too (checkpoints, reduced_models), and says so; other files stay.
TEST(Scenes, AKilledRunsTemporaryFilesAreRemoved) {
  log::setQuiet(true);
  const auto dir = freshDir("killed_run_temporaries");
  fs::create_directories(dir / "checkpoints");
  for (const fs::path& p : {dir / ".frc.csv.tmp4242", dir / "checkpoints" / ".trace.h5.tmp17", dir / "notes.tmp1",
                            dir / ".keep.tmp"})
    std::ofstream(p) << "left";
  scenes::SceneOverrides o;
  o.outputDirectory = dir.string();
  const auto summary = scenes::runSceneText(duffingSceneWith("cos: 0.18", "cos: 0.18"), "duffing.yaml", o,
                                            Tpetra::getDefaultComm());
  EXPECT_FALSE(fs::exists(dir / ".frc.csv.tmp4242"));
  EXPECT_FALSE(fs::exists(dir / "checkpoints" / ".trace.h5.tmp17"));
  EXPECT_TRUE(fs::exists(dir / "notes.tmp1"));  // not a temporary's name (no leading dot)
  EXPECT_TRUE(fs::exists(dir / ".keep.tmp"));   // no process id
  EXPECT_TRUE(fs::exists(dir / "frc.csv"));
  bool said = false;
  for (const auto& line : summary.computed) said = said || line.find("removed 2 temporary files") != std::string::npos;
  EXPECT_TRUE(said) << "the summary does not say what was removed";
}
