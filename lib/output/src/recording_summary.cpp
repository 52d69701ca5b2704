#include <spar/output/recording_summary.hpp>

#include <cstdio>

namespace spar::output {

JsonSummary& JsonSummary::add(const std::string& key, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return append(key, buffer);
}

JsonSummary& JsonSummary::add(const std::string& key, int value) { return append(key, std::to_string(value)); }

JsonSummary& JsonSummary::add(const std::string& key, long value) { return append(key, std::to_string(value)); }

JsonSummary& JsonSummary::add(const std::string& key, const std::string& value) {
  return append(key, "\"" + value + "\"");
}

JsonSummary& JsonSummary::add(const std::string& key, const std::optional<double>& value) {
  return value ? add(key, *value) : append(key, "null");
}

std::string JsonSummary::text() const { return "{" + body_ + "}"; }

void JsonSummary::print() const { std::printf("%s\n", text().c_str()); }

JsonSummary& JsonSummary::append(const std::string& key, const std::string& value) {
  if (!body_.empty()) body_ += ", ";
  body_ += "\"" + key + "\": " + value;
  return *this;
}

}  // namespace spar::output
