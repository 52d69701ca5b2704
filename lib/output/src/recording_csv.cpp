#include <spar/output/recording_csv.hpp>

#include <spar/error.hpp>

#include <charconv>
#include <cstdio>
#include <fstream>

namespace spar::output {

namespace {

/// Appends `value` as format_number() prints it.
void append_number(std::string& line, double value, int digits) {
  char buffer[40];
  if (digits == 0) {
    line.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
  } else {
    const int length = std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
    line.append(buffer, static_cast<std::size_t>(length));
  }
}

}  // namespace

struct CsvFile::Impl {
  std::string path;
  int digits = 0;
  std::ofstream file;
  std::string line;  ///< the row being built
  bool open = true;

  void check(const char* function) const {
    if (!open)
      throw Error("the CSV file '" + path + "' is closed", std::string("CsvFile::") + function,
                  "write every row before close()");
  }
  void write_line() {
    line += '\n';
    file << line;
    line.clear();
    if (!file)
      throw Error("cannot write to '" + path + "' (a full disk?)", "CsvFile", "free space or give another folder");
  }
};

CsvFile::CsvFile(const std::string& path, const std::string& header, int digits) : impl_(std::make_unique<Impl>()) {
  if (digits < 0 || digits > 17)
    throw Error("digits = " + std::to_string(digits) + " is outside [0, 17]", "CsvFile " + path,
                "give 1 to 17 significant digits, or 0 for the shortest text that reads back the same");
  impl_->path = path;
  impl_->digits = digits;
  impl_->file.open(path);
  if (!impl_->file)
    throw Error("cannot create '" + path + "'", "CsvFile", "give a folder that exists and that you may write to");
  impl_->line = header;
  impl_->write_line();
}

CsvFile::~CsvFile() = default;
CsvFile::CsvFile(CsvFile&&) noexcept = default;
CsvFile& CsvFile::operator=(CsvFile&&) noexcept = default;

void CsvFile::cell(double value) {
  impl_->check("cell");
  if (!impl_->line.empty()) impl_->line += ',';
  append_number(impl_->line, value, impl_->digits);
}

void CsvFile::end_row() {
  impl_->check("end_row");
  impl_->write_line();
}

void CsvFile::row(std::span<const double> values) {
  impl_->check("row");
  impl_->line.reserve(25 * values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) impl_->line += ',';
    append_number(impl_->line, values[i], impl_->digits);
  }
  impl_->write_line();
}

void CsvFile::close() {
  if (!impl_ || !impl_->open) return;
  impl_->open = false;
  impl_->file.close();
  if (!impl_->file)
    throw Error("cannot finish '" + impl_->path + "' (a full disk?)", "CsvFile::close", "free space or give another folder");
}

const std::string& CsvFile::path() const { return impl_->path; }

std::string format_number(double value, int digits) {
  std::string text;
  append_number(text, value, digits);
  return text;
}

}  // namespace spar::output
