#pragma once
// A small command-line reader shared by the examples: `--name value` options with defaults and
// help text, `--help`, and a clear error for unknown options or malformed numbers. Also the JSON
// summary line every example prints last.
#include <spar/error.hpp>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace spar::examples {

class CommandLine {
public:
  CommandLine(int argc, char** argv, std::string usage) : usage_(std::move(usage)) {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--help" || arg == "-h") {
        help_ = true;
      } else if (arg.rfind("--", 0) == 0 && i + 1 < argc) {
        given_[arg] = argv[++i];
      } else {
        throw Error("unexpected argument '" + arg + "'", "command line",
                    "options are --name value pairs; see --help");
      }
    }
  }

  double number(const std::string& name, double fallback, const std::string& help) {
    char shown[32];
    std::snprintf(shown, sizeof shown, "%g", fallback);
    describe(name, shown, help);
    const auto it = given_.find(name);
    if (it == given_.end()) return fallback;
    used_.push_back(name);
    char* end = nullptr;
    const double value = std::strtod(it->second.c_str(), &end);
    if (end == it->second.c_str() || *end != '\0')
      throw Error("'" + it->second + "' is not a number", "option " + name, "give a number");
    return value;
  }

  int integer(const std::string& name, int fallback, const std::string& help) {
    const double value = number(name, fallback, help);
    if (value != static_cast<int>(value))
      throw Error("'" + std::to_string(value) + "' is not an integer", "option " + name,
                  "give a whole number");
    return static_cast<int>(value);
  }

  std::string text(const std::string& name, const std::string& fallback, const std::string& help) {
    describe(name, fallback, help);
    const auto it = given_.find(name);
    if (it == given_.end()) return fallback;
    used_.push_back(name);
    return it->second;
  }

  /// Call after reading every option: prints the help and returns false for --help; throws for
  /// options that were given but never read.
  bool finish() {
    if (help_) {
      std::printf("%s\n\nOptions:\n%s  --help              this text\n", usage_.c_str(),
                  options_.str().c_str());
      return false;
    }
    for (const auto& [name, value] : given_) {
      bool known = false;
      for (const auto& used : used_) known = known || used == name;
      if (!known)
        throw Error("unknown option " + name, "command line", "see --help for the options");
    }
    return true;
  }

private:
  void describe(const std::string& name, const std::string& fallback, const std::string& help) {
    char line[256];
    std::snprintf(line, sizeof line, "  %-18s  %s (default %s)\n", name.c_str(), help.c_str(),
                  fallback.c_str());
    options_ << line;
  }

  std::string usage_;
  bool help_ = false;
  std::map<std::string, std::string> given_;
  std::vector<std::string> used_;
  std::ostringstream options_;
};

/// One flat JSON object built key by key, printed as the example's last line of stdout.
class JsonSummary {
public:
  JsonSummary& add(const std::string& key, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    return append(key, buffer);
  }
  JsonSummary& add(const std::string& key, int value) { return append(key, std::to_string(value)); }
  JsonSummary& add(const std::string& key, const std::string& value) {
    return append(key, "\"" + value + "\"");
  }
  /// A number that may be missing (e.g. a value at a time the run did not reach): null then.
  JsonSummary& add(const std::string& key, const std::optional<double>& value) {
    return value ? add(key, *value) : append(key, "null");
  }
  void print() const { std::printf("{%s}\n", body_.c_str()); }

private:
  JsonSummary& append(const std::string& key, const std::string& value) {
    if (!body_.empty()) body_ += ", ";
    body_ += "\"" + key + "\": " + value;
    return *this;
  }
  std::string body_;
};

}  // namespace spar::examples
