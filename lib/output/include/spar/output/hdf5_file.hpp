#pragma once
/// \file
/// A minimal HDF5 results file: named double datasets (vectors and matrices, row-major as
/// printed), each with its `units` and `description` attributes, string/number attributes on
/// the root group (strings variable-length UTF-8), and the schema and provenance every results
/// file carries (docs/output.md, "Schema and provenance"). Every write is followed by an
/// H5Fflush, so a run that dies leaves a readable file with everything written so far.
/// The schema of each example's file is in docs/output.md.

#include <spar/output/provenance.hpp>

#include <Eigen/Core>

#include <string>

namespace spar::output {

class Hdf5File {
public:
  /// Creates (truncates) the file with its schema and provenance (the root attributes `schema`,
  /// `spar_version`, `spar_revision` and the empty group `/options`); throws spar::Error if it
  /// cannot, or if another writer of this program (an Hdf5File or a ResultsWriter not yet
  /// closed) is writing it.
  explicit Hdf5File(const std::string& path);
  ~Hdf5File();
  Hdf5File(const Hdf5File&) = delete;
  Hdf5File& operator=(const Hdf5File&) = delete;

  /// Writes `data` (rows × cols, stored row-major) as dataset `name` with its `units` (e.g. "m";
  /// "1" for ratios) and `description`; groups in `name` ("shape/positions") are created as needed.
  void write(const std::string& name, const Eigen::MatrixXd& data, const std::string& unit,
             const std::string& description);
  /// A scalar attribute of the root group; spar::Error for a name of 0 or more than 65 000
  /// characters, and for `schema`, `spar_version` and `spar_revision`.
  void write_attribute(const std::string& name, double value);
  void write_attribute(const std::string& name, const std::string& value);
  /// The run's options as string attributes of the group `/options` (ResultsWriter::write_options).
  void write_options(const RunOptions& options);

private:
  long long file_;  // hid_t, kept out of the header so users need no HDF5 include path
  std::string path_;
  std::string claim_;  // its key among the files this program's writers write (lib/output/src/written_files.hpp)
};

}  // namespace spar::output
