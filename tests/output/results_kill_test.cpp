// Issue 29: a run killed at any moment leaves both results files readable whole. An audit's
// SIGKILLs found a sidecar cut mid-tag (2 of 76 slider-crank kills) and an HDF5 file whose
// datasets declared 140 rows but held 130 (1 of 31 truss kills). Here a run that writes often
// (kill_driver.cpp) is killed at 50 moments drawn from a seeded generator (the same 50 at every
// run), and after each kill, over the files of the earlier kills, every dataset of the HDF5 file
// must read whole, the time histories agree on their row count, the sidecar must pass xmllint and
// list no more steps than the HDF5 file holds. A correct writer passes at every moment, so the
// test does not depend on where the kills land; labelled `long` (about 15 s).

#include "output_fixtures.hpp"

#include <catch2/catch.hpp>

#include <hdf5.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

/// Runs the driver on `path` for `steps` steps (-1: until killed); returns its pid.
pid_t start_driver(const std::string& path, int steps) {
  const pid_t pid = fork();
  if (pid == 0) {
    prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlives the test
    const std::string count = std::to_string(steps < 0 ? 1000000000 : steps);
    execl(SPAR_KILL_DRIVER, SPAR_KILL_DRIVER, path.c_str(), count.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

int wait_for(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

/// What is wrong with the HDF5 file at `path` ("" if nothing): it must open, every dataset must
/// read whole, and the time histories (the datasets of unlimited rows) must have the same rows,
/// which are returned in `rows`.
std::string h5_defect(const std::string& path, hsize_t& rows) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) return "the HDF5 file does not open";
  std::vector<std::string> names;
  auto visit = [](hid_t group, const char* name, const auto*, void* data) -> herr_t {
    const hid_t object = H5Oopen(group, name, H5P_DEFAULT);
    if (object >= 0 && H5Iget_type(object) == H5I_DATASET) static_cast<std::vector<std::string>*>(data)->push_back(name);
    if (object >= 0) H5Oclose(object);
    return 0;
  };
  std::string defect;
  if (H5Lvisit(file, H5_INDEX_NAME, H5_ITER_NATIVE, visit, &names) < 0) defect = "its links cannot be visited";
  bool first_history = true;
  for (const std::string& name : names) {
    const hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
    const hid_t space = set < 0 ? -1 : H5Dget_space(set);
    hsize_t dims[4] = {}, max_dims[4] = {};
    const int rank = space < 0 ? -1 : H5Sget_simple_extent_dims(space, dims, max_dims);
    std::vector<double> values(space < 0 ? 0 : static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
    if (rank < 0 || (!values.empty() && H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0))
      defect += " dataset " + name + " does not read whole;";
    else if (rank > 0 && max_dims[0] == H5S_UNLIMITED) {
      if (!first_history && dims[0] != rows)
        defect += " dataset " + name + " has " + std::to_string(dims[0]) + " rows, others " + std::to_string(rows) + ";";
      rows = dims[0];
      first_history = false;
    }
    if (space >= 0) H5Sclose(space);
    if (set >= 0) H5Dclose(set);
  }
  H5Fclose(file);
  return defect;
}

/// What is wrong with the sidecar at `path` ("" if nothing): xmllint must accept it and it must
/// list no more steps than the HDF5 file's `rows`.
std::string xmf_defect(const std::string& path, hsize_t rows) {
  if (std::system(("'" SPAR_XMLLINT "' --noout '" + path + "' 2>/dev/null").c_str()) != 0)
    return " the sidecar is not XML to xmllint;";
  const std::string text = spar::test::read_text(path);
  std::size_t steps = 0;
  for (std::size_t at = text.find("<Time "); at != std::string::npos; at = text.find("<Time ", at + 1)) ++steps;
  if (steps > rows) return " the sidecar lists " + std::to_string(steps) + " steps, the HDF5 file holds " + std::to_string(rows) + ";";
  return "";
}

}  // namespace

TEST_CASE("SIGKILL at 50 seeded random moments leaves both results files readable whole", "[output]") {
  const std::string xmllint = SPAR_XMLLINT;
  REQUIRE(xmllint.find("NOTFOUND") == std::string::npos);  // Debian libxml2-utils
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);              // a broken file is reported below, not on stderr
  const spar::test::ScratchFolder folder("kill");
  const std::string path = folder.file("run.h5"), xmf_path = folder.file("run.xmf");
  // A whole run first, so that every kill finds the files of an earlier run to replace.
  const int complete = wait_for(start_driver(path, 20));
  REQUIRE((WIFEXITED(complete) && WEXITSTATUS(complete) == 0));

  // Kill moments from the driver's start: 0-300 ms covers its start (no file made yet), the
  // replacement of the old files and ~200 blocks, attributes and a constant.
  std::mt19937 random(29);
  std::uniform_int_distribution<int> delay_us(0, 300000);
  std::ostringstream failures;
  int failed = 0;
  for (int kill_index = 0; kill_index < 50; ++kill_index) {
    const int delay = delay_us(random);
    const pid_t pid = start_driver(path, -1);
    std::this_thread::sleep_for(std::chrono::microseconds(delay));
    kill(pid, SIGKILL);
    const int status = wait_for(pid);
    REQUIRE(WIFSIGNALED(status));  // killed, not failed on its own
    hsize_t rows = 0;
    std::string defect = h5_defect(path, rows);
    if (defect.empty() || defect.find("does not open") == std::string::npos) defect += xmf_defect(xmf_path, rows);
    if (!defect.empty()) {
      ++failed;
      failures << "kill " << kill_index << " at " << delay << " us:" << defect << "\n";
    }
  }
  INFO(failed << " of 50 kills left a file that is not readable whole:\n" << failures.str());
  CHECK(failed == 0);
}
