#pragma once
// The forces a harmonic balance solution puts on its receptance model, per time
// harmonic: what drives the recovery of a reduced model's whole field (the FE
// sector solved with them reproduces the solution at the retained DOFs, up to
// the reduced model's own error), and the model's response to them.
//
// Complex amplitudes as in ReceptanceModel.hpp: c cos(h w t) + s sin(h w t) is
// Re(F e^{i h w t}) with F = c - i s; harmonic 0 is the mean (real).
#include <Eigen/Dense>
#include <vector>

#include "cyclone/hbm/HarmonicBalanceSystem.hpp"

namespace cyclone::hbm {

struct HarmonicLoad {
  int harmonic = 0;
  long phaseIndex = 0;     ///< the inter-sector phase p of the harmonic (0 when not cyclic)
  Eigen::VectorXcd force;  ///< on the model's DOFs
};

/// f_h = s F_ex + F_static - F_nl(X) of a receptance-form system at its solution X,
/// harmonic by harmonic. When the system's receptance is a ProjectedReceptance
/// (condensed unknowns q = T_p x), the forces on q are carried to the base model's
/// DOFs as T_p^H f_q (the reaction of the element joining the previous sector
/// included), so they are always on the DOFs of the model the user built (the
/// retained DOFs of a reduced model). InputError for a matrix-form system.
std::vector<HarmonicLoad> harmonicLoads(const HarmonicBalanceSystem& system, const Eigen::VectorXd& X, double omega,
                                        double excitationScale = 1.0);

/// The model's response at its DOFs: x_h = A(h w, p_h) f_h, and for harmonic 0 the
/// undamped mean compliance times f_0 (HarmonicBalanceSystem's convention).
std::vector<Eigen::VectorXcd> harmonicResponse(const ReceptanceModel& model, const std::vector<HarmonicLoad>& loads,
                                               double omega);

}  // namespace cyclone::hbm
