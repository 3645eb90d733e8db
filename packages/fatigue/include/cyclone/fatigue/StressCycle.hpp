#pragma once
// The measures a fatigue assessment takes from one point's periodic stress,
//   sigma(t) = sigma_mean + sum_h Re(S_h e^{i h w t}),
// a multiaxial state whose components need not be in phase (friction makes
// higher harmonics; a travelling wave turns principal directions).
//   alternating von Mises: max over the period of vM(sigma(t) - sigma_mean);
//     for a proportional cycle (one harmonic, or components in phase) the
//     von Mises of the amplitude tensor, what a single-mode stress analysis
//     reports; otherwise the largest deviatoric excursion from the mean, which
//     is conservative against the minimum circumscribed ball (Dang Van).
//   alternating principal: max over the period of the largest |principal stress|
//     of sigma(t) - sigma_mean (brittle-type and crack-opening checks).
//   mean von Mises, signed: vM(sigma_mean) with the sign of its principal stress
//     of largest magnitude (tension positive), so a compressive mean is not
//     counted as a tensile one in the Goodman diagram (the convention of
//     ANSYS and nCode DesignLife's "signed von Mises").
// Voigt order as fe::elementStresses: xx yy zz yz xz xy (tensor shear).
#include <Eigen/Dense>
#include <complex>
#include <vector>

namespace cyclone::fatigue {

using Voigt = Eigen::Matrix<double, 6, 1>;
using ComplexVoigt = Eigen::Matrix<std::complex<double>, 6, 1>;

struct HarmonicStress {
  int harmonic = 1;  ///< h >= 1 (the mean goes separately)
  ComplexVoigt amplitude = ComplexVoigt::Zero();
};

struct CycleMeasures {
  double meanVonMises = 0;          ///< signed (see the file comment)
  double alternatingVonMises = 0;   ///< max_t vM(sigma(t) - mean)
  double alternatingPrincipal = 0;  ///< max_t max |principal of sigma(t) - mean|
  double maxVonMises = 0;           ///< max_t vM(sigma(t)): the largest stress in the period
};

/// The period sampled at `samples` instants (at least 16 per highest harmonic are
/// used), each maximum then narrowed by golden section between its neighbours,
/// which leaves a relative error below 1e-9 of a smooth maximum.
CycleMeasures measureCycle(const Voigt& mean, const std::vector<HarmonicStress>& harmonics, int samples = 64);

/// The stress at phase theta = w t.
Voigt stressAt(const Voigt& mean, const std::vector<HarmonicStress>& harmonics, double theta);

/// von Mises of a Voigt tensor (tensor shear).
double vonMises(const Voigt& s);
/// The principal stress of largest magnitude, with its sign.
double largestPrincipal(const Voigt& s);

}  // namespace cyclone::fatigue
