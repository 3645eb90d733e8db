#include "LocatedFrictionForce.hpp"

#include "IntervalCubic.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace cyclone::hbm::detail {
namespace {

enum class Phase { Open, Stick, Slip };

// The slider's state: the phase, the slip direction (+1, -1; 0 for a frictionless
// contact's closed phase) and the stuck slider's position.
struct SliderState {
  Phase phase = Phase::Stick;
  double direction = 0;
  double z = 0;
};

// One contact's continuous-time law marched along the Hermite interpolant of its
// motion's samples, interval by interval; when recording, the hat-weighted integrals
// of what the force leaves out of the linear springs (fbar, N x 2) and their
// sensitivities to the coefficients.
class IntervalMarch {
public:
  IntervalMarch(const FrictionContactParameters& p, const Aft& aft, const Eigen::MatrixXd& W, bool sensitivities)
      : p_(p), N_(aft.numSamples()), nc_(aft.numCoefficients()), h_(2 * pi / aft.numSamples()),
        values_(N_, 2), slopes_(N_, 2), fbar_(N_, 2) {
    const Eigen::MatrixXd DW = aft.derivativeMatrix() * W;
    for (int c = 0; c < 2; ++c) {
      aft.toTime(W.col(c).data(), values_.col(c).data());
      aft.toTime(DW.col(c).data(), slopes_.col(c).data());
    }
    slopes_ *= h_;  // per interval: d/dtau = h d/dtheta
    if (sensitivities) {
      Et_ = aft.timeFromCoefficients().transpose();
      // h (E D)^T without the product: d/dtheta of harmonic k's cos is -k sin, of its sin k cos.
      const Eigen::MatrixXd& E = aft.timeFromCoefficients();
      hEdT_.setZero(nc_, N_);
      for (int k : aft.harmonics().harmonics()) {
        if (k == 0) continue;
        const int c = aft.harmonics().cosIndex(k), s = aft.harmonics().sinIndex(k);
        hEdT_.row(c) = (-h_ * k) * E.col(s).transpose();
        hEdT_.row(s) = (h_ * k) * E.col(c).transpose();
      }
      for (auto& d : dfbar_) d.setZero(2 * nc_, N_);
    }
    fbar_.setZero();
  }
  int m() const { return 2 * nc_; }
  const Eigen::MatrixXd& integrals() const { return fbar_; }
  // Column i: d(fbar(i, c))/dvec(W).
  const Eigen::MatrixXd& integralSensitivities(int c) const { return dfbar_[c]; }

  // The state at the period's start (the relaxed slider, z = 0, unless slipping).
  SliderState initialState() const {
    const Cubic w = interpolant(0, 0), N = normalLoad(0);
    SliderState s;
    if (!(N(0) > 0)) s.phase = Phase::Open;
    else if (p_.mu == 0) s.phase = Phase::Slip, s.direction = 0;
    else if (std::abs(p_.kt * w(0)) > p_.mu * N(0)) s.phase = Phase::Slip, s.direction = w(0) > 0 ? 1 : -1;
    return s;
  }

  // One period from state s (updated); dz (m, or null) the stuck slider's
  // sensitivity, carried along; with record, fbar and its sensitivities.
  void period(SliderState& s, Eigen::VectorXd* dz, bool record) {
    for (int i = 0; i < N_; ++i) interval(i, s, dz, record);
  }

private:
  Cubic interpolant(int i, int c) const {
    const int j = (i + 1) % N_;
    return hermiteCubic(values_(i, c), slopes_(i, c), values_(j, c), slopes_(j, c));
  }
  Cubic normalLoad(int i) const { return combine(p_.kn, interpolant(i, 1), 0, Cubic{}, p_.preload); }

  // row += the sensitivity whose weights on the interval's local inputs are alpha:
  // (a_i, b_i, a_j, b_j) of t, then of n.
  void addLocal(Eigen::Ref<Eigen::VectorXd> row, const std::array<double, 8>& alpha, int i, int j) const {
    for (int c = 0; c < 2; ++c) {
      auto seg = row.segment(c * nc_, nc_);
      const double* a = &alpha[4 * c];
      if (a[0] != 0) seg.noalias() += a[0] * Et_.col(i);
      if (a[1] != 0) seg.noalias() += a[1] * hEdT_.col(i);
      if (a[2] != 0) seg.noalias() += a[2] * Et_.col(j);
      if (a[3] != 0) seg.noalias() += a[3] * hEdT_.col(j);
    }
  }

  void interval(int i, SliderState& s, Eigen::VectorXd* dz, bool record) {
    const int j = (i + 1) % N_;
    const Cubic w = interpolant(i, 0), n = interpolant(i, 1), N = normalLoad(i);
    const double kt = p_.kt, mu = p_.mu, kn = p_.kn;
    // alpha[end][component]: the hat integrals' weights on the local inputs (end 0 is
    // sample i, 1 is sample j).
    std::array<std::array<std::array<double, 8>, 2>, 2> alpha{};
    double ta = 0;
    for (int events = 0;; ++events) {
      // The phase's next instant and the phase after it (a 16th instant in one
      // interval is not looked for: a grazing the bisection cannot separate).
      double te = 2;
      SliderState next = s;
      auto consider = [&](double t, Phase phase, double direction) {
        if (t < te) te = t, next.phase = phase, next.direction = direction;
      };
      if (events >= 16) {
        // no further instant in this interval
      } else if (s.phase == Phase::Open) {
        consider(firstCrossing(N, 1, ta), Phase::Stick, 0);  // closing: phase decided below
      } else {
        consider(firstCrossing(N, -1, ta), Phase::Open, 0);
        if (s.phase == Phase::Stick) {
          consider(firstCrossing(combine(kt, w, -mu, N, -kt * s.z), 1, ta), Phase::Slip, 1);
          consider(firstCrossing(combine(kt, w, mu, N, -kt * s.z), -1, ta), Phase::Slip, -1);
        } else if (s.direction != 0) {
          // Slip holds while the trial force outgrows the limit: s kt w' > mu kn n'.
          consider(firstCrossing(combine(s.direction * kt, w.derivative(), -mu * kn, n.derivative(), 0), -1, ta),
                   Phase::Stick, 0);
        }
      }
      const double tb = std::min(te, 1.0);
      if (record) integrate(i, j, ta, tb, s, w, N, dz, alpha);
      if (te > 1) break;
      const std::array<double, 4> H = hermite(te);
      std::array<double, 8> weights{};
      if (s.phase == Phase::Open) {  // closing: stick unless the trial outgrows the limit at once
        const double trialSlope = kt * w.slope(te), limitSlope = mu * N.slope(te);
        if (mu == 0) next.phase = Phase::Slip, next.direction = 0;
        else if (std::abs(trialSlope) > limitSlope) next.phase = Phase::Slip, next.direction = trialSlope > 0 ? 1 : -1;
        else {
          next.z = w(te);
          // z = w(te) with te where N = 0: dte = -kn dn(te) / N'(te).
          for (int k = 0; k < 4; ++k) weights[k] = H[k], weights[4 + k] = -w.slope(te) * kn * H[k] / N.slope(te);
        }
      } else if (s.phase == Phase::Slip && next.phase == Phase::Stick) {
        // z = w - s mu N / kt at te; its te-derivative vanishes there (the instant's condition).
        next.z = w(te) - s.direction * mu * N(te) / kt;
        for (int k = 0; k < 4; ++k) weights[k] = H[k], weights[4 + k] = -s.direction * mu * kn * H[k] / kt;
      }
      if (dz && next.phase == Phase::Stick && s.phase != Phase::Stick) {
        dz->setZero();
        addLocal(*dz, weights, i, j);
      }
      s = next;
      ta = te;
    }
    if (!record || dfbar_[0].size() == 0) return;
    for (int end = 0; end < 2; ++end)
      for (int c = 0; c < 2; ++c) addLocal(dfbar_[c].col(end == 0 ? i : j), alpha[end][c], i, j);
  }

  // The hat-weighted integrals over [ta, tb] in the phase s of what the force leaves
  // out of the linear springs' kt w and N0 + kn n (the force is their difference):
  // kt z in stick (the stuck slider, a constant: a contact stuck throughout is exact),
  // kt w - s mu N in slip, kt w and N while open. Exact by three-point Gauss (a cubic
  // there, the hat linear).
  void integrate(int i, int j, double ta, double tb, const SliderState& s, const Cubic& w, const Cubic& N,
                 const Eigen::VectorXd* dz, std::array<std::array<std::array<double, 8>, 2>, 2>& alpha) {
    if (tb <= ta) return;
    static const double xi[3] = {-0.7745966692414834, 0, 0.7745966692414834}, gw[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
    // Frictionless, the tangential force is nil: no linear spring to take it from.
    const double L = tb - ta, kt = p_.mu == 0 ? 0.0 : p_.kt, kn = p_.kn, slipLimit = s.direction * p_.mu;
    double beta[2] = {0, 0};  // weights on dz (stick)
    for (int g = 0; g < 3; ++g) {
      const double x = ta + L * 0.5 * (1 + xi[g]), gamma = L * gw[g];
      const double hat[2] = {gamma * (1 - x), gamma * x};
      double tangential = 0, normal = 0;
      if (s.phase == Phase::Stick) tangential = kt * s.z;
      else if (s.phase == Phase::Slip) tangential = kt * w(x) - slipLimit * N(x);
      else tangential = kt * w(x), normal = N(x);
      const std::array<double, 4> H = hermite(x);
      for (int end = 0; end < 2; ++end) {
        const int sample = end == 0 ? i : j;
        fbar_(sample, 0) += hat[end] * tangential;
        fbar_(sample, 1) += hat[end] * normal;
        if (s.phase == Phase::Stick) {
          beta[end] += hat[end] * kt;
          continue;
        }
        for (int k = 0; k < 4; ++k) {
          alpha[end][0][k] += hat[end] * kt * H[k];
          if (s.phase == Phase::Slip) alpha[end][0][4 + k] -= hat[end] * slipLimit * kn * H[k];
          else alpha[end][1][4 + k] += hat[end] * kn * H[k];
        }
      }
    }
    if (dz && dfbar_[0].size() != 0 && s.phase == Phase::Stick) {
      dfbar_[0].col(i).noalias() += beta[0] * *dz;
      dfbar_[0].col(j).noalias() += beta[1] * *dz;
    }
  }

  const FrictionContactParameters& p_;
  const int N_, nc_;
  const double h_;
  Eigen::MatrixXd values_, slopes_;  // N x 2 (t, n): the samples and their slopes per interval
  Eigen::MatrixXd fbar_;             // N x 2
  Eigen::MatrixXd Et_, hEdT_;        // nc x N: E^T and h (E D)^T
  std::array<Eigen::MatrixXd, 2> dfbar_;
};

bool sameState(const SliderState& a, const SliderState& b, double settled) {
  if (a.phase != b.phase) return false;
  if (a.phase == Phase::Slip) return a.direction == b.direction;
  return a.phase == Phase::Open || std::abs(a.z - b.z) <= settled;
}

}  // namespace

void assembleFromRemainders(const Aft& aft, const Eigen::MatrixXd& W, const Eigen::VectorXd& stiffness, double preload,
                            const Eigen::MatrixXd& remainders, const std::vector<const Eigen::MatrixXd*>& sensitivities,
                            Eigen::MatrixXd& F, Eigen::MatrixXd* jacobian) {
  const int nc = aft.numCoefficients(), N = aft.numSamples(), d = int(W.cols());
  // The hat's spectral factor: a harmonic h sampled through hat integrals is scaled
  // by sinc^2(pi h / N).
  Eigen::VectorXd unhat(nc);
  for (int h : aft.harmonics().harmonics()) {
    const double x = pi * h / N, factor = h == 0 ? 1 : std::pow(x / std::sin(x), 2);
    unhat(aft.harmonics().cosIndex(h)) = factor;
    if (h > 0) unhat(aft.harmonics().sinIndex(h)) = factor;
  }
  F.resize(nc, d);
  Eigen::VectorXd r(nc);
  for (int c = 0; c < d; ++c) {
    aft.toFrequency(remainders.col(c).data(), r.data());
    F.col(c) = stiffness(c) * W.col(c) - unhat.cwiseProduct(r);
  }
  if (aft.harmonics().contains(0)) F(aft.harmonics().cosIndex(0), d - 1) += preload;
  if (!jacobian) return;
  jacobian->resize(d * nc, d * nc);
  for (int c = 0; c < d; ++c) {
    jacobian->middleRows(c * nc, nc).noalias() = (-unhat).asDiagonal() * (aft.coefficientsFromTime() * sensitivities[c]->transpose());
    jacobian->block(c * nc, c * nc, nc, nc).diagonal().array() += stiffness(c);
  }
}

bool locatedFrictionForce(const FrictionContactParameters& p, const Aft& aft, const Eigen::MatrixXd& W,
                          Eigen::MatrixXd& F, Eigen::MatrixXd* jacobian) {
  IntervalMarch march(p, aft, W, jacobian != nullptr);
  double scale = p.mu * std::abs(p.preload) / p.kt;
  scale = std::max(scale, W.cwiseAbs().maxCoeff());
  const double settled = 1e-14 * std::max(scale, 1e-300);
  SliderState s = march.initialState();
  Eigen::VectorXd dz;
  if (jacobian) dz.setZero(march.m());
  // A slip or a lift-off erases the 1D slider's memory, so the state at the period's
  // start repeats after the first period, or it never slips (stuck throughout).
  bool periodic = false;
  for (int k = 0; k < 4 && !periodic; ++k) {
    const SliderState start = s;
    march.period(s, jacobian ? &dz : nullptr, false);
    periodic = sameState(s, start, settled);
  }
  march.period(s, jacobian ? &dz : nullptr, true);
  assembleFromRemainders(aft, W, Eigen::Vector2d(p.mu == 0 ? 0.0 : p.kt, p.kn), p.preload, march.integrals(),
                         {&march.integralSensitivities(0), &march.integralSensitivities(1)}, F, jacobian);
  return periodic;
}

}  // namespace cyclone::hbm::detail
