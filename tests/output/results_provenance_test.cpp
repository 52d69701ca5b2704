// Every results file says what it is and how it was made (issue 30; docs/output.md, "Schema and
// provenance"): the schema version, spar's version and source revision as root attributes, the
// run's options in /options — for ResultsWriter's files and Hdf5File's alike.
#include "output_fixtures.hpp"

#include <spar/error.hpp>
#include <spar/output/hdf5_file.hpp>
#include <spar/output/provenance.hpp>
#include <spar/output/results_writer.hpp>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

using Catch::Matchers::Contains;
using spar::output::ResultsWriter;
using spar::output::RunOptions;
using spar::test::ReadOnlyFile;
using spar::test::SampleStep;

namespace {

/// What CMake computed when it configured this build (tests/output/CMakeLists.txt writes it):
/// project(spar VERSION …) and SPAR_SOURCE_REVISION, read from outside the library.
struct Configured {
  std::string version, revision;
};

Configured configured() {
  std::ifstream in(SPAR_TEST_PROVENANCE_FILE);
  Configured result;
  std::getline(in, result.version);
  std::getline(in, result.revision);
  return result;
}

/// The schema and provenance attributes of `file`, against the configured build.
void check_provenance(const ReadOnlyFile& file) {
  const Configured build = configured();
  REQUIRE_FALSE(build.version.empty());
  CHECK(file.integer_attribute("schema") == 3);
  CHECK(file.string_attribute("spar_version") == build.version);
  CHECK(file.string_attribute("spar_revision") == build.revision);
  CHECK_FALSE(file.string_attribute("spar_revision").empty());
  for (const char* name : {"spar_version", "spar_revision"}) {
    const auto attribute = file.string_attribute_of("/", name);
    INFO("attribute " << name);
    CHECK(attribute.variable_length);
    CHECK(attribute.utf8);
  }
}

/// A copy of the file `path` as it is on disk now, to be read while its writer still has it open
/// (HDF5 would share the writer's open file with a reader in the same process).
std::string snapshot(const std::string& path) {
  const std::string copy = path + ".snapshot.h5";
  std::filesystem::copy_file(path, copy, std::filesystem::copy_options::overwrite_existing);
  return copy;
}

const RunOptions run_options = {{"--h", "1e-4"}, {"--strategy", "frozen"}, {"--out", "results/\u03c1\u221e"}};

}  // namespace

TEST_CASE("The library knows the version and revision the build was configured with", "[output]") {
  const Configured build = configured();
  CHECK(spar::output::spar_version() == build.version);
  CHECK(spar::output::source_revision() == build.revision);
  CHECK_FALSE(spar::output::source_revision().empty());
  CHECK(spar::output::results_schema_version == 3);
}

TEST_CASE("A ResultsWriter file carries its schema and spar's version and revision and the run's options", "[output]") {
  const spar::test::ScratchFolder folder("provenance");
  const std::string path = folder.file("run.h5");
  ResultsWriter writer(path, spar::test::sample_layout(), 2);
  writer.flush();  // the file as the writer thread made it: provenance, no options yet
  {
    const ReadOnlyFile file(snapshot(path));
    check_provenance(file);
    CHECK(file.attribute_names("/options").empty());
  }
  writer.write_options(run_options);
  for (int k = 0; k < 3; ++k) writer.append(SampleStep(k).step);
  writer.write_options({{"--h", "2e-4"}, {"--t-end", "0.2"}});  // replaces --h, adds --t-end
  writer.flush();
  {
    const ReadOnlyFile file(snapshot(path));  // on disk while the run goes on: flushed like a block
    check_provenance(file);
    CHECK(file.attribute_names("/options") == std::vector<std::string>{"--h", "--out", "--strategy", "--t-end"});
    CHECK(file.string_attribute_of("/options", "--h").value == "2e-4");
    CHECK(file.string_attribute_of("/options", "--strategy").value == "frozen");
    CHECK(file.string_attribute_of("/options", "--t-end").value == "0.2");
    const auto out = file.string_attribute_of("/options", "--out");
    CHECK(out.value == "results/\u03c1\u221e");
    CHECK(out.variable_length);
    CHECK(out.utf8);
  }
  writer.close();
  const ReadOnlyFile file(path);
  check_provenance(file);
  CHECK(file.attribute_names("/options").size() == 4);
  CHECK(file.read("/time").shape == std::vector<hsize_t>{3});
}

TEST_CASE("An Hdf5File carries the same schema and provenance and the run's options", "[output]") {
  const spar::test::ScratchFolder folder("provenance_hdf5_file");
  const std::string path = folder.file("statics.h5");
  {
    spar::output::Hdf5File file(path);
    {
      const ReadOnlyFile before(snapshot(path));  // flushed at creation
      check_provenance(before);
      CHECK(before.attribute_names("/options").empty());
    }
    file.write_options(run_options);
    file.write_attribute("case", "tip-load");
  }
  const ReadOnlyFile file(path);
  check_provenance(file);
  CHECK(file.attribute_names("/") == std::vector<std::string>{"case", "schema", "spar_revision", "spar_version"});
  CHECK(file.attribute_names("/options") == std::vector<std::string>{"--h", "--out", "--strategy"});
  CHECK(file.string_attribute_of("/options", "--h").value == "1e-4");
}

TEST_CASE("The provenance attributes cannot be overwritten and option names are checked", "[output]") {
  const spar::test::ScratchFolder folder("provenance_names");
  ResultsWriter writer(folder.file("run.h5"), spar::test::sample_layout());
  spar::output::Hdf5File statics(folder.file("statics.h5"));
  const std::vector<std::pair<std::string, std::function<void(const std::string&)>>> writers = {
      {"ResultsWriter::write_attribute", [&](const std::string& name) { writer.write_attribute(name, 1.0); }},
      {"Hdf5File::write_attribute", [&](const std::string& name) { statics.write_attribute(name, "x"); }}};
  for (const auto& [call, write] : writers) {
    INFO(call);
    for (const std::string name : {"schema", "spar_version", "spar_revision"})
      CHECK_THROWS_WITH(write(name), Contains(call) && Contains("the root attribute " + name + " is the file's own"));
    CHECK_THROWS_WITH(write(""), Contains(call) && Contains("the attribute name has 0 characters"));
  }
  CHECK_THROWS_WITH(writer.write_options({{"", "x"}}),
                    Contains("ResultsWriter::write_options") && Contains("the attribute name has 0 characters"));
  CHECK_THROWS_WITH(statics.write_options({{std::string(65001, 'x'), "x"}}),
                    Contains("Hdf5File::write_options") && Contains("the attribute name has 65001 characters"));
  writer.write_options({{"schema", "an option may have any name"}});  // in /options, not the root
  writer.close();
  const ReadOnlyFile file(folder.file("run.h5"));
  check_provenance(file);
  CHECK(file.string_attribute_of("/options", "schema").value == "an option may have any name");
  CHECK_THROWS_WITH(writer.write_options({}), Contains("closed"));
}
