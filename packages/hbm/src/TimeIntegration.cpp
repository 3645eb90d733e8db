#include "cyclone/hbm/TimeIntegration.hpp"

#include <cmath>

#include "cyclone/core/Error.hpp"

namespace cyclone::hbm {

SteadyState integrateToSteadyState(const HarmonicBalanceSystem& sys, double omega, const Eigen::VectorXd& X0,
                                   const TimeIntegrationOptions& o) {
  if (sys.isCyclic())
    throw InputError("time integration", "integrates a lone system; expand a cyclic sector to its full ring first");
  const int n = sys.numDofs(), nc = sys.numCoefficients();
  const auto& H = sys.aft().harmonics();
  const int N = o.stepsPerPeriod;
  const Aft aft(H, N);  // the last period's samples -> coefficients
  const double T = 2 * M_PI / omega, dt = T / N, beta = 0.25, gamma = 0.5;

  // f(t) and the initial state from coefficient vectors.
  auto evaluate = [&](const Eigen::VectorXd& X, double t, bool derivative) {
    Eigen::VectorXd v = Eigen::VectorXd::Zero(n);
    for (int d = 0; d < n; ++d)
      for (int h : H.harmonics()) {
        if (h == 0) {
          if (!derivative) v(d) += X(d * nc + H.cosIndex(0));
          continue;
        }
        const double c = X(d * nc + H.cosIndex(h)), s = X(d * nc + H.sinIndex(h)), p = h * omega * t;
        v(d) += derivative ? h * omega * (-c * std::sin(p) + s * std::cos(p)) : c * std::cos(p) + s * std::sin(p);
      }
    return v;
  };
  const Eigen::VectorXd load = o.excitationScale * sys.excitation() + sys.staticLoad();
  const auto& elements = sys.elements();
  std::vector<Eigen::VectorXd> state, trialState;
  for (const auto& c : elements) state.push_back(c.element->initialState());
  trialState = state;
  Eigen::VectorXd x = evaluate(X0, 0, false), v = evaluate(X0, 0, true);

  // Consistent initial acceleration and the internal force with tangents.
  auto internal = [&](const Eigen::VectorXd& xx, const Eigen::VectorXd& vv, std::vector<Eigen::VectorXd>& st,
                      Eigen::MatrixXd* Kt, Eigen::MatrixXd* Ct) {
    Eigen::VectorXd f = sys.K() * xx + sys.C() * vv;
    if (Kt) *Kt = sys.K(), *Ct = sys.C();
    Eigen::MatrixXd dfdw, dfdv;
    for (std::size_t e = 0; e < elements.size(); ++e) {
      const auto& W = elements[e].W;
      const Eigen::VectorXd fe =
          elements[e].element->incremental(W.transpose() * xx, W.transpose() * vv, st[e], dfdw, dfdv);
      f += W * fe;
      if (Kt) *Kt += W * dfdw * W.transpose(), *Ct += W * dfdv * W.transpose();
    }
    return f;
  };
  const auto Mlu = sys.M().partialPivLu();
  {
    auto s0 = state;
    Eigen::VectorXd a0 = Mlu.solve(evaluate(load, 0, false) - internal(x, v, s0, nullptr, nullptr));
    x = x;  // (state from X0; the elements start relaxed)
    SteadyState out;
    Eigen::VectorXd a = a0;
    Eigen::MatrixXd previous(n, N), current(n, N);
    double t = 0;
    for (int period = 0; period < o.maxPeriods; ++period) {
      for (int k = 0; k < N; ++k) {
        const double tn = t + dt;
        const Eigen::VectorXd fext = evaluate(load, tn, false);
        Eigen::VectorXd an = a;  // Newton on the new acceleration
        for (int it = 0;; ++it) {
          const Eigen::VectorXd xn = x + dt * v + dt * dt * ((0.5 - beta) * a + beta * an);
          const Eigen::VectorXd vn = v + dt * ((1 - gamma) * a + gamma * an);
          trialState = state;
          Eigen::MatrixXd Kt, Ct;
          const Eigen::VectorXd r = sys.M() * an + internal(xn, vn, trialState, &Kt, &Ct) - fext;
          if (r.norm() <= o.newtonTolerance * std::max(1.0, fext.norm()) || it >= o.maxNewtonIterations) {
            if (it >= o.maxNewtonIterations && r.norm() > 1e-6 * std::max(1.0, fext.norm()))
              throw SolverError("time integration: Newton did not converge in a step (residual " +
                                std::to_string(r.norm()) + ")");
            x = xn, v = vn, a = an, state = trialState;
            break;
          }
          an -= (sys.M() + gamma * dt * Ct + beta * dt * dt * Kt).partialPivLu().solve(r);
        }
        t = tn;
        current.col(k) = x;
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
}

}  // namespace cyclone::hbm
