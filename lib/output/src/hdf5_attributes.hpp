#pragma once
/// \file
/// Attributes shared by the results files (Hdf5File, ResultsWriter): scalar attributes that
/// replace an existing one of the same name, strings stored variable-length UTF-8 (h5py reads
/// str, not bytes), and the `units` + `description` pair that every dataset carries
/// (docs/output.md).

#include <hdf5.h>

#include <string>

namespace spar::output::detail {

/// Writes the scalar attribute `name` of `object` from `value` (of HDF5 memory type `type`, also
/// the stored type), replacing an attribute of that name. Returns a negative value on failure.
herr_t write_scalar_attribute(hid_t object, const std::string& name, hid_t type, const void* value);

/// The same for a string, stored as a variable-length UTF-8 string.
herr_t write_string_attribute(hid_t object, const std::string& name, const std::string& value);

/// A dataset's `units` (e.g. "m/s"; "1" for ratios and counts) and `description` attributes.
herr_t describe_dataset(hid_t dataset, const std::string& unit, const std::string& description);

}  // namespace spar::output::detail
