#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/mesh/GmshIO.hpp"
#include "cyclone/mesh/MeshGeometryCheck.hpp"
#include "cyclone/mesh/RotatedNodePairing.hpp"

namespace cyclone::mesh {

namespace {
constexpr double kMaxSectorUnknowns = 2e7;    // about 20 GB for a tet10 stiffness matrix alone
constexpr double kLargeSectorUnknowns = 5e5;  // where a direct factorization nears 10 GB
}  // namespace

void ShroudedSectorParameters::validate(const std::string& where) const {
  auto need = [&](bool ok, const std::string& param, const std::string& why) {
    if (!ok) throw InputError(where, "parameter '" + param + "' " + why);
  };
  need(sectors >= 3, "sectors", "must be at least 3");
  need(boreRadius > 0, "bore_radius", "must be positive");
  need(rimRadius > boreRadius, "rim_radius", "must exceed bore_radius");
  need(discThickness > 0, "disc_thickness", "must be positive");
  need(bladeHeight > 0, "blade_height", "must be positive");
  need(bladeChord > 0, "blade_chord", "must be positive");
  need(bladeThickness > 0, "blade_thickness", "must be positive");
  need(shroudThickness > 0, "shroud_thickness", "must be positive");
  need(shroudWidth > 0, "shroud_width", "must be positive");
  need(meshSize > 0, "mesh_size", "must be positive");
  // Larger than the disc's radial depth it no longer sets the elements (the geometry's own
  // coarsest mesh came out of 1e300, exit 0; issue 49).
  need(!(meshSize > rimRadius - boreRadius), "mesh_size",
       "must be at most the disc's radial depth rim_radius - bore_radius = " + std::to_string(rimRadius - boreRadius) +
           " (the demo's is 6)");
  need(elementOrder == 1 || elementOrder == 2, "element_order", "must be 1 (tet4) or 2 (tet10)");
  need(std::abs(bladeStaggerDeg) < 80, "blade_stagger_deg", "must lie in (-80, 80) degrees");
  const double stagger = bladeStaggerDeg * M_PI / 180;
  const double tangential = bladeChord * std::abs(std::sin(stagger)) + bladeThickness * std::cos(stagger);
  const double arcAtRim = 2 * rimRadius * std::sin(M_PI / sectors);
  std::ostringstream why;
  why << "makes the blade " << tangential << " wide tangentially, more than the sector's " << arcAtRim
      << " at the rim: reduce chord or stagger, or the number of sectors";
  need(tangential < 0.8 * arcAtRim, "blade_chord", why.str());
  const double axial = bladeChord * std::cos(stagger) + bladeThickness * std::abs(std::sin(stagger));
  need(axial <= discThickness, "blade_chord",
       "makes the blade longer axially than the disc is thick (" + std::to_string(axial) + " > " +
           std::to_string(discThickness) + ")");
}

namespace {

// gmsh 4.8 throws std::string (or std::exception) from its API.
template <class F>
void gmshCall(const std::string& what, F&& f) {
  try {
    f();
  } catch (const std::string& e) {
    throw Error("gmsh failed while " + what + ": " + e);
  } catch (const cyclone::Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error("gmsh failed while " + what + ": " + e.what());
  }
}

struct GmshSession {
  GmshSession() {
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
  }
  ~GmshSession() { gmsh::finalize(); }
};

double angleOf(double x, double y) { return std::atan2(y, x); }

}  // namespace

namespace {

// Disc and shroud (differences of cylinder sectors spanning [0, alpha], turned to
// [-alpha/2, alpha/2]) fused with the staggered blade plate; returns the volume's tag.
int buildSectorGeometry(const ShroudedSectorParameters& p) {
  const double alpha = 2 * M_PI / p.sectors, rTip = p.tipRadius();
  namespace occ = gmsh::model::occ;
  gmsh::model::add("shrouded_sector");
  const int discOuter = occ::addCylinder(0, 0, -p.discThickness / 2, 0, 0, p.discThickness, p.rimRadius, -1, alpha);
  const int discInner = occ::addCylinder(0, 0, -p.discThickness / 2, 0, 0, p.discThickness, p.boreRadius, -1, alpha);
  gmsh::vectorpair disc;
  std::vector<gmsh::vectorpair> map;
  occ::cut({{3, discOuter}}, {{3, discInner}}, disc, map);
  const double rOut = rTip + p.shroudThickness;
  const int shroudOuter = occ::addCylinder(0, 0, -p.shroudWidth / 2, 0, 0, p.shroudWidth, rOut, -1, alpha);
  const int shroudInner = occ::addCylinder(0, 0, -p.shroudWidth / 2, 0, 0, p.shroudWidth, rTip, -1, alpha);
  gmsh::vectorpair shroud;
  occ::cut({{3, shroudOuter}}, {{3, shroudInner}}, shroud, map);
  gmsh::vectorpair rings = disc;
  rings.insert(rings.end(), shroud.begin(), shroud.end());
  occ::rotate(rings, 0, 0, 0, 0, 0, 1, -alpha / 2);
  // Blade: a plate along +x reaching into disc and shroud so the fuse bonds them, staggered about x.
  const double overlapIn = std::min(2.0 * p.bladeThickness, 0.25 * (p.rimRadius - p.boreRadius));
  const double overlapOut = 0.5 * p.shroudThickness;
  const int blade = occ::addBox(p.rimRadius - overlapIn, -p.bladeThickness / 2, -p.bladeChord / 2,
                                p.bladeHeight + overlapIn + overlapOut, p.bladeThickness, p.bladeChord);
  occ::rotate({{3, blade}}, 0, 0, 0, 1, 0, 0, p.bladeStaggerDeg * M_PI / 180);
  gmsh::vectorpair fused;
  std::vector<gmsh::vectorpair> fusedMap;
  occ::fuse(disc, {{3, blade}, shroud[0]}, fused, fusedMap);
  occ::synchronize();
  if (fused.size() != 1)
    throw Error("shrouded sector: disc, blade and shroud did not fuse into one volume (" +
                std::to_string(fused.size()) + " volumes)");
  // A mesh node at the blade's mid-height centre (on the stacking line, inside the plate):
  // the response and excitation point named mid_blade stays the same material point at
  // every mesh size, so a response there converges with the mesh.
  const int midBlade = occ::addPoint(p.rimRadius + 0.5 * p.bladeHeight, 0, 0);
  occ::synchronize();
  gmsh::model::mesh::embed(0, {midBlade}, 3, fused[0].second);
  gmsh::model::addPhysicalGroup(3, {fused[0].second}, 1);
  gmsh::model::setPhysicalName(3, 1, "sector");

  return fused[0].second;
}

// The side faces at -alpha/2 (left) and +alpha/2 (right), disc and shroud, meshed
// periodically: right = R(alpha) left.
void makeSideFacesPeriodic(double alpha) {
  namespace occ = gmsh::model::occ;
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  struct Face { int tag; double r, z; };
  std::vector<Face> left, right;
  for (const auto& [dim, tag] : surfaces) {
    double x, y, z;
    occ::getCenterOfMass(dim, tag, x, y, z);
    const double a = angleOf(x, y), r = std::hypot(x, y);
    if (std::abs(a + alpha / 2) < 1e-9) left.push_back({tag, r, z});
    if (std::abs(a - alpha / 2) < 1e-9) right.push_back({tag, r, z});
  }
  if (left.size() != 2 || right.size() != 2)
    throw Error("shrouded sector: expected 2 side faces per side (disc, shroud), found " +
                std::to_string(left.size()) + " left and " + std::to_string(right.size()) + " right");
  auto byRadius = [](const Face& a, const Face& b) { return a.r < b.r; };
  std::sort(left.begin(), left.end(), byRadius);
  std::sort(right.begin(), right.end(), byRadius);
  // Right = R(alpha) left: gmsh's affine transform maps the master (left) onto the slave (right).
  const double c = std::cos(alpha), s = std::sin(alpha);
  const std::vector<double> T = {c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  gmsh::model::mesh::setPeriodic(2, {right[0].tag, right[1].tag}, {left[0].tag, left[1].tag}, T);
}

// The mesh size refused (InputError) where a lower bound on the sector's unknowns would
// not fit in memory, warned about where the direct solvers' factors grow large.
void checkMeshSize(const ShroudedSectorParameters& p, int volumeTag) {
  // The sector needs at least V / (h^3 / (6 sqrt 2)) tetrahedra at size h (regular ones
  // fill it), each tet10 bringing at least 1.35 nodes (1.68 measured at h = 2), a tet4
  // 0.16: a lower bound on the unknowns, so nothing that would fit is refused. Above
  // it gmsh would spend minutes and gigabytes before the solver ran out of memory.
  double volume = 0;
  gmsh::model::occ::getMass(3, volumeTag, volume);
  const double tets = volume / (std::pow(p.meshSize, 3) / (6 * std::sqrt(2.0)));
  const double unknowns = 3 * tets * (p.elementOrder == 2 ? 1.35 : 0.16);
  if (unknowns > kMaxSectorUnknowns) {
    std::ostringstream why;
    why << "parameter 'mesh_size' " << p.meshSize << " would make at least " << tets << " elements and "
        << unknowns << " unknowns in the sector (volume " << volume << "): more than " << kMaxSectorUnknowns
        << ", whose stiffness matrix alone would fill this machine's memory; use a larger mesh_size";
    throw InputError("shrouded_sector/mesh_size", why.str());
  }
  if (unknowns > kLargeSectorUnknowns) {
    std::ostringstream cost;
    cost << "mesh_size " << p.meshSize << ": at least " << unknowns << " unknowns in the sector; the direct "
         << "solvers' factors grow faster than the model (CHOLMOD took 10 GB at 5e5, docs/solvers.md): "
         << "check the peak memory lines, or use modal: eigen_solver: lobpcg";
    log::warn(cost.str());
  }
}

void setMeshOptions(const ShroudedSectorParameters& p) {
  const double rTip = p.tipRadius();
  gmsh::option::setNumber("Mesh.CharacteristicLengthMax", p.meshSize);
  gmsh::option::setNumber("Mesh.CharacteristicLengthMin", 0.0);
  // A thin blade needs elements no thicker than itself to bend right.
  gmsh::vectorpair bladePoints;
  gmsh::model::getEntitiesInBoundingBox(p.rimRadius - 1e-6, -rTip, -p.discThickness, rTip + 1e-6, rTip,
                                        p.discThickness, bladePoints, 0);
  gmsh::model::mesh::setSize(bladePoints, std::min(p.meshSize, 2.0 * p.bladeThickness));
  gmsh::option::setNumber("Mesh.ElementOrder", p.elementOrder);
  gmsh::option::setNumber("Mesh.Algorithm3D", 1);  // Delaunay
}

// Named node sets from the geometry (tolerance relative to the model size): bore, side
// faces of disc and shroud, the mid-blade node, the shroud's contact pairs.
void addNodeSets(Mesh& mesh, const ShroudedSectorParameters& p) {
  const double alpha = 2 * M_PI / p.sectors, rTip = p.tipRadius();
  const double tol = 1e-7 * rTip;
  std::vector<Index> bore, discL, discR, shroudL, shroudR;
  const double cl = std::cos(-alpha / 2), sl = std::sin(-alpha / 2), cr = std::cos(alpha / 2), sr = std::sin(alpha / 2);
  Index midBlade = -1;
  double best = 1e300;
  const double rMid = p.rimRadius + 0.5 * p.bladeHeight;
  for (Index n = 0; n < mesh.numNodes(); ++n) {
    const auto& x = mesh.coords[n];
    const double r = std::hypot(x[0], x[1]);
    if (std::abs(r - p.boreRadius) < tol) bore.push_back(n);
    // Distance to the cyclic planes through the axis at -alpha/2 and +alpha/2 (normals in the xy-plane).
    const double dLeft = std::abs(-sl * x[0] + cl * x[1]), dRight = std::abs(-sr * x[0] + cr * x[1]);
    const bool onLeft = dLeft < tol && (cl * x[0] + sl * x[1]) > 0;
    const bool onRight = dRight < tol && (cr * x[0] + sr * x[1]) > 0;
    if (onLeft) (r < p.rimRadius + tol ? discL : shroudL).push_back(n);
    if (onRight) (r < p.rimRadius + tol ? discR : shroudR).push_back(n);
    const double d = std::hypot(x[0] - rMid, x[1], x[2]);
    if (d < best) best = d, midBlade = n;
  }
  mesh.nodeSets["bore"] = bore;
  mesh.nodeSets["disc_left"] = discL;
  mesh.nodeSets["disc_right"] = discR;
  mesh.nodeSets["shroud_left"] = shroudL;
  mesh.nodeSets["shroud_right"] = shroudR;
  if (best > tol)
    throw Error("shrouded sector: no mesh node at the embedded mid-blade point (nearest " + std::to_string(best) +
                " away)");
  mesh.nodeSets["mid_blade"] = {midBlade};
  const RotationAxis axis;
  pairRotatedNodes(mesh, discL, discR, alpha, axis, 1e-6 * rTip, "disc side faces");
  const auto contact = pairRotatedNodes(mesh, shroudL, shroudR, alpha, axis, 1e-6 * rTip, "shroud side faces");
  mesh.nodeSets["shroud_contact_left"] = contact.left;
  mesh.nodeSets["shroud_contact_right"] = contact.right;
}

}  // namespace

Mesh generateShroudedSector(const ShroudedSectorParameters& p) {
  p.validate("shrouded sector");
  Timer timer;
  GmshSession session;
  Mesh mesh;
  gmshCall("building the sector geometry", [&] {
    const int volume = buildSectorGeometry(p);
    makeSideFacesPeriodic(2 * M_PI / p.sectors);
    checkMeshSize(p, volume);
    setMeshOptions(p);
    std::ostringstream msg;
    msg << "meshing the shrouded sector (" << p.sectors << " sectors, mesh size " << p.meshSize << ")";
    log::info(msg.str());
    gmsh::model::mesh::generate(3);
    mesh = meshFromGmshModel("built-in shrouded sector");
  });
  addNodeSets(mesh, p);
  checkConsistency(mesh);
  checkElementGeometry(mesh);
  std::ostringstream msg;
  msg << "shrouded sector: " << mesh.numNodes() << " nodes, " << mesh.numElements() << " "
      << exodusName(mesh.blocks[0].type) << " elements, " << mesh.nodeSets.at("disc_left").size() << "+"
      << mesh.nodeSets.at("shroud_left").size() << " nodes per side face, " << timer.seconds() << " s";
  log::info(msg.str());
  return mesh;
}

}  // namespace cyclone::mesh
