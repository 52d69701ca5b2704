#pragma once
/// \file
/// Rewriting an output file from scratch as a new file rather than the old one truncated. ext4,
/// the default file system of most Linux machines, starts the write-back of a file that was
/// truncated to zero when it is closed (its auto_da_alloc heuristic, for programs that rewrite a
/// file in place without fsync): the close of a 4 MB results file then takes ~0.5 ms and that of
/// its sidecar ~0.2 ms, at the end of the run, on the run's thread. A new file is closed in a few
/// µs. Used by ResultsWriter for the HDF5 file and its XDMF sidecar (docs/output.md).

#include <string>

namespace spar::output::detail {

/// Removes `path` if it is a regular file of one link, so that creating it again (with O_TRUNC
/// or H5F_ACC_TRUNC) makes a new file. A symbolic link, a file with other hard links or anything
/// else is left in place, to be truncated as before: the new content then still goes where the
/// link points. A reader that has the old file open keeps reading the old content. Failures are
/// ignored: the creation that follows reports them.
void remove_for_rewrite(const std::string& path);

}  // namespace spar::output::detail
