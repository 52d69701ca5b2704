#pragma once
// One CSV row of numbers, formatted with std::to_chars (the shortest text that reads back to the
// same double) and written with one call: an iostream's `<<` of a double costs about ten times
// more, which shows where an example records hundreds of states per second of its run.
#include <charconv>
#include <ostream>
#include <string>
#include <vector>

namespace spar::examples {

/// Writes `values` comma-separated and a newline.
inline void write_csv_row(std::ostream& out, const std::vector<double>& values) {
  std::string line;
  line.reserve(25 * values.size());
  char buffer[32];
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) line += ',';
    line.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, values[i]).ptr);
  }
  line += '\n';
  out << line;
}

}  // namespace spar::examples
