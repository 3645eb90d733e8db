// Helpers shared by the scene tests (test_scene_support.hpp).
#include "test_scene_support.hpp"

#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include "cyclone/core/Error.hpp"
#include "cyclone/scenes/SceneRunner.hpp"

namespace cyclone::scene_tests {

fs::path freshDir(const std::string& name) {
  const auto dir = fs::temp_directory_path() / ("cyclone_scene_test_" + name);
  fs::remove_all(dir);
  return dir;
}

std::string smallScene(const std::string& extra, const std::string& sectorExtra) {
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

std::string duffingSceneWith(const std::string& pattern, const std::string& replacement) {
  std::ifstream in(CYCLONE_SCENE_DIR "/duffing.yaml");
  std::stringstream text;
  text << in.rdbuf();
  return std::regex_replace(text.str(), std::regex(pattern), replacement);
}

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

std::pair<double, double> largestPoint(const fs::path& dir) {
  double top = 0, at = 0;
  for (const auto& r : readCsv(dir / "frc.csv"))
    if (r.size() > 11 && r[11] > top) top = r[11], at = r[1];  // dof0_max, omega_rad_s
  return {top, at};
}

}  // namespace cyclone::scene_tests
