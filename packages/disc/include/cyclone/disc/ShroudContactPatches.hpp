#pragma once
// The shroud interface split into patches, each one contact element: the patch's mean
// relative motion (its nodes' motions weighted by their tributary areas) carries the
// friction law, and its force is spread back over the nodes by the same weights (the
// virtual work of the averaged motion: an RBE3-like multipoint constraint). A mesh's
// hundreds of contact nodes then make tens of contacts, the number a harmonic balance
// with tens of harmonics can carry; the thesis used 27 contact elements on its face.
#include <Eigen/Core>
#include <vector>

namespace cyclone::disc {

/// `count` groups of the points (indices into `points`), each a compact piece of the
/// face of about equal weight: recursive bisection, always of the heaviest group, across
/// its principal axis of largest spread (weighted), at its weighted median. count = the
/// number of points gives one point per group. InputError (key `contact/patches`) for
/// count < 1, more groups than points, or weights that are not positive and finite.
std::vector<std::vector<int>> splitIntoPatches(const std::vector<Eigen::Vector3d>& points,
                                               const std::vector<double>& weights, int count);

}  // namespace cyclone::disc
