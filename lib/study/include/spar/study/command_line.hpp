#pragma once
/// \file
/// A driver's command line: `--name value` options with defaults and help text, `--help`, and a
/// spar::Error for every value a run cannot use (docs/errors.md, "Command line"): malformed,
/// missing or non-finite numbers, values outside an option's range (the message names the range),
/// integers that are not whole or do not fit, choices not on the list, an output folder that
/// cannot be created or written, more elements than the memory holds, an option given where the
/// chosen mode ignores it. Read every option, then call finish():
///
///     study::CommandLine cli(argc, argv, "my_study: what it computes");
///     const double h = cli.number("--h", 1e-3, "time step [s]", study::Range::positive());
///     const std::string out = cli.output_folder("--out", "results/my_study", "output folder");
///     if (!cli.finish()) return 0;  // --help was given

#include <spar/output/provenance.hpp>
#include <spar/study/run_limits.hpp>

#include <exception>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace spar::study {

class CommandLine {
public:
  /// Splits argv into options; spar::Error for an option without a value, one given twice and
  /// an argument that is no option.
  CommandLine(int argc, char** argv, std::string usage);

  /// A real number in `range` (default: any finite number). NaN is always refused; an infinity
  /// only when the default is that same infinity (it then means "off", e.g. a tolerance).
  double number(const std::string& name, double fallback, const std::string& help, Range range = {});
  /// A whole number in [low, high]; "1e3" is read as 1000, "2.5" and values that do not fit are
  /// refused with the given text and the range (never cast).
  int integer(const std::string& name, int fallback, const std::string& help,
              int low = std::numeric_limits<int>::min(), int high = std::numeric_limits<int>::max());
  /// A number of elements from `low` to element_limit(memory): a count whose run would need more
  /// than memory_budget() is refused with the memory it would need.
  int elements(const std::string& name, int fallback, const std::string& help, int low, const MemoryUse& memory);
  /// A text; when `choices` is not empty, one of them.
  std::string text(const std::string& name, const std::string& fallback, const std::string& help,
                   const std::vector<std::string>& choices = {});
  /// A folder the run writes its results to. finish() creates it and proves it writable, so a
  /// folder that cannot be made (an existing file, no permission, "") is refused before solving.
  std::string output_folder(const std::string& name, const std::string& fallback, const std::string& help);
  /// Declares that option `name` has an effect only when option `other` (read before finish())
  /// has one of `values` (e.g. ancf_cantilever's --force only for the ANCF elements): finish()
  /// refuses a command line that gives `name` while `other` has another value, naming both,
  /// instead of running without it; --help says when it applies.
  void applies_only_when(const std::string& name, const std::string& other, const std::vector<std::string>& values);
  /// Call after reading every option: prints the help and returns false for --help; throws for
  /// options that were given but never read and for output folders that cannot be written.
  /// Accepted, the options become the program's finished_options().
  bool finish();
  /// Every option read so far, name → its value as given or its default: the run's options
  /// (output::ResultsWriter::write_options, output::Hdf5File::write_options).
  const output::RunOptions& options() const { return values_; }

private:
  /// `name` applies only when `other` is one of `values` (applies_only_when).
  struct Condition {
    std::string name, other;
    std::vector<std::string> values;
    std::string values_text() const;
  };

  int read_integer(const std::string& name, int fallback, const std::string& help, int low, int high,
                   const MemoryUse* memory);
  void check(const Condition& condition) const;
  /// The --help note of the options that apply only in some modes.
  std::string applicability(const std::string& name) const;
  void describe(const std::string& name, const std::string& fallback, const std::string& help,
                const std::string& accepted);

  std::string usage_;
  bool help_ = false;
  std::map<std::string, std::string> given_;
  std::vector<std::string> used_;
  std::vector<std::pair<std::string, std::string>> folders_;
  output::RunOptions values_;  ///< every option read: its value as given, or its default
  std::vector<Condition> conditions_;
  std::vector<std::pair<std::string, std::string>> options_;  ///< name and --help line, in reading order
};

/// The options of the command line whose finish() last accepted them (empty before): what every
/// study::Recorder writes to its results file's /options (docs/output.md, "Schema and provenance").
const output::RunOptions& finished_options();

/// What a driver's main returns when its run stops on an error: prints error.what() (for a
/// spar::Error: what, where and how to fix it) on stderr and returns 1.
///
///     int main(int argc, char** argv) try {
///       ...
///     } catch (const std::exception& error) { return study::exit_failure(error); }
int exit_failure(const std::exception& error);

/// The three tests of a Newton iteration (solvers::DynamicOptions), as 003 states them
/// (docs/dynamics.md D4).
struct NewtonTest {
  double tolerance;             ///< ‖[Δq, h²βΔλ]‖² (003 §5.1: 1e-6)
  double constraint_tolerance;  ///< ‖Φ‖∞ [m]
  double residual_tolerance;    ///< the dynamic residual relative to its terms; +∞: untested
};

/// --tolerance, --constraint-tolerance and --residual-tolerance; by default 003's test: the
/// increment at 1e-6, Φ at 1e-10 m, the residual untested (or tested at `residual_tolerance`).
NewtonTest newton_test_options(CommandLine& cli, double residual_tolerance = std::numeric_limits<double>::infinity());

}  // namespace spar::study
