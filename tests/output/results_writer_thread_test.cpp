#include "output_fixtures.hpp"
#include "xml_reader.hpp"

#include <spar/output/results_writer.hpp>
#include <spar/error.hpp>

#include <catch2/catch.hpp>

#include <csignal>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <utility>
#include <vector>

using Catch::Matchers::Contains;
using spar::output::ResultsWriter;
using spar::test::ReadOnlyFile;
using spar::test::SampleStep;

// ResultsWriter writes its blocks on a thread of its own (results_writer.hpp); these tests drive
// that thread: blocks handed over while the previous one is still being written, a second reader
// after flush(), an error met by the writer thread, a destructor with a block in flight.

namespace {

/// The steps of the sidecar's temporal collection.
std::size_t sidecar_steps(const ResultsWriter& writer) {
  const auto root = spar::test::XmlReader::parse(spar::test::read_text(writer.xdmf_path()));
  return root.one("Domain").one("Grid").all("Grid").size();
}

/// Every dataset of both files has the same shape and the same values (compared as doubles: the
/// integer scalars are small whole numbers, exact in a double).
void check_same_datasets(const std::string& path, const std::string& reference_path) {
  const ReadOnlyFile file(path), reference(reference_path);
  REQUIRE(file.datasets() == reference.datasets());
  for (const std::string& name : reference.datasets()) {
    INFO("dataset " << name);
    const spar::test::DatasetContents contents = file.read(name), expected = reference.read(name);
    CHECK(contents.shape == expected.shape);
    CHECK(contents.values == expected.values);
  }
}

/// Another process reading the results file, as a viewer would while the run goes on: forked
/// before any writer exists (so without threads and without the file open in its HDF5), it
/// opens the file afresh at each request and answers with its step count and last time.
class SecondReader {
public:
  explicit SecondReader(const std::string& path) {
    int requests[2], replies[2];
    if (pipe(requests) != 0 || pipe(replies) != 0) throw std::runtime_error("pipe failed");
    pid_ = fork();
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
      close(requests[1]);
      close(replies[0]);
      char request = 0;
      while (read(requests[0], &request, 1) == 1) {
        double answer[2] = {-1, -1};  // steps, last time; -1 if the file does not open
        try {
          const spar::test::DatasetContents time = ReadOnlyFile(path).read("/time");
          answer[0] = static_cast<double>(time.values.size());
          answer[1] = time.values.empty() ? -1 : time.values.back();
        } catch (...) {
        }
        if (write(replies[1], answer, sizeof answer) != sizeof answer) _exit(1);
      }
      _exit(0);
    }
    close(requests[0]);
    close(replies[1]);
    requests_ = requests[1];
    replies_ = replies[0];
  }
  ~SecondReader() {
    close(requests_);  // the child's read fails: it exits
    close(replies_);
    waitpid(pid_, nullptr, 0);
  }
  SecondReader(const SecondReader&) = delete;
  SecondReader& operator=(const SecondReader&) = delete;

  /// The steps of /time and the last one, as the other process reads them now.
  std::pair<double, double> read_time() const {
    const char request = 1;
    double answer[2] = {-2, -2};
    if (write(requests_, &request, 1) != 1 || read(replies_, answer, sizeof answer) != sizeof answer)
      throw std::runtime_error("the reader process does not answer");
    return {answer[0], answer[1]};
  }

private:
  pid_t pid_ = -1;
  int requests_ = -1, replies_ = -1;
};

/// Runs `work` in a forked process and returns the text it returned (or an exception's
/// message). The process ends with _exit, without the atexit handlers: the test process keeps
/// neither the child's resource limits nor its HDF5 state (in this process the tests' readers may
/// start HDF5 before the library does, and then HDF5's own exit cleanup crashes after a failed
/// write: docs/output.md, "A full disk").
std::string run_in_child(const std::function<std::string()>& work) {
  int output[2];
  if (pipe(output) != 0) throw std::runtime_error("pipe failed");
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    close(output[0]);
    std::string text;
    try {
      text = work();
    } catch (const std::exception& e) {
      text = std::string("unexpected exception: ") + e.what();
    }
    const bool sent = write(output[1], text.data(), text.size()) == static_cast<ssize_t>(text.size());
    _exit(sent ? 0 : 1);
  }
  close(output[1]);
  std::string text;
  char chunk[4096];
  for (ssize_t n; (n = read(output[0], chunk, sizeof chunk)) > 0;) text.append(chunk, static_cast<std::size_t>(n));
  close(output[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) text += "\nthe child process failed, status " + std::to_string(status);
  return text;
}

/// Lowers the process's file-size limit (RLIMIT_FSIZE) to `bytes` and ignores SIGXFSZ, so a
/// write past it fails with EFBIG like a full disk; restores both at the end of the scope.
class FileSizeLimit {
public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &saved_);
    previous_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{bytes, saved_.rlim_max};
    setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, previous_handler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

private:
  rlimit saved_{};
  void (*previous_handler_)(int) = nullptr;
};

}  // namespace

TEST_CASE("Blocks written on the writer thread hold the same data as one block", "[output]") {
  // 40 steps in blocks of 1, 2 or 3: append hands a block over while the writer thread is still
  // writing the previous one, and waits for it. The reference holds all 40 steps in one block,
  // written by close(); the two writers run side by side (two writer threads).
  const int flush_every = GENERATE(1, 2, 3);
  const int steps = 40;
  const spar::test::ScratchFolder folder("thread_blocks_" + std::to_string(flush_every));
  const std::string path = folder.file("blocks.h5"), reference_path = folder.file("reference.h5");
  {
    ResultsWriter writer(path, spar::test::sample_layout(), flush_every);
    ResultsWriter reference(reference_path, spar::test::sample_layout(), steps + 1);
    for (int k = 0; k < steps; ++k) {
      const SampleStep sample(k);
      writer.append(sample.step);
      reference.append(sample.step);
    }
    CHECK(writer.steps_flushed() == steps / flush_every * flush_every);
    CHECK(reference.steps_flushed() == 0);
    writer.close();
    reference.close();
    CHECK(sidecar_steps(writer) == std::size_t{steps});
    CHECK(sidecar_steps(reference) == std::size_t{steps});
  }
  check_same_datasets(path, reference_path);
  const ReadOnlyFile file(path);
  const spar::test::DatasetContents time = file.read("/time");
  REQUIRE(time.values.size() == std::size_t{steps});
  for (int k = 0; k < steps; ++k) CHECK(time.values[static_cast<std::size_t>(k)] == SampleStep(k).step.time);
}

TEST_CASE("flush() returns with every appended step readable by a second reader", "[output]") {
  const spar::test::ScratchFolder folder("thread_flush");
  const std::string path = folder.file("run.h5");
  const SecondReader reader(path);
  ResultsWriter writer(path, spar::test::sample_layout(), 4);
  int appended = 0;
  for (const int until : {10, 13, 21}) {  // 2 blocks + 2 steps buffered, 3 buffered, 2 blocks
    for (; appended < until; ++appended) writer.append(SampleStep(appended).step);
    writer.flush();
    CHECK(writer.steps_flushed() == until);
    const auto [steps, last_time] = reader.read_time();
    CHECK(steps == until);
    CHECK(last_time == SampleStep(until - 1).step.time);
    CHECK(sidecar_steps(writer) == static_cast<std::size_t>(until));
  }
}

TEST_CASE("An error on the writer thread surfaces on the caller and closes the writer", "[output]") {
  // One step of 2000 centerline points is 48 kB, written by the writer thread in a block of 1;
  // the file may not grow more than 4 kB past its empty size, so the block's write or H5Fflush
  // fails (EFBIG, as on a full disk) on the writer thread. In a child process: see run_in_child.
  const spar::test::ScratchFolder folder("thread_error");
  const std::string path = folder.file("run.h5");
  const std::string messages = run_in_child([&] {
    spar::output::ResultsLayout layout;
    layout.centerline_points = {2000};
    auto writer = std::make_unique<ResultsWriter>(path, layout, 1);
    const auto step = [](int k) {
      spar::output::ResultsStep s;
      s.time = k;
      s.centerlines = {Eigen::MatrixXd::Constant(2000, 3, k)};
      return s;
    };
    std::string text;
    writer->flush();  // the writer thread has made the file: its size is the empty file's
    const FileSizeLimit limit(std::filesystem::file_size(path) + 4096);
    // The first append hands its block over; the error surfaces at a later call (append or flush).
    try {
      for (int k = 0; k < 3; ++k) writer->append(step(k));
      writer->flush();
      text += "no error\n";
    } catch (const spar::Error& e) {
      text += std::string("first: ") + e.what() + "\n";
    }
    // The writer is closed for writing: later calls say so; close() and the destructor do not throw.
    const auto message_of = [](const std::function<void()>& call) {
      try {
        call();
        return std::string("no error");
      } catch (const spar::Error& e) {
        return std::string(e.what());
      }
    };
    text += "append: " + message_of([&] { writer->append(step(10)); }) + "\n";
    text += "flush: " + message_of([&] { writer->flush(); }) + "\n";
    text += "write_attribute: " + message_of([&] { writer->write_attribute("h", 1e-4); }) + "\n";
    text += "close: " + message_of([&] { writer->close(); }) + "\n";
    writer.reset();
    return text + "destroyed\n";
  });
  INFO(messages);
  const std::string where = "output::ResultsWriter::";
  CHECK_THAT(messages, Contains("first: spar: " + where + "flush(" + path + "): HDF5 failed to") &&
                           Contains("disk is not full"));
  for (const std::string call : {"append", "flush", "write_attribute"})
    CHECK_THAT(messages, Contains(call + ": spar: " + where + call + "(" + path + "): the results file is closed"));
  CHECK_THAT(messages, Contains("close: no error\ndestroyed\n"));
}

TEST_CASE("The destructor writes the blocks still queued and the steps still buffered", "[output]") {
  const spar::test::ScratchFolder folder("thread_destructor");
  const std::string path = folder.file("run.h5");
  const int steps = 10;
  {
    ResultsWriter writer(path, spar::test::sample_layout(), 3);
    for (int k = 0; k < 5; ++k) writer.append(SampleStep(k).step);
    ResultsWriter moved(std::move(writer));  // the writer thread goes on for the new owner
    for (int k = 5; k < steps; ++k) moved.append(SampleStep(k).step);
    // Steps 6-8 may still be with the writer thread, step 9 is buffered; `moved` then `writer`
    // (moved from: it holds nothing) are destroyed without a flush().
  }
  const ReadOnlyFile file(path);
  const spar::test::DatasetContents time = file.read("/time");
  REQUIRE(time.shape == std::vector<hsize_t>{steps});
  for (int k = 0; k < steps; ++k) CHECK(time.values[static_cast<std::size_t>(k)] == SampleStep(k).step.time);
  CHECK(file.read("/centerlines/beam1").shape == std::vector<hsize_t>{steps, 5, 3});
  const auto root = spar::test::XmlReader::parse(spar::test::read_text(folder.file("run.xmf")));
  CHECK(root.one("Domain").one("Grid").all("Grid").size() == std::size_t{steps});
}

TEST_CASE("An error of the writer thread making the file surfaces at the next call", "[output]") {
  // The constructor only checks that the path can be written; the writer thread makes the file
  // and its datasets, which need more than the 4 kB the file may grow to here (EFBIG, as on a
  // full disk). The constructor returns; the error is rethrown by the next append (once the
  // writer thread has met it: steps_flushed() waits for that without rethrowing), flush,
  // write_attribute or close. In a child process: see run_in_child.
  const spar::test::ScratchFolder folder("thread_creation_error");
  const std::string messages = run_in_child([&] {
    const FileSizeLimit limit(4096);
    std::string text;
    const std::vector<std::pair<std::string, std::function<void(ResultsWriter&)>>> calls = {
        {"append", [](ResultsWriter& w) { w.append(SampleStep(0).step); }},
        {"flush", [](ResultsWriter& w) { w.flush(); }},
        {"write_attribute", [](ResultsWriter& w) { w.write_attribute("h", 1e-4); }},
        {"close", [](ResultsWriter& w) { w.close(); }}};
    for (const auto& [name, call] : calls) {
      ResultsWriter writer(folder.file(name + ".h5"), spar::test::sample_layout(), 4);
      text += name + ": steps on disk " + std::to_string(writer.steps_flushed()) + ", ";
      try {
        call(writer);
        text += "no error\n";
      } catch (const spar::Error& e) {
        text += std::string(e.what()) + "\n";
      }
      try {
        writer.close();
        text += name + ": then closed\n";
      } catch (const spar::Error& e) {
        text += name + ": close threw " + e.what() + "\n";
      }
    }
    return text;
  });
  INFO(messages);
  for (const std::string call : {"append", "flush", "write_attribute", "close"}) {
    const std::string path = folder.file(call + ".h5");
    CHECK_THAT(messages, Contains(call + ": steps on disk 0, spar: output::ResultsWriter::ResultsWriter(" + path +
                                  "): HDF5 failed to") &&
                             Contains(call + ": then closed\n"));
  }
  CHECK_THAT(messages, !Contains("unexpected exception") && !Contains("no error"));
}
