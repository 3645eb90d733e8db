#pragma once
// The slider position of a 3D friction contact that stays stuck over a whole
// period: the point of the stuck set C = { z : |w_t(t_i) - z| <= r_i for all
// samples i } (r_i = mu N_i / kt; each disk is where the tangential spring holds
// at sample i) nearest to the relaxed state z = 0.
//
// Why: with a circular friction limit a marched slider that ends stuck stops at
// a point of C that depends on the order in which it met the disks, that is on
// the sample the march began with. The harmonic balance of a cyclic sector needs
// a force that is the time-shifted copy of itself for a time-shifted motion (the
// neighbour sector's contact is the same contact a fraction of a period later),
// so the stuck state must be a function of the set C alone. The nearest point
// to the relaxed state is that function, and in 1D it is exactly what the
// march gives (the march projects onto the stuck interval).
#include <Eigen/Dense>
#include <vector>

namespace cyclone::hbm::detail {

struct StuckSliderState {
  bool feasible = false;  ///< false: C is empty, the contact slips every period
  Eigen::Vector2d z = Eigen::Vector2d::Zero();
  std::vector<int> active;  ///< samples whose disk boundary holds z (0, 1 or 2)
};

/// centres: 2 x n tangential displacements, radii: n slip radii (all > 0).
/// Exact up to rounding: the minimum-norm point of an intersection of disks in
/// the plane is 0, the projection of 0 onto one disk or a crossing of two
/// circles, so an active-set search over at most 3 disks at a time finds it.
StuckSliderState nearestStuckState(const Eigen::Matrix2Xd& centres, const Eigen::VectorXd& radii);

/// The slider position that violates the disks least: the minimiser of
/// max_i (|z - c_i| - r_i) (the centre of C's largest inscribed disk when C is not
/// empty). Just past the onset of slip the periodic slip state lies within the
/// small violation of it, while a march from the relaxed state can stop far away:
/// the slip per period, and so the period map's pull, vanishes at the onset.
/// Exact up to rounding: an active-set search over at most 3 disks at a time.
Eigen::Vector2d leastViolatingState(const Eigen::Matrix2Xd& centres, const Eigen::VectorXd& radii);

}  // namespace cyclone::hbm::detail
