#pragma once
/// \file
/// One copy of ResultsWriter's HDF5 file (the writer keeps two: spare_copy.hpp): every time
/// history as an extendible dataset made with zero steps, the sidecar's topologies, the schema
/// and provenance; then the blocks of steps, the root attributes, the run's options and the
/// constants, each change flushed.
/// Every call is made holding the HDF5 lock (hdf5_calls()); the errors name the writer's path.

#include "time_histories.hpp"

#include <spar/output/provenance.hpp>

#include <hdf5.h>

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace spar::output::detail {

/// Where an error of the writer of `path` happened: "output::ResultsWriter::<function>(<path>)".
std::string writer_where(const std::string& path, const std::string& function);

/// The writer's check of an HDF5 call: check_hdf5 with writer_where(path, function).
void check_writer_call(herr_t status, const std::string& what, const std::string& path, const std::string& function);

/// A scalar attribute of the root group: a double, a 64-bit integer or a string.
struct RootAttribute {
  std::string name;
  std::variant<double, std::int64_t, std::string> value;
};

class ResultsCopy {
public:
  /// A copy of the results file of the writer of `path` (for the messages), not made yet.
  explicit ResultsCopy(std::string path) : path_(std::move(path)) {}
  ResultsCopy(const ResultsCopy&) = delete;
  ResultsCopy& operator=(const ResultsCopy&) = delete;

  /// Takes the new, empty HDF5 file `file` and gives it every series of `histories` with zero
  /// steps (chunks of one block of `flush_every` steps, at most ~64 KiB), the sidecar's
  /// topologies, the schema and provenance (provenance_attributes.hpp), then flushes it.
  void create(hid_t file, const TimeHistories& histories, int flush_every);
  /// Appends the steps of `block` (rows of `series`, in create's order) to every dataset and
  /// flushes.
  void write_block(const Block& block, const std::vector<Series>& series);
  /// Writes `attribute`, replacing one of its name, and flushes.
  void write_attribute(const RootAttribute& attribute);
  /// Writes `options` as attributes of /options, replacing those of their names, and flushes.
  void write_options(const RunOptions& options);
  /// Whether the file holds an object `name`.
  bool holds(const std::string& name) const;
  /// Writes the constant dataset `name` (`data`: rows × cols, row-major; a column is stored
  /// 1-D) with its `units` and `description`, making the groups in its name, and flushes.
  void write_constant(const std::string& name, const Eigen::MatrixXd& data, const std::string& unit,
                      const std::string& description);
  /// Closes the datasets and the file (if made); false if HDF5 reported a failure.
  bool close();

private:
  void check(herr_t status, const std::string& what, const std::string& function) const {
    check_writer_call(status, what, path_, function);
  }
  void create_dataset(const Series& series, int flush_every);
  /// An int dataset (`dims`) for the sidecar's topologies.
  void write_ints(const std::string& name, const std::vector<int>& values, const std::vector<hsize_t>& dims,
                  const std::string& description);
  /// Point indices 0 … count−1 of each sidecar topology: one polyline per beam, the shapes, the nodes.
  void write_topologies(const ResultsLayout& layout);

  std::string path_;
  hid_t file_ = H5I_INVALID_HID;
  std::vector<hid_t> datasets_;  ///< one per series, in their order
};

}  // namespace spar::output::detail
