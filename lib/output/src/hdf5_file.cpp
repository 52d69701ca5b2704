#include <spar/output/hdf5_file.hpp>

#include "hdf5_attributes.hpp"
#include "hdf5_lifetime.hpp"
#include "hdf5_lock.hpp"
#include "provenance_attributes.hpp"
#include "written_files.hpp"

#include <hdf5.h>

#include <mutex>
#include <vector>

namespace spar::output {

namespace {

void check(herr_t status, const std::string& what, const std::string& path) {
  detail::check_hdf5(status, what, "output::Hdf5File(" + path + ")",
                     "check that the output folder exists and is writable, and the disk is not full");
}

}  // namespace

Hdf5File::Hdf5File(const std::string& path)
    : path_(path), claim_(detail::claim_written_file(path, "output::Hdf5File(" + path + ")")) {
  const auto hdf5 = detail::hdf5_calls();
  file_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) detail::release_written_file(claim_);  // the destructor does not run
  check(static_cast<herr_t>(file_ < 0 ? -1 : 0), "create the file", path);
  const hid_t file = static_cast<hid_t>(file_);
  if (detail::write_provenance(file) < 0 || H5Fflush(file, H5F_SCOPE_GLOBAL) < 0) {
    H5Fclose(file);
    detail::release_written_file(claim_);
    check(-1, "write the schema and provenance", path);
  }
}

Hdf5File::~Hdf5File() {
  {
    const std::lock_guard<std::mutex> hdf5(detail::hdf5_mutex());
    if (H5Fclose(static_cast<hid_t>(file_)) < 0) detail::note_hdf5_failure();
  }
  detail::release_written_file(claim_);
}

void Hdf5File::write(const std::string& name, const Eigen::MatrixXd& data, const std::string& unit,
                     const std::string& description) {
  const std::lock_guard<std::mutex> hdf5(detail::hdf5_mutex());
  const hid_t file = static_cast<hid_t>(file_);
  const hid_t link_properties = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(link_properties, 1);
  const hsize_t dims[2] = {static_cast<hsize_t>(data.rows()), static_cast<hsize_t>(data.cols())};
  const hid_t space = H5Screate_simple(data.cols() == 1 ? 1 : 2, dims, nullptr);
  const hid_t set = H5Dcreate2(file, name.c_str(), H5T_NATIVE_DOUBLE, space, link_properties,
                               H5P_DEFAULT, H5P_DEFAULT);
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> row_major = data;
  herr_t status = set < 0 ? -1 : H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, row_major.data());
  if (status >= 0) status = detail::describe_dataset(set, unit, description);
  if (set >= 0) H5Dclose(set);
  H5Sclose(space);
  H5Pclose(link_properties);
  check(status, "write dataset " + name, path_);
  check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush", path_);
}

void Hdf5File::write_attribute(const std::string& name, double value) {
  detail::check_attribute_name(name, true, "output::Hdf5File::write_attribute(" + path_ + ")");
  const std::lock_guard<std::mutex> hdf5(detail::hdf5_mutex());
  check(detail::write_scalar_attribute(static_cast<hid_t>(file_), name, H5T_NATIVE_DOUBLE, &value),
        "write attribute " + name, path_);
  check(H5Fflush(static_cast<hid_t>(file_), H5F_SCOPE_GLOBAL), "flush", path_);
}

void Hdf5File::write_attribute(const std::string& name, const std::string& value) {
  detail::check_attribute_name(name, true, "output::Hdf5File::write_attribute(" + path_ + ")");
  const std::lock_guard<std::mutex> hdf5(detail::hdf5_mutex());
  check(detail::write_string_attribute(static_cast<hid_t>(file_), name, value), "write attribute " + name, path_);
  check(H5Fflush(static_cast<hid_t>(file_), H5F_SCOPE_GLOBAL), "flush", path_);
}

void Hdf5File::write_options(const RunOptions& options) {
  for (const auto& option : options)
    detail::check_attribute_name(option.first, false, "output::Hdf5File::write_options(" + path_ + ")");
  const std::lock_guard<std::mutex> hdf5(detail::hdf5_mutex());
  check(detail::write_options(static_cast<hid_t>(file_), options), "write the options", path_);
  check(H5Fflush(static_cast<hid_t>(file_), H5F_SCOPE_GLOBAL), "flush", path_);
}

}  // namespace spar::output
