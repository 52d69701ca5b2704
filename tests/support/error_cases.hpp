#pragma once
// A table of calls that must each end in a spar::Error whose message holds a word: the API
// audits' tests (tests/input) list their cases in one table and check them with one loop.
#include <spar/error.hpp>

#include <catch2/catch.hpp>

#include <functional>
#include <string>
#include <vector>

namespace spar::test {

struct ErrorCase {
  std::string name;            ///< what the call does wrong (and what it did before the check)
  std::function<void()> call;  ///< the bad call
  std::string word;            ///< a part of the message that names the problem
};

/// Runs each case; a case passes when its call throws a spar::Error whose message contains its
/// word (a call that throws nothing leaves an empty message, which fails).
inline void check_error_cases(const std::vector<ErrorCase>& cases) {
  for (const ErrorCase& c : cases) {
    INFO(c.name);
    std::string message;
    try {
      c.call();
    } catch (const Error& error) {
      message = error.what();
    }
    CHECK_THAT(message, Catch::Contains(c.word));
  }
}

}  // namespace spar::test
