#include "cyclone/mistuning/MistuningPattern.hpp"

#include <random>
#include <string>

#include "cyclone/core/Error.hpp"

namespace cyclone::mistuning {

std::vector<double> randomPattern(int blades, double sigma, std::uint64_t seed) {
  if (blades < 1) throw InputError("blades", "must be at least 1");
  if (!(sigma >= 0)) throw InputError("standard_deviation", "must be >= 0");
  std::mt19937_64 engine(seed);
  std::normal_distribution<double> normal(0.0, sigma);
  std::vector<double> delta(static_cast<std::size_t>(blades));
  for (auto& d : delta) {
    d = normal(engine);
    if (!(d > -1))
      throw InputError("standard_deviation", std::to_string(sigma) + " drew a deviation of " + std::to_string(d) +
                                                 ": a blade's stiffness would not be positive");
  }
  return delta;
}

std::vector<double> shiftedPattern(const std::vector<double>& delta, int shift) {
  const int N = int(delta.size());
  std::vector<double> out(delta.size());
  for (int n = 0; n < N; ++n) out[std::size_t(n)] = delta[std::size_t(((n - shift) % N + N) % N)];
  return out;
}

}  // namespace cyclone::mistuning
