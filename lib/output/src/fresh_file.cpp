#include "fresh_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

namespace spar::output::detail {

void remove_for_rewrite(const std::string& path) {
  struct stat status {};
  if (::lstat(path.c_str(), &status) == 0 && S_ISREG(status.st_mode) && status.st_nlink == 1) ::unlink(path.c_str());
}

}  // namespace spar::output::detail
