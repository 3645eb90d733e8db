// Helpers shared by the scene tests (regression/scenes/test_*.cpp, one executable,
// scene_tests): scratch directories, scene texts, failing runs and the products' CSV
// files read back.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace cyclone::scene_tests {

namespace fs = std::filesystem;

// A scratch directory under the system's temporary directory, removed if it exists.
fs::path freshDir(const std::string& name);

// A static scene of the built-in sector (mesh size 10, the bore held, 10 000 rpm);
// `extra` is appended to the scene, `sectorExtra` to its shrouded_sector block.
std::string smallScene(const std::string& extra = "", const std::string& sectorExtra = "");

// Runs a scene that must fail; returns the message.
std::string failure(const std::string& yaml, const fs::path& dir);

// The Duffing scene with one value replaced (a regex on its text).
std::string duffingSceneWith(const std::string& pattern, const std::string& replacement);

// frequencies.csv as (rpm, nd) -> frequencies in mode order; checks the header.
std::map<std::pair<double, int>, std::vector<double>> readFrequencies(const fs::path& dir);

// A small 8-sector disc (thin ring) with the bore held.
std::string discScene(const std::string& analysis);

// The forced response of that disc at 10 000 rpm, EO 3, harmonic 1, 5 N preload, 20 N;
// a test appends keys of disc_response.
std::string discResponseScene();

// Columns of a frc.csv as numbers (header skipped).
std::vector<std::vector<double>> readCsv(const fs::path& path);

// A matrix scene curve's largest point of DOF 0, (max|x(t)|, omega in rad/s), from frc.csv.
std::pair<double, double> largestPoint(const fs::path& dir);

}  // namespace cyclone::scene_tests
