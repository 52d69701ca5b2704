#pragma once
/// \file
/// The time histories of a results file (docs/output.md, "Time histories"): one extendible dataset
/// per quantity of the layout, in the order the file creates them, and the buffers that a step is
/// copied into until its block is handed to the writer thread.

#include <spar/output/results_writer.hpp>

#include <hdf5.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace spar::output::detail {

/// One time-history dataset of `steps × shape` values.
struct Series {
  std::string name;            ///< absolute path in the file, e.g. "/positions"
  std::string unit;            ///< stored as the dataset's `units` attribute
  std::string description;     ///< stored as the dataset's `description` attribute
  std::vector<hsize_t> shape;  ///< per-step shape, {} for one scalar per step
  bool integer = false;        ///< stored as int32 (counters), else as doubles
  std::vector<double> buffer;  ///< steps not yet handed to the writer thread, row-major

  hsize_t values_per_step() const {
    hsize_t count = 1;
    for (hsize_t extent : shape) count *= extent;
    return count;
  }
  /// {steps, shape...}: the dimensions of `steps` rows.
  std::vector<hsize_t> dims(hsize_t steps) const {
    std::vector<hsize_t> result{steps};
    result.insert(result.end(), shape.begin(), shape.end());
    return result;
  }
  void push(const double* values, std::size_t count) { buffer.insert(buffer.end(), values, values + count); }
  /// Appends `values` row by row (the datasets are row-major, Eigen's matrices column-major),
  /// without a temporary.
  void push_rows(const Eigen::MatrixXd& values);
};

/// A block of steps handed to the writer thread: the rows of every series and where they go.
struct Block {
  int first = 0;                          ///< the row of its first step
  int count = 0;                          ///< its steps
  std::vector<std::vector<double>> rows;  ///< per series, `count` steps row-major (Series::buffer's layout)
};

/// The series of a layout and the buffering of its steps.
class TimeHistories {
public:
  /// The series of `layout` (checked: check_layout): /time first, then the nodes' positions,
  /// quaternions and velocities, the multipliers, the scalars, probes, centerlines, centerline
  /// fields, profiles, the shapes' vertices and their velocities, each as the layout has them.
  explicit TimeHistories(ResultsLayout layout);

  const ResultsLayout& layout() const { return layout_; }
  const std::vector<Series>& series() const { return series_; }
  std::vector<Series>& series() { return series_; }

  /// At the first step only: the shapes' vertices in their bodies' frames, where an axes' default
  /// length is a tenth of the diagonal of the box bounding the step's nodes and centerline points.
  /// Throws spar::Error naming the call `where` at step 0 if that box is a single point.
  void place_shapes(const ResultsStep& step, const std::string& where);
  /// Appends `step` (checked: check_step) to the buffers, one push per series in their order.
  void buffer(const ResultsStep& step);
  /// The last buffered step's time.
  double last_time() const { return last_time_; }

  /// The vertices of a shape: 8 for a box, 6 for the axes (3 segments).
  static int vertex_count(const RigidBodyShape& shape) { return shape.kind == RigidBodyShape::Kind::box ? 8 : 6; }

private:
  /// Adds a series of `shape` per step and returns its index.
  int add_series(std::string name, std::string unit, std::string description, std::vector<hsize_t> shape,
                 bool integer = false);
  void buffer_nodes(const ResultsStep& step);
  /// Each shape's vertices x + R c and, if the layout has velocities, their velocities
  /// ẋ + R (Ω × c) (Ω material).
  void buffer_shapes(const ResultsStep& step);

  ResultsLayout layout_;
  std::vector<Series> series_;
  int positions_ = -1, quaternions_ = -1, velocities_ = -1, multipliers_ = -1;
  int first_scalar_ = 0, first_probe_ = 0, first_centerline_ = 0;
  int first_field_ = 0;                 ///< field f of beam k is series first_field_ + f × beams + k
  int first_profile_ = 0;               ///< profile i is series first_profile_ + i
  int first_rigid_body_ = 0;            ///< the vertices of shape k are series first_rigid_body_ + k
  int first_rigid_body_velocity_ = -1;  ///< their velocities series first_rigid_body_velocity_ + k, if any
  /// Per shape, its vertices in the body's frame (place_shapes).
  std::vector<Eigen::Matrix3Xd> shape_corners_;
  double last_time_ = 0;
};

}  // namespace spar::output::detail
