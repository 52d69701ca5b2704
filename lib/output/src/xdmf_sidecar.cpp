#include "xdmf_sidecar.hpp"

#include "format_double.hpp"
#include "fresh_file.hpp"

#include <spar/error.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

namespace spar::output::detail {

namespace {

const std::string header =
    "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
    "  <Grid Name=\"results\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
const std::string closing_tags = "  </Grid>\n </Domain>\n</Xdmf>\n";

/// `text` with the XML special characters replaced by entities.
std::string xml_escape(const std::string& text) {
  std::string result;
  for (char c : text) {
    switch (c) {
      case '&': result += "&amp;"; break;
      case '<': result += "&lt;"; break;
      case '>': result += "&gt;"; break;
      case '"': result += "&quot;"; break;
      default: result += c;
    }
  }
  return result;
}

/// "a b c" from {a, b, c}.
std::string join(const std::vector<std::string>& values) {
  std::string text;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) text += ' ';
    text += values[i];
  }
  return text;
}

/// The decimal texts of `values`.
std::vector<std::string> texts(const std::vector<int>& values) {
  std::vector<std::string> result;
  for (const int value : values) result.push_back(std::to_string(value));
  return result;
}

// A step's grid is the same text for every step but for its step number, time and the
// datasets' row count: it is generated once with these placeholders — characters XML 1.0 does
// not allow, so no content holds them — and filled in per step.
constexpr char step_placeholder = '\x01', time_placeholder = '\x02', rows_placeholder = '\x03';

}  // namespace

void XdmfSidecar::check_names(const std::string& xmf_path, const std::string& h5_name, const ResultsLayout& layout) {
  const std::string where = "output::ResultsWriter, XDMF sidecar " + xmf_path;
  if (h5_name.find_first_of(":|") != std::string::npos)
    throw Error("the results file's name " + h5_name + " contains ':' or '|', which XDMF references reserve", where,
                "name the results file without ':' and '|'");
  const auto has_control_character = [](const std::string& text) {
    return std::any_of(text.begin(), text.end(), [](char c) { return c >= 0 && c < ' ' && c != '\t'; });
  };
  bool control = has_control_character(h5_name);
  for (const CenterlineField& field : layout.centerline_fields) control = control || has_control_character(field.name);
  if (control)
    throw Error("the results file's name or a centerline field's name contains a control character, which XML 1.0 "
                "does not allow", where, "use printable characters in names");
}

XdmfSidecar::XdmfSidecar(std::string xmf_path, const std::string& h5_name, ResultsLayout layout)
    : path_(std::move(xmf_path)), h5_name_(xml_escape(h5_name)), layout_(std::move(layout)) {
  check_names(path_, h5_name, layout_);
  const std::string where = "output::ResultsWriter, XDMF sidecar " + path_;
  remove_for_rewrite(path_);  // a new file: its close does not start ext4's write-back
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw Error(std::string("cannot create the sidecar: ") + std::strerror(errno), where,
                "check that the output folder is writable");
  write_at(header + closing_tags, 0);
  body_end_ = static_cast<off_t>(header.size());
  const std::string grid = step_grid(std::string(1, step_placeholder), std::string(1, time_placeholder),
                                     std::string(1, rows_placeholder));
  grid_pieces_.emplace_back();
  for (const char c : grid) {
    if (c == step_placeholder || c == time_placeholder || c == rows_placeholder) {
      grid_placeholders_.push_back(c);
      grid_pieces_.emplace_back();
    } else {
      grid_pieces_.back() += c;
    }
  }
}

XdmfSidecar::~XdmfSidecar() {
  if (fd_ >= 0) ::close(fd_);
}

void XdmfSidecar::append(int first_step, const std::vector<double>& times, int rows) {
  if (times.empty()) return;
  std::string grids;
  // Reserved for the whole block (the pieces, 3 numbers of at most 24 characters per
  // placeholder, the closing tags), so the text of 100 steps, ~350 kB for the slider-crank, is
  // built without a reallocation and written without a copy.
  std::size_t grid_size = 24 * grid_placeholders_.size();
  for (const std::string& piece : grid_pieces_) grid_size += piece.size();
  grids.reserve(times.size() * grid_size + closing_tags.size());
  const std::string rows_text = std::to_string(rows);
  for (std::size_t i = 0; i < times.size(); ++i) {
    const std::string step_text = std::to_string(first_step + static_cast<int>(i));
    const std::string time_text = format_double(times[i]);
    for (std::size_t k = 0; k < grid_placeholders_.size(); ++k) {
      grids += grid_pieces_[k];
      const char placeholder = grid_placeholders_[k];
      grids += placeholder == step_placeholder ? step_text : placeholder == time_placeholder ? time_text : rows_text;
    }
    grids += grid_pieces_.back();
  }
  const auto body = static_cast<off_t>(grids.size());
  grids += closing_tags;
  write_at(grids, body_end_);
  body_end_ += body;
}

void XdmfSidecar::write_at(const std::string& text, off_t offset) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t written = ::pwrite(fd_, text.data() + done, text.size() - done, offset + static_cast<off_t>(done));
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0)
      throw Error(std::string("cannot write the sidecar: ") + std::strerror(errno),
                  "output::ResultsWriter::flush, XDMF sidecar " + path_,
                  "check that the output folder is writable and the disk is not full");
    done += static_cast<std::size_t>(written);
  }
}

std::string XdmfSidecar::step_item(const std::string& dataset, const std::string& step, const std::string& rows,
                                   std::vector<int> shape, int taken, const std::string& indent) const {
  std::vector<std::string> start(shape.size() + 1, "0"), stride(shape.size() + 1, "1"), count{"1"}, dims{rows};
  const std::vector<std::string> shape_texts = texts(shape);
  count.insert(count.end(), shape_texts.begin(), shape_texts.end());
  dims.insert(dims.end(), shape_texts.begin(), shape_texts.end());
  start[0] = step;
  count.back() = std::to_string(taken);
  shape.back() = taken;
  return indent + "<DataItem Dimensions=\"" + join(texts(shape)) +
         "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" + h5_name_ + ":" + dataset + "|" + join(start) +
         ":" + join(stride) + ":" + join(count) + ":" + join(dims) + "</DataItem>\n";
}

std::string XdmfSidecar::step_grid(const std::string& step, const std::string& time, const std::string& rows) const {
  std::string grid = "   <Grid Name=\"step" + step + "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n" +
                     "    <Time Value=\"" + time + "\"/>\n";
  for (std::size_t k = 0; k < layout_.centerline_points.size(); ++k) grid += beam_grid(step, k, rows);
  for (std::size_t k = 0; k < layout_.rigid_bodies.size(); ++k) grid += rigid_body_grid(step, k, rows);
  if (layout_.node_count > 0) grid += nodes_grid(step, rows);
  return grid + "   </Grid>\n";
}

std::string XdmfSidecar::beam_grid(const std::string& step, std::size_t beam, const std::string& rows) const {
  const int p = layout_.centerline_points[beam];
  const std::string k = std::to_string(beam), points = std::to_string(p);
  std::string grid =
      "    <Grid Name=\"beam" + k + "\" GridType=\"Uniform\">\n" +
      "     <Topology TopologyType=\"Polyline\" NumberOfElements=\"1\" NodesPerElement=\"" + points + "\">\n" +
      "      <DataItem Dimensions=\"1 " + points + "\" NumberType=\"Int\" Precision=\"4\" Format=\"HDF\">" + h5_name_ +
      ":/xdmf/polyline" + k + "</DataItem>\n     </Topology>\n     <Geometry GeometryType=\"XYZ\">\n" +
      step_item("/centerlines/beam" + k, step, rows, {p, 3}, 3, "      ") + "     </Geometry>\n";
  for (const CenterlineField& field : layout_.centerline_fields) {
    const bool vector = field.components > 1;
    const std::vector<int> shape = vector ? std::vector<int>{p, field.components} : std::vector<int>{p};
    grid += "     <Attribute Name=\"" + xml_escape(field.name) + "\" AttributeType=\"" + (vector ? "Vector" : "Scalar") +
            "\" Center=\"Node\">\n" +
            step_item("/centerline_fields/" + xml_escape(field.name) + "/beam" + k, step, rows, shape, shape.back(),
                      "      ") +
            "     </Attribute>\n";
  }
  return grid + "    </Grid>\n";
}

std::string XdmfSidecar::rigid_body_grid(const std::string& step, std::size_t body, const std::string& rows) const {
  const bool box = layout_.rigid_bodies[body].kind == RigidBodyShape::Kind::box;
  const int vertices = box ? 8 : 6;
  const std::string k = std::to_string(body);
  std::string grid =
      "    <Grid Name=\"rigid_body" + k + "\" GridType=\"Uniform\">\n" +
      (box ? "     <Topology TopologyType=\"Hexahedron\" NumberOfElements=\"1\">\n      <DataItem Dimensions=\"1 8\""
           : "     <Topology TopologyType=\"Polyline\" NumberOfElements=\"3\" NodesPerElement=\"2\">\n"
             "      <DataItem Dimensions=\"3 2\"") +
      " NumberType=\"Int\" Precision=\"4\" Format=\"HDF\">" + h5_name_ + (box ? ":/xdmf/hexahedron" : ":/xdmf/axes") +
      "</DataItem>\n     </Topology>\n     <Geometry GeometryType=\"XYZ\">\n" +
      step_item("/rigid_bodies/body" + k, step, rows, {vertices, 3}, 3, "      ") + "     </Geometry>\n";
  if (layout_.velocities)
    grid += "     <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n" +
            step_item("/rigid_body_fields/velocity/body" + k, step, rows, {vertices, 3}, 3, "      ") +
            "     </Attribute>\n";
  return grid + "    </Grid>\n";
}

std::string XdmfSidecar::nodes_grid(const std::string& step, const std::string& rows) const {
  const int n = layout_.node_count;
  std::string grid = "    <Grid Name=\"nodes\" GridType=\"Uniform\">\n     <Topology TopologyType=\"Polyvertex\" "
                     "NumberOfElements=\"" + std::to_string(n) + "\" NodesPerElement=\"1\">\n" +
                     "      <DataItem Dimensions=\"" + std::to_string(n) +
                     "\" NumberType=\"Int\" Precision=\"4\" Format=\"HDF\">" + h5_name_ +
                     ":/xdmf/polyvertex</DataItem>\n     </Topology>\n     <Geometry GeometryType=\"XYZ\">\n" +
                     step_item("/positions", step, rows, {n, 3}, 3, "      ") + "     </Geometry>\n";
  if (layout_.velocities)
    grid += "     <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n" +
            step_item("/velocities", step, rows, {n, 6}, 3, "      ") + "     </Attribute>\n";
  return grid + "    </Grid>\n";
}

}  // namespace spar::output::detail
