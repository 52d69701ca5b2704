#include "output_fixtures.hpp"
#include "xml_reader.hpp"

#include <spar/core/results_writer.hpp>

#include <catch2/catch.hpp>

#include <sstream>

using spar::core::ResultsWriter;
using spar::test::ReadOnlyFile;
using spar::test::SampleStep;
using spar::test::XmlElement;

namespace {

std::vector<hsize_t> parse_dimensions(const std::string& text) {
  std::istringstream in(text);
  std::vector<hsize_t> dims;
  for (hsize_t d; in >> d;) dims.push_back(d);
  return dims;
}

/// Every HDF DataItem below `element` names "run.h5:<dataset>", a dataset of exactly its
/// Dimensions; every HyperSlab selects a block inside its dataset with as many values as it
/// declares. Returns the number of HDF references checked.
int check_heavy_data(const XmlElement& element, const ReadOnlyFile& file) {
  int checked = 0;
  if (element.name == "DataItem" && element.attributes.count("Format") && element.attribute("Format") == "HDF") {
    const std::string& reference = element.text;
    REQUIRE(reference.rfind("run.h5:/", 0) == 0);
    CHECK(file.read(reference.substr(7)).shape == parse_dimensions(element.attribute("Dimensions")));
    ++checked;
  }
  if (element.name == "DataItem" && element.attributes.count("ItemType") && element.attribute("ItemType") == "HyperSlab") {
    REQUIRE(element.children.size() == 2);
    const auto selection = parse_dimensions(element.children[0].text);  // start, stride, count
    const auto source = parse_dimensions(element.children[1].attribute("Dimensions"));
    REQUIRE(selection.size() == 3 * source.size());
    hsize_t selected = 1, declared = 1;
    for (std::size_t d = 0; d < source.size(); ++d) {
      const hsize_t start = selection[d], stride = selection[source.size() + d], count = selection[2 * source.size() + d];
      CHECK(start + (count - 1) * stride < source[d]);
      selected *= count;
    }
    for (hsize_t d : parse_dimensions(element.attribute("Dimensions"))) declared *= d;
    CHECK(selected == declared);
  }
  for (const XmlElement& child : element.children) checked += check_heavy_data(child, file);
  return checked;
}

}  // namespace

TEST_CASE("The XDMF sidecar is well-formed XML and describes every flushed step", "[output]") {
  const spar::test::ScratchFolder folder("xdmf");
  const std::string path = folder.file("run.h5");
  ResultsWriter writer(path, spar::test::sample_layout(), 3);
  CHECK(writer.xdmf_path() == folder.file("run.xmf"));
  for (int k = 0; k < 4; ++k) writer.append(SampleStep(k).step);  // one block of 3 on disk, 1 buffered

  const int flushed = GENERATE(3, 4);
  if (flushed == 4) writer.flush();
  const XmlElement root = spar::test::XmlReader::parse(spar::test::read_text(writer.xdmf_path()));
  REQUIRE(root.name == "Xdmf");
  const XmlElement& series = root.one("Domain").one("Grid");
  CHECK(series.attribute("GridType") == "Collection");
  CHECK(series.attribute("CollectionType") == "Temporal");
  const auto steps = series.all("Grid");
  REQUIRE(steps.size() == static_cast<std::size_t>(flushed));
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const XmlElement& step = *steps[k];
    CHECK(step.attribute("CollectionType") == "Spatial");
    CHECK(std::stod(step.one("Time").attribute("Value")) == SampleStep(static_cast<int>(k)).step.time);
    const auto grids = step.all("Grid");
    REQUIRE(grids.size() == 3);
    for (std::size_t beam = 0; beam < 2; ++beam) {
      const XmlElement& grid = *grids[beam];
      CHECK(grid.attribute("Name") == "beam" + std::to_string(beam));
      const XmlElement& topology = grid.one("Topology");
      CHECK(topology.attribute("TopologyType") == "Polyline");
      CHECK(topology.attribute("NodesPerElement") == std::to_string(4 + beam));
      const XmlElement& slab = grid.one("Geometry").one("DataItem");
      CHECK(slab.children.at(0).text == std::to_string(k) + " 0 0 1 1 1 1 " + std::to_string(4 + beam) + " 3");
      CHECK(slab.children.at(1).text == "run.h5:/centerlines/beam" + std::to_string(beam));
    }
    CHECK(grids[2]->attribute("Name") == "nodes");
    CHECK(grids[2]->one("Attribute").attribute("Name") == "velocity");
  }
  // Every reference resolves against the file (closed first: HDF5 will not open a file a second
  // time in the process that writes it); close() flushed the buffered step, so all 4 are listed.
  writer.close();
  const ReadOnlyFile file(path);
  const XmlElement closed = spar::test::XmlReader::parse(spar::test::read_text(writer.xdmf_path()));
  CHECK(closed.one("Domain").one("Grid").all("Grid").size() == 4);
  // Per step: 2 beams × (polyline, centerline) + nodes (polyvertex, positions, velocities).
  CHECK(check_heavy_data(closed, file) == 4 * 7);
}

TEST_CASE("The XML reader of the tests rejects malformed documents", "[output]") {
  using spar::test::XmlReader;
  CHECK_NOTHROW(XmlReader::parse("<?xml version=\"1.0\" ?>\n<!DOCTYPE X []>\n<a b='1'><c/>t &amp; u</a>\n"));
  CHECK_THROWS(XmlReader::parse("<a><b></a></b>"));
  CHECK_THROWS(XmlReader::parse("<a b=1/>"));
  CHECK_THROWS(XmlReader::parse("<a b=\"1\" b=\"2\"/>"));
  CHECK_THROWS(XmlReader::parse("<a>x & y</a>"));
  CHECK_THROWS(XmlReader::parse("<a/><b/>"));
  CHECK_THROWS(XmlReader::parse("<a>"));
}
