#include "cyclone/mistuning/LumpedRing.hpp"

#include <cmath>
#include <string>

#include "cyclone/core/Error.hpp"

namespace cyclone::mistuning {

void LumpedRing::validate() const {
  if (blades < 3) throw InputError("blades", std::to_string(blades) + ": a ring needs at least 3");
  if (!(mass > 0)) throw InputError("mass", "must be positive");
  if (!(bladeStiffness > 0)) throw InputError("blade_stiffness", "must be positive");
  if (!(coupling >= 0)) throw InputError("coupling", "must be >= 0");
  if (!(lossFactor > 0)) throw InputError("loss_factor", "must be positive (an undamped resonance has no peak)");
  if (engineOrder < 0 || engineOrder >= blades)
    throw InputError("engine_order", std::to_string(engineOrder) + ": must lie in 0.." + std::to_string(blades - 1));
  if (!(std::isfinite(force) && force != 0)) throw InputError("force", "must be finite and not zero");
}

Eigen::VectorXcd ringResponse(const LumpedRing& ring, const std::vector<double>& delta, double omega) {
  ring.validate();
  const int N = ring.blades;
  if (int(delta.size()) != N)
    throw InputError("mistuning", "the pattern has " + std::to_string(delta.size()) + " deviations for " +
                                      std::to_string(N) + " blades");
  const std::complex<double> structural(1.0, ring.lossFactor);
  Eigen::MatrixXcd Z = Eigen::MatrixXcd::Zero(N, N);
  Eigen::VectorXcd f(N);
  const double phi = 2 * M_PI * ring.engineOrder / N;
  for (int n = 0; n < N; ++n) {
    if (!(delta[std::size_t(n)] > -1))
      throw InputError("mistuning", "blade " + std::to_string(n) + "'s deviation " + std::to_string(delta[std::size_t(n)]) +
                                        " makes its stiffness not positive (must be > -1)");
    const double kb = ring.bladeStiffness * (1 + delta[std::size_t(n)]);
    Z(n, n) = (kb + 2 * ring.coupling) * structural - omega * omega * ring.mass;
    Z(n, (n + 1) % N) -= ring.coupling * structural;
    Z(n, (n + N - 1) % N) -= ring.coupling * structural;
    f(n) = ring.force * std::polar(1.0, phi * n);
  }
  return Z.partialPivLu().solve(f);
}

double tunedAmplitude(const LumpedRing& ring, double omega) {
  ring.validate();
  const double phi = 2 * M_PI * ring.engineOrder / ring.blades;
  const std::complex<double> structural(1.0, ring.lossFactor);
  return std::abs(ring.force) /
         std::abs((ring.bladeStiffness + 2 * ring.coupling * (1 - std::cos(phi))) * structural - omega * omega * ring.mass);
}

double tunedResonance(const LumpedRing& ring) {
  ring.validate();
  const double phi = 2 * M_PI * ring.engineOrder / ring.blades;
  return std::sqrt((ring.bladeStiffness + 2 * ring.coupling * (1 - std::cos(phi))) / ring.mass);
}

BladePeaks bladePeaks(const LumpedRing& ring, const std::vector<double>& delta, const std::vector<double>& omegas) {
  if (omegas.empty()) throw InputError("frequencies", "the sweep needs at least one frequency");
  Eigen::MatrixXcd X(ring.blades, Eigen::Index(omegas.size()));
  for (std::size_t k = 0; k < omegas.size(); ++k) X.col(Eigen::Index(k)) = ringResponse(ring, delta, omegas[k]);
  return bladePeaksOf(X, omegas);
}

BladePeaks bladePeaksOf(const Eigen::MatrixXcd& responses, const std::vector<double>& omegas) {
  if (omegas.empty()) throw InputError("frequencies", "the sweep needs at least one frequency");
  const int N = int(responses.rows());
  BladePeaks out;
  out.amplitude.assign(std::size_t(N), 0.0);
  out.omega.assign(std::size_t(N), omegas.front());
  std::vector<Eigen::Index> at(std::size_t(N), 0);
  for (Eigen::Index k = 0; k < responses.cols(); ++k)
    for (int n = 0; n < N; ++n)
      if (std::abs(responses(n, k)) > out.amplitude[std::size_t(n)])
        out.amplitude[std::size_t(n)] = std::abs(responses(n, k)), out.omega[std::size_t(n)] = omegas[std::size_t(k)],
        at[std::size_t(n)] = k;
  for (int n = 0; n < N; ++n)
    if (out.amplitude[std::size_t(n)] > out.amplitude[std::size_t(out.worstBlade)]) out.worstBlade = n;
  out.localisation = inverseParticipationRatio(responses.col(at[std::size_t(out.worstBlade)]));
  return out;
}

double inverseParticipationRatio(const Eigen::VectorXcd& x) {
  const double sum2 = x.squaredNorm();
  if (!(sum2 > 0)) return 0;
  double sum4 = 0;
  for (Eigen::Index n = 0; n < x.size(); ++n) sum4 += std::pow(std::norm(x(n)), 2);
  return sum4 / (sum2 * sum2);
}

double whiteheadBound(int blades) { return 0.5 * (1 + std::sqrt(double(blades))); }

}  // namespace cyclone::mistuning
