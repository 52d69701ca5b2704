#include "time_histories.hpp"

#include <spar/error.hpp>
#include <spar/lie/quaternion.hpp>

#include <Eigen/Geometry>

#include <utility>

namespace spar::output::detail {

namespace {

/// The vertices of `shape` in its body's material frame (columns), `length` the axes' length
/// where the shape leaves it to the model: a box's 8 corners in VTK's hexahedron order (the face
/// z = −½ counterclockwise seen from +z, then the face z = +½), or the axes as 3 segments
/// (origin, end) along X, Y, Z.
Eigen::Matrix3Xd shape_vertices(const RigidBodyShape& shape, double length) {
  if (shape.kind == RigidBodyShape::Kind::box) {
    Eigen::Matrix<double, 3, 8> corners;
    corners << -1, 1, 1, -1, -1, 1, 1, -1,  //
        -1, -1, 1, 1, -1, -1, 1, 1,         //
        -1, -1, -1, -1, 1, 1, 1, 1;
    return (0.5 * shape.size.asDiagonal() * corners).colwise() + shape.offset;
  }
  const Eigen::Vector3d lengths = shape.size.isZero(0.0) ? Eigen::Vector3d::Constant(length) : shape.size;
  Eigen::Matrix3Xd ends = Eigen::Matrix3Xd::Zero(3, 6);
  for (int axis = 0; axis < 3; ++axis) ends(axis, 2 * axis + 1) = lengths(axis);
  return ends.colwise() + shape.offset;
}

}  // namespace

void Series::push_rows(const Eigen::MatrixXd& values) {
  const std::size_t at = buffer.size();
  buffer.resize(at + static_cast<std::size_t>(values.size()));
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(buffer.data() + at, values.rows(),
                                                                                    values.cols()) = values;
}

TimeHistories::TimeHistories(ResultsLayout layout) : layout_(std::move(layout)) {
  const auto n = static_cast<hsize_t>(layout_.node_count);
  add_series("/time", "s", "time of each step", {});
  if (n > 0) {
    positions_ = add_series("/positions", "m", "node positions x (inertial frame), node by node", {n, 3});
    quaternions_ = add_series("/quaternions", "1",
                              "node rotations R (material to inertial) as unit quaternions (w, x, y, z), w >= 0",
                              {n, 4});
    if (layout_.velocities)
      velocities_ = add_series("/velocities", "m/s, rad/s",
                               "node velocities: x dot (inertial, m/s) in columns 0-2, then the angular velocity "
                               "Omega (material frame, rad/s) in columns 3-5",
                               {n, 6});
  }
  if (layout_.multiplier_count > 0)
    multipliers_ = add_series("/multipliers", "N, N m",
                              "Lagrange multipliers of the constraints, constraint by constraint: forces (N) for "
                              "position constraints, moments (N m) for rotation constraints",
                              {static_cast<hsize_t>(layout_.multiplier_count)});
  first_scalar_ = static_cast<int>(series_.size());
  for (const ResultsQuantity& scalar : layout_.scalars)
    add_series("/scalars/" + scalar.name, scalar.unit, scalar.description, {}, scalar.integer);
  first_probe_ = static_cast<int>(series_.size());
  for (const ResultsQuantity& probe : layout_.probes) add_series("/probes/" + probe.name, probe.unit, probe.description, {3});
  first_centerline_ = static_cast<int>(series_.size());
  for (std::size_t k = 0; k < layout_.centerline_points.size(); ++k)
    add_series("/centerlines/beam" + std::to_string(k), "m",
               "beam " + std::to_string(k) +
                   "'s centerline (inertial frame) at points equally spaced in its knot parameter, root to tip",
               {static_cast<hsize_t>(layout_.centerline_points[k]), 3});
  first_field_ = static_cast<int>(series_.size());
  for (const CenterlineField& field : layout_.centerline_fields)
    for (std::size_t k = 0; k < layout_.centerline_points.size(); ++k) {
      std::vector<hsize_t> shape{static_cast<hsize_t>(layout_.centerline_points[k])};
      if (field.components > 1) shape.push_back(static_cast<hsize_t>(field.components));
      add_series("/centerline_fields/" + field.name + "/beam" + std::to_string(k), field.unit,
                 field.description + " (beam " + std::to_string(k) + ", at its centerline points)", shape);
    }
  first_profile_ = static_cast<int>(series_.size());
  for (const ResultsProfile& profile : layout_.profiles)
    add_series("/profiles/" + profile.quantity.name, profile.quantity.unit, profile.quantity.description,
               {static_cast<hsize_t>(profile.points), static_cast<hsize_t>(profile.components)});
  first_rigid_body_ = static_cast<int>(series_.size());
  for (std::size_t k = 0; k < layout_.rigid_bodies.size(); ++k)
    add_series("/rigid_bodies/body" + std::to_string(k), "m",
               "vertices x + R c of shape " + std::to_string(k) + " (layout.rigid_bodies) at node " +
                   std::to_string(layout_.rigid_bodies[k].node) +
                   " (inertial frame): a box's 8 corners in VTK hexahedron order, or the axes' 3 segments "
                   "(origin, end) along material X, Y, Z",
               {static_cast<hsize_t>(vertex_count(layout_.rigid_bodies[k])), 3});
  if (layout_.velocities && !layout_.rigid_bodies.empty()) {
    first_rigid_body_velocity_ = static_cast<int>(series_.size());
    for (std::size_t k = 0; k < layout_.rigid_bodies.size(); ++k)
      add_series("/rigid_body_fields/velocity/body" + std::to_string(k), "m/s",
                 "velocity x dot + R (Omega x c) of each vertex of shape " + std::to_string(k) + " (inertial frame)",
                 {static_cast<hsize_t>(vertex_count(layout_.rigid_bodies[k])), 3});
  }
}

int TimeHistories::add_series(std::string name, std::string unit, std::string description, std::vector<hsize_t> shape,
                              bool integer) {
  series_.push_back(Series{std::move(name), std::move(unit), std::move(description), std::move(shape), integer, {}});
  return static_cast<int>(series_.size()) - 1;
}

void TimeHistories::place_shapes(const ResultsStep& step, const std::string& where) {
  if (layout_.rigid_bodies.empty() || !shape_corners_.empty()) return;
  Eigen::AlignedBox3d extent;
  for (const Eigen::Vector3d& x : step.configuration->position) extent.extend(x);
  for (const Eigen::MatrixXd& centerline : step.centerlines)
    for (Eigen::Index p = 0; p < centerline.rows(); ++p) extent.extend(Eigen::Vector3d(centerline.row(p).transpose()));
  const double length = 0.1 * extent.diagonal().norm();
  for (std::size_t k = 0; k < layout_.rigid_bodies.size(); ++k) {
    const RigidBodyShape& shape = layout_.rigid_bodies[k];
    if (shape.kind == RigidBodyShape::Kind::axes && shape.size.isZero(0.0) && !(length > 0.0))
      throw Error("layout.rigid_bodies[" + std::to_string(k) + "] leaves its axes' length to the model's extent, "
                      "but the first step's nodes and centerlines are all at one point",
                  where + " at step 0", "give the axes' lengths in size");
  }
  for (const RigidBodyShape& shape : layout_.rigid_bodies) shape_corners_.push_back(shape_vertices(shape, length));
}

void TimeHistories::buffer_nodes(const ResultsStep& step) {
  if (positions_ < 0) return;
  const core::Configuration& q = *step.configuration;
  for (int i = 0; i < layout_.node_count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    series_[static_cast<std::size_t>(positions_)].push(q.position[k].data(), 3);
    const Eigen::Quaterniond quaternion = lie::quaternion_from_rotation(q.rotation[k]);
    const double wxyz[4] = {quaternion.w(), quaternion.x(), quaternion.y(), quaternion.z()};
    series_[static_cast<std::size_t>(quaternions_)].push(wxyz, 4);
  }
  if (velocities_ >= 0)
    series_[static_cast<std::size_t>(velocities_)].push(step.velocity->data(), static_cast<std::size_t>(step.velocity->size()));
}

void TimeHistories::buffer_shapes(const ResultsStep& step) {
  if (shape_corners_.empty()) return;  // a layout without shapes may have steps without a configuration
  const core::Configuration& q = *step.configuration;
  for (std::size_t k = 0; k < shape_corners_.size(); ++k) {
    const auto node = static_cast<std::size_t>(layout_.rigid_bodies[k].node);
    const Eigen::Matrix3Xd& corners = shape_corners_[k];
    const Eigen::Matrix3Xd vertices = (q.rotation[node] * corners).colwise() + q.position[node];
    series_[static_cast<std::size_t>(first_rigid_body_) + k].push(vertices.data(), static_cast<std::size_t>(vertices.size()));
    if (first_rigid_body_velocity_ < 0) continue;
    const auto i = static_cast<Eigen::Index>(6 * node);
    const Eigen::Vector3d x_dot = step.velocity->segment<3>(i), omega = step.velocity->segment<3>(i + 3);
    Eigen::Matrix3Xd velocities(3, corners.cols());
    for (Eigen::Index c = 0; c < corners.cols(); ++c)
      velocities.col(c) = x_dot + q.rotation[node] * omega.cross(corners.col(c));
    series_[static_cast<std::size_t>(first_rigid_body_velocity_) + k].push(velocities.data(),
                                                                          static_cast<std::size_t>(velocities.size()));
  }
}

void TimeHistories::buffer(const ResultsStep& step) {
  series_[0].push(&step.time, 1);
  buffer_nodes(step);
  if (multipliers_ >= 0)
    series_[static_cast<std::size_t>(multipliers_)].push(step.multipliers->data(),
                                                        static_cast<std::size_t>(step.multipliers->size()));
  for (std::size_t i = 0; i < step.scalars.size(); ++i)
    series_[static_cast<std::size_t>(first_scalar_) + i].push(&step.scalars[i], 1);
  for (std::size_t i = 0; i < step.probes.size(); ++i)
    series_[static_cast<std::size_t>(first_probe_) + i].push(step.probes[i].data(), 3);
  for (std::size_t k = 0; k < step.centerlines.size(); ++k)
    series_[static_cast<std::size_t>(first_centerline_) + k].push_rows(step.centerlines[k]);
  for (std::size_t k = 0; k < step.centerline_fields.size(); ++k)
    for (std::size_t f = 0; f < step.centerline_fields[k].size(); ++f)
      series_[static_cast<std::size_t>(first_field_) + f * step.centerline_fields.size() + k].push_rows(
          step.centerline_fields[k][f]);
  for (std::size_t i = 0; i < step.profiles.size(); ++i)
    series_[static_cast<std::size_t>(first_profile_) + i].push_rows(step.profiles[i]);
  buffer_shapes(step);
  last_time_ = step.time;
}

}  // namespace spar::output::detail
