#pragma once
/// \file
/// The output files the library's HDF5 writers (ResultsWriter, Hdf5File) of this process are
/// writing, by canonical path, so that a second writer of a file is refused by its constructor.
/// HDF5 itself refuses to create (truncate) a file it has open, but a ResultsWriter makes its
/// file on its writer thread, after removing an old file (fresh_file.hpp): without this record, a
/// second writer of the same file would replace the first one's file, which would go on writing
/// into a removed file, instead of being refused.

#include <string>

namespace spar::output::detail {

/// Records `path` as written until release_written_file(key) and returns the key. Throws
/// spar::Error (`where`) if a writer of this process is writing it.
std::string claim_written_file(const std::string& path, const std::string& where);

/// Ends the record of a claim_written_file (an empty key: nothing).
void release_written_file(const std::string& key);

}  // namespace spar::output::detail
