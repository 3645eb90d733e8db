#include "cyclone/hbm/FrictionContact.hpp"

#include <atomic>
#include <cmath>
#include <memory>
#include <string>

#include "LocatedFrictionForce.hpp"
#include "StuckSliderState.hpp"
#include "cyclone/core/Error.hpp"

namespace cyclone::hbm {

FrictionContact::FrictionContact(const FrictionContactParameters& p) : p_(p) {
  auto bad = [](const std::string& what) { throw InputError("friction contact", what); };
  if (p.tangentialDirections != 1 && p.tangentialDirections != 2)
    bad("tangential directions must be 1 (2D contact) or 2 (3D contact), got " + std::to_string(p.tangentialDirections));
  if (!(std::isfinite(p.kt) && p.kt > 0)) bad("kt must be positive, got " + std::to_string(p.kt));
  if (!(std::isfinite(p.kn) && p.kn >= 0)) bad("kn must be >= 0, got " + std::to_string(p.kn));
  if (!(std::isfinite(p.mu) && p.mu >= 0)) bad("mu must be >= 0, got " + std::to_string(p.mu));
  if (!std::isfinite(p.preload)) bad("preload must be finite");
  if (p.kn == 0 && !(p.preload > 0))
    bad("with kn = 0 the normal load is the constant preload, which must then be positive (got " +
        std::to_string(p.preload) + ")");
}

namespace {

std::atomic<long> unsettled{0};  // FrictionContact::unsettledEvaluations()

// One step of the contact law (return mapping). Inputs: tangential w_t, normal
// approach n, slider z (updated). Outputs the force [f_t, f_n] and, if asked,
// its sensitivities: with dwt (dt x m), dn (1 x m) and dz (dt x m) the
// sensitivities of the inputs to m parameters, df (d x m) and the updated dz;
// dTrial (dt x m) is work. Called per time sample and contact: nothing is allocated
// (the tangential vectors have at most 2 entries, stored inside).
struct StepSensitivity {
  const Eigen::MatrixXd* dwt;
  const Eigen::RowVectorXd* dn;
  Eigen::MatrixXd* dz;
  Eigen::MatrixXd* df;
  Eigen::MatrixXd* dTrial;
};

using Tangential = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 2, 1>;

void contactStep(const FrictionContactParameters& p, const Eigen::Ref<const Eigen::VectorXd>& wt, double n, Eigen::VectorXd& z,
                 Eigen::VectorXd& f, StepSensitivity* s) {
  const int dt = p.tangentialDirections;
  const double normal = p.preload + p.kn * n;
  f.setZero(dt + 1);
  if (s) s->df->setZero();
  if (normal <= 0) {  // open: no force, the slider follows the surface
    z = wt;
    if (s) *s->dz = *s->dwt;
    return;
  }
  f(dt) = normal;
  if (s) s->df->row(dt) = p.kn * *s->dn;
  if (p.mu == 0) {  // frictionless: the tangential spring never holds
    z = wt;
    if (s) *s->dz = *s->dwt;
    return;
  }
  const Tangential trial = p.kt * (wt - z);
  const double t = trial.norm(), limit = p.mu * normal;
  if (t <= limit) {  // stick
    f.head(dt) = trial;
    if (s) s->df->topRows(dt) = p.kt * (*s->dwt - *s->dz);
    return;
  }
  const Tangential u = trial / t;  // slip along the trial force (circular limit)
  f.head(dt) = limit * u;
  if (s) {
    // df_t = mu kn u dn + (limit / t) (I - u u^T) kt (dwt - dz)
    Eigen::MatrixXd& dTrial = *s->dTrial;
    Eigen::MatrixXd& df = *s->df;
    dTrial = p.kt * (*s->dwt - *s->dz);
    const double a = limit / t, b = p.mu * p.kn;
    for (int r = 0; r < dt; ++r) {
      df.row(r) = (b * u(r)) * *s->dn + a * dTrial.row(r);
      for (int k = 0; k < dt; ++k) df.row(r) -= (a * u(r) * u(k)) * dTrial.row(k);
    }
  }
  z = wt - f.head(dt) / p.kt;
  if (s) *s->dz = *s->dwt - s->df->topRows(dt) / p.kt;
}

}  // namespace

bool FrictionContact::stuckThroughout(const Aft& aft, const Eigen::MatrixXd& w, Eigen::MatrixXd& f,
                                      Eigen::MatrixXd* jacobian) const {
  // 1D: the march itself projects the relaxed slider onto the stuck interval.
  if (p_.tangentialDirections != 2 || p_.mu == 0) return false;
  const int N = aft.numSamples(), nc = aft.numCoefficients();
  const Eigen::VectorXd normal = (p_.preload + p_.kn * w.col(2).array()).matrix();
  if (normal.minCoeff() <= 0) return false;  // opening resets the slider: the march is unique
  const Eigen::Matrix2Xd centres = w.leftCols(2).transpose();
  const Eigen::VectorXd radii = p_.mu / p_.kt * normal;
  const detail::StuckSliderState stuck = detail::nearestStuckState(centres, radii);
  if (!stuck.feasible) return false;
  for (int i = 0; i < N; ++i) {
    f(i, 0) = p_.kt * (w(i, 0) - stuck.z(0));
    f(i, 1) = p_.kt * (w(i, 1) - stuck.z(1));
    f(i, 2) = normal(i);
  }
  if (!jacobian) return true;
  // dz/dvec(W) (2 x 3nc) from the active disks: z = c - r u on one circle, or
  // the crossing of two, (z - c_a) . (dz - dc_a) = r_a dr_a for each.
  const Eigen::MatrixXd& E = aft.timeFromCoefficients();
  const Eigen::MatrixXd& P = aft.coefficientsFromTime();
  const int m = 3 * nc;
  auto dCentre = [&](int i) {
    Eigen::MatrixXd dc = Eigen::MatrixXd::Zero(2, m);
    dc.block(0, 0, 1, nc) = E.row(i), dc.block(1, nc, 1, nc) = E.row(i);
    return dc;
  };
  auto dRadius = [&](int i) {
    Eigen::RowVectorXd dr = Eigen::RowVectorXd::Zero(m);
    dr.segment(2 * nc, nc) = (p_.mu * p_.kn / p_.kt) * E.row(i);
    return dr;
  };
  Eigen::MatrixXd dz = Eigen::MatrixXd::Zero(2, m);
  if (stuck.active.size() == 1) {
    const int i = stuck.active[0];
    const Eigen::Vector2d c = centres.col(i), u = c.normalized();
    const Eigen::MatrixXd dc = dCentre(i);
    dz = dc - u * dRadius(i) - (radii(i) / c.norm()) * (Eigen::Matrix2d::Identity() - u * u.transpose()) * dc;
  } else if (stuck.active.size() == 2) {
    Eigen::Matrix2d A;
    Eigen::MatrixXd b(2, m);
    for (int k = 0; k < 2; ++k) {
      const int i = stuck.active[k];
      const Eigen::Vector2d g = stuck.z - centres.col(i);
      A.row(k) = g.transpose();
      b.row(k) = radii(i) * dRadius(i) + g.transpose() * dCentre(i);
    }
    dz = A.partialPivLu().solve(b);
  }
  jacobian->setZero(m, m);
  for (int c = 0; c < 2; ++c) {  // f_t = kt (w_t - z): P E = I for the w_t part
    jacobian->block(c * nc, c * nc, nc, nc) = p_.kt * Eigen::MatrixXd::Identity(nc, nc);
    jacobian->middleRows(c * nc, nc) -= (p_.kt * P.rowwise().sum()) * dz.row(c);
  }
  jacobian->block(2 * nc, 2 * nc, nc, nc) = p_.kn * Eigen::MatrixXd::Identity(nc, nc);
  return true;
}

long FrictionContact::unsettledEvaluations() { return unsettled.load(); }

void FrictionContact::harmonicForce(const Aft& aft, const Eigen::MatrixXd& W, double, Eigen::MatrixXd& F,
                                    Eigen::MatrixXd* jacobian) const {
  if (p_.tangentialDirections == 1) {
    if (W.rows() != aft.numCoefficients() || W.cols() != 2)
      throw InputError("friction contact", "expected " + std::to_string(aft.numCoefficients()) +
                                               " x 2 coefficients, got " + std::to_string(W.rows()) + " x " +
                                               std::to_string(W.cols()));
    if (!detail::locatedFrictionForce(p_, aft, W, F, jacobian)) ++unsettled;
    return;
  }
  Eigen::MatrixXd w, f;
  sampledForce(aft, W, w, f, jacobian);
  F.resize(aft.numCoefficients(), dimension());
  for (int c = 0; c < dimension(); ++c) aft.toFrequency(f.col(c).data(), F.col(c).data());
}

Eigen::MatrixXd FrictionContact::forceSamples(const Aft& aft, const Eigen::MatrixXd& W, double) const {
  Eigen::MatrixXd w, f;
  sampledForce(aft, W, w, f, nullptr);
  return f;
}

namespace {

// One contact's slider marched through periods of the motion w (N x d samples), with
// its sensitivities: d/dvec(W) of the coefficients (m = nc d columns) and d/d(the
// period's starting slider state); when recording, the force samples and the
// coefficient Jacobian.
class PeriodMarch {
public:
  PeriodMarch(const FrictionContactParameters& p, const Aft& aft, const Eigen::MatrixXd& w, Eigen::MatrixXd& f,
              Eigen::MatrixXd* jacobian)
      : p_(p), aft_(aft), E_(aft.timeFromCoefficients()), w_(w), f_(f), jacobian_(jacobian),
        N_(aft.numSamples()), nc_(aft.numCoefficients()), d_(int(w.cols())), dt_(p.tangentialDirections) {}
  int m() const { return nc_ * d_; }

  // One period from the slider state z (updated). With dz, the sensitivities are
  // carried through it: its first wCols columns d/dvec(W) (0 or m), the others
  // d/d(the period's starting slider). Recording with sensitivities keeps the force
  // samples' sensitivities to W (and to the starting slider when dz has those columns)
  // for coefficientJacobian.
  void period(Eigen::VectorXd& z, Eigen::MatrixXd* dz, int wCols, bool record) {
    StepSensitivity sens{&dwt_, &dn_, dz, &df_, &dTrial_};
    if (dz) dwt_.setZero(dt_, dz->cols()), dn_.setZero(dz->cols()), df_.setZero(d_, dz->cols());
    if (dz) dTrial_.resize(dt_, dz->cols());
    const int startCols = dz && record ? int(dz->cols()) - m() : 0;  // d/d(starting slider) columns
    if (record && jacobian_) dfSamples_.resize(N_, d_ * m()), dfStart_.resize(N_, d_ * startCols);
    fi_.resize(d_), wt_.resize(dt_);
    auto& fi = fi_;
    auto& wt = wt_;
    for (int i = 0; i < N_; ++i) {
      wt = w_.row(i).head(dt_).transpose();
      if (dz && wCols > 0) {
        for (int c = 0; c < dt_; ++c) dwt_.block(c, c * nc_, 1, nc_) = E_.row(i);
        dn_.segment(dt_ * nc_, nc_) = E_.row(i);
      }
      contactStep(p_, wt, w_(i, dt_), z, fi, dz ? &sens : nullptr);
      if (!record) continue;
      f_.row(i) = fi.transpose();
      if (jacobian_)
        for (int c = 0; c < d_; ++c) {
          dfSamples_.block(i, c * m(), 1, m()) = df_.row(c).head(m());
          if (startCols > 0) dfStart_.block(i, c * startCols, 1, startCols) = df_.row(c).tail(startCols);
        }
    }
  }

  // The recorded period's coefficient Jacobian into *jacobian, the slider's start moving
  // with W as dzStart (dt x m; empty: the recorded sensitivities hold it already): P times
  // the sampled force sensitivities, by an FFT per sensitivity column (at H = 30 and 512
  // samples the dense product was about half of a contact's Jacobian time).
  void coefficientJacobian(const Eigen::MatrixXd& dzStart) {
    for (int c = 0; c < d_; ++c) {
      if (dzStart.size() != 0)
        dfSamples_.middleCols(c * m(), m()).noalias() += dfStart_.middleCols(c * dt_, dt_) * dzStart;
      aft_.toFrequencyColumns(dfSamples_.middleCols(c * m(), m()), jacobian_->middleRows(c * nc_, nc_));
    }
  }

  // The fixed point of the period map z -> Phi(z) from y, by Newton on its dt
  // unknowns: each step halved until it lowers the mismatch (the period map is only
  // piecewise smooth: a full step can cross a slip instant's switch and cycle), else
  // the march's own step. False after 50 steps.
  bool settle(Eigen::VectorXd& y, double settled) {
    const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(dt_, dt_);
    Eigen::MatrixXd dPhi(dt_, dt_);
    for (int iteration = 0; iteration < 50; ++iteration) {
      Eigen::VectorXd image = y;
      dPhi.setIdentity();
      period(image, &dPhi, 0, false);
      const Eigen::VectorXd r = image - y;
      if (r.norm() <= settled) {
        y = image;
        return true;
      }
      const Eigen::VectorXd step = (I - dPhi).fullPivLu().solve(r);
      bool lowered = false;
      for (double t = 1; t > 1e-3 && !lowered && step.allFinite(); t *= 0.5) {
        const Eigen::VectorXd trial = y + t * step;
        Eigen::VectorXd trialImage = trial;
        period(trialImage, nullptr, 0, false);
        if ((trialImage - trial).norm() < r.norm()) y = trial, lowered = true;
      }
      if (!lowered) y = image;
    }
    return false;
  }

  // The periodic slider's sensitivity by the implicit-function theorem,
  // dz*/dW = (I - dPhi/dz)^-1 dPhi/dW; where I - dPhi/dz is singular (a neutral
  // direction), the sensitivity marched over 200 periods instead.
  Eigen::MatrixXd sliderSensitivity(const Eigen::VectorXd& z) {
    const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(dt_, dt_);
    Eigen::MatrixXd sensitivity = Eigen::MatrixXd::Zero(dt_, m() + dt_);
    sensitivity.rightCols(dt_).setIdentity();
    Eigen::VectorXd image = z;
    period(image, &sensitivity, m(), false);
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(I - sensitivity.rightCols(dt_));
    Eigen::MatrixXd dz = lu.solve(sensitivity.leftCols(m()));
    if (!lu.isInvertible() || !dz.allFinite()) {
      dz.setZero(dt_, m());
      for (int k = 0; k < 200; ++k) period(image = z, &dz, m(), false);
    }
    return dz;
  }

private:
  const FrictionContactParameters& p_;
  const Aft& aft_;
  const Eigen::MatrixXd &E_, &w_;
  Eigen::MatrixXd& f_;
  Eigen::MatrixXd* jacobian_;
  const int N_, nc_, d_, dt_;
  Eigen::MatrixXd dwt_, df_, dTrial_;  // work: the step's sensitivities
  Eigen::MatrixXd dfSamples_;          // the recorded period's df, a row per sample
  Eigen::MatrixXd dfStart_;            // its sensitivity to the period's starting slider
  Eigen::RowVectorXd dn_;
  Eigen::VectorXd fi_, wt_;
};

}  // namespace

namespace {

// The slider's state z at the period's start that the period map returns to. Marching
// periods reaches it in one or two for 1D slip or an opening contact; circular slip in
// 3D contracts only geometrically, and near the onset of slip by a factor close to one
// per period, so a march of a bounded count would leave a state off the periodic one, a
// residual that jumps from point to point and Newton that cannot converge. There the
// fixed point of the period map is found by Newton (PeriodMarch::settle). False if it
// did not settle (z is then the last state reached).
bool periodicStart(const FrictionContactParameters& p, PeriodMarch& march, const Eigen::MatrixXd& w, Eigen::VectorXd& z) {
  const int d = int(w.cols()), dt = p.tangentialDirections, m = march.m();
  double scale = p.mu * std::abs(p.preload) / p.kt;
  for (int c = 0; c < d; ++c) scale = std::max(scale, w.col(c).cwiseAbs().maxCoeff());
  const double settled = 1e-14 * std::max(scale, 1e-300);
  z = Eigen::VectorXd::Zero(dt);
  const int marchedPeriods = 3;
  for (int k = 0; k < marchedPeriods; ++k) {
    const Eigen::VectorXd start = z;
    march.period(z, nullptr, m, false);
    if ((z - start).norm() <= settled) return true;
  }
  // Just past the onset of circular slip the march from the relaxed state creeps
  // (the slip per period vanishes there) and can end far from the periodic state,
  // which lies near the least violating slider position: a force that jumps
  // between nearby motions, a wall no Newton crosses. Start there first.
  if (dt == 2 && p.mu > 0) {
    const Eigen::VectorXd normal = (p.preload + p.kn * w.col(2).array()).matrix();
    if (normal.minCoeff() > 0) {
      Eigen::VectorXd y = detail::leastViolatingState(w.leftCols(2).transpose(), p.mu / p.kt * normal);
      if (march.settle(y, settled)) {
        z = y;
        return true;
      }
    }
  }
  return march.settle(z, settled);
}

// The 3D contact's Jacobian (d = 3, dt = 2) as its tangent per sample (ElementLinearization): each step
// of the recorded period maps the motion's and the slider's perturbations [dw_i; dz_i-1]
// linearly to [df_i; dz_i], a (d + dt) square matrix read off contactStep itself (so the
// products are the formed Jacobian's to rounding); the period's start moves with W as
// dz_0 = (I - Phi_z)^-1 Phi_W dW (the fixed point of the period map, as sampledForce).
class ContactTangent final : public ElementLinearization {
public:
  ContactTangent(const FrictionContactParameters& p, const Aft& aft, const Eigen::MatrixXd& w, Eigen::VectorXd z)
      : aft_(aft), N_(aft.numSamples()), nc_(aft.numCoefficients()), d_(3), dt_(2) {
    const int s = d_ + dt_;
    steps_.resize(s, s * N_);
    Eigen::MatrixXd dwt = Eigen::MatrixXd::Zero(dt_, s), dz(dt_, s), df(d_, s), dTrial(dt_, s);
    dwt.leftCols(dt_).setIdentity();
    Eigen::RowVectorXd dn = Eigen::RowVectorXd::Zero(s);
    dn(dt_) = 1;
    StepSensitivity sens{&dwt, &dn, &dz, &df, &dTrial};
    // Work made once: the march over the samples allocates nothing.
    Eigen::Matrix2d phi = Eigen::Matrix2d::Identity(), Zz;
    Eigen::VectorXd fi(d_), wt(dt_);
    for (int i = 0; i < N_; ++i) {
      dz.setZero();
      dz.rightCols(dt_).setIdentity();
      wt = w.row(i).head(dt_).transpose();
      contactStep(p, wt, w(i, dt_), z, fi, &sens);
      auto S = step(i);
      S.topRows(d_) = df;
      S.bottomRows(dt_) = dz;
      Zz = dz.rightCols<2>();
      phi = (Zz * phi).eval();
    }
    start_.compute(Eigen::Matrix2d::Identity() - phi);
    w_.resize(N_, d_), f_.resize(N_, d_);
  }
  // Whether the period's start is an isolated fixed point (I - Phi_z invertible); where
  // it is not, the formed Jacobian's march over periods is used instead.
  bool isolated() const { return start_.isInvertible(); }

  void apply(const Eigen::MatrixXd& dW, Eigen::MatrixXd& dF) const override {
    for (int c = 0; c < 3; ++c) aft_.toTime(dW.col(c).data(), w_.col(c).data());
    Eigen::Matrix<double, 5, 1> in, out;
    Eigen::Vector2d dz = Eigen::Vector2d::Zero();
    for (int i = 0; i < N_; ++i) {  // the period's end from a fixed start: Phi_W dW
      in << w_(i, 0), w_(i, 1), w_(i, 2), dz;
      dz.noalias() = step(i).bottomRows<2>() * in;
    }
    dz = start_.solve(dz);
    for (int i = 0; i < N_; ++i) {
      in << w_(i, 0), w_(i, 1), w_(i, 2), dz;
      out.noalias() = step(i) * in;
      f_(i, 0) = out(0), f_(i, 1) = out(1), f_(i, 2) = out(2);
      dz = out.tail<2>();
    }
    dF.resize(nc_, 3);
    for (int c = 0; c < 3; ++c) aft_.toFrequency(f_.col(c).data(), dF.col(c).data());
  }

  Eigen::MatrixXd harmonicBlock(const std::vector<int>& slots) const override {
    const int m = int(slots.size());
    const Eigen::MatrixXd &E = aft_.timeFromCoefficients(), &P = aft_.coefficientsFromTime();
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(d_ * m, d_ * m);
    for (int i = 0; i < N_; ++i) {
      const auto T = step(i).topLeftCorner(d_, d_);
      for (int k = 0; k < d_; ++k)
        for (int l = 0; l < d_; ++l) {
          if (T(k, l) == 0) continue;
          for (int r = 0; r < m; ++r)
            for (int q = 0; q < m; ++q) B(k * m + r, l * m + q) += P(slots[r], i) * T(k, l) * E(i, slots[q]);
        }
    }
    return B;
  }

private:
  // Sample i's step matrix: contiguous, columns 5 i .. of steps_.
  using Step = Eigen::Matrix<double, 5, 5>;
  Eigen::Map<const Step> step(int i) const { return Eigen::Map<const Step>(steps_.data() + Eigen::Index(i) * 25); }
  Eigen::Map<Step> step(int i) { return Eigen::Map<Step>(steps_.data() + Eigen::Index(i) * 25); }

  const Aft& aft_;
  const int N_, nc_, d_, dt_;
  Eigen::MatrixXd steps_;  // sample i's step matrix in columns i (d + dt) ..
  Eigen::FullPivLU<Eigen::Matrix2d> start_;
  mutable Eigen::MatrixXd w_, f_;  // apply()'s samples of the direction and of its force
};

}  // namespace

std::unique_ptr<ElementLinearization> FrictionContact::linearization(const Aft& aft, const Eigen::MatrixXd& W,
                                                                     double) const {
  // The 2D contact's located law keeps its formed Jacobian.
  if (p_.tangentialDirections != 2) return nullptr;
  const int N = aft.numSamples(), d = dimension();
  if (W.rows() != aft.numCoefficients() || W.cols() != d) return nullptr;  // harmonicForce names the mismatch
  Eigen::MatrixXd w(N, d), f(N, d);
  for (int c = 0; c < d; ++c) aft.toTime(W.col(c).data(), w.col(c).data());
  // Open all period, or stuck all period: the formed Jacobian has few nonzeros and is
  // held sparse (JacobianBlocks), cheaper than a march per product.
  if ((p_.preload + p_.kn * w.col(2).array()).maxCoeff() <= 0) return nullptr;
  if (stuckThroughout(aft, w, f, nullptr)) return nullptr;
  PeriodMarch march(p_, aft, w, f, nullptr);
  Eigen::VectorXd z;
  if (!periodicStart(p_, march, w, z)) return nullptr;  // the formed path reports it unsettled
  auto tangent = std::make_unique<ContactTangent>(p_, aft, w, z);
  if (!tangent->isolated()) return nullptr;
  return tangent;
}

void FrictionContact::sampledForce(const Aft& aft, const Eigen::MatrixXd& W, Eigen::MatrixXd& w, Eigen::MatrixXd& f,
                                   Eigen::MatrixXd* jacobian) const {
  const int N = aft.numSamples(), nc = aft.numCoefficients(), d = dimension(), dt = p_.tangentialDirections;
  if (W.rows() != nc || W.cols() != d)
    throw InputError("friction contact", "expected " + std::to_string(nc) + " x " + std::to_string(d) +
                                             " coefficients, got " + std::to_string(W.rows()) + " x " +
                                             std::to_string(W.cols()));
  w.resize(N, d), f.resize(N, d);
  for (int c = 0; c < d; ++c) aft.toTime(W.col(c).data(), w.col(c).data());
  if (stuckThroughout(aft, w, f, jacobian)) return;
  PeriodMarch march(p_, aft, w, f, jacobian);
  const int m = march.m();
  // Settle the hysteresis loop: the slider's state at the period's start must be
  // the one it returns to (periodicStart).
  Eigen::VectorXd z;
  if (!periodicStart(p_, march, w, z)) ++unsettled;
  if (jacobian) jacobian->setZero(m, m);
  if (!jacobian) {
    march.period(z, nullptr, m, true);
    return;
  }
  // The recorded period carries the sensitivities to W and to its starting slider at
  // once; the start is the period map's fixed point, so it moves with W as
  // dz*/dW = (I - dPhi/dz)^-1 dPhi/dW (implicit function), both read off this same
  // period's end: one period with sensitivities instead of one per marched period.
  Eigen::MatrixXd sensitivity = Eigen::MatrixXd::Zero(dt, m + dt);
  sensitivity.rightCols(dt).setIdentity();
  const Eigen::VectorXd start = z;
  march.period(z, &sensitivity, m, true);
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(Eigen::MatrixXd::Identity(dt, dt) - sensitivity.rightCols(dt));
  Eigen::MatrixXd dzStart = lu.solve(sensitivity.leftCols(m));
  if (!lu.isInvertible() || !dzStart.allFinite()) {
    // A neutral direction of the period map: the sensitivity marched over periods instead.
    z = start;
    dzStart = march.sliderSensitivity(z);
    march.period(z, &dzStart, m, true);
    dzStart.resize(0, 0);
  }
  march.coefficientJacobian(dzStart);
}

Eigen::MatrixXd FrictionContact::stiffestTangent() const {
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(dimension(), dimension());
  for (int t = 0; t < p_.tangentialDirections; ++t) k(t, t) = p_.kt;
  k(p_.tangentialDirections, p_.tangentialDirections) = p_.kn;
  return k;
}

Eigen::VectorXd FrictionContact::incremental(const Eigen::VectorXd& w, const Eigen::VectorXd&, Eigen::VectorXd& state,
                                             Eigen::MatrixXd& dfdw, Eigen::MatrixXd& dfdwdot) const {
  const int d = dimension(), dt = p_.tangentialDirections;
  Eigen::MatrixXd dwt = Eigen::MatrixXd::Zero(dt, d), dz = Eigen::MatrixXd::Zero(dt, d), df(d, d);
  dwt.leftCols(dt).setIdentity();
  Eigen::RowVectorXd dn = Eigen::RowVectorXd::Zero(d);
  dn(dt) = 1;
  Eigen::MatrixXd dTrial(dt, d);
  StepSensitivity sens{&dwt, &dn, &dz, &df, &dTrial};  // dz = 0: the committed state is fixed within the step
  Eigen::VectorXd f;
  contactStep(p_, w.head(dt), w(dt), state, f, &sens);
  dfdw = df;
  dfdwdot = Eigen::MatrixXd::Zero(d, d);
  return f;
}

// The force alone: contactStep without the sensitivities, no temporaries on the heap.
void FrictionContact::stepForce(const Eigen::VectorXd& w, const Eigen::VectorXd&, Eigen::VectorXd& state,
                                Eigen::VectorXd& f) const {
  const int dt = p_.tangentialDirections;
  contactStep(p_, w.head(dt), w(dt), state, f, nullptr);
}

std::shared_ptr<const NonlinearElement> FrictionContact::withParameter(const std::string& name, double value) const {
  FrictionContactParameters p = p_;
  if (name == "kt") p.kt = value;
  else if (name == "kn") p.kn = value;
  else if (name == "mu") p.mu = value;
  else if (name == "preload") p.preload = value;
  else if (name == "stiffness") p.kt = p.kn = value;  // a contact stiffness study's kn = kt
  else throw InputError("friction contact", "unknown parameter '" + name + "' (kt, kn, stiffness, mu, preload)");
  return std::make_shared<FrictionContact>(p);
}

}  // namespace cyclone::hbm
