// A run whose disk fills up reports the failure and ends normally (docs/output.md, "A full
// disk"): HDF5 1.10's cleanup at exit crashes after a failed write, so the library ends HDF5
// itself and skips that cleanup then (lib/output/src/hdf5_lifetime.hpp).
//
// A program of its own rather than a Catch2 case: the protection holds in a process whose first
// HDF5 call is the library's, and what is tested is the process's exit — CTest fails the test on
// a crash (SIGSEGV at exit without the protection) or a nonzero status.
//
//   test_output_disk_full_exit FOLDER
#include <spar/output/results_writer.hpp>
#include <spar/error.hpp>

#include <sys/resource.h>

#include <csignal>
#include <filesystem>
#include <iostream>
#include <memory>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: test_output_disk_full_exit FOLDER\n";
    return 2;
  }
  std::filesystem::create_directories(argv[1]);
  const std::string path = std::string(argv[1]) + "/run.h5";
  spar::output::ResultsLayout layout;
  layout.centerline_points = {2000};  // 48 kB per step, written in blocks of one step
  auto writer = std::make_unique<spar::output::ResultsWriter>(path, layout, 1);
  writer->flush();  // the writer thread has made the file: its size is the empty file's
  // The file may grow 4 kB past its empty size: the first block's write fails with EFBIG (a
  // file-size limit, ignored as a signal), as on a full disk.
  std::signal(SIGXFSZ, SIG_IGN);
  rlimit limit{};
  getrlimit(RLIMIT_FSIZE, &limit);
  limit.rlim_cur = std::filesystem::file_size(path) + 4096;
  setrlimit(RLIMIT_FSIZE, &limit);
  std::string error;
  try {
    for (int k = 0; k < 10; ++k) {
      spar::output::ResultsStep step;
      step.time = k;
      step.centerlines = {Eigen::MatrixXd::Constant(2000, 3, k)};
      writer->append(step);
    }
    writer->close();
  } catch (const spar::Error& e) {
    error = e.what();
  }
  writer.reset();
  if (error.find("HDF5 failed") == std::string::npos) {
    std::cerr << "expected the write to fail with an HDF5 error; got: '" << error << "'\n";
    return 1;
  }
  std::cout << "the failure, as reported: " << error << "\nthe process now ends normally\n";
  return 0;  // HDF5's cleanup would crash from here on
}
