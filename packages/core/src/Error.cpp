#include "cyclone/core/Error.hpp"

namespace cyclone {

InputError::InputError(const std::string& where, const std::string& what)
    : Error(where.empty() ? what : where + ": " + what), where_(where), problem_(what) {}

std::string atLine(const std::string& file, long line) { return file + ":" + std::to_string(line); }

}  // namespace cyclone
