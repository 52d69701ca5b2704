#include "provenance_attributes.hpp"

#include "hdf5_attributes.hpp"
#include "hdf5_handle.hpp"

#include <spar/error.hpp>

#include <cstdint>

namespace spar::output::detail {

namespace {

const char* const options_group = "/options";

}  // namespace

herr_t write_provenance(hid_t file) {
  const std::int64_t schema = results_schema_version;
  if (write_scalar_attribute(file, "schema", H5T_NATIVE_INT64, &schema) < 0 ||
      write_string_attribute(file, "spar_version", spar_version()) < 0 ||
      write_string_attribute(file, "spar_revision", source_revision()) < 0)
    return -1;
  const Hid group(H5Gcreate2(file, options_group, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  return group.valid() ? 0 : -1;
}

herr_t write_options(hid_t file, const RunOptions& options) {
  const Hid group(H5Gopen2(file, options_group, H5P_DEFAULT), H5Gclose);
  if (!group.valid()) return -1;
  for (const auto& [name, value] : options)
    if (write_string_attribute(group, name, value) < 0) return -1;
  return 0;
}

void check_attribute_name(const std::string& name, bool root, const std::string& where) {
  // HDF5 keeps an attribute in one header message of at most 64 KiB (a double's name may have
  // 65 479 bytes in HDF5 1.10); 65 000 leaves the type and the value room.
  if (name.empty() || name.size() > 65000)
    throw Error("the attribute name has " + std::to_string(name.size()) + " characters", where,
                "give a name of 1 to 65 000 characters, e.g. time_step");
  if (root && (name == "schema" || name == "spar_version" || name == "spar_revision"))
    throw Error("the root attribute " + name + " is the file's own schema and provenance (docs/output.md)", where,
                "give the run's attribute another name; pass the run's options to write_options");
}

}  // namespace spar::output::detail
