// Cyclone's continuation engine (ContinuationOptions::Engine::PredictorCorrector).
//
// Where the steps are measured: x over the current solution's norm and p over the
// range, so a step is a relative change of the response or a fraction of the range
// (NLvib's dynamic scaling, tmdsimpy's DynamicCtoP; docs/architecture.md says why
// this is not LOCA's stepper). Each step: a tangent predictor; Newton on F = 0 with
// the pseudo-arclength hyperplane through the predictor; where that fails or lands
// far away, on the sphere of the step's radius around the last point, which meets a
// path that turns by more than 90 degrees (a stick-slip corner) where no hyperplane
// does. The next step grows or shrinks with Newton's iteration count and the
// tangent's turn. A step that goes back onto the path already traced is refused.
#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <map>
#include <sstream>
#include <vector>

#include "ContinuationEngines.hpp"
#include "cyclone/continuation/DenseLu.hpp"
#include "cyclone/continuation/KrylovSolve.hpp"
#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/continuation/TraceCheckpoint.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"

namespace cyclone::continuation {

namespace {

struct Point {
  Eigen::VectorXd x;
  double p = 0;
};

// Distances in the scaled space: ||dx||^2 / sx^2 + dp^2 / sp^2.
// The arclength's inner product: each unknown divided by its group's scale, the
// parameter by the range. w holds 1 / scale^2 per unknown.
struct Metric {
  Eigen::VectorXd w;
  double sp = 1;
  double dot(const Point& a, const Point& b) const {
    return (a.x.array() * b.x.array() * w.array()).sum() + a.p * b.p / (sp * sp);
  }
  double norm(const Point& a) const { return std::sqrt(dot(a, a)); }
  Point difference(const Point& a, const Point& b) const { return {a.x - b.x, a.p - b.p}; }
};

enum class Constraint { Plane, Sphere };

// The corrector's bordered Jacobian [J, dF/dp; c^T, d]: formed (dense), or, for a
// problem solved by Krylov (ContinuationOptions::linearSolver), J as the problem's
// operator with dF/dp and the border beside it.
struct Bordered {
  Eigen::MatrixXd dense;
  std::shared_ptr<JacobianOperator> op;
  Eigen::VectorXd column, row;
  double corner = 0;
  void setBottom(const Eigen::VectorXd& c, double d) {
    if (op) {
      row = c, corner = d;
      return;
    }
    const Eigen::Index n = dense.rows() - 1;
    dense.bottomLeftCorner(1, n) = c.transpose();
    dense(n, n) = d;
  }
};

// What a bordered system is solved with: a dense LU (DenseLu) or GMRES preconditioned
// by the operator's preconditioner (BorderedKrylovSolve).
struct BorderedFactors {
  DenseLu lu;
  BorderedKrylovSolve krylov;
  bool isKrylov() const { return !krylov.empty(); }
};

struct Correction {
  bool converged = false;
  int iterations = 0;
  Point z;
  BorderedFactors lu;     // of the last bordered Jacobian
  bool factored = false;  // lu holds one (no iteration: the predictor solved it)
};

class Tracer {
public:
  Tracer(const ContinuationProblem& problem, const ContinuationOptions& o, Branch& branch,
         const TraceCheckpointing* checkpointing)
      : problem_(problem), o_(o), branch_(branch), n_(problem.size), checkpointing_(checkpointing) {
    cornerStep_ = std::max(16 * o.minStep, 1e-3);
    krylov_ = useKrylov(problem, o);
    makeGroups();
  }

  void run(const Eigen::VectorXd& guess);

private:
  // A problem's evaluation, timed into `seconds`: false where it throws or is not finite
  // (the step is then cut, as for a failed corrector).
  template <class Evaluate>
  static bool guarded(double& seconds, Evaluate&& evaluate) {
    Timer t;
    bool ok = false;
    try {
      ok = evaluate();
    } catch (...) {
      ok = false;
    }
    seconds += t.seconds();
    return ok;
  }
  bool residual(const Point& z, Eigen::VectorXd& F) {
    ++stats().residuals;
    return guarded(stats().residualSeconds, [&] {
      problem_.residual(z.x, z.p, F);
      return F.allFinite();
    });
  }
  // [J, dF/dp] at z (dF/dp by a forward difference from F = F(z)).
  bool jacobian(const Point& z, const Eigen::VectorXd& F, Bordered& A) {
    ++stats().jacobians;
    const double eps = 1.5e-8 * std::max(std::abs(z.p), metric_.sp);
    Eigen::VectorXd Fe;
    if (krylov_) {
      A.dense.resize(0, 0);
      A.op.reset();  // the last step's blocks freed before the next are made
      if (!guarded(stats().jacobianSeconds, [&] {
            A.op = problem_.jacobianOperator(z.x, z.p);
            return bool(A.op);
          }))
        return false;
      if (!guarded(stats().preconditionerSeconds, [&] {
            A.op->preparePreconditioner();
            return true;
          }))
        return false;
      if (!residual({z.x, z.p + eps}, Fe)) return false;
      A.column = (Fe - F) / eps;
      return true;
    }
    Eigen::MatrixXd& J = jacobianWork_;  // kept: a fresh n x n block per call is page faults
    if (!guarded(stats().jacobianSeconds, [&] {
          problem_.jacobian(z.x, z.p, J);
          return J.allFinite();
        }))
      return false;
    if (!residual({z.x, z.p + eps}, Fe)) return false;
    A.dense.resize(n_ + 1, n_ + 1);
    A.dense.topLeftCorner(n_, n_) = J;
    A.dense.topRightCorner(n_, 1) = (Fe - F) / eps;
    return true;
  }
  // Takes A's storage (A is refilled by jacobian() before its next use). For an
  // operator: the bordered preconditioner's set-up (one application of P).
  void factor(Bordered& A, BorderedFactors& lu) {
    Timer t;
    if (A.op) {
      lu.krylov = BorderedKrylovSolve(A.op, A.column, A.row, A.corner, o_.krylov);
      stats().preconditionerSeconds += t.seconds();
      return;
    }
    ++stats().factorizations;
    lu.krylov = BorderedKrylovSolve();
    lu.lu.computeTaking(A.dense, o_.mixedPrecisionLu ? DenseLu::Precision::Auto : DenseLu::Precision::Double);
    stats().factorSeconds += t.seconds();
  }
  // The Newton step's factors: the ones kept from the iteration or point before where
  // they still serve (DenseLu::reuseFactorsFor: the solves iterate with them), else A's.
  void factorOrReuse(Bordered& A, Correction& c) {
    if (reusingFactors()) {
      if (!c.factored) {
        c.lu = std::move(kept_);
        kept_ = BorderedFactors();
      }
      if (c.lu.lu.reuseFactorsFor(A.dense)) {
        ++stats().reusedFactorizations;
        return;
      }
    }
    factor(A, c.lu);
  }
  // Every kFreshFactorsEvery points the kept factors are dropped and the next step
  // factors its own: the trace's state there holds no factors, so a trace saved there
  // and continued is the same, to the bit, as one that ran through (the checkpoints
  // are saved only there).
  static constexpr std::size_t kFreshFactorsEvery = 8;
  bool reusingFactors() const { return !krylov_ && o_.reuseFactorizations && n_ + 1 >= DenseLu::reuseFrom; }
  bool atFreshFactors() const { return !reusingFactors() || branch_.points.size() % kFreshFactorsEvery == 0; }
  // The factors of a finished correction kept for the next one.
  void keepFactors(Correction& c) {
    if (!c.factored || !reusingFactors()) return;
    kept_ = std::move(c.lu);
    c.factored = false;
  }
  // lu's solve, timed; a solve that made the factorisation again (in double: DenseLu's
  // fallback from single precision; or of a matrix whose kept factors did not serve)
  // is counted with the factorisations.
  // `tolerance`: GMRES's relative residual for this solve (0: the options'); a direct
  // solve ignores it.
  Eigen::VectorXd solve(const BorderedFactors& factors, const Eigen::VectorXd& rhs, double tolerance = 0) {
    if (factors.isKrylov()) {
      const long before = factors.krylov.iterations();
      Timer t;
      Eigen::VectorXd x = factors.krylov.solve(rhs, tolerance);
      stats().solveSeconds += t.seconds();
      stats().krylovIterations += factors.krylov.iterations() - before;
      ++stats().krylovSolves;
      return x;
    }
    const DenseLu& lu = factors.lu;
    const int before = lu.doubleFallbacks(), refactoredBefore = lu.staleRefactorizations();
    const long krylovBefore = lu.krylovIterations();
    Timer t;
    Eigen::VectorXd x = lu.solve(rhs);
    const double seconds = t.seconds();
    stats().krylovIterations += lu.krylovIterations() - krylovBefore;
    if (lu.staleRefactorizations() > refactoredBefore) {
      ++stats().factorizations;
      stats().factorSeconds += seconds;
    } else if (lu.doubleFallbacks() > before) {
      ++stats().doubleFallbacks;
      stats().factorSeconds += seconds;
    } else {
      stats().solveSeconds += seconds;
    }
    return x;
  }
  ContinuationStatistics& stats() { return branch_.statistics; }
  // Inexact Newton (a Krylov solve; Eisenstat & Walker 1996): the Newton step's GMRES
  // stops at a relative residual eta that Newton's own progress asks for, not at the
  // options' 1e-8. eta is at least what the step needs to bring ||F|| to the tolerance
  // (0.5 tol / ||rhs||), at least Eisenstat-Walker's 0.9 (||F_k|| / ||F_k-1||)^2 where
  // Newton converges slowly, and at most kMaxForcing: a Newton iteration (a Jacobian, its
  // preconditioner, a residual) costs about as much as 30 GMRES iterations, so a looser
  // step that adds an iteration costs more than it saves (measured on the demo's H = 30
  // curve: eta up to 1e-2 took 148 points and 600 iterations where 1e-4 took 111 and 383).
  // Convergence is still judged on ||F|| itself.
  static constexpr double kMaxForcing = 1e-4;
  // The tangent sets only the predictor (a relative error of 1e-6 in it moves the
  // predictor far less than the corrector's tolerance); at 1e-4 the correctors took more
  // iterations. The polish after convergence takes the error down by 1e-4 more.
  static constexpr double kTangentTolerance = 1e-6, kPolishTolerance = 1e-4;
  double forcingTerm(double rhsNorm, const std::vector<double>& history) const {
    double eta = rhsNorm > 0 ? 0.5 * o_.tolerance / rhsNorm : 1.0;
    if (history.size() >= 2) eta = std::max(eta, 0.9 * std::pow(history.back() / history[history.size() - 2], 2));
    return std::clamp(eta, o_.krylov.tolerance, std::max(o_.krylov.tolerance, kMaxForcing));
  }

  // The unit tangent at z (metric_), oriented along `along` (a direction in (x, p)).
  bool tangentFrom(const BorderedFactors& lu, const Point& along, Point& t) {
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n_ + 1);
    rhs(n_) = 1;
    const Eigen::VectorXd v = solve(lu, rhs, std::max(o_.krylov.tolerance, kTangentTolerance));
    if (!v.allFinite()) return false;
    t = {v.head(n_), v(n_)};
    const double norm = metric_.norm(t);
    if (!(norm > 0)) return false;
    const double s = metric_.dot(t, along) < 0 ? -1.0 : 1.0;
    t.x *= s / norm, t.p *= s / norm;
    return true;
  }
  // The bordering row is `along` made unit: a chord of a step near the smallest (1e-9 in
  // the metric, where kinks hold the steps down) as the row made the bordered matrix
  // singular to its rounding, and every step there failed for want of a tangent (the
  // hammering disc's walls at H >= 6, docs/solvers.md).
  bool freshTangent(const Point& z, const Point& along, Point& t) {
    Eigen::VectorXd F;
    Bordered A;
    const double length = metric_.norm(along);
    if (!(length > 0) || !residual(z, F) || !jacobian(z, F, A)) return false;
    A.setBottom(along.x.cwiseProduct(metric_.w) / length, along.p / (metric_.sp * metric_.sp * length));
    BorderedFactors lu;
    factor(A, lu);
    return tangentFrom(lu, along, t);
  }

  Correction correct(Constraint kind, const Point& z0, const Point& t0, double ds);
  void append(const Point& z, const Point& tangent = {}) {
    branch_.points.push_back({z.p, z.x});
    tangents_.push_back(tangent);
    measures_.push_back(problem_.measure ? problem_.measure(z.x) : 0.0);
  }
  void dropLast() {
    branch_.points.pop_back();
    measures_.pop_back();
    tangents_.pop_back();
  }
  double lastSegmentLength() const {
    const auto& pts = branch_.points;
    if (pts.size() < 2) return 0;
    return metric_.norm(
        metric_.difference(Point{pts.back().x, pts.back().parameter}, Point{pts[pts.size() - 2].x, pts[pts.size() - 2].parameter}));
  }
  void refinePeak(const Point& t0);
  bool onTracedPath(const Point& z, double ds) const;
  bool fixedParameterStep(const Point& z0, const Point& t0, Point& z1);
  bool passCreep(Point& z, Point& t, double dir);
  void rescale(const Point& z);
  bool endAt(double p, const Point& inside, const Point& outside);
  void progress();
  bool start(const Eigen::VectorXd& guess, Point& z, Point& t);
  enum class StepOutcome { Taken, Retract, Cut, CutHard };
  StepOutcome correctStep(const Point& z, const Point& t, double ds, Correction& c, Point& t1, double& cosTurn);
  void retract(Point& z, Point& t, double& ds);
  bool passWall(Point& z, Point& t, double& ds);
  double nextStep(int iterations, double cosTurn, double ds) const;
  void switchPredictor(double tangentTurn, double next, double p);
  bool leftTheRange(const Point& previous, const Point& z, const Point& t);
  bool atTheEnd(const Point& z, const Point& t, double ds);
  double stepToMark(const Point& z, const Point& along, double ds) const;
  double markBefore(double from, double to) const;
  void logSummary() const;
  // The state between two steps (z is the last point): saved every intervalSeconds of
  // work, and restored to continue a saved trace exactly.
  void save(const Point& t, double ds);
  void restore(const TraceState& s, Point& z, Point& t, double& ds);

  const ContinuationProblem& problem_;
  const ContinuationOptions& o_;
  Eigen::MatrixXd jacobianWork_;
  BorderedFactors kept_;  // the last correction's factors (reuseFactorizations)
  bool krylov_ = false;   // Newton steps by GMRES on the problem's operator (useKrylov)
  Branch& branch_;
  const int n_;
  Metric metric_;
  // Per scale group (problem.scaleGroups): its unknowns, current scale, largest norm
  // seen and floor.
  std::vector<std::vector<int>> groups_;
  std::vector<double> groupScale_, largestNorm_, sxFloor_;
  void setWeights();
  void makeGroups() {
    const auto& g = problem_.scaleGroups;
    if (!g.empty() && int(g.size()) != n_)
      throw InputError("continuation", "scale groups: one per unknown expected, got " + std::to_string(g.size()));
    std::map<int, std::vector<int>> byId;
    for (int i = 0; i < n_; ++i) byId[g.empty() ? 0 : g[std::size_t(i)]].push_back(i);
    for (auto& [id, members] : byId) groups_.push_back(std::move(members));
    groupScale_.assign(groups_.size(), 1.0);
    largestNorm_.assign(groups_.size(), 0.0);
    sxFloor_.assign(groups_.size(), 0.0);
    setWeights();
  }
  std::vector<double> measures_;  // problem_.measure at each point
  static constexpr int kMaxRetractions = 200;  // a bound on retaken steps (each shortens the step)
  int retractions_ = 0;
  double cornerStep_ = 1e-3;  // a corner's step, max(16 minStep, 1e-3): where the turn stops cutting
  // Secant steps (see run() and switchPredictor): on where the tangent's turns do not
  // shrink with the step.
  bool secant_ = false;
  std::deque<bool> heldSteps_;  // the last steps' verdicts: held small by the tangent's turn
  int smoothRun_ = 0;           // secant steps in a row whose tangent turned less than the aim
  Point lastChord() const {
    const auto& pts = branch_.points;
    const Point c = metric_.difference(Point{pts.back().x, pts.back().parameter},
                                       Point{pts[pts.size() - 2].x, pts[pts.size() - 2].parameter});
    const double L = metric_.norm(c);
    return {c.x / L, c.p / L};
  }
  // The last point a retraction may not drop: one a fixed-parameter step reached (from
  // where the arclength steps had all failed, to which dropping it would return).
  std::size_t anchor_ = 0;
  std::size_t creepChecked_ = 0;  // passCreep looked back from this point and found no step
  std::vector<Point> tangents_;   // the tangent along the path at each point (empty where not known)
  Timer total_, sinceLog_, sinceSave_;
  const TraceCheckpointing* checkpointing_;
  double secondsBefore_ = 0;  // of the saved trace this one continues
};

// Newton on [F(z); g(z)] = 0 from the predictor z0 + ds t0 (ds < 0: behind z0, for
// the peak's refinement): g the hyperplane through
// the predictor normal to t0, or the sphere of radius ds around z0 (g scaled to
// unit gradient). Full Newton steps, backtracked while ||F|| grows; a run that moves
// 4 steps away from the predictor, or whose ||F|| grew three times, has failed.
Correction Tracer::correct(Constraint kind, const Point& z0, const Point& t0, double ds) {
  Correction c;
  const Point predictor{z0.x + ds * t0.x, z0.p + ds * t0.p};
  Point z = predictor;
  const double sp2 = metric_.sp * metric_.sp;
  auto constraint = [&](const Point& y) {
    if (kind == Constraint::Plane) return metric_.dot(t0, metric_.difference(y, predictor));
    const double r = metric_.norm(metric_.difference(y, z0));
    return (r * r - ds * ds) / (2 * ds);
  };
  Eigen::VectorXd F, Ft, rhs(n_ + 1);
  Bordered A;
  if (!residual(z, F)) return c;
  int growths = 0;
  std::vector<double> history;  // ||F|| at each iteration
  const int maxIterations = std::min(o_.maxNewtonIterations, 12);
  for (; c.iterations <= maxIterations; ++c.iterations) {
    const double g = constraint(z);
    if (F.norm() <= o_.tolerance && std::abs(g) <= 1e-6 * std::abs(ds)) {
      c.converged = c.iterations > 0 || kind == Constraint::Plane;
      // One more step with the last factorisation (a residual and a solve, no
      // Jacobian): Newton stops just under the tolerance, and near a resonance a
      // residual of 1e-10 is an error of 1e-7 in x.
      if (c.factored) {
        rhs << -F, -g;
        const Eigen::VectorXd d = solve(c.lu, rhs, std::max(o_.krylov.tolerance, kPolishTolerance));
        const Point polished{z.x + d.head(n_), z.p + d(n_)};
        if (d.allFinite() && residual(polished, Ft) && Ft.norm() < F.norm()) z = polished;
      }
      break;
    }
    if (c.iterations == maxIterations) break;
    // A run that has not halved ||F|| in three iterations has stalled: at a kink of the
    // nonsmooth residual Newton cycles between the pieces' linearisations, and the
    // remaining iterations (each a Jacobian) would be spent on the cycle; a shorter step
    // is cheaper.
    history.push_back(F.norm());
    if (history.size() >= 4 && history.back() > 0.5 * *std::min_element(history.begin(), history.end() - 3)) break;
    ++stats().newtonIterations;
    if (!jacobian(z, F, A)) return c;
    if (kind == Constraint::Plane) A.setBottom(t0.x.cwiseProduct(metric_.w), t0.p / sp2);
    else A.setBottom((z.x - z0.x).cwiseProduct(metric_.w) / ds, (z.p - z0.p) / (sp2 * ds));
    factorOrReuse(A, c);
    c.factored = true;
    rhs << -F, -g;
    const Eigen::VectorXd d = solve(c.lu, rhs, forcingTerm(rhs.norm(), history));
    if (!d.allFinite()) return c;
    Point next;
    bool decreased = false;
    for (double a = 1; a >= 0.125; a *= 0.5) {  // backtracking while ||F|| grows
      next = {z.x + a * d.head(n_), z.p + a * d(n_)};
      if (residual(next, Ft) && Ft.norm() < F.norm()) {
        decreased = true;
        break;
      }
    }
    if (!decreased) {  // a full step that grows ||F|| (a kink of the nonsmooth residual)
      next = {z.x + d.head(n_), z.p + d(n_)};
      if (++growths > 2 || !residual(next, Ft)) return c;
    }
    z = std::move(next);
    F = Ft;
    if (metric_.norm(metric_.difference(z, predictor)) > 4 * std::abs(ds)) return c;
  }
  c.z = std::move(z);
  return c;
}

// True when z lies on the path already traced (within 2 % of the step: a corrector
// that went back lands on the path, up to the chords' sagitta, about 1.5 % of a step
// at the aimed turn; the far side of a hairpin corner, which the scaled metric makes
// of a sharp corner, keeps a few percent away). Every segment is checked, not only
// the last few, and as the cubic through its ends with their tangents, not as its
// chord: after a stretch of tiny steps (a friction peak's stick-slip kinks) a
// corrector can land back on a stretch that was crossed in long steps, whose chords
// lie far from the path.
bool Tracer::onTracedPath(const Point& z, double ds) const {
  const auto& pts = branch_.points;
  const std::size_t n = pts.size();
  const double reach = 0.02 * ds, reachP = reach * metric_.sp;  // |dp| / sp bounds the distance
  constexpr int kPieces = 8;
  std::array<Point, kPieces + 1> c;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const Point a{pts[i].x, pts[i].parameter}, b{pts[i + 1].x, pts[i + 1].parameter};
    const Point chord = metric_.difference(b, a);
    const double L = metric_.norm(chord);
    // The ends' tangents scaled to the chord's length (the chord where none is known).
    auto scaled = [&](const Point& t) {
      const double tn = t.x.size() == n_ ? metric_.norm(t) : 0.0;
      return tn > 0 ? Point{t.x * (L / tn), t.p * (L / tn)} : chord;
    };
    const Point ta = scaled(tangents_[i]), tb = scaled(tangents_[i + 1]);
    auto h = [](double s) {
      return std::array<double, 4>{2 * s * s * s - 3 * s * s + 1, s * s * s - 2 * s * s + s, -2 * s * s * s + 3 * s * s,
                                   s * s * s - s * s};
    };
    double pmin = std::min(a.p, b.p), pmax = std::max(a.p, b.p);
    for (int k = 1; k < kPieces; ++k) {
      const auto w = h(double(k) / kPieces);
      const double pk = w[0] * a.p + w[1] * ta.p + w[2] * b.p + w[3] * tb.p;
      pmin = std::min(pmin, pk), pmax = std::max(pmax, pk);
    }
    if (z.p < pmin - reachP || z.p > pmax + reachP) continue;
    for (int k = 0; k <= kPieces; ++k) {
      const auto w = h(double(k) / kPieces);
      c[k] = {w[0] * a.x + w[1] * ta.x + w[2] * b.x + w[3] * tb.x, w[0] * a.p + w[1] * ta.p + w[2] * b.p + w[3] * tb.p};
    }
    for (int k = 0; k < kPieces; ++k) {
      const Point ab = metric_.difference(c[k + 1], c[k]), az = metric_.difference(z, c[k]);
      const double L2 = metric_.dot(ab, ab);
      const double s = L2 > 0 ? std::clamp(metric_.dot(az, ab) / L2, 0.0, 1.0) : 0.0;
      const Point q{c[k].x + s * ab.x, c[k].p + s * ab.p};
      const bool atStart = i + 2 == n && k + 1 == kPieces && s == 1.0;  // the last point: a step from it, not back
      if (!atStart && metric_.norm(metric_.difference(z, q)) < reach) return true;
    }
  }
  return false;
}

// When the measure has a local maximum at the second last point z0 (between its
// neighbours), its top by parabolic interpolation (golden section where the parabola
// leaves the bracket) in the arclength coordinate sigma = t0 . (z - z0), each trial
// point solved on the hyperplane at sigma; the top is inserted in path order.
void Tracer::refinePeak(const Point& t0) {
  const std::size_t n = branch_.points.size();
  if (!problem_.measure || n < 3) return;
  const double ga = measures_[n - 3], g0 = measures_[n - 2], gb = measures_[n - 1];
  if (!(g0 >= ga && g0 > gb)) return;
  const Point z0{branch_.points[n - 2].x, branch_.points[n - 2].parameter};
  auto sigmaOf = [&](std::size_t i) {
    return metric_.dot(t0, metric_.difference(Point{branch_.points[i].x, branch_.points[i].parameter}, z0));
  };
  double a = sigmaOf(n - 3), b = sigmaOf(n - 1), m = 0, fa = ga, fb = gb, fm = g0;
  if (!(a < 0 && b > 0)) return;
  const double width = b - a;
  Point best = z0;
  for (int it = 0; it < 20 && b - a > 1e-5 * width; ++it) {
    // The parabola's vertex through (a, fa), (m, fm), (b, fb).
    const double p1 = (m - a) * (fm - fb), p2 = (m - b) * (fm - fa);
    const double den = 2 * (p1 - p2);
    double s = den != 0 ? m - ((m - a) * p1 - (m - b) * p2) / den : m;
    const double tooClose = 1e-3 * (b - a);
    if (!(s > a + tooClose && s < b - tooClose) || std::abs(s - m) < 1e-2 * tooClose)
      s = m - a > b - m ? m - 0.381966 * (m - a) : m + 0.381966 * (b - m);
    Correction c = correct(Constraint::Plane, z0, t0, s);
    keepFactors(c);
    if (!c.converged) break;
    const double gs = problem_.measure(c.z.x);
    if (gs > fm) {
      (s > m ? a : b) = m;
      (s > m ? fa : fb) = fm;
      m = s, fm = gs, best = c.z;
    } else {
      (s > m ? b : a) = s;
      (s > m ? fb : fa) = gs;
    }
  }
  if (m == 0) return;
  const auto at = branch_.points.begin() + long(m < 0 ? n - 2 : n - 1);
  if (std::size_t(at - branch_.points.begin()) <= anchor_) ++anchor_;
  measures_.insert(measures_.begin() + (at - branch_.points.begin()), fm);
  tangents_.insert(tangents_.begin() + (at - branch_.points.begin()), t0);
  branch_.points.insert(at, BranchPoint{best.p, best.x});
}

// The last resort where no arclength step passes: Newton at a fixed parameter a
// little beyond z0 (1, 1/4, 4 times the last step's change of p, at least 1e-4 of the
// range) in the direction the tangent points. Where the tangent points back, the
// sweep's direction is tried first, but a point there is taken only close to z0 (the
// same sheet of the path continued past the wall): the tangent at a point where every
// arclength step failed is poor, and where it points back along a drift of the
// unknowns (the contacts' mean tangential slip, at a square-root branch of the
// residual) the steps back lead into the same wall (docs/decisions.md); a point
// farther away is another branch across a fold, which must not be skipped.
bool Tracer::fixedParameterStep(const Point& z0, const Point& t0, Point& z1) {
  const auto& pts = branch_.points;
  double dp = pts.size() >= 2 ? std::abs(pts.back().parameter - pts[pts.size() - 2].parameter) : 0.0;
  dp = std::max(dp, 1e-4 * metric_.sp);
  const double sweep = o_.to >= o_.from ? 1.0 : -1.0, along = t0.p >= 0 ? 1.0 : -1.0;
  constexpr double kNear = 0.01;  // in the step's metric: 1 % of the response, or of the range
  for (double sign : {sweep, along}) {  // one pass where they agree (the break below)
    const bool againstTangent = sign != along;
    for (double f : {1.0, 0.25, 4.0}) {
      z1 = {z0.x, z0.p + sign * f * dp};  // from x0: the tangent is poor where the arclength steps failed
      if (!solveNewton(problem_, z1.x, z1.p, o_.tolerance, 12, nullptr, o_.linearSolver).converged) continue;
      const double distance = metric_.norm(metric_.difference(z1, z0));
      if (againstTangent && distance > kNear) continue;
      if (!onTracedPath(z1, distance)) return true;
    }
    if (sweep == along) break;
  }
  return false;
}

// A creep: the last 6 points moved the parameter by less than 1e-5 of the range
// (on the default disc at H = 3, a superharmonic resonance where many contacts start
// to slip: corners about 1e-6 apart, each crossed in steps of 1e-6 .. 1e-3, and one
// whose outgoing branch turns by 106 degrees and wanders back). Newton at a fixed
// parameter 1e-3 (then 2.5e-4) of the range ahead in the sweep's direction, from the
// last point, takes the branch past it when it lands close (5 % of the response or
// of the range) and off the traced path: the same sheet, every parameter covered.
bool Tracer::passCreep(Point& z, Point& t, double dir) {
  constexpr std::size_t kWindow = 6;
  const auto& pts = branch_.points;
  if (pts.size() < std::max(anchor_, creepChecked_) + kWindow) return false;
  double lo = pts.back().parameter, hi = lo;
  for (std::size_t i = pts.size() - kWindow; i < pts.size(); ++i)
    lo = std::min(lo, pts[i].parameter), hi = std::max(hi, pts[i].parameter);
  if (hi - lo >= 1e-5 * metric_.sp) return false;
  for (double f : {1e-3, 2.5e-4}) {
    Point z1{z.x, markBefore(z.p, z.p + dir * f * metric_.sp)};
    if (!solveNewton(problem_, z1.x, z1.p, o_.tolerance, 12, nullptr, o_.linearSolver).converged) continue;
    const Point chord = metric_.difference(z1, z);
    const double distance = metric_.norm(chord);
    Point t1;
    if (distance > 0.05 || onTracedPath(z1, distance) || !freshTangent(z1, chord, t1)) continue;
    std::ostringstream msg;
    msg << "continuation: creeping at p = " << z.p << " (" << kWindow << " points within " << hi - lo
        << "); stepped over at a fixed parameter to p = " << z1.p;
    log::info(msg.str());
    append(z1, t1);
    anchor_ = pts.size() - 1;
    z = std::move(z1);
    rescale(z);
    const double norm = metric_.norm(t1);
    t = {t1.x / norm, t1.p / norm};
    return true;
  }
  creepChecked_ = pts.size() - 1;  // not again before another window
  return false;
}

// The unknowns' scale follows the solution (never below a tenth of the largest
// seen, nor below the floor set at the start): steps are relative changes where the
// response grows, and a response passing near zero does not make every corner
// there a hairpin.
void Tracer::rescale(const Point& z) {
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    double norm2 = 0;
    for (int i : groups_[g]) norm2 += z.x(i) * z.x(i);
    const double norm = std::sqrt(norm2);
    largestNorm_[g] = std::max(largestNorm_[g], norm);
    groupScale_[g] = std::max({norm, 0.1 * largestNorm_[g], sxFloor_[g]});
  }
  setWeights();
}

void Tracer::setWeights() {
  metric_.w.resize(n_);
  for (std::size_t g = 0; g < groups_.size(); ++g)
    for (int i : groups_[g]) metric_.w(i) = 1.0 / (groupScale_[g] * groupScale_[g]);
}

// The branch left the range between `inside` and `outside`: its point at p, by
// Newton at that p from the interpolation between the two, else from either end
// (at a kink of a friction residual one start can cycle where another converges).
// False when none converges.
bool Tracer::endAt(double p, const Point& inside, const Point& outside) {
  const double s = (p - inside.p) / (outside.p - inside.p);
  for (const Eigen::VectorXd& start : {Eigen::VectorXd(inside.x + s * (outside.x - inside.x)), inside.x, outside.x}) {
    Eigen::VectorXd x = start;
    if (solveNewton(problem_, x, p, o_.tolerance, 30, nullptr, o_.linearSolver).converged) {
      append({std::move(x), p});
      return true;
    }
  }
  return false;
}

void Tracer::progress() {
  if (sinceLog_.seconds() < 10) return;
  const auto& s = branch_.statistics;
  std::ostringstream msg;
  msg << "continuation: " << branch_.points.size() << " points, parameter " << branch_.points.back().parameter << ", "
      << total_.seconds() << " s; " << s.newtonIterations << " Newton iterations, " << s.rejectedSteps
      << " steps cut";
  log::info(msg.str());
  sinceLog_.restart();
}

void Tracer::save(const Point& t, double ds) {
  if (!checkpointing_ || !checkpointing_->save || sinceSave_.seconds() < checkpointing_->intervalSeconds ||
      !atFreshFactors())
    return;
  TraceState s;
  s.branch = branch_;
  s.branch.statistics.seconds = secondsBefore_ + total_.seconds();
  for (const auto& tz : tangents_) {
    s.tangentX.push_back(tz.x);
    s.tangentP.push_back(tz.p);
  }
  s.measures = measures_;
  s.directionX = t.x, s.directionP = t.p, s.step = ds;
  s.scaleX = groupScale_, s.scaleP = metric_.sp, s.largestNorm = largestNorm_, s.scaleFloor = sxFloor_;
  s.retractions = retractions_, s.anchor = long(anchor_), s.creepChecked = long(creepChecked_);
  s.secant = secant_, s.smoothRun = smoothRun_, s.heldSteps.assign(heldSteps_.begin(), heldSteps_.end());
  checkpointing_->save(s);
  sinceSave_.restart();
}

void Tracer::restore(const TraceState& s, Point& z, Point& t, double& ds) {
  branch_ = s.branch;
  secondsBefore_ = s.branch.statistics.seconds;
  tangents_.clear();
  for (std::size_t i = 0; i < s.tangentX.size(); ++i) tangents_.push_back({s.tangentX[i], s.tangentP[i]});
  measures_ = s.measures;
  t = {s.directionX, s.directionP}, ds = s.step;
  if (s.scaleX.size() != groups_.size() || s.largestNorm.size() != groups_.size() ||
      s.scaleFloor.size() != groups_.size())
    throw InputError("continuation", "a saved trace's scale groups do not match the problem's");
  groupScale_ = s.scaleX, metric_.sp = s.scaleP, largestNorm_ = s.largestNorm, sxFloor_ = s.scaleFloor;
  setWeights();
  retractions_ = int(s.retractions), anchor_ = std::size_t(s.anchor), creepChecked_ = std::size_t(s.creepChecked);
  secant_ = s.secant != 0, smoothRun_ = int(s.smoothRun), heldSteps_.assign(s.heldSteps.begin(), s.heldSteps.end());
  z = {branch_.points.back().x, branch_.points.back().parameter};
}

// The first point (Newton from the guess) and the first tangent; false with the stop
// reason set where there is none.
bool Tracer::start(const Eigen::VectorXd& guess, Point& z, Point& t) {
  z = {guess, o_.from};
  const auto start = solveNewton(problem_, z.x, o_.from, o_.tolerance, 100, nullptr, o_.linearSolver);
  if (!start.converged) {
    branch_.end = BranchEnd::NoStart;
    branch_.stopReason = noConvergedStart(start, o_.tolerance);
    return false;
  }
  const double dir = o_.to >= o_.from ? 1.0 : -1.0;
  metric_.sp = std::abs(o_.to - o_.from);
  if (!(metric_.sp > 0)) {
    append(z);
    branch_.finished = true;
    branch_.end = BranchEnd::SinglePoint;
    branch_.stopReason = "the range is a single point";
    return false;
  }
  // The first tangent: dp = dir, J dx = -dF/dp dp; the unknowns' floor scale from it
  // (the change of x over the range at the start's slope), for a start from rest.
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    double norm2 = 0;
    for (int i : groups_[g]) norm2 += z.x(i) * z.x(i);
    groupScale_[g] = std::max(std::sqrt(norm2), 1e-300);
  }
  setWeights();
  Eigen::VectorXd F;
  Bordered A;
  if (!residual(z, F) || !jacobian(z, F, A)) {
    branch_.end = BranchEnd::StartFailed;
    branch_.stopReason = "the residual or Jacobian failed at the start of the range";
    return false;
  }
  A.setBottom(Eigen::VectorXd::Zero(n_), 1.0);
  BorderedFactors lu;
  factor(A, lu);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n_ + 1);
  rhs(n_) = dir;
  const Eigen::VectorXd v = solve(lu, rhs);
  if (!v.allFinite()) {
    branch_.end = BranchEnd::StartFailed;
    branch_.stopReason = "singular Jacobian at the start of the range";
    return false;
  }
  // Each group's floor from its own slope, and at least 1e-2 of the whole's: a group that
  // stays at zero (the mean of a symmetric system) does not make round-off a step.
  const double whole = std::max(1e-3 * v.head(n_).norm() * metric_.sp, 1e-300);
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    double norm2 = 0;
    for (int i : groups_[g]) norm2 += v(i) * v(i);
    sxFloor_[g] = std::max(1e-3 * std::sqrt(norm2) * metric_.sp, 1e-2 * whole);
  }
  rescale(z);
  t = {v.head(n_), v(n_)};
  const double norm = metric_.norm(t);
  t.x /= norm, t.p /= norm;
  append(z, t);
  return true;
}

// Plane, then sphere. A converged point is taken unless it lies back on the path or
// too far away; a tangent turned by more than 60 degrees refuses it unless the step is
// already down to a corner's size. On Taken, c holds the point, t1 its tangent and
// cosTurn the turn from t.
Tracer::StepOutcome Tracer::correctStep(const Point& z, const Point& t, double ds, Correction& c, Point& t1,
                                        double& cosTurn) {
  for (Constraint kind : {Constraint::Plane, Constraint::Sphere}) {
    keepFactors(c);
    c = correct(kind, z, t, ds);
    if (!c.converged) continue;
    const Point chord = metric_.difference(c.z, z);
    const double length = metric_.norm(chord);
    if (length > 3 * ds || onTracedPath(c.z, ds)) continue;
    if (!(c.factored && tangentFrom(c.lu, chord, t1)) && !freshTangent(c.z, chord, t1)) continue;
    // The turn in the metric of the step (the scale is updated after it): of the
    // tangent, or with secant steps of the chord against the last one.
    cosTurn = std::clamp(secant_ ? metric_.dot(t, chord) / length : metric_.dot(t, t1), -1.0, 1.0);
    // A point behind the last one (a sphere's) or whose tangent reverses is a
    // hairpin's far side only if the path just traced is resolved at this step's
    // scale; after a long last step (which may have crossed a stretch of stick-slip
    // kinks) it can be that step's own path, and the step is retaken shorter instead.
    if ((metric_.dot(chord, t) < 0 || cosTurn < 0) && lastSegmentLength() > ds &&
        branch_.points.size() > anchor_ + 1 && retractions_ < kMaxRetractions)
      return StepOutcome::Retract;
    if (cosTurn < 0.5 && ds > cornerStep_) return StepOutcome::CutHard;
    if (kind == Constraint::Sphere) ++stats().sphericalSteps;
    return StepOutcome::Taken;
  }
  return StepOutcome::Cut;
}

// The last point dropped and the step retaken from the one before, a quarter as long
// as the dropped segment.
void Tracer::retract(Point& z, Point& t, double& ds) {
  ++stats().rejectedSteps, ++retractions_;
  ds = lastSegmentLength() / 4;
  dropLast();
  z = {branch_.points.back().x, branch_.points.back().parameter};
  rescale(z);
  const Point& tz = tangents_.back();
  const double norm = tz.x.size() == n_ ? metric_.norm(tz) : 0.0;
  if (norm > 0) t = {tz.x / norm, tz.p / norm};
  ds = std::max(ds, o_.minStep);
}

// No arclength step passes z down to the smallest step: a fixed-parameter step, or
// the trace stops (false, with the reason).
bool Tracer::passWall(Point& z, Point& t, double& ds) {
  Point z1, t1;
  if (fixedParameterStep(z, t, z1) && freshTangent(z1, metric_.difference(z1, z), t1)) {
    log::info("continuation: no arclength step passes p = " + std::to_string(z.p) +
              "; stepped over at a fixed parameter to p = " + std::to_string(z1.p));
    append(z1, t1);
    anchor_ = branch_.points.size() - 1;
    z = std::move(z1);
    rescale(z);
    const double norm = metric_.norm(t1);  // unit in the updated metric
    t = {t1.x / norm, t1.p / norm};
    ds = cornerStep_;
    return true;
  }
  std::ostringstream why;
  why << "no step passes p = " << z.p << ": the arclength correctors (plane and sphere) failed down to the "
      << "smallest step " << o_.minStep << ", and so did Newton at a fixed parameter beyond it (the branch so "
      << "far is kept)";
  branch_.end = BranchEnd::Wall;
  branch_.stopReason = why.str();
  return false;
}

// The next step from the corrector's effort and the turn. Below a corner's size the
// turn no longer shortens the step: a tangent that keeps turning as the step shrinks
// is a kink of the nonsmooth residual (a contact's stick-slip instant crossing a time
// sample), not a curvature to resolve, and a friction peak crosses thousands of them.
double Tracer::nextStep(int iterations, double cosTurn, double ds) const {
  const double turn = std::acos(cosTurn);
  const double byNewton = std::clamp(4.0 / std::max(iterations, 1), 0.5, 2.0);
  // Secant steps are held by the chord's turn only beyond four times the aim (one
  // radian): over a stair of kinks the chord wanders by up to about that at the kinks'
  // scale and settles (to less than the aim on the default disc's hammering shroud) only
  // at steps spanning many of them, which a turn of the aim would never let it reach.
  const double aim = secant_ ? 4 * o_.turnAngle : o_.turnAngle;
  const double byTurn = secant_ && turn < aim ? 2.0 : std::clamp(aim / std::max(turn, 1e-12), 0.25, 2.0);
  double next = ds * std::min(byNewton, byTurn);
  if (byTurn < byNewton) next = std::max(next, std::min(ds * byNewton, cornerStep_));
  return std::clamp(next, o_.minStep, o_.maxStep);
}

// Secant steps where 6 of the last 10 steps were held within twice the corner's size
// by the tangent's turn (a stair of kinks: the tangent turns about as much whatever the
// step); back to the tangent after 5 steps in a row whose tangent turned less than the
// aim (the curve smooth again at the step's scale).
void Tracer::switchPredictor(double tangentTurn, double next, double p) {
  if (!o_.secantOverKinks) return;
  if (!secant_) {
    heldSteps_.push_back(next <= 2 * cornerStep_ && tangentTurn > o_.turnAngle);
    if (heldSteps_.size() > 10) heldSteps_.pop_front();
    if (std::count(heldSteps_.begin(), heldSteps_.end(), true) < 6) return;
    secant_ = true, smoothRun_ = 0;
    log::info("continuation: a stair of kinks at p = " + std::to_string(p) + ": secant steps");
    return;
  }
  smoothRun_ = tangentTurn < o_.turnAngle ? smoothRun_ + 1 : 0;
  if (smoothRun_ < 5) return;
  secant_ = false;
  heldSteps_.clear();
  log::info("continuation: smooth again at p = " + std::to_string(p) + ": tangent steps");
}

// After a taken step from `previous` to z: true (the trace ends) when z left the range,
// at its end (the end itself by Newton there; where that does not converge, the
// converged point just past it stays, and the reason says so) or back past its start.
bool Tracer::leftTheRange(const Point& previous, const Point& z, const Point& t) {
  const double dir = o_.to >= o_.from ? 1.0 : -1.0;
  if ((z.p - o_.to) * dir >= 0) {
    dropLast();
    branch_.finished = true;
    branch_.end = BranchEnd::RangeEnd;
    branch_.stopReason = "end of the parameter range reached";
    if (!endAt(o_.to, previous, z)) {
      append(z, t);
      branch_.stopReason += " (the last point lies just past it, at p = " + std::to_string(z.p) +
                            ": Newton at the end itself did not converge)";
    }
    return true;
  }
  if ((z.p - o_.from) * dir >= 0) return false;
  dropLast();
  if (!endAt(o_.from, previous, z)) append(z, t);
  double reached = o_.from;
  for (const auto& pt : branch_.points) reached = dir > 0 ? std::max(reached, pt.parameter) : std::min(reached, pt.parameter);
  branch_.returnedToStart = true;
  branch_.reached = reached;
  std::ostringstream why;
  why << "the branch turned back at p = " << reached << " and returned to the start of the range (p = " << o_.from
      << "): " << reached << " .. " << o_.to << " not traced (the branch so far is kept)";
  branch_.end = BranchEnd::ReturnedToStart;
  branch_.stopReason = why.str();
  return true;
}

// True (the trace ends) when the point budget is spent or the next predictor passes
// the range's end and Newton there converges (the end reached).
// `to`, or the first parameter mark (ContinuationOptions::parameterMarks) strictly
// between `from` and it: a step at a fixed parameter does not pass over one either.
double Tracer::markBefore(double from, double to) const {
  double nearest = to;
  for (const double mark : o_.parameterMarks)
    if ((mark - from) * (nearest - mark) > 0) nearest = mark;
  return nearest;
}

// The step shortened so that its predictor lands on the first parameter mark it would
// pass (ContinuationOptions::parameterMarks) by a long way, more than a tenth of the
// mark's value (a resonance of that width is not passed over unseen by the steps' own
// control, whose steps near it are a few percent; a curve over decades steps past it by
// hundreds of times): the point there is the curve's, and the steps beyond start from it.
double Tracer::stepToMark(const Point& z, const Point& along, double ds) const {
  if (o_.parameterMarks.empty() || along.p == 0) return ds;
  const double to = z.p + ds * along.p;
  if (!(std::abs(to - z.p) > 0.1 * std::abs(markBefore(z.p, to)))) return ds;
  double shortest = ds;
  for (const double mark : o_.parameterMarks) {
    const double d = (mark - z.p) / along.p;  // the step that lands on it
    if ((mark - z.p) * (to - mark) > 0 && d > o_.minStep && d < shortest) shortest = d;
  }
  return shortest;
}

bool Tracer::atTheEnd(const Point& z, const Point& t, double ds) {
  if (int(branch_.points.size()) >= o_.maxSteps) {
    branch_.end = BranchEnd::PointBudget;
    branch_.stopReason = "the largest number of points (max_points " + std::to_string(o_.maxSteps) +
                         ") was reached at p = " + std::to_string(z.p) + " (the branch so far is kept)";
    return true;
  }
  const double dir = o_.to >= o_.from ? 1.0 : -1.0;
  const Point predictor{z.x + ds * t.x, z.p + ds * t.p};
  // A step that would pass a parameter mark (a linear resonance) lands on it first: the
  // range's end is not reached over it (a step of 1000 went from 0.5 to the end at 2,
  // over the Duffing resonance at 1.27, and called the range finished; issue 49).
  if (stepToMark(z, t, ds) < ds) return false;
  if ((predictor.p - o_.to) * dir > 0 && endAt(o_.to, z, predictor)) {
    branch_.finished = true;
    branch_.end = BranchEnd::RangeEnd;
    branch_.stopReason = "end of the parameter range reached";
    return true;
  }
  return false;
}

void Tracer::run(const Eigen::VectorXd& guess) {
  const double dir = o_.to >= o_.from ? 1.0 : -1.0;
  Point z, t;
  double ds = 0;
  if (checkpointing_ && checkpointing_->resumeFrom) {
    restore(*checkpointing_->resumeFrom, z, t, ds);
  } else {
    if (!start(guess, z, t)) return;
    ds = std::clamp(o_.initialStep, o_.minStep, o_.maxStep);
  }
  while (true) {
    if (int(branch_.points.size()) < o_.maxSteps) {
      progress();
      if (atFreshFactors()) kept_ = BorderedFactors();
      save(t, ds);
      if (passCreep(z, t, dir)) {
        ds = cornerStep_;
        continue;
      }
    }
    if (atTheEnd(z, t, ds)) break;
    Correction c;
    Point t1;
    double cosTurn = 1;
    // The predictor: along the tangent, or along the last chord where the curve is a
    // stair of kinks (a friction contact's stick, slip or lift-off instant crossing a
    // time sample; the hammering shroud crosses thousands along one resonance): there
    // the tangent turns by about as much at any step and points anywhere (a micro-fold
    // reverses it), while the chord over several kinks follows the curve.
    const Point along = secant_ && branch_.points.size() >= 2 ? lastChord() : t;
    ds = stepToMark(z, along, ds);
    const StepOutcome outcome = correctStep(z, along, ds, c, t1, cosTurn);
    keepFactors(c);
    if (outcome == StepOutcome::Retract) {
      retract(z, t, ds);
      continue;
    }
    if (outcome != StepOutcome::Taken) {
      ++stats().rejectedSteps;
      ds /= outcome == StepOutcome::CutHard ? 4 : 2;
      if (ds >= o_.minStep || passWall(z, t, ds)) continue;
      break;
    }
    if (secant_) ++stats().secantSteps;
    const Point previous = z;
    z = std::move(c.z);
    append(z, t1);
    refinePeak(t);  // a maximum of the measure at the point before, whose tangent t is
    // The tangent's own turn (the switch to and from secant steps), in the step's metric.
    const double tangentTurn = std::acos(std::clamp(metric_.dot(t, t1) / metric_.norm(t1), -1.0, 1.0));
    rescale(z);
    const double tnorm = metric_.norm(t1);
    t = {t1.x / tnorm, t1.p / tnorm};
    ds = nextStep(c.iterations, cosTurn, ds);
    switchPredictor(tangentTurn, ds, z.p);
    if (leftTheRange(previous, z, t)) break;
  }
  stats().seconds = secondsBefore_ + total_.seconds();
  logSummary();
}

void Tracer::logSummary() const {
  const auto& s = branch_.statistics;
  std::ostringstream msg;
  msg << "continuation: " << branch_.points.size() << " points, " << s.newtonIterations << " Newton iterations ("
      << s.rejectedSteps << " steps cut, " << s.sphericalSteps << " spherical), " << s.seconds << " s: residuals "
      << s.residualSeconds << " s (" << s.residuals << "), Jacobians " << s.jacobianSeconds << " s (" << s.jacobians
      << "), factorisations " << s.factorSeconds << " s (" << s.factorizations;
  if (s.doubleFallbacks > 0) msg << ", " << s.doubleFallbacks << " again in double";
  msg << "), solves " << s.solveSeconds << " s";
  if (s.secantSteps > 0) msg << "; " << s.secantSteps << " secant steps over stairs of kinks";
  if (s.reusedFactorizations > 0)
    msg << " (" << s.reusedFactorizations << " Newton steps with kept factors, " << s.krylovIterations
        << " GMRES iterations)";
  log::info(msg.str());
}

}  // namespace

Branch traceBranchWithPredictorCorrector(const ContinuationProblem& problem, const Eigen::VectorXd& guess,
                                         const ContinuationOptions& o, const TraceCheckpointing* checkpointing) {
  Branch branch;
  Tracer(problem, o, branch, checkpointing).run(guess);
  return branch;
}

}  // namespace cyclone::continuation
