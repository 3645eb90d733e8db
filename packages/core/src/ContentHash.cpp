#include "cyclone/core/ContentHash.hpp"

#include <cstdio>
#include <cstring>

namespace cyclone {

ContentHash& ContentHash::add(const void* data, std::size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) {
    a_ = (a_ ^ p[i]) * 1099511628211ull;
    b_ = (b_ ^ (p[i] + 0x9eu)) * 0x100000001b3ull;
    b_ ^= b_ >> 29;
  }
  return *this;
}

ContentHash& ContentHash::add(const std::string& s) {
  add((long long)s.size());
  return add(s.data(), s.size());
}

ContentHash& ContentHash::add(double v) {
  unsigned char bytes[sizeof v];
  std::memcpy(bytes, &v, sizeof v);
  return add(bytes, sizeof v);
}

ContentHash& ContentHash::add(long long v) { return add(&v, sizeof v); }

std::string ContentHash::hex() const {
  char out[33];
  std::snprintf(out, sizeof out, "%016llx%016llx", (unsigned long long)a_, (unsigned long long)b_);
  return out;
}

}  // namespace cyclone
