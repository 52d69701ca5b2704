#include "written_files.hpp"

#include "spare_copy.hpp"

#include <spar/error.hpp>

#include <filesystem>
#include <mutex>
#include <set>

namespace spar::output::detail {

namespace {

std::mutex& files_mutex() {
  static std::mutex mutex;
  return mutex;
}

std::set<std::string>& written_files() {
  static std::set<std::string> files;
  return files;
}

}  // namespace

std::string claim_written_file(const std::string& path, const std::string& where) {
  std::error_code ec;
  // Through symbolic links, also to a file not made yet (spare_copy.hpp): a writer makes its file
  // on its own thread, a moment after its constructor has claimed it.
  const std::string target = write_target(path);
  std::filesystem::path key = std::filesystem::weakly_canonical(std::filesystem::absolute(target, ec), ec);
  if (ec) key = std::filesystem::absolute(target, ec);  // the creation that follows reports what is wrong
  const std::lock_guard<std::mutex> lock(files_mutex());
  if (!written_files().insert(key.string()).second)
    throw Error("the file " + path + " is being written by another results writer of this program", where,
                "close() the other writer first, or write to another path");
  return key.string();
}

void release_written_file(const std::string& key) {
  if (key.empty()) return;
  const std::lock_guard<std::mutex> lock(files_mutex());
  written_files().erase(key);
}

}  // namespace spar::output::detail
