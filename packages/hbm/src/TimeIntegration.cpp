#include "cyclone/hbm/TimeIntegration.hpp"

#include <cmath>

#include "cyclone/core/Error.hpp"

namespace cyclone::hbm {

namespace {

// Newmark's average acceleration (beta 1/4, gamma 1/2) of M x'' + C x' + K x + the
// elements' forces = f(t), the elements marched by their incremental laws.
class NewmarkMarch {
public:
  NewmarkMarch(const HarmonicBalanceSystem& sys, double omega, const TimeIntegrationOptions& o)
      : sys_(sys), o_(o), omega_(omega), n_(sys.numDofs()), nc_(sys.numCoefficients()),
        load_(o.excitationScale * sys.excitation() + sys.staticLoad()) {
    for (const auto& c : sys.elements()) state_.push_back(c.element->initialState());
  }
  // Values (or time derivatives) at time t of a coefficient vector (X's layout).
  Eigen::VectorXd evaluate(const Eigen::VectorXd& X, double t, bool derivative) const {
    const auto& H = sys_.aft().harmonics();
    Eigen::VectorXd v = Eigen::VectorXd::Zero(n_);
    for (int d = 0; d < n_; ++d)
      for (int h : H.harmonics()) {
        if (h == 0) {
          if (!derivative) v(d) += X(d * nc_ + H.cosIndex(0));
          continue;
        }
        const double c = X(d * nc_ + H.cosIndex(h)), s = X(d * nc_ + H.sinIndex(h)), p = h * omega_ * t;
        v(d) += derivative ? h * omega_ * (-c * std::sin(p) + s * std::cos(p)) : c * std::cos(p) + s * std::sin(p);
      }
    return v;
  }
  // The state from X0 at t = 0, the elements relaxed, with a consistent acceleration.
  void start(const Eigen::VectorXd& X0) {
    x_ = evaluate(X0, 0, false), v_ = evaluate(X0, 0, true);
    auto s0 = state_;
    a_ = sys_.M().partialPivLu().solve(evaluate(load_, 0, false) - internal(x_, v_, s0, nullptr, nullptr));
  }
  // One step of dt to time tn, Newton on the new acceleration.
  void step(double tn, double dt) {
    const double beta = 0.25, gamma = 0.5;
    const Eigen::VectorXd fext = evaluate(load_, tn, false);
    Eigen::VectorXd an = a_;
    for (int it = 0;; ++it) {
      const Eigen::VectorXd xn = x_ + dt * v_ + dt * dt * ((0.5 - beta) * a_ + beta * an);
      const Eigen::VectorXd vn = v_ + dt * ((1 - gamma) * a_ + gamma * an);
      auto trialState = state_;
      Eigen::MatrixXd Kt, Ct;
      const Eigen::VectorXd r = sys_.M() * an + internal(xn, vn, trialState, &Kt, &Ct) - fext;
      if (r.norm() <= o_.newtonTolerance * std::max(1.0, fext.norm()) || it >= o_.maxNewtonIterations) {
        if (it >= o_.maxNewtonIterations && r.norm() > 1e-6 * std::max(1.0, fext.norm()))
          throw SolverError("time integration: Newton did not converge in a step (residual " + std::to_string(r.norm()) +
                            ")");
        x_ = xn, v_ = vn, a_ = an, state_ = std::move(trialState);
        return;
      }
      an -= (sys_.M() + gamma * dt * Ct + beta * dt * dt * Kt).partialPivLu().solve(r);
    }
  }
  const Eigen::VectorXd& x() const { return x_; }

private:
  // The internal force with its tangents (the elements' states in st advanced).
  Eigen::VectorXd internal(const Eigen::VectorXd& xx, const Eigen::VectorXd& vv, std::vector<Eigen::VectorXd>& st,
                           Eigen::MatrixXd* Kt, Eigen::MatrixXd* Ct) const {
    Eigen::VectorXd f = sys_.K() * xx + sys_.C() * vv;
    if (Kt) *Kt = sys_.K(), *Ct = sys_.C();
    Eigen::MatrixXd dfdw, dfdv;
    const auto& elements = sys_.elements();
    for (std::size_t e = 0; e < elements.size(); ++e) {
      const auto& W = elements[e].W;
      const Eigen::VectorXd fe =
          elements[e].element->incremental(W.transpose() * xx, W.transpose() * vv, st[e], dfdw, dfdv);
      f += W * fe;
      if (Kt) *Kt += W * dfdw * W.transpose(), *Ct += W * dfdv * W.transpose();
    }
    return f;
  }

  const HarmonicBalanceSystem& sys_;
  const TimeIntegrationOptions& o_;
  const double omega_;
  const int n_, nc_;
  const Eigen::VectorXd load_;
  std::vector<Eigen::VectorXd> state_;
  Eigen::VectorXd x_, v_, a_;
};

}  // namespace

SteadyState integrateToSteadyState(const HarmonicBalanceSystem& sys, double omega, const Eigen::VectorXd& X0,
                                   const TimeIntegrationOptions& o) {
  if (sys.isCyclic())
    throw InputError("time integration", "integrates a lone system; expand a cyclic sector to its full ring first");
  const int n = sys.numDofs(), nc = sys.numCoefficients();
  const int N = o.stepsPerPeriod;
  const Aft aft(sys.aft().harmonics(), N);  // the last period's samples -> coefficients
  const double T = 2 * M_PI / omega, dt = T / N;
  NewmarkMarch march(sys, omega, o);
  march.start(X0);
  SteadyState out;
  Eigen::MatrixXd previous(n, N), current(n, N);
  double t = 0;
  for (int period = 0; period < o.maxPeriods; ++period) {
    for (int k = 0; k < N; ++k) {
      t += dt;
      march.step(t, dt);
      current.col(k) = march.x();
    }
    if (period > 0) {
      const double scale = std::max(current.cwiseAbs().maxCoeff(), 1e-300);
      out.periodChange = (current - previous).cwiseAbs().maxCoeff() / scale;
      out.periods = period + 1;
      if (out.periodChange < o.periodTolerance) {
        out.converged = true;
        break;
      }
    }
    previous = current;
  }
  // The samples at t = T/N .. T of the last period: shift to tau_k = 2 pi k / N.
  out.coefficients.resize(n * nc);
  Eigen::VectorXd samples(N);
  for (int d = 0; d < n; ++d) {
    for (int k = 0; k < N; ++k) samples((k + 1) % N) = current(d, k);
    out.coefficients.segment(d * nc, nc) = aft.toFrequency(samples);
  }
  return out;
}

}  // namespace cyclone::hbm
