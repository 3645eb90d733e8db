#include "cyclone/mistuning/BladeMistuning.hpp"

#include <cmath>
#include <string>

#include "cyclone/core/Error.hpp"
#include "cyclone/mistuning/MistuningPattern.hpp"

namespace cyclone::mistuning {

namespace {

void checkLength(std::size_t size, int blades, const std::string& key) {
  if (blades < 2) throw InputError(key, "the disc must have at least 2 blades (got " + std::to_string(blades) + ")");
  if (int(size) != blades)
    throw InputError(key, "has " + std::to_string(size) + " entries; the disc has " + std::to_string(blades) +
                              " blades (one entry per blade)");
}

}  // namespace

std::vector<double> BladeMistuning::deviations() const {
  std::vector<double> d(youngsFactors.size());
  for (std::size_t j = 0; j < d.size(); ++j) d[j] = youngsFactors[j] - 1.0;
  return d;
}

void BladeMistuning::validate(int blades) const {
  const std::string key = "mistuning/youngs_modulus_factors";
  checkLength(youngsFactors.size(), blades, key);
  for (std::size_t j = 0; j < youngsFactors.size(); ++j) {
    const double f = youngsFactors[j];
    if (!std::isfinite(f) || !(f > 0))
      throw InputError(key, "blade " + std::to_string(j) + "'s factor is " + std::to_string(f) +
                                ": a Young's modulus factor must be finite and positive");
  }
}

BladeMistuning youngsModulusFactors(std::vector<double> factors, int blades) {
  BladeMistuning m{std::move(factors)};
  m.validate(blades);
  return m;
}

BladeMistuning fromFrequencyDeviations(const std::vector<double>& deltas, int blades) {
  const std::string key = "mistuning/frequency_deviations";
  checkLength(deltas.size(), blades, key);
  BladeMistuning m;
  for (std::size_t j = 0; j < deltas.size(); ++j) {
    const double d = deltas[j];
    if (!std::isfinite(d) || !(d > -1))
      throw InputError(key, "blade " + std::to_string(j) + "'s deviation is " + std::to_string(d) +
                                ": (w_j / w)^2 - 1 must be finite and above -1");
    m.youngsFactors.push_back(1.0 + d);
  }
  return m;
}

BladeMistuning randomBladeMistuning(int blades, double sigma, std::uint64_t seed) {
  if (!std::isfinite(sigma) || sigma < 0)
    throw InputError("mistuning/standard_deviation", "must be finite and >= 0 (got " + std::to_string(sigma) + ")");
  std::vector<double> delta;
  try {
    delta = randomPattern(blades, sigma, seed);
  } catch (const InputError& e) {
    throw InputError("mistuning/" + e.where(), e.problem());
  }
  return fromFrequencyDeviations(delta, blades);
}

std::vector<mesh::Index> bladeElementsAboveRadius(const mesh::Mesh& mesh, const mesh::RotationAxis& axis,
                                                  double radius) {
  const Eigen::Vector3d a = axis.direction.normalized();
  std::vector<mesh::Index> out;
  mesh::Index g = 0;
  for (const auto& block : mesh.blocks) {
    const int nn = mesh::nodesPerElement(block.type);
    for (mesh::Index e = 0; e < block.numElements(); ++e, ++g) {
      const mesh::Index* nodes = block.element(e);
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for (int k = 0; k < nn; ++k) c += Eigen::Vector3d(mesh.coords[nodes[k]].data());
      c /= nn;
      const Eigen::Vector3d r = c - axis.point;
      if ((r - r.dot(a) * a).norm() > radius) out.push_back(g);
    }
  }
  if (out.empty() || mesh::Index(out.size()) == g)
    throw InputError("blade_elements", std::to_string(out.size()) + " of " + std::to_string(g) +
                                           " elements have their centroid beyond radius " + std::to_string(radius) +
                                           ": that radius does not split the disc from the blade");
  return out;
}

std::vector<mesh::Index> bladeElements(const mesh::Mesh& mesh, const std::string& setName) {
  const auto it = mesh.elementSets.find(setName);
  if (it == mesh.elementSets.end() || it->second.empty())
    throw InputError("mistuning/blade_element_set",
                     "the mesh (" + mesh.source + ") has no element set '" + setName + "' with elements");
  return it->second;
}

}  // namespace cyclone::mistuning
