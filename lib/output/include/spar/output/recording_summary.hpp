#pragma once
/// \file
/// The JSON summary line a run prints last on stdout (../shared/DESIGN.md, "Examples"): one flat
/// object built key by key, so scripts and regression tests read a run's key figures.

#include <optional>
#include <string>

namespace spar::output {

class JsonSummary {
public:
  /// A number, with 17 significant digits (it reads back to the same double).
  JsonSummary& add(const std::string& key, double value);
  /// A whole number (counters).
  JsonSummary& add(const std::string& key, int value);
  JsonSummary& add(const std::string& key, long value);
  /// A string (written as given: no quotes or backslashes in it).
  JsonSummary& add(const std::string& key, const std::string& value);
  JsonSummary& add(const std::string& key, const char* value) { return add(key, std::string(value)); }
  /// A number that may be missing (e.g. a value at a time the run did not reach): null then.
  JsonSummary& add(const std::string& key, const std::optional<double>& value);
  /// The object, e.g. {"h": 0.001, "steps": 1000}.
  std::string text() const;
  /// Prints text() and a newline on stdout.
  void print() const;

private:
  JsonSummary& append(const std::string& key, const std::string& value);
  std::string body_;
};

}  // namespace spar::output
