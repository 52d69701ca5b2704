// A driver's command line (spar::study::CommandLine, <spar/study/command_line.hpp>) refuses every value a run cannot use with a
// spar::Error naming the option, the problem and the accepted values (issue 15's audit, carried
// over to the CommandLine class: each case is the argument list and a word its message must hold).
#include <spar/study/command_line.hpp>

#include <common/memory_use.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using spar::study::CommandLine;
using spar::study::Range;

namespace {

/// Reads the options of a typical dynamic example from `args` (without the program name).
void read_dynamic_example(std::vector<std::string> args) {
  std::vector<char*> argv{const_cast<char*>("example")};
  for (auto& arg : args) argv.push_back(arg.data());
  CommandLine cli(static_cast<int>(argv.size()), argv.data(), "example");
  const double h = cli.number("--h", 1e-3, "time step [s]", Range::positive());
  const double t_end = cli.number("--t-end", 1.0, "end time [s]", Range::positive());
  cli.number("--rho-inf", 0.9, "spectral radius at infinity", Range::between(0, 1));
  cli.number("--tolerance", 1e-6, "Newton tolerance", spar::study::newton_tolerances);
  cli.number("--residual-tolerance", INFINITY, "relative residual (inf: off)", Range::positive(1));
  cli.number("--length", 1.0, "length [m]", Range::positive(1e3));
  cli.elements("--elements", 8, "elements", 1, spar::study::MemoryUse{.per_element = 1e5});
  cli.integer("--steps", 10, "load steps", 1, 100000);
  cli.text("--strategy", "frozen", "iteration matrix", {"update", "frozen", "modified"});
  if (cli.finish()) spar::study::time_steps(h, t_end);
}

std::string message_of(const std::vector<std::string>& args) {
  try {
    read_dynamic_example(args);
  } catch (const spar::Error& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST_CASE("the command line refuses each bad value of the audit with a message naming it",
          "[cli]") {
  struct Case {
    std::vector<std::string> args;
    std::string word;
  };
  const std::vector<Case> cases = {
      {{"--t-end", "inf"}, "infinite"},                 // heavy_top, flexible_pendulum hung
      {{"--t-end", "1e300"}, "steps"},                  // 10^303 steps
      {{"--h", "1e-9", "--t-end", "100"}, "1e+11 steps"},
      {{"--steps", "1e9"}, "[1, 100000]"},              // cantilever_statics hung
      {{"--h", "1e300"}, "longer than the span"},       // ran zero steps, exit 0
      {{"--h", "1e-2", "--t-end", "1e-3"}, "longer than the span"},
      {{"--t-end", "-1"}, "(0, inf)"},
      {{"--t-end", "nan"}, "NaN"},
      {{"--length", "-1"}, "outside the range"},
      {{"--residual-tolerance", "nan"}, "NaN"},         // silently disabled the check
      {{"--residual-tolerance", "-1"}, "outside the range"},
      {{"--tolerance", "1e300"}, "(0, 0.01]"},          // an 8660 % deformation
      {{"--tolerance", "0"}, "(0, 0.01]"},
      {{"--rho-inf", "1.5"}, "[0, 1]"},
      {{"--elements", "1e6"}, "'1e6' elements would need about 100 GB"},  // std::bad_alloc after 13-24 s
      {{"--elements", "2147483648"}, "'2147483648' elements would need"},
      {{"--elements", "2.5"}, "not a whole number"},
      {{"--elements", "0"}, "[1, "},
      {{"--elements", ""}, "not a whole number"},
      {{"--h", "abc"}, "not a number"},
      {{"--h", "1e-3x"}, "not a number"},
      {{"--h"}, "has no value"},                        // read "unexpected argument '--h'"
      {{"--h", "--t-end", "1"}, "option --h has no value"},
      {{"--h", "1e-3", "--h", "1e-4"}, "twice"},
      {{"--strategy", "fast"}, "update | frozen | modified"},
      {{"--unknown", "1"}, "unknown option"},
      {{"stray"}, "unexpected argument"},
  };
  for (const Case& c : cases) {
    std::string joined;
    for (const auto& arg : c.args) joined += arg + " ";
    INFO("arguments: " << joined);
    const std::string message = message_of(c.args);
    CHECK_THAT(message, Catch::Contains(c.word));
  }
}

TEST_CASE("good command lines pass: negative numbers, exponents, the default infinity", "[cli]") {
  CHECK(message_of({}).empty());
  CHECK(message_of({"--h", "2.5e-4", "--t-end", "0.5", "--elements", "1e2"}).empty());
  CHECK(message_of({"--residual-tolerance", "inf"}).empty());  // the default: the check is off
  CHECK(message_of({"--h", "1e-3", "--t-end", "1e-3"}).empty());  // exactly one step
  CHECK(message_of({"--strategy", "update"}).empty());
  CHECK(spar::study::time_steps(1e-3, 1.0) == 1000);
  CHECK(spar::study::time_steps(0.1, 0.3) == 3);  // 0.3/0.1 = 2.9999999999999996
}

TEST_CASE("a negative number is a value, not a missing one", "[cli]") {
  std::vector<std::string> args{"example", "--load", "-1"};
  std::vector<char*> argv;
  for (auto& arg : args) argv.push_back(arg.data());
  CommandLine cli(static_cast<int>(argv.size()), argv.data(), "example");
  CHECK(cli.number("--load", 0.0, "load", Range::between(-100, 100)) == -1.0);
  CHECK(cli.finish());
}

TEST_CASE("a default outside its own range is caught as the example's mistake", "[cli]") {
  std::vector<std::string> args{"example"};
  std::vector<char*> argv{args[0].data()};
  CommandLine cli(1, argv.data(), "example");
  CHECK_THROWS_WITH(cli.number("--h", -1.0, "step", Range::positive()), Catch::Contains("the default -1"));
  CHECK_THROWS_WITH(cli.integer("--elements", 0, "elements", 1, 10), Catch::Contains("the default 0"));
}

TEST_CASE("an output folder that cannot be made or written is refused by finish, before solving",
          "[cli]") {
  namespace fs = std::filesystem;
  const fs::path scratch = fs::temp_directory_path() / "spar_cli_output_folder_test";
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  std::ofstream(scratch / "a_file") << "x";
  const auto finish_with = [](const std::string& folder) -> std::string {
    std::vector<std::string> args{"example", "--out", folder};
    std::vector<char*> argv;
    for (auto& arg : args) argv.push_back(arg.data());
    CommandLine cli(3, argv.data(), "example");
    cli.output_folder("--out", "results/example", "output folder");
    try {
      cli.finish();
    } catch (const spar::Error& error) {
      return error.what();
    }
    return "";
  };
  CHECK_THAT(finish_with(""), Catch::Contains("empty"));
  CHECK_THAT(finish_with((scratch / "a_file").string()), Catch::Contains("cannot create"));
  CHECK_THAT(finish_with((scratch / "a_file" / "below").string()), Catch::Contains("cannot create"));
  CHECK_THAT(finish_with("/proc/spar_cli_test"), Catch::Contains("cannot create"));
  CHECK(finish_with((scratch / "new" / "folder").string()).empty());
  CHECK(fs::is_directory(scratch / "new" / "folder"));
  CHECK(fs::is_empty(scratch / "new" / "folder"));  // the write probe is gone
  fs::remove_all(scratch);
}

TEST_CASE("--help lists each option's accepted values and creates no folder", "[cli]") {
  std::vector<std::string> args{"example", "--help"};
  std::vector<char*> argv{args[0].data(), args[1].data()};
  CommandLine cli(2, argv.data(), "example");
  cli.output_folder("--out", "/proc/never_created", "output folder");
  CHECK_FALSE(cli.finish());
}

TEST_CASE("ranges print with significant digits", "[cli]") {
  CHECK(spar::significant(-1e-9) == "-1e-09");
  CHECK(Range::between(-1, 0.5).text() == "[-1, 0.5]");
  CHECK(Range{-1, 0.5, true, true}.text() == "(-1, 0.5)");
}

namespace {

/// The message of the spar::Error that `read` throws for the command line `args`, or "".
template <class Read>
std::string refusal(std::vector<std::string> args, Read read) {
  std::vector<char*> argv{const_cast<char*>("example")};
  for (auto& arg : args) argv.push_back(arg.data());
  try {
    CommandLine cli(static_cast<int>(argv.size()), argv.data(), "example");
    read(cli);
  } catch (const spar::Error& error) {
    return error.what();
  }
  return "";
}

/// ancf_cantilever's --element and the options of its ANCF elements (issue 29).
void read_element_options(CommandLine& cli) {
  cli.text("--element", "24", "element", {"24", "30", "gebt"});
  cli.text("--force", "gerstmayr", "elastic forces", {"invariant", "gerstmayr"});
  cli.integer("--case", 2, "load case", 1, 2);
  cli.number("--t-f", 20.0, "deployment time", Range::positive());
  cli.applies_only_when("--force", "--element", {"24", "30"});
  cli.applies_only_when("--t-f", "--case", {"2"});
  cli.finish();
}

}  // namespace

TEST_CASE("an option the chosen mode ignores is refused, naming both options (issue 29)", "[cli]") {
  // Refused: the option is given while the other has a value it does not apply to, as given or
  // by default (ancf_cantilever --element gebt --force invariant ran the beam without a word).
  const std::string gebt = refusal({"--element", "gebt", "--force", "invariant"}, read_element_options);
  CHECK_THAT(gebt, Catch::Contains("option --force applies only when --element is 24 or 30, and --element is gebt"));
  CHECK_THAT(gebt, Catch::Contains("options --force, --element"));
  CHECK_THAT(refusal({"--case", "1", "--t-f", "5"}, read_element_options),
             Catch::Contains("--t-f applies only when --case is 2, and --case is 1"));
  CHECK_THAT(refusal({"--case", "1e0", "--t-f", "5"}, read_element_options),  // an integer compared as read
             Catch::Contains("--case is 1:"));
  // Accepted: the mode it applies to, given or by default; or the option not given at all.
  CHECK(refusal({"--element", "30", "--force", "invariant"}, read_element_options).empty());
  CHECK(refusal({"--force", "invariant"}, read_element_options).empty());
  CHECK(refusal({"--element", "gebt"}, read_element_options).empty());
  CHECK(refusal({"--case", "1"}, read_element_options).empty());
  CHECK(refusal({"--t-f", "5"}, read_element_options).empty());
  // A condition on an option the example never read is the example's mistake.
  CHECK_THAT(refusal({"--force", "invariant"},
                     [](CommandLine& cli) {
                       cli.text("--force", "gerstmayr", "elastic forces", {"invariant", "gerstmayr"});
                       cli.applies_only_when("--force", "--element", {"24"});
                       cli.finish();
                     }),
             Catch::Contains("which was not read"));
}

TEST_CASE("the element limit is one example's memory per element in half the memory (issue 29)", "[cli]") {
  using spar::study::MemoryUse;
  using spar::study::element_limit;
  using spar::study::memory_budget;
  // Each example's own figure (memory_use.hpp): its maximum is accepted, one more is refused with
  // the memory that run would need, without building anything.
  const std::vector<std::pair<std::string, MemoryUse>> examples = {
      {"cantilever_statics", spar::examples::memory_use::cantilever_statics},
      {"slider_crank", spar::examples::memory_use::slider_crank},
      {"modal_beam", spar::examples::memory_use::modal_beam},
      {"falling_beam", spar::examples::memory_use::falling_beam},
      {"flexible_pendulum", spar::examples::memory_use::flexible_pendulum},
      {"truss_deployment", spar::examples::memory_use::truss_deployment},
  };
  for (const auto& [name, memory] : examples) {
    INFO(name);
    const int limit = element_limit(memory);
    CHECK(limit >= 1);
    CHECK(memory.bytes(limit) <= memory_budget());
    CHECK(memory.bytes(limit + 1.0) > memory_budget());
    const auto read = [&memory = memory](CommandLine& cli) {
      cli.elements("--elements", 1, "elements", 1, memory);
      cli.finish();
    };
    CHECK(refusal({"--elements", std::to_string(limit)}, read).empty());
    const std::string beyond = refusal({"--elements", std::to_string(limit + 1)}, read);
    CHECK_THAT(beyond, Catch::Contains("'" + std::to_string(limit + 1) + "' elements would need about"));
    CHECK_THAT(beyond, Catch::Contains("GB of memory"));
    CHECK_THAT(beyond, Catch::Contains("kB per element"));
    CHECK_THAT(beyond, Catch::Contains("give at most " + std::to_string(limit) + " elements"));
  }
  // The former common bound (10⁵ bytes per element) let slider_crank, modal_beam, falling_beam and
  // flexible_pendulum take 126380 elements on a 23 GB machine: their runs need more than that.
  for (const MemoryUse& memory : {spar::examples::memory_use::slider_crank, spar::examples::memory_use::modal_beam,
                                  spar::examples::memory_use::falling_beam, spar::examples::memory_use::flexible_pendulum})
    CHECK(element_limit(memory) < element_limit(MemoryUse{.per_element = 1e5}));
  // A dense matrix's n² term: the limit is the root of a n² + b n = budget.
  const MemoryUse dense{.per_element = 0.0, .per_element_squared = 8.0};
  CHECK(element_limit(dense) == static_cast<int>(std::floor(std::sqrt(memory_budget() / 8.0))));
}

TEST_CASE("a time later than the run's end is refused, naming both options (issue 29)", "[cli]") {
  using spar::study::require_within_run;
  // four_bar --output-interval 1e300 wrote the state at t = 0 only; truss_deployment --t-f 1e300
  // deployed nothing.
  CHECK_THROWS_WITH(require_within_run(1e300, "--output-interval", "the file would hold t = 0 only", 1.0),
                    Catch::Contains("--output-interval = 1e+300 s is later than the end of the run, --t-end = 1 s"));
  CHECK_THROWS_WITH(require_within_run(20.5, "--t-f", "nothing deploys", 20.0), Catch::Contains("options --t-f, --t-end"));
  CHECK_NOTHROW(require_within_run(20.0, "--t-f", "nothing deploys", 20.0));  // the law ends with the run
  CHECK_NOTHROW(require_within_run(0.0, "--output-interval", "", 1.0));       // 0: every step
}

TEST_CASE("a beam that is no slender beam is refused before solving (issue 29)", "[cli]") {
  using spar::study::require_slender_beam;
  // modal_beam --length 1e-6 --width 1 --height 1: a "beam" a million times thicker than long.
  CHECK_THROWS_WITH(require_slender_beam(1e-6, "--length", 1, "--width", 1, "--height"),
                    Catch::Contains("slenderness of 1e-06") && Catch::Contains("deep beam") &&
                        Catch::Contains("options --length, --width, --height"));
  // cantilever_statics --length 1e3 --width 1e-6: 10⁹, Newton failed at load factor 0.
  CHECK_THROWS_WITH(require_slender_beam(1e3, "--length", 1e-6, "--width", 1e-6, "--width"),
                    Catch::Contains("slenderness of 1e+09, more than 10000") &&
                        Catch::Contains("options --length, --width") && Catch::Contains("at most 0.01 m"));
  // The bounds themselves are beams: 3 and 10⁴.
  CHECK_NOTHROW(require_slender_beam(3.0, "--length", 1.0, "--width", 1.0, "--width"));
  CHECK_NOTHROW(require_slender_beam(1e3, "--length", 0.1, "--width", 0.1, "--width"));
  CHECK_NOTHROW(require_slender_beam(1.0, "--length", 0.01, "--height", 0.02, "--width"));  // modal_beam's default
  CHECK_THROWS(require_slender_beam(2.9, "--length", 0.01, "--height", 1.0, "--width"));      // a 1 m deep section
  // An example's own upper bound (modal_beam: 3·10³).
  CHECK_THROWS_WITH(require_slender_beam(1e3, "--length", 0.1, "--width", 0.1, "--height", 3e3),
                    Catch::Contains("more than 3000"));
}
