#include "spare_copy.hpp"

#include <spar/error.hpp>

#include <fcntl.h>
#include <stdio.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace spar::output::detail {

namespace {

[[noreturn]] void fail(const std::string& what, const std::string& where) {
  throw Error(what + ": " + std::strerror(errno), where, "check that the output folder is writable and the disk is not full");
}

}  // namespace

std::string spare_path(const std::string& path) { return path + ".spare"; }

std::string write_target(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path target = path;
  // Link by link, so that a link to a file not made yet (the results of a writer that has just
  // started) resolves too; 40 links at most, as the kernel allows.
  for (int links = 0; links < 40 && fs::is_symlink(target, ec); ++links) {
    const fs::path next = fs::read_symlink(target, ec);
    if (ec) break;
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
  return target.lexically_normal().string();
}

void exchange_names(const std::string& a, const std::string& b, const std::string& where) {
  if (::renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) == 0) return;
  if (errno != EINVAL && errno != ENOSYS) fail("cannot swap " + a + " and " + b, where);
  const std::string previous = b + ".previous";
  ::unlink(previous.c_str());
  if (::link(b.c_str(), previous.c_str()) != 0) fail("cannot link " + previous + " to " + b, where);
  replace_file(a, b, where);
  replace_file(previous, a, where);
}

void replace_file(const std::string& from, const std::string& to, const std::string& where) {
  if (::rename(from.c_str(), to.c_str()) != 0) fail("cannot rename " + from + " to " + to, where);
}

}  // namespace spar::output::detail
