#pragma once
/// \file
/// A CSV file of numbers for plot scripts: a header line, then one row of numbers per call, each
/// number printed with a fixed count of significant digits or as the shortest text that reads
/// back to the same double. What a study writes beside its results file (docs/output.md).

#include <initializer_list>
#include <memory>
#include <span>
#include <string>

namespace spar::output {

class CsvFile {
public:
  /// Creates (truncates) `path` and writes `header`, the column names comma-separated, and a
  /// newline. Numbers are printed with `digits` significant digits (1 … 17: printf's %.<digits>g,
  /// which is what a C++ stream of that precision prints; "nan", "inf" for those) or, with
  /// digits = 0, as the shortest text that reads back to the same double (std::to_chars, about
  /// ten times cheaper than a stream). Throws spar::Error naming the path if it cannot be written
  /// or `digits` is out of range.
  CsvFile(const std::string& path, const std::string& header, int digits = 0);
  ~CsvFile();
  CsvFile(CsvFile&&) noexcept;
  CsvFile& operator=(CsvFile&&) noexcept;

  /// Writes `values` comma-separated and a newline (whole numbers print without a point: 3, not
  /// 3.0). spar::Error if the file could not be written (a full disk) or is closed.
  void row(std::span<const double> values);
  void row(std::initializer_list<double> values) { row(std::span<const double>(values.begin(), values.size())); }
  /// Appends one number and its comma to the row being built; end_row() ends it.
  void cell(double value);
  void end_row();
  /// Closes the file (later rows are refused); spar::Error if a write failed.
  void close();
  const std::string& path() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The text of `value` as CsvFile prints it with `digits` (0: the shortest round trip).
std::string format_number(double value, int digits);

}  // namespace spar::output
