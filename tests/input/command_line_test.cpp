// The examples' command line (examples/common/cli.hpp) refuses every value a run cannot use with a
// spar::Error naming the option, the problem and the accepted values (issue 15's audit, carried
// over to the CommandLine class: each case is the argument list and a word its message must hold).
#include <common/cli.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using spar::examples::CommandLine;
using spar::examples::Range;

namespace {

/// Reads the options of a typical dynamic example from `args` (without the program name).
void read_dynamic_example(std::vector<std::string> args) {
  std::vector<char*> argv{const_cast<char*>("example")};
  for (auto& arg : args) argv.push_back(arg.data());
  CommandLine cli(static_cast<int>(argv.size()), argv.data(), "example");
  const double h = cli.number("--h", 1e-3, "time step [s]", Range::positive());
  const double t_end = cli.number("--t-end", 1.0, "end time [s]", Range::positive());
  cli.number("--rho-inf", 0.9, "spectral radius at infinity", Range::between(0, 1));
  cli.number("--tolerance", 1e-6, "Newton tolerance", spar::examples::newton_tolerances);
  cli.number("--residual-tolerance", INFINITY, "relative residual (inf: off)", Range::positive(1));
  cli.number("--length", 1.0, "length [m]", Range::positive(1e3));
  cli.integer("--elements", 8, "elements", 1, spar::examples::element_limit(spar::examples::bytes_per_element));
  cli.integer("--steps", 10, "load steps", 1, 100000);
  cli.text("--strategy", "frozen", "iteration matrix", {"update", "frozen", "modified"});
  if (cli.finish()) spar::examples::time_steps(h, t_end);
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
      {{"--elements", "1e6"}, "outside the range"},     // std::bad_alloc after 13-24 s
      {{"--elements", "2147483648"}, "'2147483648' is outside the range"},
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
  CHECK(spar::examples::time_steps(1e-3, 1.0) == 1000);
  CHECK(spar::examples::time_steps(0.1, 0.3) == 3);  // 0.3/0.1 = 2.9999999999999996
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
