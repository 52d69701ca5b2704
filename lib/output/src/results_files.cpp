#include "results_files.hpp"

#include "fresh_file.hpp"
#include "hdf5_handle.hpp"
#include "hdf5_lifetime.hpp"
#include "spare_copy.hpp"

#include <spar/error.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <utility>

namespace spar::output::detail {

namespace {

/// Why `path` cannot be created, as far as the file system tells, else `otherwise`.
std::string creation_failure_reason(const std::string& path, const std::string& otherwise) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path folder = fs::absolute(path, ec).parent_path();
  if (!fs::exists(folder, ec)) return "its folder " + folder.string() + " does not exist";
  if (!fs::is_directory(folder, ec)) return folder.string() + " is not a folder";
  if (access(folder.c_str(), W_OK) != 0) return "its folder " + folder.string() + " is not writable";
  if (fs::is_directory(path, ec)) return "it is a folder";
  return otherwise;
}

/// Opens the spare copy of `target` (the file `path` names) for writing, creating it (empty,
/// with `mode`) if it does not exist; `target` itself is not touched, so a kill leaves no empty
/// file under its name. Throws spar::Error naming `path` and the reason.
void check_spare_writable(const std::string& path, const std::string& target, mode_t mode, const std::string& what,
                          const std::string& where) {
  std::error_code ec;
  if (std::filesystem::is_directory(target, ec))
    throw Error("cannot create " + what + " " + path + ": it is a folder", where, "pass the path of a file");
  const std::string spare = spare_path(target);
  const int fd = ::open(spare.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, mode);
  if (fd < 0) {
    const std::string system_reason = std::strerror(errno);
    throw Error("cannot create " + what + " " + path + ": " + creation_failure_reason(spare, system_reason), where,
                "pass a path in an existing, writable folder");
  }
  ::close(fd);
}

}  // namespace

ResultsFiles::ResultsFiles(std::string path, std::string xdmf_path)
    : path_(std::move(path)),
      xdmf_path_(std::move(xdmf_path)),
      target_(write_target(path_)),
      xdmf_target_(write_target(xdmf_path_)),
      copies_{ResultsCopy(path_), ResultsCopy(path_)} {}

void ResultsFiles::check_writable(const ResultsLayout& layout) const {
  const std::string where = "output::ResultsWriter(" + path_ + ")";
  XdmfSidecar::check_names(xdmf_path_, std::filesystem::path(path_).filename().string(), layout);
  check_spare_writable(path_, target_, 0666, "the results file", where);  // HDF5's own mode for the files it makes
  check_spare_writable(xdmf_path_, xdmf_target_, 0644, "the XDMF sidecar", where);
}

void ResultsFiles::create_copy(int c, const TimeHistories& histories, int flush_every) {
  const Hid access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
#if H5_VERSION_GE(1, 10, 7)
  // No lock: the file can be read (after a flush) while the run goes on.
  H5Pset_file_locking(access, false, true);
#endif
  const std::string spare = spare_path(target_);
  remove_for_rewrite(spare);  // a new file: its close does not start ext4's write-back
  const hid_t file = H5Fcreate(spare.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access);
  if (file < 0)
    throw Error("cannot create the results file " + path_ + ": " +
                    creation_failure_reason(spare, "HDF5 refused to create it (the file may be open in another "
                                                   "program, or the disk full)"),
                "output::ResultsWriter(" + path_ + ")", "pass a path in an existing, writable folder");
  copies_[static_cast<std::size_t>(c)].create(file, histories, flush_every);
}

void ResultsFiles::create(const TimeHistories& histories, int flush_every) {
  const std::string h5_name = std::filesystem::path(path_).filename().string();
  for (int c = 0; c < 2; ++c) {
    {
      const auto hdf5 = hdf5_calls();
      create_copy(c, histories, flush_every);
    }
    sidecars_[static_cast<std::size_t>(c)] = std::make_unique<XdmfSidecar>(spare_path(xdmf_target_), h5_name, histories.layout());
    if (c == 1) continue;
    replace_file(spare_path(xdmf_target_), xdmf_target_, writer_where(path_, "ResultsWriter"));
    replace_file(spare_path(target_), target_, writer_where(path_, "ResultsWriter"));
  }
  h5_spare_ = xmf_spare_ = 1;
}

void ResultsFiles::publish_h5() {
  exchange_names(spare_path(target_), target_, writer_where(path_, "flush"));
  h5_spare_ = 1 - h5_spare_;
}

void ResultsFiles::publish_xmf() {
  exchange_names(spare_path(xdmf_target_), xdmf_target_, writer_where(path_, "flush"));
  xmf_spare_ = 1 - xmf_spare_;
}

void ResultsFiles::write_block(const Block& block, const std::vector<Series>& series) {
  for (int pass = 0; pass < 2; ++pass) {
    {
      const auto hdf5 = hdf5_calls();
      copies_[static_cast<std::size_t>(h5_spare_)].write_block(block, series);
    }
    sidecars_[static_cast<std::size_t>(xmf_spare_)]->append(block.first, block.rows[0], block.first + block.count);
    if (pass > 0) continue;
    publish_h5();
    publish_xmf();
  }
}

void ResultsFiles::change_both(const std::function<void(ResultsCopy&)>& change) {
  change(copies_[static_cast<std::size_t>(h5_spare_)]);
  publish_h5();
  change(copies_[static_cast<std::size_t>(h5_spare_)]);
}

void ResultsFiles::write_attribute(const RootAttribute& attribute) {
  const auto hdf5 = hdf5_calls();
  change_both([&](ResultsCopy& copy) { copy.write_attribute(attribute); });
}

void ResultsFiles::write_options(const RunOptions& options) {
  const auto hdf5 = hdf5_calls();
  change_both([&](ResultsCopy& copy) { copy.write_options(options); });
}

void ResultsFiles::write_constant(const std::string& name, const Eigen::MatrixXd& data, const std::string& unit,
                                  const std::string& description) {
  const auto hdf5 = hdf5_calls();
  if (copies_[0].holds(name))
    throw Error("the file already holds an object named " + name, writer_where(path_, "write_constant"),
                "write each constant once, under a name not used by the time histories (docs/output.md)");
  change_both([&](ResultsCopy& copy) { copy.write_constant(name, data, unit, description); });
}

bool ResultsFiles::release() {
  for (auto& sidecar : sidecars_) sidecar.reset();
  const auto hdf5 = hdf5_calls();
  bool ok = true;
  for (ResultsCopy& copy : copies_) ok = copy.close() && ok;
  ::unlink(spare_path(target_).c_str());
  ::unlink(spare_path(xdmf_target_).c_str());
  if (!ok) note_hdf5_failure();
  return ok;
}

}  // namespace spar::output::detail
