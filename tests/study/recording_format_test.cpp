// What the recorder writes besides the results file: CSV numbers exactly as a C++ stream of the
// same precision prints them (the examples' CSVs stayed byte for byte the same when they moved to
// output::CsvFile), the shortest round trip, the JSON summary line, and the schedules' rules.
#include <spar/output/recording_csv.hpp>
#include <spar/output/recording_summary.hpp>
#include <spar/study/schedule.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace spar;

namespace {

const std::vector<double> numbers = {0.0, -0.0, 1.0, 3.0, 0.1, 1.0 / 3.0, -123456.789, 2.5e-300, 1e300,
                                     1e15, 123456789012345678.0, 4.9e-324,
                                     std::numeric_limits<double>::quiet_NaN(),
                                     std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

/// The steps 0 … n_end (the last one the run's last) a schedule records, steps of h from t = 0.
std::vector<long> due_steps(study::Schedule schedule, double h, long n_end) {
  std::vector<long> due;
  for (long n = 0; n <= n_end; ++n)
    if (schedule.due(n, static_cast<double>(n) * h, h, n == n_end)) due.push_back(n);
  return due;
}

}  // namespace

TEST_CASE("CSV numbers print as a stream of that precision, or as the shortest round trip", "[study]") {
  for (const int digits : {6, 9, 12, 15, 17})
    for (const double x : numbers) {
      std::ostringstream stream;
      stream.precision(digits);
      stream << x;
      INFO("digits " << digits << ", x = " << stream.str());
      CHECK(output::format_number(x, digits) == stream.str());
    }
  for (const double x : numbers) {
    if (!std::isfinite(x)) continue;
    const std::string text = output::format_number(x, 0);
    const double back = std::strtod(text.c_str(), nullptr);
    CHECK(std::memcmp(&back, &x, sizeof x) == 0);  // the same bits, −0 included
    CHECK(text.size() <= output::format_number(x, 17).size());
  }
  CHECK(output::format_number(3.0, 0) == "3");  // a counter prints as a whole number
}

TEST_CASE("a CSV file is its header and one line per row", "[study]") {
  const std::string path = (std::filesystem::temp_directory_path() / "spar_study_csv_test.csv").string();
  {
    output::CsvFile csv(path, "t,x", 12);
    csv.row({0.0, 1.0 / 3.0});
    csv.row({0.5, -2.0});
    csv.close();
    CHECK_THROWS_WITH(csv.row({1.0, 1.0}), Catch::Contains("closed"));
  }
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  CHECK(text.str() == "t,x\n0,0.333333333333\n0.5,-2\n");
  std::filesystem::remove(path);
  CHECK_THROWS_WITH(output::CsvFile(path, "t", 18), Catch::Contains("[0, 17]"));
  CHECK_THROWS_WITH(output::CsvFile("/proc/spar_no/x.csv", "t"), Catch::Contains("cannot create"));
}

TEST_CASE("the JSON summary line: 17 digits, whole numbers, strings, null for a missing value", "[study]") {
  const std::string text =
      output::JsonSummary().add("a", 0.1).add("n", 3).add("steps", 40000000000L).add("s", "frozen")
          .add("missing", std::optional<double>{}).text();
  CHECK(text == "{\"a\": 0.10000000000000001, \"n\": 3, \"steps\": 40000000000, \"s\": \"frozen\", \"missing\": null}");
}

TEST_CASE("schedules: every n-th step, the first step past each interval, given times, the last", "[study]") {
  CHECK(due_steps(study::Schedule::every_step(), 0.1, 3) == std::vector<long>{0, 1, 2, 3});
  CHECK(due_steps(study::Schedule::every_steps(3), 0.1, 10) == std::vector<long>{0, 3, 6, 9});
  CHECK(due_steps(study::Schedule::every_steps(3).and_last(), 0.1, 10) == std::vector<long>{0, 3, 6, 9, 10});
  // Multiples of 0.1 with h = 0.03: the first step at t ≥ k·0.1 − h/2 (0.09 for 0.1, 0.21 for 0.2).
  CHECK(due_steps(study::Schedule::every_interval(0.1), 0.03, 13) == std::vector<long>{0, 3, 7, 10, 13});
  CHECK(due_steps(study::Schedule::at_times({0.5, 0.72}), 0.1, 10) == std::vector<long>{5, 7});
  CHECK(due_steps(study::Schedule::every_interval(0.5).and_at({0.2}).and_last(), 0.1, 8) ==
        std::vector<long>{0, 2, 5, 8});
  CHECK(study::Schedule::sampled_every(0.25).sampled());
  CHECK_THROWS_WITH(study::Schedule::every_steps(0), Catch::Contains("no step would be recorded"));
  CHECK_THROWS_WITH(study::Schedule::every_interval(-1.0), Catch::Contains("positive"));
  CHECK_THROWS_WITH(study::Schedule::sampled_every(INFINITY), Catch::Contains("positive"));
}
