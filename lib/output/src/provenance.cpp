// Compiled into an object library of its own with SPAR_VERSION and SPAR_SOURCE_REVISION defined
// (lib/output/CMakeLists.txt), so that a new revision recompiles this file only.
#include <spar/output/provenance.hpp>

namespace spar::output {

const std::string& spar_version() {
  static const std::string version = SPAR_VERSION;
  return version;
}

const std::string& source_revision() {
  static const std::string revision = SPAR_SOURCE_REVISION;
  return revision;
}

}  // namespace spar::output
