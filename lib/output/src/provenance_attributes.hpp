#pragma once
/// \file
/// The schema and provenance in a results file (docs/output.md, "Schema and provenance"), shared by
/// ResultsWriter and Hdf5File: the root attributes `schema` (int64), `spar_version` and
/// `spar_revision` (strings), and the group `/options` whose string attributes are the run's
/// options.

#include <spar/output/provenance.hpp>

#include <hdf5.h>

#include <string>

namespace spar::output::detail {

/// Writes the schema and provenance attributes on the root group of `file` and makes the empty
/// group /options. Returns a negative value on failure.
herr_t write_provenance(hid_t file);

/// Writes `options` as string attributes of the group /options of `file` (made by
/// write_provenance), replacing those of the same names. Returns a negative value on failure.
herr_t write_options(hid_t file, const RunOptions& options);

/// Throws spar::Error naming `where` for a name that HDF5 cannot give an attribute (empty, or
/// over 65 000 characters) or, if `root`, that names one of the provenance attributes.
void check_attribute_name(const std::string& name, bool root, const std::string& where);

}  // namespace spar::output::detail
