#include "output_fixtures.hpp"
#include "xml_reader.hpp"

#include <spar/output/results_writer.hpp>

#include <catch2/catch.hpp>

#include <csignal>
#include <filesystem>
#include <set>
#include <sys/wait.h>

using spar::output::ResultsWriter;
using spar::test::SampleStep;

namespace {

/// A child process, killed with SIGKILL and reaped when the test leaves the scope.
struct Child {
  pid_t pid;
  ~Child() {
    if (pid > 0) kill_now();
  }
  int kill_now() {
    int status = 0;
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    pid = -1;
    return status;
  }
};

/// The child's part: 6 steps with blocks of 4, an explicit flush (so 6 on disk), 3 more steps
/// that stay buffered, then a signal to the parent and a wait for SIGKILL. Never returns.
[[noreturn]] void write_and_hang(const std::string& path, int ready_fd) {
  try {
    ResultsWriter writer(path, spar::test::sample_layout(), 4);
    for (int k = 0; k < 6; ++k) writer.append(SampleStep(k).step);
    writer.flush();
    for (int k = 6; k < 9; ++k) writer.append(SampleStep(k).step);
    const char byte = 1;
    if (write(ready_fd, &byte, 1) != 1) _exit(3);
    while (true) pause();
  } catch (...) {
    _exit(2);
  }
}

/// The file opens and holds exactly the 6 flushed steps; the sidecar lists them; nothing else is
/// in the folder but the spare copies of both (spare_copy.hpp), which close() removes.
void check_flushed_steps(const std::string& path, const std::string& xmf_path) {
  std::set<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(path).parent_path()))
    files.insert(entry.path().filename().string());
  CHECK(files == std::set<std::string>{"run.h5", "run.xmf", "run.h5.spare", "run.xmf.spare"});
  const spar::test::ReadOnlyFile file(path);
  CHECK(file.read("/time").shape == std::vector<hsize_t>{6});
  CHECK(file.read("/time").values.back() == SampleStep(5).step.time);
  CHECK(file.read("/positions").shape == std::vector<hsize_t>{6, 3, 3});
  CHECK(file.read("/centerlines/beam1").shape == std::vector<hsize_t>{6, 5, 3});
  const auto root = spar::test::XmlReader::parse(spar::test::read_text(xmf_path));
  CHECK(root.one("Domain").one("Grid").all("Grid").size() == 6);
}

}  // namespace

TEST_CASE("A killed run leaves files that open, with every flushed step", "[output]") {
  const spar::test::ScratchFolder folder("crash");
  const std::string path = folder.file("run.h5"), xmf_path = folder.file("run.xmf");
  int ready[2];
  REQUIRE(pipe(ready) == 0);
  Child child{fork()};
  REQUIRE(child.pid >= 0);
  if (child.pid == 0) write_and_hang(path, ready[1]);
  close(ready[1]);
  char byte = 0;
  const bool child_ready = read(ready[0], &byte, 1) == 1;
  close(ready[0]);
  REQUIRE(child_ready);

  SECTION("readable while the writer is alive") { check_flushed_steps(path, xmf_path); }
  SECTION("readable after SIGKILL") {
    const int status = child.kill_now();
    CHECK(WIFSIGNALED(status));
    check_flushed_steps(path, xmf_path);
  }
}
