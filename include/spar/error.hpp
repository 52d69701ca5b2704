#pragma once
/// \file
/// The one exception type of spar. Every error in user input or in a run that cannot go on raises
/// a spar::Error whose message says what went wrong, where, and how to fix it.

#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>

namespace spar {

/// A number for an error message with 6 significant digits: "-1e-09", "2.14748e+09", "0.33"
/// (std::to_string's fixed six decimals print 1e-7 as "0.000000" and hide the value).
inline std::string significant(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

/// An error a user can act on: `what` went wrong, `where` (function, object, index, time),
/// and `fix` (what to change). `what()` returns the three joined into one message.
class Error : public std::runtime_error {
public:
  Error(std::string_view what, std::string_view where, std::string_view fix)
      : std::runtime_error(compose(what, where, fix)), where_(where), fix_(fix) {}

  /// The place the error was detected, e.g. "lie::log".
  const std::string& where() const noexcept { return where_; }
  /// What the user can do about it.
  const std::string& fix() const noexcept { return fix_; }

private:
  static std::string compose(std::string_view what, std::string_view where, std::string_view fix) {
    std::string message = "spar: ";
    message.append(where).append(": ").append(what);
    if (!fix.empty()) message.append(" (fix: ").append(fix).append(")");
    return message;
  }

  std::string where_;
  std::string fix_;
};

/// Bad input met in the middle of a computation (a load history that is NaN at some time): the
/// solvers pass it on at once instead of retrying with a shorter step, which cannot help.
class InputError : public Error {
public:
  using Error::Error;
};

}  // namespace spar
