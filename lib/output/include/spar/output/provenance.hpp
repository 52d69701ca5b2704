#pragma once
/// \file
/// What every results file says about itself (docs/output.md, "Schema and provenance"): the
/// version of its schema, the spar it was written by and the run's options.

#include <map>
#include <string>

namespace spar::output {

/// The version of the results files' schema, stored as the int64 root attribute `schema` of
/// every file ResultsWriter and Hdf5File write. Bumped by every change to what they write
/// (docs/output.md, "Schema and provenance", lists the versions).
inline constexpr int results_schema_version = 3;

/// spar's version, "MAJOR.MINOR.PATCH" (project(spar VERSION …) in CMakeLists.txt): the root
/// attribute `spar_version`.
const std::string& spar_version();

/// The source revision this spar was built from: `git describe --always --dirty` of the source
/// tree when CMake last configured the build (a commit hash, "-dirty" if files had changed), or
/// "unknown" where the sources are no git checkout: the root attribute `spar_revision`.
const std::string& source_revision();

/// The options a run was given, name → value as text, e.g. {"--h", "1e-4"}, {"--strategy",
/// "frozen"}: the string attributes of the group `/options` of its results file
/// (ResultsWriter::write_options, Hdf5File::write_options).
using RunOptions = std::map<std::string, std::string>;

}  // namespace spar::output
