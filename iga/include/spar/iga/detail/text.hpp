#pragma once
/// \file
/// Number formatting for error messages: enough digits that a user sees which value was wrong.

#include <sstream>
#include <string>

namespace spar::iga::detail {

/// `value` printed with 17 significant digits (round-trip exact).
inline std::string number(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

}  // namespace spar::iga::detail
