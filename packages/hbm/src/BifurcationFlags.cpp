#include "cyclone/hbm/BifurcationFlags.hpp"

#include <cmath>

namespace cyclone::hbm {

std::vector<std::string> bifurcationFlags(const std::vector<CurvePointStability>& pts) {
  const std::size_t n = pts.size();
  std::vector<std::string> flags(n);
  // A fold: the parameter turns at i and keeps its direction for two steps on
  // each side (a single step back, as at the end of a range, is no fold).
  auto dp = [&](std::size_t i) { return pts[i].parameter - pts[i - 1].parameter; };
  for (std::size_t i = 2; i + 2 < n; ++i)
    if (dp(i) * dp(i + 1) < 0 && dp(i - 1) * dp(i) > 0 && dp(i + 1) * dp(i + 2) > 0)
      flags[i] = (pts[i - 1].stable >= 0 && pts[i - 1].stable == pts[i + 1].stable) ? "turn" : "fold";
  auto nearFold = [&](std::size_t i) {
    for (std::size_t j = i > 1 ? i - 2 : 0; j <= i + 1 && j < n; ++j)
      if (flags[j] == "fold" || flags[j] == "turn") return true;
    return false;
  };
  for (std::size_t i = 1; i < n; ++i) {
    if (pts[i].stable < 0 || pts[i - 1].stable < 0 || pts[i].stable == pts[i - 1].stable || nearFold(i)) continue;
    // The crossing exponent is the leading one on the unstable side.
    const auto& u = pts[i].stable == 0 ? pts[i] : pts[i - 1];
    const double im = std::abs(u.leading.imag()), w = u.omega;
    if (im < 1e-3 * w) flags[i] = "branch_point";
    else if (std::abs(im - 0.5 * w) < 0.02 * w) flags[i] = "period_doubling";
    else flags[i] = "neimark_sacker";
  }
  return flags;
}

}  // namespace cyclone::hbm
