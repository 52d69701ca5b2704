// The run that results_kill_test.cpp kills: a ResultsWriter that writes often (a block of 5
// steps of 2 beams, 6 nodes and their fields, about every millisecond, a root attribute every 50
// steps, a constant at the start), until it has written `steps` steps or is killed.
//
//   test_output_kill_driver FILE.h5 STEPS

#include <spar/output/results_writer.hpp>

#include <Eigen/Geometry>

#include <cstdio>
#include <exception>
#include <string>

namespace {

spar::output::ResultsLayout kill_layout() {
  spar::output::ResultsLayout layout;
  layout.node_count = 6;
  layout.multiplier_count = 4;
  layout.scalars = {{.name = "energy", .unit = "J", .description = "a number per step"},
                    {.name = "iterations", .unit = "1", .description = "a counter", .integer = true}};
  layout.probes = {{.name = "tip", .unit = "m", .description = "a point per step"}};
  layout.centerline_points = {101, 61};
  layout.centerline_fields = {{.name = "speed", .unit = "m/s", .description = "a value per point"},
                              {.name = "velocity", .unit = "m/s", .description = "a vector per point", .components = 3}};
  layout.rigid_bodies = {{.node = 1, .kind = spar::output::RigidBodyShape::Kind::box, .size = {0.4, 0.2, 0.1}}};
  return layout;
}

void run(const std::string& path, int steps) {
  const spar::output::ResultsLayout layout = kill_layout();
  spar::output::ResultsWriter writer(path, layout, 5);
  writer.write_attribute("purpose", std::string("killed at random moments by results_kill_test"));
  writer.write_constant("reference/centerline", Eigen::MatrixXd::Constant(101, 3, 0.5), "m", "a constant");
  spar::core::Configuration q;
  for (int i = 0; i < layout.node_count; ++i) q.add_frame(Eigen::Vector3d(i, 0, 0), Eigen::Matrix3d::Identity());
  const Eigen::VectorXd velocity = Eigen::VectorXd::Ones(6 * layout.node_count);
  const Eigen::VectorXd multipliers = Eigen::VectorXd::Ones(layout.multiplier_count);
  for (int k = 0; k < steps; ++k) {
    spar::output::ResultsStep step{.time = 1e-3 * k, .configuration = &q, .velocity = &velocity,
                                 .multipliers = &multipliers, .scalars = {0.5 * k, double(k % 7)},
                                 .probes = {Eigen::Vector3d(k, 0, 1)}};
    for (int points : layout.centerline_points) {
      step.centerlines.push_back(Eigen::MatrixXd::Constant(points, 3, k));
      step.centerline_fields.push_back({Eigen::MatrixXd::Constant(points, 1, k), Eigen::MatrixXd::Constant(points, 3, -k)});
    }
    writer.append(step);
    if (k % 50 == 49) writer.write_attribute("steps_so_far", k + 1);
  }
  writer.close();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s FILE.h5 STEPS\n", argv[0]);
    return 2;
  }
  try {
    run(argv[1], std::stoi(argv[2]));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
