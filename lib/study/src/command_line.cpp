#include <spar/study/command_line.hpp>

#include <spar/error.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace spar::study {

namespace {

/// finished_options(): the program's command line, once accepted.
output::RunOptions& last_finished_options() {
  static output::RunOptions options;
  return options;
}

/// A default outside its own range is the driver's mistake, caught the first time it runs.
void check_default(const std::string& name, double fallback, const Range& range) {
  if (!std::isnan(fallback) && (std::isinf(fallback) || range.contains(fallback))) return;
  throw Error("the default " + significant(fallback) + " is outside the range " + range.text(), "option " + name,
              "the example must give a default inside its range");
}

void prepare_folder(const std::string& name, const std::string& folder) {
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
  if (!writable) throw Error("cannot write into the output folder '" + folder + "'", where, "give a folder you may write to");
}

}  // namespace

CommandLine::CommandLine(int argc, char** argv, std::string usage) : usage_(std::move(usage)) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      help_ = true;
    } else if (arg.rfind("--", 0) == 0) {
      // A value is the next argument unless there is none or it is the next option (values may
      // be negative numbers, "-1", but never start with "--").
      if (i + 1 >= argc || std::string(argv[i + 1]).rfind("--", 0) == 0)
        throw Error("option " + arg + " has no value", "command line", "give it one: " + arg + " <value> (see --help)");
      if (given_.count(arg)) throw Error("option " + arg + " is given twice", "command line", "give each option once");
      given_[arg] = argv[++i];
    } else {
      throw Error("unexpected argument '" + arg + "'", "command line", "options are --name value pairs; see --help");
    }
  }
}

double CommandLine::number(const std::string& name, double fallback, const std::string& help, Range range) {
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

int CommandLine::integer(const std::string& name, int fallback, const std::string& help, int low, int high) {
  return read_integer(name, fallback, help, low, high, nullptr);
}

int CommandLine::elements(const std::string& name, int fallback, const std::string& help, int low,
                          const MemoryUse& memory) {
  return read_integer(name, fallback, help, low, element_limit(memory), &memory);
}

void CommandLine::applies_only_when(const std::string& name, const std::string& other,
                                    const std::vector<std::string>& values) {
  conditions_.push_back({name, other, values});
}

std::string CommandLine::text(const std::string& name, const std::string& fallback, const std::string& help,
                              const std::vector<std::string>& choices) {
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

std::string CommandLine::output_folder(const std::string& name, const std::string& fallback, const std::string& help) {
  const std::string folder = text(name, fallback, help);
  folders_.emplace_back(name, folder);
  return folder;
}

bool CommandLine::finish() {
  if (help_) {
    std::printf("%s\n\nOptions:\n", usage_.c_str());
    for (const auto& [name, line] : options_) std::printf("%s%s\n", line.c_str(), applicability(name).c_str());
    std::printf("  --help              this text\n");
    return false;
  }
  for (const auto& [name, value] : given_) {
    bool known = false;
    for (const auto& used : used_) known = known || used == name;
    if (!known) throw Error("unknown option " + name, "command line", "see --help for the options");
  }
  for (const Condition& condition : conditions_) check(condition);
  for (const auto& [name, folder] : folders_) prepare_folder(name, folder);
  last_finished_options() = values_;
  return true;
}

const output::RunOptions& finished_options() { return last_finished_options(); }

std::string CommandLine::Condition::values_text() const {
  std::string text;
  for (const auto& value : values) text += (text.empty() ? "" : " or ") + value;
  return text;
}

int CommandLine::read_integer(const std::string& name, int fallback, const std::string& help, int low, int high,
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
  if (given.empty() || end == given.c_str() || *end != '\0' || !std::isfinite(value) || value != std::floor(value))
    throw Error("'" + given + "' is not a whole number", "option " + name, "give a whole number in " + accepted);
  if (memory && value > high) require_memory(value, *memory, "option " + name, given);
  if (!range.contains(value))
    throw Error("'" + given + "' is outside the range " + accepted, "option " + name,
                "give a whole number in " + accepted);
  values_[name] = std::to_string(static_cast<int>(value));
  return static_cast<int>(value);
}

void CommandLine::check(const Condition& condition) const {
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

std::string CommandLine::applicability(const std::string& name) const {
  std::string note;
  for (const Condition& condition : conditions_)
    if (condition.name == name) note += " [only when " + condition.other + " is " + condition.values_text() + "]";
  return note;
}

void CommandLine::describe(const std::string& name, const std::string& fallback, const std::string& help,
                           const std::string& accepted) {
  std::ostringstream line;
  line << "  " << name << std::string(name.size() < 18 ? 18 - name.size() : 0, ' ') << "  " << help << " (default "
       << fallback << (accepted.empty() ? "" : "; " + accepted) << ")";
  options_.emplace_back(name, line.str());
}

int exit_failure(const std::exception& error) {
  std::fprintf(stderr, "%s\n", error.what());
  return 1;
}

NewtonTest newton_test_options(CommandLine& cli, double residual_tolerance) {
  return {.tolerance = cli.number("--tolerance", 1e-6, "Newton: |[dq, h^2 beta dlambda]|^2 (003: 1e-6)",
                                  newton_tolerances),
          .constraint_tolerance = cli.number("--constraint-tolerance", 1e-10, "Newton: |Phi|_inf [m]", newton_tolerances),
          .residual_tolerance = cli.number("--residual-tolerance", residual_tolerance,
                                           "Newton: relative dynamic residual (inf: off, 003's test)", Range::positive(1))};
}

}  // namespace spar::study
