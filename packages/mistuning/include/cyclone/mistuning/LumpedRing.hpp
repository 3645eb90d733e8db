#pragma once
// The single-family model of a bladed disc: N blades, each a spring-mass (m, k_b (1 +
// delta_n)) on its own DOF, each coupled to its neighbours by a spring k_c (the disc), a
// structural loss factor eta on every spring, and the engine-order excitation F e^{i 2 pi
// EO n / N} on blade n. The reference model of the mistuning literature (Whitehead 1966;
// Castanier & Pierre 2006): tuned (delta = 0) its response is one travelling wave, closed
// form; mistuned, the energy localises on a few blades.
#include <complex>
#include <vector>

#include <Eigen/Dense>

namespace cyclone::mistuning {

struct LumpedRing {
  int blades = 24;
  double mass = 1;            ///< m
  double bladeStiffness = 1;  ///< k_b: the blade-alone natural frequency sqrt(k_b / m)
  double coupling = 0.05;     ///< k_c: the disc's coupling between neighbouring blades
  double lossFactor = 0.005;  ///< eta: K (1 + i eta)
  int engineOrder = 3;
  double force = 1;           ///< F on every blade
  /// InputError naming the field where it is out of range (blades >= 3, m, k_b > 0,
  /// k_c >= 0, eta > 0, 0 <= EO < N, F != 0).
  void validate() const;
};

/// Blade n's complex amplitude x_n at omega (rad/s), with blade stiffness deviations
/// delta (the blade-alone frequency deviation as ANSYS takes it: (w_n / w)^2 - 1), by one
/// dense complex solve of the N x N dynamic stiffness. InputError when delta has not N
/// entries or a blade's stiffness would not be positive (delta <= -1).
Eigen::VectorXcd ringResponse(const LumpedRing& ring, const std::vector<double>& delta, double omega);

/// The tuned ring's blade amplitude at omega in closed form: the engine order's travelling
/// wave, |F| / |k_b (1 + i eta) + 2 k_c (1 - cos phi)(1 + i eta) - omega^2 m|, phi = 2 pi EO / N.
double tunedAmplitude(const LumpedRing& ring, double omega);

/// The tuned ring's resonance (rad/s): sqrt((k_b + 2 k_c (1 - cos phi)) / m).
double tunedResonance(const LumpedRing& ring);

/// Each blade's largest amplitude over the frequencies `omegas` (a sweep across the
/// family's band), and where it was reached.
struct BladePeaks {
  std::vector<double> amplitude;  ///< per blade, the largest |x_n| over the sweep
  std::vector<double> omega;      ///< per blade, where
  int worstBlade = 0;             ///< the blade with the largest peak
  /// The inverse participation ratio of the response at the worst blade's peak frequency.
  double localisation = 0;
  double largest() const { return amplitude[std::size_t(worstBlade)]; }
};
BladePeaks bladePeaks(const LumpedRing& ring, const std::vector<double>& delta, const std::vector<double>& omegas);
/// The same from any ring's blade responses (N x omegas.size(), column k at omegas[k]).
BladePeaks bladePeaksOf(const Eigen::MatrixXcd& responses, const std::vector<double>& omegas);

/// Inverse participation ratio of a response, sum |x_n|^4 / (sum |x_n|^2)^2: 1 / N for a
/// travelling wave spread over every blade, 1 for one blade alone (localisation).
double inverseParticipationRatio(const Eigen::VectorXcd& x);

/// Whitehead's bound on the amplification of a single-family ring of N blades:
/// (1 + sqrt(N)) / 2.
double whiteheadBound(int blades);

}  // namespace cyclone::mistuning
