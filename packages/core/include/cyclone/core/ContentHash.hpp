#pragma once
// A digest of the inputs of a stage (mesh, material, speed, options), so a
// product whose inputs did not change (modes, reduced models) is reused
// instead of recomputed. Two independent 64-bit FNV-1a streams: a change
// detector for cached files, not a cryptographic hash.
#include <cstdint>
#include <string>
#include <vector>

namespace cyclone {

class ContentHash {
public:
  ContentHash& add(const void* data, std::size_t bytes);
  ContentHash& add(const std::string& s);  ///< with its length, so "ab"+"c" differs from "a"+"bc"
  ContentHash& add(double v);              ///< exact bits (-0 and 0 differ; so be it)
  ContentHash& add(long long v);
  ContentHash& add(int v) { return add((long long)v); }
  template <class T>
  ContentHash& addAll(const std::vector<T>& values) {
    add((long long)values.size());
    for (const auto& v : values) add(v);
    return *this;
  }
  /// 32 hex digits.
  std::string hex() const;

private:
  std::uint64_t a_ = 14695981039346656037ull, b_ = 0x84222325cbf29ce4ull;
};

}  // namespace cyclone
