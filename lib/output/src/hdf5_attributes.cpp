#include "hdf5_attributes.hpp"

namespace spar::output::detail {

herr_t write_scalar_attribute(hid_t object, const std::string& name, hid_t type, const void* value) {
  if (H5Aexists(object, name.c_str()) > 0 && H5Adelete(object, name.c_str()) < 0) return -1;
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attribute = H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  const herr_t status = attribute < 0 ? -1 : H5Awrite(attribute, type, value);
  if (attribute >= 0) H5Aclose(attribute);
  H5Sclose(space);
  return status;
}

herr_t write_string_attribute(hid_t object, const std::string& name, const std::string& value) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  const char* text = value.c_str();  // a variable-length string is written through its pointer
  const herr_t status = write_scalar_attribute(object, name, type, &text);
  H5Tclose(type);
  return status;
}

herr_t describe_dataset(hid_t dataset, const std::string& unit, const std::string& description) {
  const herr_t units = write_string_attribute(dataset, "units", unit);
  const herr_t meaning = write_string_attribute(dataset, "description", description);
  return units < 0 || meaning < 0 ? -1 : 0;
}

}  // namespace spar::output::detail
