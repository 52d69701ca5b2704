#pragma once
/// \file
/// How the results files and their error messages print a double.

#include <charconv>
#include <string>

namespace spar::output::detail {

/// The shortest decimal text that reads back as the same double.
inline std::string format_double(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

}  // namespace spar::output::detail
