#pragma once
// A small command-line reader shared by the examples: `--name value` options with defaults and
// help text, `--help`, and a spar::Error for every value a run cannot use (docs/errors.md):
// malformed, missing or non-finite numbers, values outside an option's range (the message names
// the range), integers that are not whole or do not fit, choices not on the list, an output
// folder that cannot be created or written, a time span with too many steps, more elements than
// the memory holds, an option given where the chosen mode ignores it, and a beam that is no
// slender beam. Also the JSON summary line every example prints last.
#include <spar/error.hpp>

#include "memory_use.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace spar::examples {

/// The values a numeric option accepts: an interval with open or closed ends. The default accepts
/// every finite number.
struct Range {
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();
  bool low_open = false;
  bool high_open = false;

  /// (0, high], or (0, inf) without a bound: step sizes, lengths, tolerances.
  static Range positive(double high = std::numeric_limits<double>::infinity()) {
    return {0.0, high, true, std::isinf(high)};
  }
  /// [low, high].
  static Range between(double low, double high) { return {low, high, false, false}; }

  bool contains(double value) const {
    return (low_open ? value > low : value >= low) && (high_open ? value < high : value <= high);
  }
  /// The interval as the message shows it, e.g. "(0, 1]" or "[-0.999, 0.5)".
  std::string text() const {
    return std::string(low_open ? "(" : "[") + significant(low) + ", " + significant(high) + (high_open ? ")" : "]");
  }
};

/// The Newton tolerances an example accepts (|[dq, h²β dλ]|², |Φ|_∞ in m): a tolerance above 10⁻²
/// accepts increments of decimetres and makes the result meaningless (1e300 gave an 8660 %
/// deformation).
inline constexpr Range newton_tolerances{0.0, 1e-2, true, false};

/// The most steps a time span may take (t_end/h): far above the examples' runs (400 to 3·10⁴ steps
/// by default, 10⁵ RK4 steps for heavy_top's reference), low enough that a mistyped step ends at
/// once instead of running for days.
inline constexpr double max_time_steps = 1e7;

/// The number of steps of size h that reach t_end, or a spar::Error naming the options when h and
/// t_end are not positive finite numbers with h ≤ t_end and t_end/h ≤ max_time_steps.
inline long time_steps(double h, double t_end, const std::string& h_name = "--h",
                       const std::string& t_end_name = "--t-end") {
  const std::string where = "options " + h_name + ", " + t_end_name;
  if (!(std::isfinite(h) && h > 0.0 && std::isfinite(t_end) && t_end > 0.0))
    throw Error(h_name + " = " + significant(h) + " and " + t_end_name + " = " + significant(t_end) +
                    " must be positive finite times", where, "give e.g. " + h_name + " 1e-3 " + t_end_name + " 1");
  if (h > t_end * (1 + 1e-12))
    throw Error("the step " + h_name + " = " + significant(h) + " s is longer than the span " + t_end_name +
                    " = " + significant(t_end) + " s: no step would be taken",
                where, "give a step no longer than the end time");
  const double steps = std::ceil(t_end / h - 1e-9);
  if (steps > max_time_steps)
    throw Error(t_end_name + " / " + h_name + " = " + significant(steps) + " steps, more than the " +
                    significant(max_time_steps) + " a run may take",
                where, "raise " + h_name + " or lower " + t_end_name);
  return static_cast<long>(steps);
}

/// A time the run must reach to mean anything (an output interval, a deployment time): a
/// spar::Error naming both options when `time` = `name` is later than the end time `t_end`
/// (four_bar --output-interval 1e300 wrote the state at t = 0 only; truss_deployment --t-f 1e300
/// deployed nothing).
inline void require_within_run(double time, const std::string& name, const std::string& what, double t_end,
                               const std::string& t_end_name = "--t-end") {
  if (time <= t_end * (1 + 1e-12)) return;
  throw Error(name + " = " + significant(time) + " s is later than the end of the run, " + t_end_name + " = " +
                  significant(t_end) + " s: " + what,
              "options " + name + ", " + t_end_name,
              "give " + name + " at most " + t_end_name + " (" + significant(t_end) + " s), or raise " + t_end_name);
}

/// The slenderness (length over the section's side in the plane of bending) a beam example
/// accepts, [3, 10⁴]:
/// - at least 3: a member shorter than 3 times its section's depth is a deep beam, not a beam
///   (EN 1992-1-1 §5.3.1(3)), whose sections do not stay plane; modal_beam --length 1e-6 --width 1
///   --height 1 (10⁻⁶) compared a cube's "modes" with Timoshenko's beam;
/// - at most 10⁴: the tangent's axial stiffness EA/L_e over its bending stiffness EI/L³ grows as
///   12 n (L/t)², 10¹⁰ at L/t = 10⁴ with 16 elements, and as digits are lost the Newton test at
///   10⁻⁹ of the forces can no longer be met: cantilever_statics on its default mesh (16 cubic
///   elements, load 6) converges in both cases for L = 10⁻³, 1 and 10³ m up to L/t = 10⁴ and fails
///   from 3·10⁴ at L = 10³ m (at 10⁹, --length 1e3 --width 1e-6, at load factor 0). A mesh too
///   coarse for the load (one element rolled up) fails at any slenderness: that is no input error.
inline constexpr double min_slenderness = 3.0;
inline constexpr double max_slenderness = 1e4;

/// A spar::Error naming the options when a beam of length `length` (option `length_name`) with
/// section sides `thin` (`thin_name`) ≤ `thick` (`thick_name`) is no slender beam: L/thick <
/// min_slenderness or L/thin > `most` (max_slenderness, or an example's tighter bound).
inline void require_slender_beam(double length, const std::string& length_name, double thin, const std::string& thin_name,
                                 double thick, const std::string& thick_name, double most = max_slenderness) {
  const std::string where = "options " + length_name + ", " + thin_name + (thick_name == thin_name ? "" : ", " + thick_name);
  if (length < min_slenderness * thick)
    throw Error("a beam of " + length_name + " = " + significant(length) + " m and a section side " + thick_name +
                    " = " + significant(thick) + " m has a slenderness of " + significant(length / thick) +
                    ": a member shorter than " + significant(min_slenderness) +
                    " times its section's depth is a deep beam, not a beam (EN 1992-1-1 5.3.1)",
                where, "give " + length_name + " at least " + significant(min_slenderness * thick) + " m or a thinner section");
  if (length > most * thin)
    throw Error("a beam of " + length_name + " = " + significant(length) + " m and a section side " + thin_name +
                    " = " + significant(thin) + " m has a slenderness of " + significant(length / thin) +
                    ", more than " + significant(most) +
                    ": its axial stiffness swamps its bending stiffness in double precision (the digits lost grow "
                    "as the slenderness squared)",
                where, "give " + length_name + " at most " + significant(most * thin) + " m or a thicker section");
}

/// The physical memory of this machine in bytes (sysconf; 4 GB if it cannot say), the budget of
/// element_limit.
inline double physical_memory() {
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page_size > 0 ? static_cast<double>(pages) * static_cast<double>(page_size) : 4e9;
}

/// The memory a run may use: half the physical memory, so a run leaves room for the system and
/// for a second run beside it.
inline double memory_budget() { return 0.5 * physical_memory(); }

/// The most elements whose memory (MemoryUse::bytes) fits in memory_budget(), capped at the int
/// range: the upper end of an --elements option, so a run that would end in std::bad_alloc after
/// minutes is refused at once.
inline int element_limit(const MemoryUse& memory) {
  const double a = memory.per_element_squared, b = memory.per_element, c = memory_budget();
  const double limit = a > 0.0 ? 2 * c / (b + std::sqrt(b * b + 4 * a * c)) : c / b;  // the root of a n² + b n = c
  return static_cast<int>(std::min(std::floor(limit), static_cast<double>(std::numeric_limits<int>::max())));
}

/// The memory figures of a message: "1.3 GB" (6 significant digits are noise here: 3).
inline std::string gigabytes(double bytes) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g GB", bytes / 1e9);
  return buffer;
}

/// A spar::Error naming `names` when `elements` elements (as given: `given`) need more than
/// memory_budget().
inline void require_memory(double elements, const MemoryUse& memory, const std::string& names,
                           const std::string& given = "") {
  if (memory.bytes(elements) <= memory_budget()) return;
  char per_element[48];
  std::snprintf(per_element, sizeof per_element, "%.3g kB per element", memory.per_element / 1e3);
  const std::string count = given.empty() ? significant(elements) : "'" + given + "'";
  throw Error(count + " elements would need about " + gigabytes(memory.bytes(elements)) + " of memory (" +
                  per_element + (memory.per_element_squared > 0.0 ? " and a dense matrix of the model's size" : "") +
                  ", measured), more than the " + gigabytes(memory_budget()) + " a run may use (half of this machine's " +
                  gigabytes(physical_memory()) + ")",
              names, "give at most " + std::to_string(element_limit(memory)) + " elements");
}

class CommandLine {
public:
  CommandLine(int argc, char** argv, std::string usage) : usage_(std::move(usage)) {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--help" || arg == "-h") {
        help_ = true;
      } else if (arg.rfind("--", 0) == 0) {
        // A value is the next argument unless there is none or it is the next option (values may
        // be negative numbers, "-1", but never start with "--").
        if (i + 1 >= argc || std::string(argv[i + 1]).rfind("--", 0) == 0)
          throw Error("option " + arg + " has no value", "command line",
                      "give it one: " + arg + " <value> (see --help)");
        if (given_.count(arg))
          throw Error("option " + arg + " is given twice", "command line", "give each option once");
        given_[arg] = argv[++i];
      } else {
        throw Error("unexpected argument '" + arg + "'", "command line",
                    "options are --name value pairs; see --help");
      }
    }
  }

  /// A real number in `range` (default: any finite number). NaN is always refused; an infinity
  /// only when the default is that same infinity (it then means "off", e.g. a tolerance).
  double number(const std::string& name, double fallback, const std::string& help, Range range = {}) {
    describe(name, significant(fallback), help, range.text());
    check_default(name, fallback, range);
    values_[name] = significant(fallback);
    const auto it = given_.find(name);
    if (it == given_.end()) return fallback;
    used_.push_back(name);
    const std::string& given = it->second;
    values_[name] = given;
    char* end = nullptr;
    const double value = std::strtod(given.c_str(), &end);
    if (given.empty() || end == given.c_str() || *end != '\0')
      throw Error("'" + given + "' is not a number", "option " + name, "give a number in " + range.text());
    if (std::isnan(value))
      throw Error("'" + given + "' is not a number (NaN)", "option " + name, "give a number in " + range.text());
    if (std::isinf(value) && value != fallback)
      throw Error("'" + given + "' is infinite or overflows a double", "option " + name,
                  "give a finite number in " + range.text());
    if (!std::isinf(value) && !range.contains(value))
      throw Error("'" + given + "' is outside the range " + range.text(), "option " + name,
                  "give a number in " + range.text());
    return value;
  }

  /// A whole number in [low, high]; "1e3" is read as 1000, "2.5" and values that do not fit are
  /// refused with the given text and the range (never cast).
  int integer(const std::string& name, int fallback, const std::string& help,
              int low = std::numeric_limits<int>::min(), int high = std::numeric_limits<int>::max()) {
    return read_integer(name, fallback, help, low, high, nullptr);
  }

  /// A number of elements from `low` to element_limit(memory): a count whose run would need more
  /// than memory_budget() is refused with the memory it would need.
  int elements(const std::string& name, int fallback, const std::string& help, int low, const MemoryUse& memory) {
    return read_integer(name, fallback, help, low, element_limit(memory), &memory);
  }

  /// Declares that option `name` has an effect only when option `other` (read before finish())
  /// has one of `values` (e.g. ancf_cantilever's --force only for the ANCF elements): finish()
  /// refuses a command line that gives `name` while `other` has another value, naming both,
  /// instead of running without it and echoing it as used; --help says when it applies.
  void applies_only_when(const std::string& name, const std::string& other, const std::vector<std::string>& values) {
    conditions_.push_back({name, other, values});
  }

  /// A text; when `choices` is not empty, one of them.
  std::string text(const std::string& name, const std::string& fallback, const std::string& help,
                   const std::vector<std::string>& choices = {}) {
    std::string list;
    for (const auto& choice : choices) list += (list.empty() ? "" : " | ") + choice;
    describe(name, fallback, help, list);
    values_[name] = fallback;
    const auto it = given_.find(name);
    if (it == given_.end()) return fallback;
    used_.push_back(name);
    values_[name] = it->second;
    if (choices.empty()) return it->second;
    for (const auto& choice : choices)
      if (choice == it->second) return it->second;
    throw Error("'" + it->second + "' is not one of " + list, "option " + name, "give one of " + list);
  }

  /// A folder the run writes its results to. finish() creates it and proves it writable, so a
  /// folder that cannot be made (an existing file, no permission, "") is refused before solving.
  std::string output_folder(const std::string& name, const std::string& fallback, const std::string& help) {
    const std::string folder = text(name, fallback, help);
    folders_.emplace_back(name, folder);
    return folder;
  }

  /// Call after reading every option: prints the help and returns false for --help; throws for
  /// options that were given but never read and for output folders that cannot be written.
  bool finish() {
    if (help_) {
      std::printf("%s\n\nOptions:\n", usage_.c_str());
      for (const auto& [name, line] : options_) std::printf("%s%s\n", line.c_str(), applicability(name).c_str());
      std::printf("  --help              this text\n");
      return false;
    }
    for (const auto& [name, value] : given_) {
      bool known = false;
      for (const auto& used : used_) known = known || used == name;
      if (!known)
        throw Error("unknown option " + name, "command line", "see --help for the options");
    }
    for (const Condition& condition : conditions_) check(condition);
    for (const auto& [name, folder] : folders_) prepare_folder(name, folder);
    return true;
  }

private:
  /// `name` applies only when `other` is one of `values` (applies_only_when).
  struct Condition {
    std::string name, other;
    std::vector<std::string> values;

    std::string values_text() const {
      std::string text;
      for (const auto& value : values) text += (text.empty() ? "" : " or ") + value;
      return text;
    }
  };

  int read_integer(const std::string& name, int fallback, const std::string& help, int low, int high,
                   const MemoryUse* memory) {
    const Range range = Range::between(low, high);
    std::string accepted = "[";  // appended piecewise: GCC 12 warns falsely (-Wrestrict) on "[" + …
    accepted.append(std::to_string(low)).append(", ").append(std::to_string(high)).append("]");
    describe(name, std::to_string(fallback), help, accepted);
    check_default(name, fallback, range);
    values_[name] = std::to_string(fallback);
    const auto it = given_.find(name);
    if (it == given_.end()) return fallback;
    used_.push_back(name);
    const std::string& given = it->second;
    char* end = nullptr;
    const double value = std::strtod(given.c_str(), &end);
    if (given.empty() || end == given.c_str() || *end != '\0' || !std::isfinite(value) ||
        value != std::floor(value))
      throw Error("'" + given + "' is not a whole number", "option " + name,
                  "give a whole number in " + accepted);
    if (memory && value > high) require_memory(value, *memory, "option " + name, given);
    if (!range.contains(value))
      throw Error("'" + given + "' is outside the range " + accepted, "option " + name,
                  "give a whole number in " + accepted);
    values_[name] = std::to_string(static_cast<int>(value));
    return static_cast<int>(value);
  }

  void check(const Condition& condition) const {
    if (!given_.count(condition.name)) return;
    const auto other = values_.find(condition.other);
    if (other == values_.end())
      throw Error("option " + condition.name + " is declared to depend on " + condition.other + ", which was not read",
                  "CommandLine::applies_only_when", "the example must read " + condition.other + " before finish()");
    for (const auto& value : condition.values)
      if (value == other->second) return;
    throw Error("option " + condition.name + " applies only when " + condition.other + " is " + condition.values_text() +
                    ", and " + condition.other + " is " + other->second + ": it would be ignored",
                "options " + condition.name + ", " + condition.other,
                "drop " + condition.name + ", or give " + condition.other + " " + condition.values_text());
  }

  /// The --help note of the options that apply only in some modes.
  std::string applicability(const std::string& name) const {
    std::string note;
    for (const Condition& condition : conditions_)
      if (condition.name == name) note += " [only when " + condition.other + " is " + condition.values_text() + "]";
    return note;
  }

  void describe(const std::string& name, const std::string& fallback, const std::string& help,
                const std::string& accepted) {
    std::ostringstream line;
    line << "  " << name << std::string(name.size() < 18 ? 18 - name.size() : 0, ' ') << "  " << help
         << " (default " << fallback << (accepted.empty() ? "" : "; " + accepted) << ")";
    options_.emplace_back(name, line.str());
  }

  /// A default outside its own range is the example's mistake, caught the first time it runs.
  static void check_default(const std::string& name, double fallback, const Range& range) {
    if (!std::isnan(fallback) && (std::isinf(fallback) || range.contains(fallback))) return;
    throw Error("the default " + significant(fallback) + " is outside the range " + range.text(),
                "option " + name, "the example must give a default inside its range");
  }

  static void prepare_folder(const std::string& name, const std::string& folder) {
    namespace fs = std::filesystem;
    const std::string where = "option " + name;
    if (folder.empty()) throw Error("the output folder is empty", where, "give a folder, e.g. results/run");
    std::error_code error;
    fs::create_directories(folder, error);
    if (error || !fs::is_directory(folder))
      throw Error("cannot create the output folder '" + folder + "'" +
                      (error ? ": " + error.message() : ": a file of that name exists"),
                  where, "give a folder you may write to");
    const fs::path probe = fs::path(folder) / ".spar_write_probe";
    const bool writable = static_cast<bool>(std::ofstream(probe));
    fs::remove(probe, error);
    if (!writable)
      throw Error("cannot write into the output folder '" + folder + "'", where,
                  "give a folder you may write to");
  }

  std::string usage_;
  bool help_ = false;
  std::map<std::string, std::string> given_;
  std::vector<std::string> used_;
  std::vector<std::pair<std::string, std::string>> folders_;
  std::map<std::string, std::string> values_;  ///< every option read: its value as given, or its default
  std::vector<Condition> conditions_;
  std::vector<std::pair<std::string, std::string>> options_;  ///< name and --help line, in reading order
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
