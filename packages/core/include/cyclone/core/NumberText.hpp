#pragma once
// A number as a person reads it in a summary line or a plot: the stream's shortest form
// at a given count of significant digits (6 as std::ostream's default).
#include <sstream>
#include <string>

namespace cyclone {

inline std::string numberText(double v, int significantDigits = 6) {
  std::ostringstream s;
  s.precision(significantDigits);
  s << v;
  return s.str();
}

}  // namespace cyclone
