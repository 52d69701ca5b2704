#pragma once
/// \file
/// A results file that a kill at any moment leaves whole (issue 29, docs/output.md "Surviving a
/// kill"): the file is kept twice, as `path` (published: what readers open) and its spare
/// `path.spare`, both complete. A change (a block of steps, an attribute) is made to the spare
/// and flushed, the two names are swapped in one atomic step (exchange_names), and the same change
/// is made to the other copy, now the spare. The published file is therefore never written while
/// it has its name: a kill leaves it as it was before the change or after it, never in between,
/// at the cost of writing every change twice (O(change), not O(file) as a copy would).
///
/// This holds whatever order HDF5 writes its metadata in: a kill during H5Dwrite or H5Fflush
/// (which write the chunk index, the dataspace and the superblock's end of allocation with
/// separate writes, in an order HDF5 does not promise) leaves only the spare inconsistent. It
/// assumes a kill, not a power cut: what was written before the kill is in the page cache.

#include <string>

namespace spar::output::detail {

/// `path` with ".spare" appended: the spare copy's name, beside the file.
std::string spare_path(const std::string& path);

/// The file a write to `path` must replace: `path` itself, or, if `path` is a symbolic link, the
/// file it points to (resolved link by link, also to a file that does not exist yet), so the
/// results still go where the link points.
std::string write_target(const std::string& path);

/// Swaps the names `a` and `b` (both existing files in one folder) in one atomic step
/// (renameat2 RENAME_EXCHANGE). Where the file system cannot (EINVAL), three atomic steps do it
/// instead: a hard link `b.previous` to `b`, `a` renamed over `b`, `b.previous` renamed to `a`;
/// `b` names a whole file after each. Throws spar::Error naming `where` on failure.
void exchange_names(const std::string& a, const std::string& b, const std::string& where);

/// Renames `from` over `to` (one atomic step); throws spar::Error naming `where` on failure.
void replace_file(const std::string& from, const std::string& to, const std::string& where);

}  // namespace spar::output::detail
