#include "cyclone/hbm/TravellingWaveIntegration.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <numeric>
#include <string>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"

namespace cyclone::hbm {

namespace {
using cd = std::complex<double>;

// One integrated phase: its modes and where it sits in the ring.
struct Phase {
  long p = 0;
  double weight = 2;            // 1 for a real phase (p = 0 or N / 2): no conjugate partner
  Eigen::MatrixXcd U, Vt;       // Vt = V^T
  Eigen::VectorXd l, c;
  Eigen::VectorXcd factor;      // e^{-i 2 pi p j / N} per integrated sector j
};

// An element's coupling matrix as its nonzeros: what w = W^T x and f -= W fe touch.
struct Entry {
  int dof, coordinate;
  double value;
};
std::vector<Entry> nonzeros(const Eigen::MatrixXd& W) {
  std::vector<Entry> out;
  for (int c = 0; c < W.cols(); ++c)
    for (int a = 0; a < W.rows(); ++a)
      if (W(a, c) != 0) out.push_back({a, c, W(a, c)});
  return out;
}

std::vector<Phase> integratedPhases(const HarmonicBalanceSystem& sys, int sectorsIntegrated) {
  const int N = sys.cyclic().sectors, g = N / sectorsIntegrated;
  std::vector<Phase> out;
  for (long p = 0; 2 * p <= N; p += g) {
    const auto r = sys.receptance()->modalRealization(p);
    if (!r)
      throw InputError("time integration", "the model of phase index " + std::to_string(p) +
                                               " has no modal form: the time integration needs modes");
    const double scale = std::max(r->U.norm() * r->V.norm(), 1e-300);
    if (r->R.size() != 0 && r->R.norm() > 1e-12 * scale)
      throw InputError("time integration",
                       "the model of phase index " + std::to_string(p) +
                           " has a constant part (a static correction): its displacement would follow the contact "
                           "forces at the same instant; integrate its causal modal model (causalModalModel)");
    if (r->lossFactor != 0)
      throw InputError("time integration", "the model of phase index " + std::to_string(p) +
                                               " has structural damping, which has no causal time-domain form; "
                                               "integrate its viscous equivalent (causalModalModel)");
    Phase ph;
    ph.p = p;
    ph.weight = (2 * p) % N == 0 ? 1.0 : 2.0;
    ph.U = r->U;
    ph.Vt = r->V.transpose();
    ph.l = r->eigenvalues;
    ph.c = r->viscous.size() ? r->viscous : Eigen::VectorXd::Zero(r->numModes());
    if (ph.weight == 1.0 && (ph.U.imag().norm() > 1e-10 * ph.U.norm() || ph.Vt.imag().norm() > 1e-10 * ph.Vt.norm()))
      throw InputError("time integration", "the modes of the real phase " + std::to_string(p) + " are not real");
    ph.factor.resize(sectorsIntegrated);
    for (int j = 0; j < sectorsIntegrated; ++j) {
      const double a = -2 * M_PI * double(p) * double(j) / double(N);
      ph.factor(j) = cd(std::cos(a), std::sin(a));
    }
    out.push_back(std::move(ph));
  }
  return out;
}

// The largest frequency of the modes with every element at its stiffest (a friction
// contact stuck and closed, with or without a preload): the explicit step's limit.
double largestStuckFrequency(const HarmonicBalanceSystem& sys, const std::vector<Phase>& phases) {
  const int n = sys.numDofs(), N = sys.cyclic().sectors;
  double top = 0;
  for (const Phase& ph : phases) {
    const double a = 2 * M_PI * double(ph.p) / double(N);
    Eigen::MatrixXcd K = Eigen::MatrixXcd::Zero(n, n);
    for (const auto& conn : sys.elements()) {
      const Eigen::MatrixXd k = conn.element->stiffestTangent();
      Eigen::MatrixXcd B = conn.W.transpose().cast<cd>();  // w = B x~ for phase p's motion
      if (conn.Wnext.size()) B += cd(std::cos(a), -std::sin(a)) * conn.Wnext.transpose().cast<cd>();
      K.noalias() += B.adjoint() * k.cast<cd>() * B;
    }
    Eigen::MatrixXcd S = ph.Vt * K * ph.U;
    S.diagonal() += ph.l.cast<cd>();
    if (S.rows() == 0) continue;
    const Eigen::ComplexEigenSolver<Eigen::MatrixXcd> es(S, false);
    top = std::max(top, std::sqrt(es.eigenvalues().cwiseAbs().maxCoeff()));
  }
  return top;
}

int integratedSectors(const HarmonicBalanceSystem& sys) {
  if (!sys.isReceptance() || !sys.isCyclic())
    throw InputError("time integration", "the travelling-wave integration needs a cyclic system in receptance form");
  const int N = sys.cyclic().sectors;
  const int eo = int(((sys.cyclic().engineOrder % N) + N) % N);
  return N / std::gcd(eo, N);
}

}  // namespace

TravellingWaveState travellingWaveStart(const HarmonicBalanceSystem& sys, const Eigen::VectorXd& X, double omega,
                                        double excitationScale) {
  const int Ns = integratedSectors(sys);
  const std::vector<Phase> phases = integratedPhases(sys, Ns);
  const int n = sys.numDofs(), nc = sys.numCoefficients(), N = sys.cyclic().sectors;
  if (X.size() != sys.numUnknowns()) throw InputError("time integration", "the coefficients do not fit the system");
  Eigen::VectorXd Fnl;
  sys.nonlinearForces(X, omega, Fnl, nullptr);
  const Eigen::VectorXd F = excitationScale * sys.excitation() + sys.staticLoad() - Fnl;
  const HarmonicSet& H = sys.aft().harmonics();
  TravellingWaveState st;
  for (const Phase& ph : phases) {
    st.q.push_back(Eigen::VectorXcd::Zero(ph.l.size()));
    st.velocity.push_back(Eigen::VectorXcd::Zero(ph.l.size()));
  }
  // Phase p's modal part of a force f e^{i s t} (s = +-h w): D(s) V^T f e^{i s t}, D = 1 / (l + i c s - s^2).
  auto add = [&](std::size_t k, const Eigen::VectorXcd& f, double s) {
    const Phase& ph = phases[k];
    const Eigen::VectorXcd g = ph.Vt * f;
    for (Eigen::Index i = 0; i < g.size(); ++i) {
      const cd q = g(i) / cd(ph.l(i) - s * s, ph.c(i) * s);
      st.q[k](i) += q;
      st.velocity[k](i) += cd(0, s) * q;
    }
  };
  for (int h : H.harmonics()) {
    Eigen::VectorXcd Fh(n);
    for (int a = 0; a < n; ++a)
      Fh(a) = h == 0 ? cd(F(a * nc + H.cosIndex(0))) : cd(F(a * nc + H.cosIndex(h)), -F(a * nc + H.sinIndex(h)));
    const long p = sys.phaseIndex(h);
    for (std::size_t k = 0; k < phases.size(); ++k) {
      const long q = phases[k].p;
      if (h == 0) {
        if (q == 0) add(k, Fh, 0);
        continue;
      }
      // Harmonic h of sector j is Re(F_h e^{-i 2 pi p j / N} e^{i h w t}): half on phase p at
      // +h w, half (conjugate) on phase N - p at -h w; the integrated phase holds its own half.
      if (q == p) add(k, Fh / 2.0, h * omega);
      if ((N - q) % N == p) add(k, Fh.conjugate() / 2.0, -h * omega);
    }
  }
  for (const auto& conn : sys.elements())
    for (int j = 0; j < Ns; ++j) st.elementStates.push_back(conn.element->initialState());
  return st;
}

double TravellingWaveResponse::peak(int dof) const { return motion.col(dof).cwiseAbs().maxCoeff(); }

TravellingWaveResponse integrateTravellingWave(const HarmonicBalanceSystem& sys, double omega,
                                               const TravellingWaveOptions& opt, const TravellingWaveState* start) {
  const int Ns = integratedSectors(sys);
  if (!(omega > 0)) throw InputError("time integration", "the frequency must be > 0");
  if (opt.stepsPerPeriod < 8 || opt.maxPeriods < 2 || !(opt.tolerance > 0) || !(opt.amplitudeTolerance > 0) ||
      opt.window < 2)
    throw InputError("time integration",
                     "steps per period >= 8, periods >= 2, a window >= 2 and tolerances > 0 are needed");
  Timer timer;
  const int N = sys.cyclic().sectors, n = sys.numDofs();
  const std::vector<Phase> phases = integratedPhases(sys, Ns);
  for (int a : opt.steadyDofs)
    if (a < 0 || a >= n) throw InputError("time integration", "a DOF to watch is outside 0.." + std::to_string(n - 1));
  const auto& conns = sys.elements();
  const int ne = int(conns.size());

  // The excitation per DOF and harmonic (complex c - i s, delayed per sector) and the
  // constant loads; the elements' coupling by nonzeros.
  const HarmonicSet& H = sys.aft().harmonics();
  const int nc = sys.numCoefficients();
  struct Load {
    int dof, harmonic;
    Eigen::VectorXcd perSector;
  };
  std::vector<Load> loads;
  Eigen::VectorXd constant = Eigen::VectorXd::Zero(n);
  for (int a = 0; a < n; ++a)
    for (int h : H.harmonics()) {
      const double cs = opt.excitationScale * sys.excitation()(a * nc + H.cosIndex(h));
      if (h == 0) {
        constant(a) += cs + sys.staticLoad()(a * nc + H.cosIndex(0));
        continue;
      }
      const double sn = opt.excitationScale * sys.excitation()(a * nc + H.sinIndex(h));
      if (cs == 0 && sn == 0) continue;
      Load L{a, h, Eigen::VectorXcd(Ns)};
      for (int j = 0; j < Ns; ++j) {
        const double ang = -2 * M_PI * double(sys.phaseIndex(h)) * double(j) / double(N);
        L.perSector(j) = cd(cs, -sn) * cd(std::cos(ang), std::sin(ang));
      }
      loads.push_back(std::move(L));
    }
  std::vector<std::vector<Entry>> Wnz(ne), Wnextnz(ne);
  for (int e = 0; e < ne; ++e) {
    Wnz[e] = nonzeros(conns[e].W);
    if (conns[e].Wnext.size()) Wnextnz[e] = nonzeros(conns[e].Wnext);
  }

  const double period = 2 * M_PI / omega;
  const double wmax = largestStuckFrequency(sys, phases);
  int S = std::max(opt.stepsPerPeriod, int(std::ceil(period * wmax)));

  TravellingWaveResponse out;
  out.sectors = Ns;
  for (const Phase& ph : phases) out.modes += int(ph.l.size());
  for (int attempt = 0;; ++attempt) {
    const double dt = period / S;
    // State: per phase q_n and q_{n-1}; per element and sector the law's state and last w.
    const std::size_t np = phases.size();
    // qPrev is set at the first step, q(-dt) = q - dt v + dt^2 / 2 a with that step's
    // forces: second order, so a start on the periodic motion stays on it.
    std::vector<Eigen::VectorXcd> q(np), qPrev(np), v0(np), xt(np), ft(np), g(np);
    for (std::size_t k = 0; k < np; ++k) {
      const int m = int(phases[k].l.size());
      q[k] = Eigen::VectorXcd::Zero(m), qPrev[k] = Eigen::VectorXcd::Zero(m), v0[k] = Eigen::VectorXcd::Zero(m);
      if (start && start->q.size() == np && start->q[k].size() == m) q[k] = start->q[k], v0[k] = start->velocity[k];
      xt[k].resize(n), ft[k].resize(n), g[k].resize(m);
    }
    std::vector<Eigen::VectorXd> states(std::size_t(ne) * Ns), wLast(std::size_t(ne) * Ns);
    for (int e = 0; e < ne; ++e)
      for (int j = 0; j < Ns; ++j) {
        const std::size_t s = std::size_t(e) * Ns + j;
        const bool given = start && start->elementStates.size() == states.size();
        states[s] = given ? start->elementStates[s] : conns[e].element->initialState();
        wLast[s] = Eigen::VectorXd::Zero(conns[e].element->dimension());
      }
    Eigen::MatrixXd x(n, Ns), f(n, Ns), motion(S, n), last(S, n);
    Eigen::VectorXd w, wdot, fe;
    std::vector<cd> rotation(std::size_t(H.maxHarmonic()) + 1);
    double change = 0, lastChange = 0, estimate = 0, spread = 0;
    TravellingWaveResponse::Ending ending = TravellingWaveResponse::Ending::NotSteady;
    std::vector<int> watched = opt.steadyDofs;
    if (watched.empty())
      for (int a = 0; a < n; ++a) watched.push_back(a);
    // per DOF watched, the last `window` periods' max |x| (a ring buffer)
    Eigen::MatrixXd amplitudes(int(watched.size()), std::max(opt.window, 2));
    std::vector<double> history;
    bool diverged = false, converged = false;
    double nextReport = 10;
    int periods = 0;
    for (int k = 1; k <= opt.maxPeriods; ++k) {
      for (int s = 0; s < S; ++s) {
        const double t = s * dt;
        // The ring's motion from the phases.
        x.setZero();
        for (std::size_t k2 = 0; k2 < np; ++k2) {
          xt[k2].noalias() = phases[k2].U * q[k2];
          for (int j = 0; j < Ns; ++j) x.col(j) += phases[k2].weight * (phases[k2].factor(j) * xt[k2]).real();
        }
        motion.row(s) = x.col(0).transpose();
        // The forces on every sector: loads less the elements'.
        f.colwise() = constant;
        for (int h = 1; h <= H.maxHarmonic(); ++h) rotation[h] = cd(std::cos(h * omega * t), std::sin(h * omega * t));
        for (const Load& L : loads)
          for (int j = 0; j < Ns; ++j) f(L.dof, j) += (L.perSector(j) * rotation[L.harmonic]).real();
        for (int e = 0; e < ne; ++e) {
          const int d = conns[e].element->dimension();
          for (int j = 0; j < Ns; ++j) {
            const int jn = (j + 1) % Ns;
            w.setZero(d);
            for (const Entry& z : Wnz[e]) w(z.coordinate) += z.value * x(z.dof, j);
            for (const Entry& z : Wnextnz[e]) w(z.coordinate) += z.value * x(z.dof, jn);
            const std::size_t si = std::size_t(e) * Ns + j;
            wdot = (w - wLast[si]) / dt;
            wLast[si] = w;
            conns[e].element->stepForce(w, wdot, states[si], fe);
            for (const Entry& z : Wnz[e]) f(z.dof, j) -= z.value * fe(z.coordinate);
            for (const Entry& z : Wnextnz[e]) f(z.dof, jn) -= z.value * fe(z.coordinate);
          }
        }
        // Each phase's modes one central-difference step on.
        for (std::size_t k2 = 0; k2 < np; ++k2) {
          const Phase& ph = phases[k2];
          ft[k2].setZero();
          for (int j = 0; j < Ns; ++j) ft[k2] += std::conj(ph.factor(j)) * f.col(j).cast<cd>();
          ft[k2] /= double(Ns);
          g[k2].noalias() = ph.Vt * ft[k2];
          for (Eigen::Index i = 0; i < ph.l.size(); ++i) {
            if (k == 1 && s == 0)
              qPrev[k2](i) = q[k2](i) - dt * v0[k2](i) +
                             0.5 * dt * dt * (g[k2](i) - ph.c(i) * v0[k2](i) - ph.l(i) * q[k2](i));
            const double h2 = 0.5 * ph.c(i) * dt;
            const cd next = (dt * dt * g[k2](i) + (2 - dt * dt * ph.l(i)) * q[k2](i) - (1 - h2) * qPrev[k2](i)) / (1 + h2);
            qPrev[k2](i) = q[k2](i);
            q[k2](i) = next;
          }
        }
      }
      periods = k;
      if (!motion.allFinite() || motion.cwiseAbs().maxCoeff() > 1e12) {
        diverged = true;
        break;
      }
      history.push_back(motion.col(watched.front()).cwiseAbs().maxCoeff());
      if (k >= 2) {
        const double size = std::max(motion.cwiseAbs().maxCoeff(), 1e-300);
        change = (motion - last).cwiseAbs().maxCoeff() / size;
        const double ratio = lastChange > 0 ? change / lastChange : 1.0;
        estimate = ratio < 0.999 ? change * std::max(1.0, ratio / (1 - ratio)) : HUGE_VAL;
        if (change == 0) estimate = 0;
        lastChange = change;
        if (timer.seconds() > nextReport) {  // long runs show their progress
          nextReport += 10;
          log::info("time integration at " + std::to_string(omega / (2 * M_PI)) + " Hz: period " + std::to_string(k) +
                    ", change " + std::to_string(change) + ", max |x| of DOF " + std::to_string(watched.front()) +
                    " " + std::to_string(history.back()));
        }
        if (k >= 3 && estimate <= opt.tolerance) {
          converged = true;
          ending = TravellingWaveResponse::Ending::Periodic;
          break;
        }
      }
      const int W = int(amplitudes.cols());
      for (std::size_t a = 0; a < watched.size(); ++a)
        amplitudes(Eigen::Index(a), (k - 1) % W) = motion.col(watched[a]).cwiseAbs().maxCoeff();
      if (k >= W) {
        const double largest = std::max(amplitudes.maxCoeff(), 1e-300);
        spread = (amplitudes.rowwise().maxCoeff() - amplitudes.rowwise().minCoeff()).maxCoeff() / largest;
        if (spread <= opt.amplitudeTolerance) {
          converged = true;
          ending = TravellingWaveResponse::Ending::SteadyAmplitude;
          break;
        }
      }
      last = motion;
    }
    if (diverged) {
      if (attempt < 3) {
        S *= 2;  // the stuck estimate of the step's limit missed a stiffer state: halve the step
        continue;
      }
      throw Error("time integration: the motion grows without bound at " + std::to_string(S) +
                  " steps a period (the explicit step's limit from the stuck contacts: " +
                  std::to_string(int(std::ceil(period * wmax))) + ")");
    }
    out.motion = std::move(motion);
    out.stepsPerPeriod = S;
    out.periods = periods;
    out.periodChange = change;
    out.errorEstimate = estimate;
    out.converged = converged;
    out.ending = ending;
    out.amplitudeSpread = spread;
    out.amplitudeHistory = std::move(history);
    out.state.q = q;
    out.state.velocity.resize(np);
    for (std::size_t k = 0; k < np; ++k) out.state.velocity[k] = (q[k] - qPrev[k]) / dt;
    out.state.elementStates = std::move(states);
    break;
  }
  out.seconds = timer.seconds();
  return out;
}

}  // namespace cyclone::hbm
