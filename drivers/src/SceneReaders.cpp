// Readers shared by the scene stages: the rotation axis, prestress kind, harmonic
// list, stability, harmonics check, cyclic faces and material of a scene section.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "SceneStages.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/scenes/SceneSection.hpp"

namespace cyclone::scenes {

mesh::RotationAxis readRotationAxis(SceneSection& section) {
  const auto p = section.getVector3("axis_point", {0, 0, 0}), d = section.getVector3("axis_direction", {0, 0, 1});
  mesh::RotationAxis axis{Eigen::Vector3d(p[0], p[1], p[2]), Eigen::Vector3d(d[0], d[1], d[2])};
  if (!(axis.direction.norm() > 0)) throw InputError(section.where("axis_direction"), "must not be zero");
  return axis;
}

cyclic::PrestressKind readPrestressKind(SceneSection& section, const std::string& fallback) {
  using Kind = cyclic::PrestressKind;
  return section.getChoice<Kind>(
      "prestress", fallback, {{"linear", Kind::Linear}, {"nonlinear", Kind::Nonlinear}, {"none", Kind::None}},
      [](const std::string& value) { return "unknown prestress '" + value + "' (use linear, nonlinear or none)"; });
}

std::vector<int> readHarmonicList(SceneSection& section, int defaultMax) {
  if (section.isWord("harmonics", "auto")) {  // by an error target: from 0..1 up (readHarmonicsTarget)
    section.getString("harmonics", "");  // marks the key read
    return {0, 1};
  }
  std::vector<int> list = section.getIntList("harmonics", {defaultMax});
  if (list.size() == 1) {  // a single number H means 0..H
    const int H = list[0];
    if (H < 1) throw InputError(section.where("harmonics"), "needs at least harmonic 1 (a single number H means 0..H)");
    list.clear();
    for (int h = 0; h <= H; ++h) list.push_back(h);
  }
  // The harmonic set's own refusals under the key: they named its class (issue 49 probe).
  if (list.empty()) throw InputError(section.where("harmonics"), "is empty: give a list of harmonics or H (0..H)");
  std::vector<int> sorted = list;
  std::sort(sorted.begin(), sorted.end());
  if (sorted.front() < 0)
    throw InputError(section.where("harmonics"), "harmonic " + std::to_string(sorted.front()) + " is negative");
  for (std::size_t i = 1; i < sorted.size(); ++i)
    if (sorted[i] == sorted[i - 1])
      throw InputError(section.where("harmonics"), "harmonic " + std::to_string(sorted[i]) + " is listed twice");
  return list;
}

response::ForcedResponseSetup::Stability readStability(SceneSection& section) {
  using Stability = response::ForcedResponseSetup::Stability;
  return section.getChoice<Stability>(
      "stability", "auto", {{"auto", Stability::Auto}, {"true", Stability::Always}, {"false", Stability::Never}},
      [](const std::string&) { return "must be auto, true or false"; });
}

HarmonicsTargetKeys readHarmonicsTarget(SceneSection& section, int defaultMax) {
  HarmonicsTargetKeys keys;
  if (!section.isWord("harmonics", "auto")) {
    for (const char* key : {"harmonics_tolerance", "harmonics_max"})
      if (section.has(key)) throw InputError(section.where(key), "applies to harmonics: auto only");
    return keys;
  }
  keys.tolerance = section.getDouble("harmonics_tolerance", 0.01);
  if (!(keys.tolerance > 0 && keys.tolerance < 0.5))
    throw InputError(section.where("harmonics_tolerance"),
                     "a relative change of the peak between harmonic counts, 0 < tolerance < 0.5");
  keys.max = section.getInt("harmonics_max", defaultMax);
  if (keys.max < 3 || keys.max > 64)
    throw InputError(section.where("harmonics_max"),
                     "the highest harmonic tried must lie in 3..64 (two raises from H = 1 meet the tolerance at "
                     "H = 3 at the earliest; beyond 64 a shroud's contact law is resolved by its samples, not by "
                     "more harmonics)");
  return keys;
}

int readHarmonicsCheckTo(SceneSection& section, int maxHarmonic, const HarmonicsTargetKeys& target) {
  if (target.tolerance > 0) {
    if (section.has("harmonics_check_to"))
      throw InputError(section.where("harmonics_check_to"), "with harmonics: auto the check runs to harmonics_max");
    return target.max;
  }
  const int upTo = section.getInt("harmonics_check_to", 0);
  if (section.has("harmonics_check_to") && upTo <= maxHarmonic)
    throw InputError(section.where("harmonics_check_to"),
                     "must exceed the curve's highest harmonic " + std::to_string(maxHarmonic) + ", got " +
                         std::to_string(upTo) + " (the check raises H from there)");
  return upTo;
}

std::vector<std::string> CyclicFaces::left() const {
  auto faces = discLeft;
  if (shroudCyclic) faces.insert(faces.end(), shroudLeft.begin(), shroudLeft.end());
  return faces;
}

std::vector<std::string> CyclicFaces::right() const {
  auto faces = discRight;
  if (shroudCyclic) faces.insert(faces.end(), shroudRight.begin(), shroudRight.end());
  return faces;
}

CyclicFaces readCyclicFaces(SceneSection& cy) {
  CyclicFaces f;
  f.shroudCyclic = cy.getChoice<bool>(
      "configuration", "fixed_shroud", {{"fixed_shroud", true}, {"cantilever", false}}, [](const std::string& word) {
        return "unknown configuration '" + word + "' (fixed_shroud: disc and shroud faces cyclic; cantilever: disc "
                                                  "faces only)";
      });
  f.discLeft = cy.getStringList("disc_left_node_sets", f.discLeft);
  f.discRight = cy.getStringList("disc_right_node_sets", f.discRight);
  f.shroudLeft = cy.getStringList("shroud_left_node_sets", f.shroudLeft);
  f.shroudRight = cy.getStringList("shroud_right_node_sets", f.shroudRight);
  if (f.discLeft.empty() || f.discLeft.size() != f.discRight.size())
    throw InputError(cy.where("disc_right_node_sets"), "the disc's left and right side faces need as many sets each "
                                                       "(at least one): right = left rotated by +360/N degrees");
  if (f.shroudLeft.size() != f.shroudRight.size())
    throw InputError(cy.where("shroud_right_node_sets"), "the shroud's left and right side faces need as many sets each");
  return f;
}

void checkCentrifugalStrain(const fe::IsotropicElastic& material, double rpm, const mesh::Mesh& mesh,
                            const mesh::RotationAxis& axis, const std::string& speedKey, const std::string& meshKey) {
  const double radius = mesh::outermostRadius(mesh, axis);
  // A mesh in metres with the mm-N-s-t material (or in mm with SI) reached the prestress
  // and failed there as "10000 rpm cannot be reached" (issue 49 probe): a bladed disc's
  // outer radius lies between 1 mm and 20 m in any unit set (other: a unit not known).
  const double metres = radius * fe::lengthUnitInMetres(material.units);
  if (radius > 0 && material.units != fe::UnitSystem::Other && !(metres >= 1e-3 && metres <= 20)) {
    std::ostringstream why;
    why << "its outermost radius about the axis is " << radius << " in the material's units ("
        << fe::unitSystemName(material.units) << "): " << metres
        << " m, no bladed disc's; a mesh in other length units than the material's? (material/units: mm-N-s-t takes "
           "millimetres, SI metres)";
    throw InputError(meshKey, why.str());
  }
  const double strain = fe::centrifugalStrainScale(material, rpm, radius);
  if (!(strain <= 0.05)) {
    std::ostringstream why;
    why << rpm << " rpm: rho (Omega r)^2 at the outermost radius " << radius << " is " << strain
        << " times E (rho " << material.rho << ", E " << material.E
        << "): the disc would be torn apart long before (a strain of 5 % is the limit; titanium bursts near 1 %). "
           "Check the speed and the material's units (mm-N-s-t: rho in t/mm^3, E in MPa)";
    throw InputError(speedKey, why.str());
  }
}

fe::IsotropicElastic readMaterial(SceneSection m) {
  fe::IsotropicElastic material;
  material.name = m.getString("name", material.name);
  material.E = m.getDouble("E", material.E);
  material.nu = m.getDouble("nu", material.nu);
  material.rho = m.getDouble("rho", material.rho);
  using Quadrature = fe::MassQuadrature;
  material.massQuadrature = m.getChoice<Quadrature>(
      "mass_quadrature", "exact", {{"exact", Quadrature::Exact}, {"stiffness_rule", Quadrature::StiffnessRule}},
      [](const std::string& word) {
        return "'" + word + "': exact (the default) or stiffness_rule (CalculiX's C3D10 mass and centrifugal load, "
                            "for comparing with it)";
      });
  // The unit set, said rather than guessed from E (a stress unit, fatigue data by name).
  using Units = fe::UnitSystem;
  material.units = m.getChoice<Units>(
      "units", "mm-N-s-t",
      {{"mm-N-s-t", Units::MillimetreNewtonSecondTonne}, {"SI", Units::SI}, {"other", Units::Other}},
      [](const std::string& word) {
        return "'" + word + "': mm-N-s-t (the default: mm, N, s, t; stresses in MPa), SI (m, N, s, kg; Pa) or "
                            "other (a consistent set the code cannot name)";
      });
  if (m.has("fatigue")) m.section("fatigue");  // read where a margin is asked for (readPeakStressSpec)
  m.rejectUnknownKeys();
  material.validate(m.location());
  material.checkPlausible(m.location());
  return material;
}

}  // namespace cyclone::scenes
