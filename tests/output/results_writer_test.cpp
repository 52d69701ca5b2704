#include "output_fixtures.hpp"
#include "xml_reader.hpp"

#include <spar/output/hdf5_file.hpp>
#include <spar/output/results_writer.hpp>
#include <spar/error.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

using Catch::Matchers::Contains;
using spar::output::ResultsLayout;
using spar::output::ResultsWriter;
using spar::test::DatasetContents;
using spar::test::ReadOnlyFile;
using spar::test::SampleStep;

namespace {

constexpr int sample_steps = 5;

/// The material-frame vertices of the sample layout's shapes, written out by hand: the box's
/// corners offset + ½ (±0.4, ±0.2, ±0.1) in VTK's hexahedron order, and the axes' segments of the
/// default length, a tenth of the diagonal of the first step's extent — its nodes and
/// centerlines span [0, 4] × [0, 4] × [0, 5] (output_fixtures.hpp), a diagonal of √57.
std::vector<Eigen::Vector3d> sample_shape_corners(int shape) {
  if (shape == 0) {
    const int signs[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                             {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    std::vector<Eigen::Vector3d> corners;
    for (const auto& s : signs)
      corners.push_back(Eigen::Vector3d(0.05, -0.1, 0.2) + Eigen::Vector3d(0.2 * s[0], 0.1 * s[1], 0.05 * s[2]));
    return corners;
  }
  const double L = 0.1 * std::sqrt(57.0);
  return {Eigen::Vector3d::Zero(), Eigen::Vector3d(L, 0, 0), Eigen::Vector3d::Zero(),
          Eigen::Vector3d(0, L, 0),  Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, L)};
}

/// Each shape's vertices are x + R c and their velocities ẋ + R (Ω × c), c its material-frame
/// vertices; computed here vertex by vertex, in the writer as one product, so they agree to
/// round-off: 1e-14 for positions of size 10, 1e-12 for velocities of size 500 (Ω ~ 400 rad/s).
void check_shapes(const ReadOnlyFile& file, int steps) {
  const auto S = static_cast<hsize_t>(steps);
  for (int shape = 0; shape < 2; ++shape) {
    const std::vector<Eigen::Vector3d> corners = sample_shape_corners(shape);
    const auto V = corners.size();
    const std::string k = std::to_string(shape);
    const DatasetContents vertices = file.read("/rigid_bodies/body" + k),
                          velocities = file.read("/rigid_body_fields/velocity/body" + k);
    REQUIRE(vertices.shape == std::vector<hsize_t>{S, V, 3});
    REQUIRE(velocities.shape == std::vector<hsize_t>{S, V, 3});
    const int node = shape == 0 ? 1 : 2;
    for (int step = 0; step < steps; ++step) {
      const SampleStep sample(step);
      const Eigen::Matrix3d& R = sample.configuration.rotation[static_cast<std::size_t>(node)];
      const Eigen::Vector3d& x = sample.configuration.position[static_cast<std::size_t>(node)];
      const Eigen::Vector3d x_dot = sample.velocity.segment<3>(6 * node), omega = sample.velocity.segment<3>(6 * node + 3);
      for (std::size_t v = 0; v < V; ++v) {
        const Eigen::Vector3d expected = x + R * corners[v], expected_velocity = x_dot + R * omega.cross(corners[v]);
        for (std::size_t c = 0; c < 3; ++c) {
          const std::size_t at = (static_cast<std::size_t>(step) * V + v) * 3 + c;
          CHECK(std::abs(vertices.values[at] - expected(static_cast<int>(c))) <= 1e-14);
          CHECK(std::abs(velocities.values[at] - expected_velocity(static_cast<int>(c))) <= 1e-12);
        }
      }
    }
  }
  CHECK(file.read("/xdmf/hexahedron").values == std::vector<double>{0, 1, 2, 3, 4, 5, 6, 7});
  CHECK(file.read("/xdmf/axes").shape == std::vector<hsize_t>{3, 2});
  CHECK(file.read("/xdmf/axes").values == std::vector<double>{0, 1, 2, 3, 4, 5});
}

/// Every value but the quaternions is copied, not computed, so the round trip must be exact; the
/// quaternions are checked against the stored rotations through an independent formula.
void check_round_trip(const ReadOnlyFile& file, int steps) {
  const auto S = static_cast<hsize_t>(steps);
  const DatasetContents time = file.read("/time"), positions = file.read("/positions"),
                        quaternions = file.read("/quaternions"), velocities = file.read("/velocities"),
                        multipliers = file.read("/multipliers"), tip = file.read("/probes/tip");
  CHECK(time.shape == std::vector<hsize_t>{S});
  CHECK(positions.shape == std::vector<hsize_t>{S, 3, 3});
  CHECK(quaternions.shape == std::vector<hsize_t>{S, 3, 4});
  CHECK(velocities.shape == std::vector<hsize_t>{S, 3, 6});
  CHECK(multipliers.shape == std::vector<hsize_t>{S, 2});
  CHECK(tip.shape == std::vector<hsize_t>{S, 3});
  for (int k = 0; k < steps; ++k) {
    const SampleStep sample(k);
    const auto s = static_cast<std::size_t>(k);
    CHECK(time.values[s] == sample.step.time);
    for (std::size_t i = 0; i < 3; ++i) {
      // The stored (w, x, y, z) must be the unit quaternion, w ≥ 0, of the stored rotation:
      // rebuilt here by Rodrigues' form R = (w² − v·v) I + 2 v vᵀ + 2 w [v]×, independent of the
      // writer's conversion. A unit quaternion rounded to doubles gives R to a few ulp: 1e-15.
      const double* stored_q = &quaternions.values[(s * 3 + i) * 4];
      const double w = stored_q[0];
      const Eigen::Vector3d v(stored_q[1], stored_q[2], stored_q[3]);
      Eigen::Matrix3d v_hat;
      v_hat << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
      const Eigen::Matrix3d R = (w * w - v.squaredNorm()) * Eigen::Matrix3d::Identity() +
                                2.0 * v * v.transpose() + 2.0 * w * v_hat;
      CHECK(w >= 0);
      CHECK(std::abs(w * w + v.squaredNorm() - 1.0) <= 1e-15);
      CHECK((R - sample.configuration.rotation[i]).cwiseAbs().maxCoeff() <= 1e-15);
      for (std::size_t c = 0; c < 3; ++c) CHECK(positions.values[(s * 3 + i) * 3 + c] == sample.configuration.position[i](static_cast<int>(c)));
    }
    for (std::size_t j = 0; j < 18; ++j) CHECK(velocities.values[s * 18 + j] == sample.velocity(static_cast<int>(j)));
    for (std::size_t j = 0; j < 2; ++j) CHECK(multipliers.values[s * 2 + j] == sample.multipliers(static_cast<int>(j)));
    CHECK(file.read("/scalars/kinetic_energy").values[s] == sample.step.scalars[0]);
    CHECK(file.read("/scalars/newton_iterations").values[s] == sample.step.scalars[1]);
    for (std::size_t c = 0; c < 3; ++c) CHECK(tip.values[s * 3 + c] == sample.step.probes[0](static_cast<int>(c)));
    for (std::size_t beam = 0; beam < 2; ++beam) {
      const DatasetContents centerline = file.read("/centerlines/beam" + std::to_string(beam));
      const Eigen::MatrixXd& expected = sample.step.centerlines[beam];
      REQUIRE(centerline.shape == std::vector<hsize_t>{S, static_cast<hsize_t>(expected.rows()), 3});
      for (int p = 0; p < expected.rows(); ++p)
        for (int c = 0; c < 3; ++c)
          CHECK(centerline.values[(s * static_cast<std::size_t>(expected.rows()) + static_cast<std::size_t>(p)) * 3 +
                                  static_cast<std::size_t>(c)] == expected(p, c));
      const std::string k = std::to_string(beam);
      const DatasetContents arc_length = file.read("/centerline_fields/arc_length/beam" + k),
                            velocity = file.read("/centerline_fields/velocity/beam" + k);
      const auto P = static_cast<std::size_t>(expected.rows());
      REQUIRE(arc_length.shape == std::vector<hsize_t>{S, P});
      REQUIRE(velocity.shape == std::vector<hsize_t>{S, P, 3});
      for (std::size_t p = 0; p < P; ++p) {
        CHECK(arc_length.values[s * P + p] == sample.step.centerline_fields[beam][0](static_cast<int>(p), 0));
        for (std::size_t c = 0; c < 3; ++c)
          CHECK(velocity.values[(s * P + p) * 3 + c] ==
                sample.step.centerline_fields[beam][1](static_cast<int>(p), static_cast<int>(c)));
      }
    }
  }
}

}  // namespace

TEST_CASE("ResultsWriter round-trips every dataset whatever the block size", "[output]") {
  const int flush_every = GENERATE(1, 2, sample_steps, 64);
  const spar::test::ScratchFolder folder("round_trip_" + std::to_string(flush_every));
  const std::string path = folder.file("run.h5");
  {
    ResultsWriter writer(path, spar::test::sample_layout(), flush_every);
    writer.write_attribute("strategy", std::string("frozen"));
    writer.write_attribute("h", 5e-4);
    writer.write_attribute("h", 1e-4);  // replaced, not duplicated
    for (int k = 0; k < sample_steps; ++k) {
      writer.append(SampleStep(k).step);
      CHECK(writer.steps_written() == k + 1);
      CHECK(writer.steps_flushed() == (k + 1) / flush_every * flush_every);
    }
    writer.write_attribute("newton_iterations", 42);
    writer.write_constant("reference/centerline", Eigen::MatrixXd::Identity(4, 3), "m", "reference centerline");
    writer.close();
    CHECK(writer.steps_flushed() == sample_steps);
    writer.close();  // idempotent
  }
  const ReadOnlyFile file(path);
  check_round_trip(file, sample_steps);
  check_shapes(file, sample_steps);
  CHECK(file.string_attribute("strategy") == "frozen");
  CHECK(file.double_attribute("h") == 1e-4);
  CHECK(file.integer_attribute("schema") == 3);  // results_provenance_test.cpp: the provenance
  CHECK(file.integer_attribute("newton_iterations") == 42);
  const DatasetContents reference = file.read("reference/centerline");
  CHECK(reference.shape == std::vector<hsize_t>{4, 3});
  CHECK(reference.values[0] == 1.0);
  CHECK(reference.values[4] == 1.0);
  CHECK(reference.values[1] == 0.0);
  CHECK(file.read("/xdmf/polyline1").values == std::vector<double>{0, 1, 2, 3, 4});
  CHECK(file.read("/xdmf/polyvertex").values == std::vector<double>{0, 1, 2});
}

TEST_CASE("ResultsWriter writes only the datasets of its layout", "[output]") {
  const spar::test::ScratchFolder folder("minimal");
  const std::string path = folder.file("minimal.h5");
  ResultsLayout layout;
  layout.scalars = {{.name = "total_energy", .unit = "J", .description = "total energy"}};
  {
    ResultsWriter writer(path, layout, 3);
    for (int k = 0; k < 4; ++k) {
      spar::output::ResultsStep step;
      step.time = k;
      step.scalars = {10.0 * k};
      writer.append(step);
    }
  }  // the destructor flushes and closes
  const ReadOnlyFile file(path);
  CHECK(file.read("/time").values == std::vector<double>{0, 1, 2, 3});
  CHECK(file.read("/scalars/total_energy").values == std::vector<double>{0, 10, 20, 30});
  for (const char* absent :
       {"/positions", "/quaternions", "/velocities", "/multipliers", "/probes", "/centerlines", "/centerline_fields",
        "/rigid_bodies", "/rigid_body_fields", "/xdmf/hexahedron", "/xdmf/axes"})
    CHECK_FALSE(file.has(absent));
}

TEST_CASE("ResultsWriter rejects steps that do not match the layout", "[output]") {
  const spar::test::ScratchFolder folder("validation");
  ResultsWriter writer(folder.file("run.h5"), spar::test::sample_layout(), 2);
  writer.append(SampleStep(0).step);
  SampleStep sample(1);
  spar::output::ResultsStep& step = sample.step;

  SECTION("configuration") {
    step.configuration = nullptr;
    CHECK_THROWS_WITH(writer.append(step), Contains("step.configuration nodes") && Contains("expected 3"));
  }
  SECTION("velocity") {
    const Eigen::VectorXd short_velocity = Eigen::VectorXd::Zero(12);
    step.velocity = &short_velocity;
    CHECK_THROWS_WITH(writer.append(step), Contains("step.velocity has 12 entries") && Contains("18"));
    step.velocity = nullptr;
    CHECK_THROWS_WITH(writer.append(step), Contains("step.velocity has 0 entries"));
  }
  SECTION("multipliers") {
    step.multipliers = nullptr;
    CHECK_THROWS_WITH(writer.append(step), Contains("step.multipliers has 0 entries, expected 2"));
  }
  SECTION("counters") {
    step.scalars[1] = 2.5;
    CHECK_THROWS_WITH(writer.append(step), Contains("step.scalars[1] = 2.5") && Contains("newton_iterations") &&
                                               Contains("not a whole number"));
  }
  SECTION("scalars and probes") {
    step.scalars.pop_back();
    CHECK_THROWS_WITH(writer.append(step), Contains("step.scalars has 1 entries, expected 2"));
    step.scalars.push_back(0);
    step.probes.push_back(Eigen::Vector3d::Zero());
    CHECK_THROWS_WITH(writer.append(step), Contains("step.probes has 2 entries, expected 1"));
  }
  SECTION("centerlines") {
    step.centerlines[1] = Eigen::MatrixXd::Zero(4, 3);
    CHECK_THROWS_WITH(writer.append(step), Contains("step.centerlines[1]") && Contains("5 × 3") && Contains("got 4 × 3"));
    step.centerlines.pop_back();
    CHECK_THROWS_WITH(writer.append(step), Contains("step.centerlines has 1 entries, expected 2 beams"));
  }
  SECTION("centerline fields") {
    step.centerline_fields[1][1] = Eigen::MatrixXd::Zero(5, 1);
    CHECK_THROWS_WITH(writer.append(step), Contains("step.centerline_fields[1][1] (velocity)") && Contains("5 × 3") &&
                                               Contains("got 5 × 1"));
    step.centerline_fields[1].pop_back();
    CHECK_THROWS_WITH(writer.append(step), Contains("step.centerline_fields[1] has 1 entries, expected 2"));
    step.centerline_fields.clear();
    CHECK_THROWS_WITH(writer.append(step), Contains("step.centerline_fields has 0 entries, expected 2 beams"));
  }
  // NaN is a value only where the layout declares it may be undefined (issue 29: a NaN probe and
  // a NaN position were written silently).
  SECTION("a NaN probe") {
    step.probes[0].y() = NAN;
    CHECK_THROWS_WITH(writer.append(step), Contains("step.probes[0] (tip)") && Contains("is not finite") &&
                                               Contains("at step 1") && Contains("may_be_undefined"));
    ResultsLayout undefined = spar::test::sample_layout();
    undefined.probes[0].may_be_undefined = true;
    ResultsWriter lenient(folder.file("undefined.h5"), undefined, 2);
    CHECK_NOTHROW(lenient.append(step));
    step.probes[0].y() = INFINITY;
    step.time += 1.0;
    CHECK_THROWS_WITH(lenient.append(step), Contains("step.probes[0] (tip) component 1 = inf is not finite"));
  }
  SECTION("a NaN or infinite value in the configuration, velocity, multipliers, centerlines or fields") {
    sample.configuration.position[2].x() = NAN;
    CHECK_THROWS_WITH(writer.append(step), Contains("step.configuration position of node 2") &&
                                               Contains("is not finite") && Contains("at step 1"));
    sample.configuration.position[2].x() = 0;
    sample.configuration.rotation[1](0, 0) = NAN;
    CHECK_THROWS_WITH(writer.append(step), Contains("step.configuration rotation of node 1"));
    sample.configuration.rotation[1] = Eigen::Matrix3d::Identity();
    sample.velocity(4) = INFINITY;
    CHECK_THROWS_WITH(writer.append(step), Contains("step.velocity") && Contains("entry 4"));
    sample.velocity(4) = 0;
    sample.multipliers(1) = NAN;
    CHECK_THROWS_WITH(writer.append(step), Contains("step.multipliers") && Contains("entry 1"));
    sample.multipliers(1) = 0;
    step.centerlines[1](3, 2) = NAN;
    CHECK_THROWS_WITH(writer.append(step), Contains("step.centerlines[1]") && Contains("row 3"));
    step.centerlines[1](3, 2) = 0;
    step.centerline_fields[0][1](2, 0) = NAN;
    CHECK_THROWS_WITH(writer.append(step), Contains("step.centerline_fields[0][1] (velocity)") && Contains("row 2"));
  }
  SECTION("time") {
    step.time = SampleStep(0).step.time;
    CHECK_THROWS_WITH(writer.append(step), Contains("step.time") && Contains("not after the previous step"));
  }
  // A rejected step leaves nothing behind: the writer goes on with the next valid one.
  CHECK(writer.steps_written() == 1);
  writer.append(SampleStep(1).step);
  CHECK(writer.steps_written() == 2);
  CHECK(writer.steps_flushed() == 2);
}

TEST_CASE("ResultsWriter reports bad layouts, paths and late writes", "[output]") {
  const spar::test::ScratchFolder folder("errors");
  ResultsLayout layout = spar::test::sample_layout();

  SECTION("a folder that does not exist") {
    const std::string path = folder.file("missing/run.h5");
    CHECK_THROWS_AS(ResultsWriter(path, layout), spar::Error);
    CHECK_THROWS_WITH(ResultsWriter(path, layout), Contains(path) && Contains("does not exist"));
  }
  SECTION("a path that is a folder") {
    // The writer thread makes the file; the constructor still refuses a path it could not write.
    const std::string path = folder.file("run.h5");
    std::filesystem::create_directory(path);
    CHECK_THROWS_WITH(ResultsWriter(path, layout), Contains("cannot create the results file " + path + ": it is a folder"));
  }
  SECTION("layout") {
    layout.centerline_points[0] = 1;
    CHECK_THROWS_WITH(ResultsWriter(folder.file("a.h5"), layout), Contains("layout.centerline_points[0] = 1"));
    layout = spar::test::sample_layout();
    layout.scalars.push_back(layout.scalars[0]);
    CHECK_THROWS_WITH(ResultsWriter(folder.file("b.h5"), layout), Contains("\"kinetic_energy\" twice"));
    layout = spar::test::sample_layout();
    layout.probes[0].name = "a/b";
    CHECK_THROWS_WITH(ResultsWriter(folder.file("c.h5"), layout), Contains("contains '/'"));
    layout = spar::test::sample_layout();
    layout.scalars[0].unit = "";
    CHECK_THROWS_WITH(ResultsWriter(folder.file("e.h5"), layout), Contains("\"kinetic_energy\" has no unit"));
    layout = spar::test::sample_layout();
    layout.probes[0].description = "";
    CHECK_THROWS_WITH(ResultsWriter(folder.file("f.h5"), layout), Contains("\"tip\" has no description"));
    layout = spar::test::sample_layout();
    layout.probes[0].integer = true;
    CHECK_THROWS_WITH(ResultsWriter(folder.file("g.h5"), layout), Contains("\"tip\" is marked integer"));
    layout = spar::test::sample_layout();
    layout.centerline_fields[1].components = 2;
    CHECK_THROWS_WITH(ResultsWriter(folder.file("h.h5"), layout), Contains("\"velocity\" has 2 components"));
    layout = spar::test::sample_layout();
    layout.centerline_fields[0].name = "s|t";
    CHECK_THROWS_WITH(ResultsWriter(folder.file("i.h5"), layout), Contains("\"s|t\" contains ':' or '|'"));
    layout = spar::test::sample_layout();
    layout.centerline_fields[0].name = std::string("s") + char(1) + "t";
    CHECK_THROWS_WITH(ResultsWriter(folder.file("j.h5"), layout), Contains("control character"));
    CHECK_THROWS_WITH(ResultsWriter(folder.file("d.h5"), spar::test::sample_layout(), 0), Contains("flush_every = 0"));
  }
  SECTION("rigid-body shapes") {
    layout.rigid_bodies[0].node = 3;
    CHECK_THROWS_WITH(ResultsWriter(folder.file("k.h5"), layout),
                      Contains("layout.rigid_bodies[0].node = 3 is not a node") && Contains("node_count = 3"));
    layout = spar::test::sample_layout();
    layout.rigid_bodies[0].size.z() = 0.0;
    CHECK_THROWS_WITH(ResultsWriter(folder.file("l.h5"), layout),
                      Contains("layout.rigid_bodies[0] has size (0.4, 0.2, 0)") && Contains("box's three edge lengths"));
    layout = spar::test::sample_layout();
    layout.rigid_bodies[1].size = {0.1, 0.0, 0.1};  // axes: all given or all left to the model
    CHECK_THROWS_WITH(ResultsWriter(folder.file("m.h5"), layout), Contains("all zero for a tenth"));
    layout = spar::test::sample_layout();
    layout.rigid_bodies[1].offset.x() = NAN;
    CHECK_THROWS_WITH(ResultsWriter(folder.file("n.h5"), layout), Contains("layout.rigid_bodies[1]"));
  }
  SECTION("names taken and a closed file") {
    ResultsWriter writer(folder.file("run.h5"), layout);
    CHECK_THROWS_WITH(writer.write_constant("time", Eigen::MatrixXd::Zero(1, 1), "s", "t"), Contains("already holds an object named time"));
    // Attributes are written by the writer thread; a name HDF5 would refuse is refused at the call.
    CHECK_THROWS_WITH(writer.write_attribute("", 1.0), Contains("the attribute name has 0 characters"));
    CHECK_THROWS_WITH(writer.write_attribute(std::string(65001, 'x'), 1.0),
                      Contains("the attribute name has 65001 characters"));
    CHECK_THROWS_WITH(writer.write_constant("reference", Eigen::Matrix2d::Constant(NAN), "m", "r"),
                      Contains("write_constant") && Contains("reference") && Contains("row 0, column 0") &&
                          Contains("is not finite"));
    writer.close();
    CHECK_THROWS_WITH(writer.append(SampleStep(0).step), Contains("closed"));
    CHECK_THROWS_WITH(writer.write_attribute("x", 1.0), Contains("closed"));
  }
}

TEST_CASE("ResultsWriter draws a rotated body's box at x + R c and its axes at their default length", "[output]") {
  // One body at x = (1, 2, 3) turned by 90° about Z: R maps material X to Y and Y to −X, so the
  // box's corner c = (−a, −b, −c)/2 + offset lies at x + (b/2 − o_y, −a/2 + o_x, −c/2 + o_z), and
  // the axes' ends at x + L Y, x − L X, x + L Z. Every number is a sum of a few exact binary
  // fractions and 2^-k multiples, but cos(π/2) = 6e-17 rounds R: 1e-15.
  const spar::test::ScratchFolder folder("shapes");
  const std::string path = folder.file("run.h5");
  spar::output::ResultsLayout layout;
  layout.node_count = 2;
  layout.velocities = false;
  layout.rigid_bodies = {{.node = 0, .kind = spar::output::RigidBodyShape::Kind::box, .size = {0.5, 0.25, 1.0},
                          .offset = {0.125, 0.0, -0.5}},
                         {.node = 0}};
  spar::core::Configuration q;
  q.add_frame(Eigen::Vector3d(1, 2, 3), Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix());
  q.add_frame(Eigen::Vector3d(1, 2, 3) + Eigen::Vector3d(3, 4, 0), Eigen::Matrix3d::Identity());  // extent: diagonal 5
  {
    ResultsWriter writer(path, layout, 1);
    writer.append({.time = 0.0, .configuration = &q});
  }
  const ReadOnlyFile file(path);
  const DatasetContents box = file.read("/rigid_bodies/body0"), axes = file.read("/rigid_bodies/body1");
  REQUIRE(box.shape == std::vector<hsize_t>{1, 8, 3});
  REQUIRE(axes.shape == std::vector<hsize_t>{1, 6, 3});
  const Eigen::Vector3d corner0(1 + 0.125 - 0.0, 2 - 0.25 + 0.125, 3 - 0.5 - 0.5);  // x + (b/2, −a/2 + o_x, −c/2 + o_z)
  const Eigen::Vector3d corner6(1 - 0.125, 2 + 0.25 + 0.125, 3 + 0.5 - 0.5);        // c = (a, b, c)/2 + offset
  for (int c = 0; c < 3; ++c) {
    CHECK(std::abs(box.values[static_cast<std::size_t>(c)] - corner0(c)) <= 1e-15);
    CHECK(std::abs(box.values[static_cast<std::size_t>(18 + c)] - corner6(c)) <= 1e-15);
  }
  const double L = 0.5;  // a tenth of the diagonal 5 of the nodes' extent
  const Eigen::Vector3d x(1, 2, 3);
  const Eigen::Vector3d ends[6] = {x, x + L * Eigen::Vector3d::UnitY(), x, x - L * Eigen::Vector3d::UnitX(),
                                   x, x + L * Eigen::Vector3d::UnitZ()};
  for (std::size_t v = 0; v < 6; ++v)
    for (int c = 0; c < 3; ++c) CHECK(std::abs(axes.values[3 * v + static_cast<std::size_t>(c)] - ends[v](c)) <= 1e-15);
  CHECK_FALSE(file.has("/rigid_body_fields"));  // no velocities in this layout
}

TEST_CASE("ResultsWriter refuses default axes on a model of one point", "[output]") {
  const spar::test::ScratchFolder folder("one_point");
  spar::output::ResultsLayout layout;
  layout.node_count = 1;
  layout.velocities = false;
  layout.rigid_bodies = {{.node = 0}};
  spar::core::Configuration q;
  q.add_frame(Eigen::Vector3d(1, 2, 3), Eigen::Matrix3d::Identity());
  ResultsWriter writer(folder.file("run.h5"), layout, 1);
  CHECK_THROWS_WITH(writer.append({.time = 0.0, .configuration = &q}),
                    Contains("all at one point") && Contains("give the axes' lengths in size"));
}

TEST_CASE("A moved ResultsWriter keeps writing the same file", "[output]") {
  const spar::test::ScratchFolder folder("move");
  const std::string path = folder.file("run.h5");
  {
    ResultsWriter first(path, spar::test::sample_layout(), 10);
    first.append(SampleStep(0).step);
    ResultsWriter second = std::move(first);
    second.append(SampleStep(1).step);
  }
  const ReadOnlyFile file(path);
  check_round_trip(file, 2);
}

TEST_CASE("A moved-from ResultsWriter refuses every call with an error, not a crash", "[output]") {
  // Issue 29: append on a moved-from writer dereferenced its null state (SIGSEGV).
  const spar::test::ScratchFolder folder("moved_from");
  ResultsWriter first(folder.file("run.h5"), spar::test::sample_layout(), 10);
  const ResultsWriter second = std::move(first);
  CHECK_THROWS_WITH(first.append(SampleStep(0).step), Contains("was moved from") && Contains("output::ResultsWriter::append"));
  CHECK_THROWS_WITH(first.flush(), Contains("was moved from") && Contains("output::ResultsWriter::flush"));
  CHECK_THROWS_WITH(first.write_attribute("x", 1.0), Contains("was moved from") && Contains("output::ResultsWriter::write_attribute"));
  CHECK_THROWS_WITH(first.write_constant("c", Eigen::MatrixXd::Zero(1, 1), "m", "c"), Contains("was moved from") && Contains("output::ResultsWriter::write_constant"));
  CHECK_THROWS_WITH(first.steps_written(), Contains("was moved from") && Contains("output::ResultsWriter::steps_written"));
  CHECK_THROWS_WITH(first.steps_flushed(), Contains("was moved from") && Contains("output::ResultsWriter::steps_flushed"));
  CHECK_THROWS_WITH(first.xdmf_path(), Contains("was moved from") && Contains("output::ResultsWriter::xdmf_path"));
  first.close();  // closing what it no longer holds does nothing, as the destructor does
}

TEST_CASE("A second run replaces the files, and writes through a symbolic link", "[output]") {
  // The writer renames a new file over the old one (a kill leaves one or the other whole:
  // spare_copy.hpp); a symbolic link stays a link, the file it points to replaced. The spare
  // copies are gone once the writers are closed.
  const spar::test::ScratchFolder folder("rewrite");
  namespace fs = std::filesystem;
  const std::string path = folder.file("run.h5"), target = folder.file("target.h5");
  const auto run = [](const std::string& h5, int steps) {
    ResultsWriter writer(h5, spar::test::sample_layout(), 2);
    for (int k = 0; k < steps; ++k) writer.append(SampleStep(k).step);
  };
  run(path, 5);
  run(path, 3);  // the old file of 5 steps replaced
  check_round_trip(ReadOnlyFile(path), 3);
  run(target, 5);
  fs::remove(path);
  fs::remove(folder.file("run.xmf"));
  fs::create_symlink(target, path);
  fs::create_symlink(folder.file("target.xmf"), folder.file("run.xmf"));
  run(path, 2);
  CHECK(fs::is_symlink(path));
  CHECK(fs::is_symlink(folder.file("run.xmf")));
  check_round_trip(ReadOnlyFile(target), 2);
  const auto root = spar::test::XmlReader::parse(spar::test::read_text(folder.file("target.xmf")));
  CHECK(root.one("Domain").one("Grid").all("Grid").size() == 2);
  for (const auto& entry : fs::directory_iterator(fs::path(path).parent_path()))
    CHECK(entry.path().extension() != ".spare");
}

TEST_CASE("A file being written is refused to a second writer of the program until it is closed", "[output]") {
  // HDF5 refuses to truncate a file it has open; a ResultsWriter makes its file on its writer
  // thread after removing an old one, so the constructors refuse it themselves (written_files.hpp),
  // also under another name of the same file.
  const spar::test::ScratchFolder folder("claims");
  const std::string path = folder.file("run.h5"), link = folder.file("link.h5");
  const std::string refusal = "is being written by another results writer of this program";
  {
    ResultsWriter first(path, spar::test::sample_layout());
    std::filesystem::create_symlink(path, link);
    CHECK_THROWS_WITH(ResultsWriter(path, spar::test::sample_layout()), Contains(path) && Contains(refusal));
    CHECK_THROWS_WITH(ResultsWriter(link, spar::test::sample_layout()), Contains(link) && Contains(refusal));
    CHECK_THROWS_WITH(spar::output::Hdf5File(path), Contains("output::Hdf5File(" + path + ")") && Contains(refusal));
    first.append(SampleStep(0).step);
    first.close();
    const spar::output::Hdf5File constants(path);  // free once closed
    CHECK_THROWS_WITH(ResultsWriter(path, spar::test::sample_layout()), Contains(refusal));
  }
  ResultsWriter again(path, spar::test::sample_layout());  // and once the Hdf5File is destroyed
  again.append(SampleStep(0).step);
  again.close();
  check_round_trip(ReadOnlyFile(path), 1);
}

TEST_CASE("Every dataset states its units and meaning; strings are UTF-8; counters are integers", "[output]") {
  const spar::test::ScratchFolder folder("units");
  const std::string path = folder.file("run.h5");
  {
    ResultsWriter writer(path, spar::test::sample_layout(), 2);
    writer.write_attribute("example", "pendule \u03c1\u221e = 1");  // ρ∞: not ASCII
    writer.write_attribute("steps", std::int64_t{3'000'000'000});     // beyond 32 bits
    for (int k = 0; k < 3; ++k) writer.append(SampleStep(k).step);
    writer.write_constant("reference/centerline", Eigen::MatrixXd::Identity(4, 3), "m", "reference centerline");
  }
  const ReadOnlyFile file(path);
  for (const char* name : {"spar_version", "spar_revision", "example"}) {
    const auto attribute = file.string_attribute_of("/", name);
    INFO("attribute " << name);
    CHECK(attribute.variable_length);
    CHECK(attribute.utf8);
  }
  CHECK(file.string_attribute("example") == "pendule \u03c1\u221e = 1");
  CHECK(file.integer_attribute("steps") == 3'000'000'000);

  const std::vector<std::string> datasets = file.datasets();
  // time, 4 node series, 2 scalars, 1 probe, 2 beams × (centerline, 2 fields), 2 shapes ×
  // (vertices, velocities), 5 topologies, 1 constant
  CHECK(datasets.size() == 24);
  for (const std::string& name : datasets) {
    INFO("dataset " << name);
    for (const char* key : {"units", "description"}) {
      const auto attribute = file.string_attribute_of(name, key);
      CHECK_FALSE(attribute.value.empty());
      CHECK(attribute.variable_length);
      CHECK(attribute.utf8);
    }
  }
  CHECK(file.string_attribute_of("/time", "units").value == "s");
  CHECK(file.string_attribute_of("/scalars/kinetic_energy", "units").value == "J");
  CHECK(file.string_attribute_of("/scalars/kinetic_energy", "description").value == "kinetic energy");
  CHECK(file.string_attribute_of("/probes/tip", "units").value == "m");
  CHECK(file.string_attribute_of("/reference/centerline", "units").value == "m");

  using Type = std::pair<H5T_class_t, std::size_t>;
  CHECK(file.dataset_type("/scalars/newton_iterations") == Type{H5T_INTEGER, 4});
  CHECK(file.read("/scalars/newton_iterations").values == std::vector<double>{0, 1, 2});
  CHECK(file.dataset_type("/scalars/kinetic_energy") == Type{H5T_FLOAT, 8});
  CHECK(file.dataset_type("/xdmf/polyvertex") == Type{H5T_INTEGER, 4});
}
