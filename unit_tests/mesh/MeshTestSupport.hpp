#pragma once
// Helpers shared by the mesh reader/writer tests: a private temporary directory,
// file writing, InputError expectations and an independent volume integral.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

#include "cyclone/core/Error.hpp"
#include "cyclone/mesh/Mesh.hpp"
#include "cyclone/mesh/ReferenceElement.hpp"

namespace cyclone::mesh::testing {

/// A fresh directory under the system temp path, removed with its contents at scope exit.
class TempDirectory {
public:
  TempDirectory() {
    static std::atomic<int> counter{0};
    std::random_device random;
    path_ = std::filesystem::temp_directory_path() /
            ("cyclone_mesh_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) + "_" +
             std::to_string(random()));
    std::filesystem::create_directories(path_);
  }
  ~TempDirectory() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDirectory(const TempDirectory&) = delete;
  TempDirectory& operator=(const TempDirectory&) = delete;

  std::string file(const std::string& name) const { return (path_ / name).string(); }
  /// Writes `text` to `name` (creating sub-directories) and returns the full path.
  std::string write(const std::string& name, const std::string& text) const {
    const auto p = path_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p.string();
  }
  /// Names of the entries in the directory (to prove nothing was left behind).
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(path_)) names.push_back(entry.path().filename());
    return names;
  }

private:
  std::filesystem::path path_;
};

/// Runs f, expecting an InputError whose message contains every one of `parts`.
inline void expectInputError(const std::function<void()>& f, const std::vector<std::string>& parts) {
  try {
    f();
    ADD_FAILURE() << "no InputError thrown; expected one mentioning '" << (parts.empty() ? "" : parts[0]) << "'";
  } catch (const InputError& e) {
    const std::string message = e.what();
    for (const auto& part : parts) EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
  }
}

/// Volume by Gauss integration of det(dx/dxi) (exact for straight-edged elements).
inline double meshVolume(const Mesh& mesh) {
  double volume = 0;
  for (const auto& block : mesh.blocks) {
    const int n = nodesPerElement(block.type);
    const auto& rule = stiffnessRule(block.type);
    Eigen::Matrix<double, Eigen::Dynamic, 3> x(n, 3);
    ShapeValues N(n);
    ShapeGradients dN(n, 3);
    for (Index e = 0; e < block.numElements(); ++e) {
      for (int a = 0; a < n; ++a)
        for (int d = 0; d < 3; ++d) x(a, d) = mesh.coords[block.element(e)[a]][d];
      for (std::size_t q = 0; q < rule.points.size(); ++q) {
        evaluateShape(block.type, rule.points[q], N, dN);
        const Eigen::Matrix3d J = x.transpose() * dN;
        volume += rule.weights[q] * J.determinant();
      }
    }
  }
  return volume;
}

/// Exodus mid-edge node pairs (ElementType.hpp) for the quadratic types.
inline const std::vector<std::pair<int, int>>& midEdgeCorners(ElementType type) {
  static const std::vector<std::pair<int, int>> tet10 = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  static const std::vector<std::pair<int, int>> hex20 = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                                         {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  static const std::vector<std::pair<int, int>> none;
  return type == ElementType::Tet10 ? tet10 : type == ElementType::Hex20 ? hex20 : none;
}

/// Largest distance of a mid-edge node from the midpoint of its edge's corners.
inline double maxMidEdgeOffset(const Mesh& mesh) {
  double worst = 0;
  for (const auto& block : mesh.blocks) {
    const auto& edges = midEdgeCorners(block.type);
    const int corners = block.type == ElementType::Tet10 ? 4 : 8;
    for (Index e = 0; e < block.numElements(); ++e) {
      const Index* nodes = block.element(e);
      for (std::size_t k = 0; k < edges.size(); ++k) {
        const auto& a = mesh.coords[nodes[edges[k].first]];
        const auto& b = mesh.coords[nodes[edges[k].second]];
        const auto& m = mesh.coords[nodes[corners + k]];
        double d2 = 0;
        for (int i = 0; i < 3; ++i) d2 += (m[i] - 0.5 * (a[i] + b[i])) * (m[i] - 0.5 * (a[i] + b[i]));
        worst = std::max(worst, std::sqrt(d2));
      }
    }
  }
  return worst;
}

}  // namespace cyclone::mesh::testing
