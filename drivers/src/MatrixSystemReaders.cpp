// A matrix scene's system and its nonlinear elements, read and checked (the matrices'
// sizes and physics, each element's law under its own key, where it acts).
#include "MatrixSystemReaders.hpp"

#include <cmath>
#include <sstream>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/NumberText.hpp"
#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/JenkinsElement.hpp"
#include "cyclone/hbm/ModalDamping.hpp"
#include "cyclone/hbm/QuadraticDamper.hpp"
#include "cyclone/hbm/ScalarElementAdapter.hpp"
#include "cyclone/hbm/UnilateralSpring.hpp"

namespace cyclone::scenes {

namespace {

Eigen::MatrixXd squareMatrix(SceneSection& s, const std::string& key, int n, bool required) {
  if (!s.has(key)) {
    if (required) throw InputError(s.where(key), "is required (" + std::to_string(n * n) + " numbers, row by row)");
    return Eigen::MatrixXd::Zero(n, n);
  }
  if (s.isSection(key)) {  // sparse: {rows: [...], cols: [...], values: [...]}, 0-based, duplicates summed
    auto t = s.section(key);
    const auto r = t.getIntList("rows", {}), c = t.getIntList("cols", {});
    const auto v = t.getDoubleList("values", {});
    t.rejectUnknownKeys();
    if (r.size() != v.size() || c.size() != v.size())
      throw InputError(t.location(), "rows, cols and values must have the same length");
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
    for (std::size_t k = 0; k < v.size(); ++k) {
      if (r[k] < 0 || r[k] >= n || c[k] < 0 || c[k] >= n)
        throw InputError(t.location(), "entry " + std::to_string(k) + " (" + std::to_string(r[k]) + ", " +
                                           std::to_string(c[k]) + ") is outside " + std::to_string(n) + " x " +
                                           std::to_string(n));
      A(r[k], c[k]) += v[k];
    }
    return A;
  }
  const auto v = s.getDoubleList(key, {});
  if ((long long)v.size() != (long long)n * n)  // 1e5 DOFs: n * n overflowed an int in the message
    throw InputError(s.where(key), "needs " + std::to_string((long long)n * n) + " numbers (row by row for " +
                                       std::to_string(n) + " DOFs), got " + std::to_string(v.size()));
  Eigen::MatrixXd A(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) A(i, j) = v[i * n + j];
  return A;
}


// Forced response of a matrix-defined system with nonlinear elements: harmonic
// balance (AFT) traced by arclength continuation in the excitation frequency.

std::shared_ptr<const hbm::NonlinearElement> elementLaw(SceneSection& e) {
  const std::string type = e.getString("type", "");
  auto scalar = [](std::shared_ptr<const hbm::ScalarElement> s) {
    return std::make_shared<hbm::ScalarElementAdapter>(std::move(s));
  };
  if (type == "cubic") return scalar(std::make_shared<hbm::CubicSpring>(e.requireDouble("k3")));
  if (type == "unilateral")
    return scalar(std::make_shared<hbm::UnilateralSpring>(e.requireDouble("k"), e.getDouble("gap", 0.0)));
  if (type == "quadratic_damper") return scalar(std::make_shared<hbm::QuadraticDamper>(e.requireDouble("c2")));
  if (type == "jenkins")
    return scalar(std::make_shared<hbm::JenkinsElement>(e.requireDouble("kt"), e.requireDouble("slip_force")));
  if (type == "friction2d" || type == "friction3d") {
    hbm::FrictionContactParameters p;
    p.tangentialDirections = type == "friction2d" ? 1 : 2;
    p.kt = e.requireDouble("kt");
    p.kn = e.getDouble("kn", 0.0);
    p.mu = e.requireDouble("mu");
    p.preload = e.getDouble("preload", 0.0);
    return std::make_shared<hbm::FrictionContact>(p);
  }
  throw InputError(e.where("type"), "unknown element type '" + type +
                                        "' (cubic, unilateral, quadratic_damper, jenkins, friction2d, friction3d)");
}

// The element's law, a law's own refusal ("UnilateralSpring: stiffness must be ...") put
// under the element's key in the scene (it named neither; issue 49 probe).
std::shared_ptr<const hbm::NonlinearElement> readElementLaw(SceneSection& e) {
  try {
    return elementLaw(e);
  } catch (const InputError& err) {
    if (err.where().rfind(e.location(), 0) == 0) throw;  // a key of the element, named already
    throw InputError(e.location(), err.what());
  }
}

}  // namespace

MatrixSystemInput readMatrixSystem(SceneSection& scene) {
  MatrixSystemInput in;
  auto sys = scene.section("system");
  const int n = in.n = sys.getInt("dofs", 0);
  if (n < 1) throw InputError(sys.where("dofs"), "is required: the number of DOFs (>= 1)");
  in.M = squareMatrix(sys, "M", n, true), in.K = squareMatrix(sys, "K", n, true);
  in.C = squareMatrix(sys, "C", n, false);
  const auto &M = in.M, &K = in.K;
  auto& C = in.C;
  if ((M - M.transpose()).norm() > 1e-12 * M.norm() || (K - K.transpose()).norm() > 1e-12 * K.norm())
    throw InputError(sys.location(), "M and K must be symmetric");
  // Damping on top of C: Rayleigh a M + b K, or a modal damping ratio for every
  // mode of (K, M) (C = M Phi diag(2 zeta w_j) Phi^T M with M-normalised Phi).
  if (sys.has("rayleigh")) {
    const auto ab = sys.getDoubleList("rayleigh", {});
    if (ab.size() != 2) throw InputError(sys.where("rayleigh"), "needs two numbers [a, b]: C += a M + b K");
    C += ab[0] * M + ab[1] * K;
  }
  if (sys.has("modal_damping_ratio")) {
    const double ratio = sys.getDouble("modal_damping_ratio", 0.0);
    C += sys.underKey("modal_damping_ratio", [&] { return hbm::modalDamping(M, K, ratio); });
  }
  in.dofNames = sys.getStringList("dof_names", {});
  if (!in.dofNames.empty() && int(in.dofNames.size()) != n)
    throw InputError(sys.where("dof_names"), "needs one name per DOF (" + std::to_string(n) + ")");
  auto& coupling = in.coupling;
  coupling.sectors = sys.getInt("sectors", 1);
  if (coupling.sectors < 1) throw InputError(sys.where("sectors"), "must be >= 1 (1: not cyclic)");
  const bool cyclic = coupling.sectors > 1;
  for (const char* key : {"K_next", "C_next", "M_next"})
    if (sys.has(key) && !cyclic)
      throw InputError(sys.where(key), "couples a sector to the next one: set sectors >= 2 for a cyclic system");
  coupling.Knext = squareMatrix(sys, "K_next", n, false);
  coupling.Cnext = squareMatrix(sys, "C_next", n, false);
  coupling.Mnext = squareMatrix(sys, "M_next", n, false);
  sys.rejectUnknownKeys();
  // No physical system has a mass matrix that is not positive definite, or damping
  // whose symmetric part (the part that dissipates) has a negative eigenvalue: such
  // input was accepted and traced (issue 20). A cyclic sector's own matrices are
  // checked only without next-sector coupling of the same kind (the ring's matrices
  // per nodal diameter are what must be definite then).
  if (coupling.Mnext.isZero(0) && Eigen::LLT<Eigen::MatrixXd>(M).info() != Eigen::Success)
    throw InputError(sys.where("M"), "must be positive definite (a mass matrix: every DOF carries mass)");
  if (coupling.Cnext.isZero(0) && C.size() > 0) {
    const Eigen::MatrixXd dissipative = 0.5 * (C + C.transpose());
    const double lowest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dissipative, Eigen::EigenvaluesOnly).eigenvalues().minCoeff();
    if (lowest < -1e-12 * dissipative.norm())
      throw InputError(sys.location(), "the damping (C with rayleigh and modal_damping_ratio) generates energy: its "
                                       "symmetric part has the eigenvalue " + std::to_string(lowest) + " < 0");
  }

  return in;
}

std::vector<PlacedElement> readNonlinearElements(SceneSection& scene, const MatrixSystemInput& in,
                                                 std::vector<std::string>& names) {
  const int n = in.n;
  auto matrixOf = [&](SceneSection& e, const std::string& key, int d) {
    const auto v = e.getDoubleList(key, {});
    if (int(v.size()) != n * d)
      throw InputError(e.where(key), "needs " + std::to_string(n * d) + " numbers: " + std::to_string(d) +
                                         " direction vector(s) of " + std::to_string(n) +
                                         " DOFs one after another (element coordinates in order)");
    return Eigen::Map<const Eigen::MatrixXd>(v.data(), n, d).eval();
  };
  std::vector<PlacedElement> placed;
  auto elements = scene.section("nonlinear_elements");
  for (const auto& name : elements.sectionNames()) {
    auto e = elements.section(name);
    const std::string type = e.getString("type", "");
    PlacedElement pl{readElementLaw(e), {}, {}};
    const int d = pl.element->dimension();
    if (e.has("direction") && e.has("W"))
      throw InputError(e.location(), "give either direction (one coordinate) or W, not both");
    if (e.has("direction")) {
      if (d != 1) throw InputError(e.where("direction"), "is for one-coordinate elements; use W for " + type);
      pl.W = matrixOf(e, "direction", 1);
    } else if (e.has("W")) {
      pl.W = matrixOf(e, "W", d);
    } else {
      throw InputError(e.location(), "needs direction (n numbers) or W (" + std::to_string(d) + " x " +
                                         std::to_string(n) + " numbers): w = W^T x");
    }
    if (e.has("W_next")) {
      if (!in.cyclic()) throw InputError(e.where("W_next"), "joins a sector to the next one: the system must be cyclic");
      pl.Wnext = matrixOf(e, "W_next", d);
    }
    // Each element coordinate must see some motion (issue 49: direction [0] made an element
    // that never acts, and the curve was the linear one, exit 0). A coordinate across the
    // sector boundary may be W_next's alone.
    const char* key = e.has("direction") ? "direction" : "W";
    for (int j = 0; j < d; ++j)
      if (pl.W.col(j).norm() == 0 && (pl.Wnext.size() == 0 || pl.Wnext.col(j).norm() == 0))
        throw InputError(e.where(key), "coordinate " + std::to_string(j) + " of the element is zero on every DOF: "
                                       "the element would never act (give the DOFs it acts on)");
    e.rejectUnknownKeys();
    placed.push_back(std::move(pl));
    names.push_back(name);
  }
  elements.rejectUnknownKeys();
  return placed;
}

}  // namespace cyclone::scenes
