#pragma once
// Errors with context: every message names what was wrong and where (file,
// line, parameter or entity), so a user can fix the input without a debugger.
#include <stdexcept>
#include <string>

namespace cyclone {

/// Base of all Cyclone errors.
class Error : public std::runtime_error {
public:
  explicit Error(const std::string& what) : std::runtime_error(what) {}
};

/// Bad user input: a file, a scene parameter, a mesh entity.
/// The message reads "<where>: <what>", e.g. "deck.inp:12: element 7 refers to missing node 99".
class InputError : public Error {
public:
  InputError(const std::string& where, const std::string& what);
  const std::string& where() const { return where_; }
  const std::string& problem() const { return problem_; }

private:
  std::string where_, problem_;
};

/// Builds "file:line" for InputError.
std::string atLine(const std::string& file, long line);

/// A numerical failure (non-convergence, singular matrix) with the reason.
class SolverError : public Error {
public:
  explicit SolverError(const std::string& what) : Error(what) {}
};

/// A solver that ran out of memory (a factor larger than the machine gives): a caller
/// that can do without the solve (a check) goes on without it.
class OutOfMemoryError : public SolverError {
public:
  explicit OutOfMemoryError(const std::string& what) : SolverError(what) {}
};

}  // namespace cyclone
