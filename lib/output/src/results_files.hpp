#pragma once
/// \file
/// The files of a ResultsWriter and their life (docs/output.md, "Surviving a kill"): the HDF5 file
/// and its XDMF sidecar, each kept twice (spare_copy.hpp), as the file readers open and its spare.
/// A change is made to the spares, which then take the files' names (the HDF5 file first, so that
/// the sidecar never lists a step the HDF5 file lacks), and made again to the new spares.

#include "results_copy.hpp"
#include "time_histories.hpp"
#include "xdmf_sidecar.hpp"

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace spar::output::detail {

class ResultsFiles {
public:
  /// The files of the writer of `path` (as the caller gave it) and of its sidecar `xdmf_path`:
  /// those they name, or the files they link to (write_target). Touches no file.
  ResultsFiles(std::string path, std::string xdmf_path);
  ResultsFiles(const ResultsFiles&) = delete;
  ResultsFiles& operator=(const ResultsFiles&) = delete;

  /// What the constructor of the writer checks before its writer thread makes the files: names
  /// the sidecar can reference (XdmfSidecar::check_names) and both files writable, by opening
  /// their spares for writing as the writer thread will (creating them empty if they do not
  /// exist). The files themselves stay what they were (an earlier run's results) until create()
  /// replaces them. Throws spar::Error naming the path and the reason.
  void check_writable(const ResultsLayout& layout) const;
  /// The writer thread's first job: both copies of the HDF5 file, with every series of
  /// `histories` (ResultsCopy::create), and of the sidecar. The first copies replace the files of
  /// an earlier run (the sidecar first, so that it never lists steps the HDF5 file does not
  /// hold), the second stay the spares.
  void create(const TimeHistories& histories, int flush_every);
  /// A block of steps (rows of `series`) and its steps in the sidecar (series 0 holds their
  /// times) to the spares, the spares published, then the same to the new spares: both files are
  /// complete up to the block when it returns, and a kill at any moment leaves them whole.
  void write_block(const Block& block, const std::vector<Series>& series);
  /// A root attribute to the spare, which is flushed and published, then to the other copy.
  void write_attribute(const RootAttribute& attribute);
  /// The run's options (ResultsCopy::write_options), likewise.
  void write_options(const RunOptions& options);
  /// A constant dataset (ResultsCopy::write_constant) to the spare, published, then to the other
  /// copy; throws spar::Error if the file holds `name` already.
  void write_constant(const std::string& name, const Eigen::MatrixXd& data, const std::string& unit,
                      const std::string& description);
  /// Closes both copies of both files (those made) and removes the spares; false if HDF5
  /// reported a failure.
  bool release();

private:
  /// Makes copy `c` of the HDF5 file under the spare's name.
  void create_copy(int c, const TimeHistories& histories, int flush_every);
  /// Gives the spare HDF5 copy, just changed and flushed, the file's name (spare_copy.hpp).
  void publish_h5();
  void publish_xmf();
  /// `change` (which flushes) to the spare HDF5 copy, the spare published, then `change` to the
  /// other copy, with the HDF5 lock held.
  void change_both(const std::function<void(ResultsCopy&)>& change);

  std::string path_, xdmf_path_;  ///< as the caller gave them
  std::string target_, xdmf_target_;  ///< the files written (write_target)
  /// The two copies of the HDF5 file: copy h5_spare_ is named spare_path(target_), the other
  /// target_ (once create() has run); likewise the sidecars.
  std::array<ResultsCopy, 2> copies_;
  int h5_spare_ = 0;
  std::array<std::unique_ptr<XdmfSidecar>, 2> sidecars_;
  int xmf_spare_ = 0;
};

}  // namespace spar::output::detail
