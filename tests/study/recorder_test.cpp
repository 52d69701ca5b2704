// study::Recorder on a run whose motion is known in closed form: a body falling freely,
//     x(t) = x₀ + ½ g t²,
// which generalized-α from consistent accelerations reproduces to round-off (tests/output's run
// test). What the recorder writes (the CSV at its schedule, the results file, states sampled
// between steps) and what it reduces (last, max, min, spread, the energy drift) are compared with
// that motion; the declarations it must refuse are refused.
#include <spar/core/model.hpp>
#include <spar/joints/spherical_joint.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/study/command_line.hpp>
#include <spar/study/recorder.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../../examples/heavy_top/reference.hpp"
#include "output_fixtures.hpp"

using namespace spar;
namespace top = spar::examples::heavy_top;

namespace {

const Eigen::Vector3d x0(0.1, 2.0, -0.3), g(0.0, -9.81, 0.0);

/// A body of 2 kg at x0 under gravity, initialized.
struct FallingBody {
  core::Model model;
  int node = 0;
  std::unique_ptr<solvers::GeneralizedAlpha> integrator;

  explicit FallingBody(double h) {
    node = core::rigid_body(model, core::add_rigid_body(model, {.center_of_mass = x0, .mass = 2.0,
                                                               .inertia = Eigen::Matrix3d::Identity()}))
               .node;
    model.set_gravity(g);
    integrator = std::make_unique<solvers::GeneralizedAlpha>(
        model, solvers::ConstraintList{}, solvers::DynamicOptions{.time_step = h, .tolerance = 1e-24});
    integrator->initialize();
  }
};

Eigen::Vector3d exact(double t) { return x0 + 0.5 * g * t * t; }

/// The rows of a CSV file (header first), each split at its commas.
std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::ifstream file(path);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(file, line);) {
    std::vector<std::string> cells;
    std::stringstream stream(line);
    for (std::string cell; std::getline(stream, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

// Round-off of 10 to 40 steps on numbers of O(1): 1e-13 is 100 times what the run test measures.
constexpr double tolerance = 1e-13;

}  // namespace

TEST_CASE("the recorder writes its CSV and results file at its schedule and reduces every step", "[study]") {
  const double h = 0.01, t_end = 0.1;
  FallingBody body(h);
  const spar::test::ScratchFolder folder("study_recorder");
  study::Recorder rec(*body.integrator, {.folder = folder.file(""), .name = "fall", .time_step = h,
                                         .schedule = study::Schedule::every_steps(4).and_last(), .nodes = true,
                                         .csv_digits = 17, .report = false});
  rec.attributes({{"example", "falling body"}, {"elements", 0L}});
  rec.vector({.name = "x", .unit = "m", .description = "the body's position", .csv = "x,y,z"},
             [&](const study::State& s) { return s.q.position[body.node]; });
  rec.vector({.name = "planar", .unit = "m", .description = "its X and Y", .csv = "px,py"},
             [&](const study::State& s) -> Eigen::Vector2d { return s.q.position[body.node].head<2>(); });
  const study::Scalar height = rec.scalar(
      {.name = "height", .every_step = true, .spread_from = 0.05, .file = false},
      [&](const study::State& s) { return s.q.position[body.node].y(); });
  const study::Scalar drift = rec.energy_drift(1.0, {.description = "E - E(0) in J", .every_step = true});
  rec.energy_balance();
  rec.newton_iterations();
  rec.csv({"x", "height", "planar", "newton_iterations"});
  rec.run(t_end);
  rec.close();

  // The CSV: steps 0, 4, 8 and the last, 10; the time first, 17 digits read back exactly.
  const auto rows = read_csv(folder.file("fall.csv"));
  REQUIRE(rows.size() == 5);
  CHECK(rows[0] == std::vector<std::string>{"t", "x", "y", "z", "height", "px", "py", "newton_iterations"});
  const std::vector<long> steps = {0, 4, 8, 10};
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const double t = std::stod(rows[k + 1][0]);
    CHECK(std::abs(t - h * static_cast<double>(steps[k])) < tolerance);
    for (int i = 0; i < 3; ++i) CHECK(std::abs(std::stod(rows[k + 1][1 + i]) - exact(t)(i)) < tolerance);
    CHECK(rows[k + 1][4] == rows[k + 1][2]);  // height is y
    CHECK(rows[k + 1][5] == rows[k + 1][1]);
    CHECK(rows[k + 1][6] == rows[k + 1][2]);
  }
  CHECK(rec.states_written() == 4);

  // The results file: the same four states, the planar probe with z = 0, the counters.
  const spar::test::ReadOnlyFile file(folder.file("fall.h5"));
  const spar::test::DatasetContents time = file.read("/time"), planar = file.read("/probes/planar");
  REQUIRE(time.values.size() == 4);
  CHECK(std::abs(time.values[3] - t_end) < tolerance);
  CHECK(planar.values[3 * 3 + 2] == 0.0);
  CHECK(std::abs(planar.values[3 * 3 + 1] - exact(time.values[3]).y()) < tolerance);
  CHECK(file.has("/scalars/kinetic_energy"));
  CHECK(file.has("/scalars/physical_dissipation"));
  CHECK_FALSE(file.has("/scalars/height"));  // file = false

  // The reductions cover every step (every_step), the start included.
  CHECK(std::abs(height.max() - x0.y()) < tolerance);
  CHECK(std::abs(height.min() - exact(t_end).y()) < tolerance);
  CHECK(std::abs(height.last() - exact(t_end).y()) < tolerance);
  // The spread from t = 0.05 on: the steps 5 … 10.
  std::vector<double> tail;
  for (int n = 5; n <= 10; ++n) tail.push_back(exact(h * n).y());
  double mean = 0.0, sum = 0.0, peak = 0.0;
  for (const double y : tail) mean += y / static_cast<double>(tail.size());
  for (const double y : tail) sum += (y - mean) * (y - mean), peak = std::max(peak, std::abs(y - mean));
  REQUIRE(height.spread());
  CHECK(std::abs(height.spread()->rms - std::sqrt(sum / static_cast<double>(tail.size()))) < tolerance);
  CHECK(std::abs(height.spread()->peak - peak) < tolerance);
  // A falling body keeps its energy: the drift from the start is round-off (|E| ≈ 40 J).
  CHECK(drift.max_abs() < 1e-11);
}

TEST_CASE("a sampled schedule records states between the steps, at the given interval", "[study]") {
  const double h = 0.01, t_end = 0.1;
  FallingBody body(h);
  const spar::test::ScratchFolder folder("study_sampled");
  study::Recorder rec(*body.integrator, {.folder = folder.file(""), .name = "fall", .time_step = h,
                                         .schedule = study::Schedule::sampled_every(0.025), .csv_digits = 17,
                                         .report = false});
  rec.vector({.name = "x", .unit = "m", .description = "the body's position", .csv = "x,y,z"},
             [&](const study::State& s) { return s.q.position[body.node]; });
  rec.csv({"x"});
  rec.run(t_end);
  rec.close();
  // t = 0, 0.025, …, 0.1: off the steps, where the cubic Hermite interpolation of the time sampler
  // is exact for a constant acceleration (docs/dynamics.md D10).
  const auto rows = read_csv(folder.file("fall.csv"));
  REQUIRE(rows.size() == 6);
  for (int k = 0; k < 5; ++k) {
    const double t = std::stod(rows[k + 1][0]);
    CHECK(std::abs(t - 0.025 * k) < tolerance);
    CHECK(std::abs(std::stod(rows[k + 1][2]) - exact(t).y()) < tolerance);
  }
}

TEST_CASE("the recorder refuses a name twice, an unknown CSV column and a declaration after run()", "[study]") {
  FallingBody body(0.01);
  const spar::test::ScratchFolder folder("study_refusals");
  study::Recorder rec(*body.integrator, {.folder = folder.file(""), .name = "fall", .time_step = 0.01, .report = false});
  rec.scalar({.name = "y", .file = false}, [&](const study::State& s) { return s.q.position[body.node].y(); });
  CHECK_THROWS_WITH(rec.scalar({.name = "y", .file = false}, [] { return 0.0; }), Catch::Contains("declared twice"));
  rec.csv({"y", "nothing"});
  CHECK_THROWS_WITH(rec.run(0.05), Catch::Contains("'nothing' names no declared"));
  CHECK_THROWS_WITH(study::Recorder(*body.integrator, {.folder = folder.file(""), .name = "fall"}),
                    Catch::Contains("time step"));

  study::Recorder after(*body.integrator, {.folder = folder.file(""), .name = "after", .time_step = 0.01,
                                           .report = false});
  after.run(0.02);
  CHECK_THROWS_WITH(after.scalar({.name = "late", .file = false}, [] { return 0.0; }), Catch::Contains("after run()"));
  after.close();
}

TEST_CASE("the recorder's results file holds the options of the command line the program finished", "[study]") {
  const spar::test::ScratchFolder folder("study_options");
  std::vector<std::string> args = {"driver", "--h", "0.02", "--out", folder.file("")};
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  study::CommandLine cli(static_cast<int>(argv.size()), argv.data(), "driver");
  const double h = cli.number("--h", 0.01, "time step [s]", study::Range::positive());
  cli.number("--t-end", 0.04, "end time [s]", study::Range::positive());
  const std::string out = cli.output_folder("--out", "results/driver", "output folder");
  REQUIRE(cli.finish());
  CHECK(study::finished_options() == cli.options());
  FallingBody body(h);
  study::Recorder rec(*body.integrator, {.folder = out, .name = "fall", .time_step = h, .report = false});
  rec.run(0.04);
  rec.close();
  const spar::test::ReadOnlyFile file(folder.file("fall.h5"));
  CHECK(file.string_attribute_of("/options", "--h").value == "0.02");        // as given
  CHECK(file.string_attribute_of("/options", "--t-end").value == "0.04");    // its default
  CHECK(file.string_attribute_of("/options", "--out").value == out);
}

TEST_CASE("a profile is written per state as points × components, with its arc lengths", "[study]") {
  // A profile of two points, (y, t) and (2y, 2t), on the falling body: every state's values and
  // the constant arc lengths read back as declared.
  const double h = 0.01;
  FallingBody body(h);
  const spar::test::ScratchFolder folder("study_profile");
  study::Recorder rec(*body.integrator, {.folder = folder.file(""), .name = "fall", .time_step = h, .report = false});
  rec.profile({.name = "pair", .unit = "m, s", .description = "(y, t) at the first point, twice that at the second"},
              Eigen::Vector2d(0.25, 0.75), 2, [&](const study::State& s) {
                Eigen::MatrixXd values(2, 2);
                values << s.q.position[body.node].y(), s.time, 2 * s.q.position[body.node].y(), 2 * s.time;
                return values;
              });
  CHECK_THROWS_WITH(rec.profile({.name = "pair", .unit = "1", .description = "again"}, Eigen::Vector2d(0, 1), 1,
                                [](const study::State&) { return Eigen::MatrixXd::Zero(2, 1); }),
                    Catch::Contains("declared twice"));
  CHECK_THROWS_WITH(rec.profile({.name = "none", .unit = "1", .description = "no points"}, Eigen::VectorXd(), 1,
                                [](const study::State&) { return Eigen::MatrixXd(); }),
                    Catch::Contains("0 points"));
  rec.run(0.05);
  rec.close();

  const spar::test::ReadOnlyFile file(folder.file("fall.h5"));
  const spar::test::DatasetContents pair = file.read("/profiles/pair"), time = file.read("/time");
  REQUIRE(pair.shape == std::vector<hsize_t>{6, 2, 2});
  for (std::size_t k = 0; k < 6; ++k) {
    const double t = time.values[k], y = exact(t).y();
    CHECK(std::abs(pair.values[4 * k + 0] - y) < tolerance);
    CHECK(pair.values[4 * k + 1] == t);
    CHECK(std::abs(pair.values[4 * k + 2] - 2 * y) < tolerance);
    CHECK(pair.values[4 * k + 3] == 2 * t);
  }
  CHECK(file.read("/profiles/pair_arc_length").values == std::vector<double>{0.25, 0.75});
}

TEST_CASE("a profile of the wrong size or with a NaN stops the run with the profile's name", "[study]") {
  FallingBody body(0.01);
  const spar::test::ScratchFolder folder("study_profile_refusals");
  study::Recorder rec(*body.integrator, {.folder = folder.file(""), .name = "fall", .time_step = 0.01, .report = false});
  rec.profile({.name = "short", .unit = "1", .description = "one row where two are declared"}, Eigen::Vector2d(0, 1), 1,
              [](const study::State&) { return Eigen::MatrixXd::Zero(1, 1); });
  CHECK_THROWS_WITH(rec.run(0.05), Catch::Contains("profiles[0] (short)") && Catch::Contains("2 × 1"));

  study::Recorder nan(*body.integrator, {.folder = folder.file(""), .name = "nan", .time_step = 0.01, .report = false});
  nan.profile({.name = "undefined", .unit = "1", .description = "NaN"}, Eigen::VectorXd::Zero(1), 1,
              [](const study::State&) { return Eigen::MatrixXd::Constant(1, 1, std::nan("")); });
  CHECK_THROWS_WITH(nan.run(0.05), Catch::Contains("profiles[0] (undefined)") && Catch::Contains("not finite"));
}

TEST_CASE("the recorder writes the energy alarm of a run that created energy, and none otherwise", "[study]") {
  // The heavy top at ρ∞ = 1, h = 1e-3 (docs/dynamics.md D8a): the alarm at t = 0.428 s.
  const top::TopParameters p = top::classic_top();
  for (const double rho : {1.0, 0.9}) {
    core::Model model;
    const int body = core::rigid_body(model, core::add_rigid_body(model, {.center_of_mass = p.center_of_mass,
                                                                          .mass = p.mass, .inertia = p.inertia}))
                         .node;
    model.set_gravity(p.gravity);
    solvers::ConstraintList joints;
    joints.push_back(std::make_unique<joints::SphericalJoint>(
        joints::Attachment{.node = body, .offset = -p.center_of_mass},
        joints::Attachment{.node = -1, .offset = Eigen::Vector3d::Zero()}, model.state()));
    solvers::GeneralizedAlpha integrator(model, std::move(joints), {.time_step = 1e-3, .spectral_radius = rho});
    const Eigen::Vector3d omega(0.0, 150.0, -4.61538);
    integrator.set_velocity(body, omega.cross(p.center_of_mass), omega);
    integrator.initialize();
    const spar::test::ScratchFolder folder("study_energy_alarm");
    study::Recorder rec(integrator, {.folder = folder.file(""), .name = "top", .time_step = 1e-3,
                                     .schedule = study::Schedule::every_steps(100), .report = false});
    rec.energy_balance();
    rec.run(0.6);
    rec.close();
    const spar::test::ReadOnlyFile file(folder.file("top.h5"));
    CHECK(file.has("/scalars/created_energy"));
    if (rho == 1.0) {
      REQUIRE(integrator.energy_alarm());
      CHECK(file.double_attribute("energy_alarm_time") == integrator.energy_alarm()->time);
      CHECK(file.double_attribute("energy_alarm_created") == integrator.energy_alarm()->created);
      CHECK(file.double_attribute("energy_alarm_scale") == integrator.energy_alarm()->scale);
    } else {
      CHECK_FALSE(integrator.energy_alarm());
      CHECK_THROWS(file.double_attribute("energy_alarm_time"));
    }
  }
}
