#include "results_copy.hpp"

#include "hdf5_attributes.hpp"
#include "hdf5_handle.hpp"
#include "hdf5_lifetime.hpp"
#include "provenance_attributes.hpp"

#include <algorithm>

namespace spar::output::detail {

namespace {

/// Steps per chunk: one block (flush_every steps), capped at about 64 KiB per chunk, so a block
/// write fills whole chunks and a chunk stays small enough for the default chunk cache.
hsize_t chunk_steps(hsize_t values_per_step, int flush_every) {
  const hsize_t cap = std::max<hsize_t>(1, 65536 / (sizeof(double) * values_per_step));
  return std::min<hsize_t>(cap, static_cast<hsize_t>(flush_every));
}

}  // namespace

std::string writer_where(const std::string& path, const std::string& function) {
  return "output::ResultsWriter::" + function + "(" + path + ")";
}

void check_writer_call(herr_t status, const std::string& what, const std::string& path, const std::string& function) {
  check_hdf5(status, what, writer_where(path, function), "check that the output folder is writable and the disk is not full");
}

void ResultsCopy::create(hid_t file, const TimeHistories& histories, int flush_every) {
  file_ = file;
  for (const Series& s : histories.series()) create_dataset(s, flush_every);
  write_topologies(histories.layout());
  check(write_provenance(file_), "write the schema and provenance", "ResultsWriter");
  check(H5Fflush(file_, H5F_SCOPE_GLOBAL), "flush", "ResultsWriter");
}

void ResultsCopy::create_dataset(const Series& s, int flush_every) {
  const std::vector<hsize_t> dims = s.dims(0);
  std::vector<hsize_t> max_dims = dims, chunk = s.dims(chunk_steps(s.values_per_step(), flush_every));
  max_dims[0] = H5S_UNLIMITED;
  const int rank = static_cast<int>(dims.size());
  const Hid space(H5Screate_simple(rank, dims.data(), max_dims.data()), H5Sclose);
  const Hid creation(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_chunk(creation, rank, chunk.data());
  const Hid links(intermediate_groups(), H5Pclose);
  const hid_t set = H5Dcreate2(file_, s.name.c_str(), s.integer ? H5T_STD_I32LE : H5T_IEEE_F64LE, space, links, creation,
                               H5P_DEFAULT);
  datasets_.push_back(set);
  check(set < 0 ? -1 : 0, "create dataset " + s.name, "ResultsWriter");
  check(describe_dataset(set, s.unit, s.description), "describe dataset " + s.name, "ResultsWriter");
}

void ResultsCopy::write_ints(const std::string& name, const std::vector<int>& values, const std::vector<hsize_t>& dims,
                             const std::string& description) {
  const Hid space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
  const Hid links(intermediate_groups(), H5Pclose);
  const Hid set(H5Dcreate2(file_, name.c_str(), H5T_STD_I32LE, space, links, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
  check(set.valid() ? H5Dwrite(set, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) : -1,
        "write dataset " + name, "ResultsWriter");
  check(describe_dataset(set, "1", description), "describe dataset " + name, "ResultsWriter");
}

void ResultsCopy::write_topologies(const ResultsLayout& layout) {
  auto indices = [](int count) {
    std::vector<int> result(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) result[static_cast<std::size_t>(i)] = i;
    return result;
  };
  for (std::size_t k = 0; k < layout.centerline_points.size(); ++k) {
    const int p = layout.centerline_points[k];
    write_ints("/xdmf/polyline" + std::to_string(k), indices(p), {1, static_cast<hsize_t>(p)},
               "point indices 0 ... P-1 of beam " + std::to_string(k) + "'s polyline in the XDMF sidecar");
  }
  const auto drawn = [&](RigidBodyShape::Kind kind) {
    return std::any_of(layout.rigid_bodies.begin(), layout.rigid_bodies.end(),
                       [kind](const RigidBodyShape& shape) { return shape.kind == kind; });
  };
  if (drawn(RigidBodyShape::Kind::box))
    write_ints("/xdmf/hexahedron", indices(8), {1, 8}, "vertex indices 0 ... 7 of a box's hexahedron in the XDMF sidecar");
  if (drawn(RigidBodyShape::Kind::axes))
    write_ints("/xdmf/axes", indices(6), {3, 2},
               "vertex indices of the axes' three segments (0 1, 2 3, 4 5: X, Y, Z) in the XDMF sidecar");
  if (layout.node_count > 0)
    write_ints("/xdmf/polyvertex", indices(layout.node_count), {static_cast<hsize_t>(layout.node_count)},
               "point indices 0 ... n-1 of the nodes' point cloud in the XDMF sidecar");
}

void ResultsCopy::write_block(const Block& b, const std::vector<Series>& series) {
  const auto start = static_cast<hsize_t>(b.first);
  const auto count = static_cast<hsize_t>(b.count);
  for (std::size_t k = 0; k < series.size(); ++k) {
    const Series& s = series[k];
    const std::vector<hsize_t> total = s.dims(start + count), rows = s.dims(count);
    std::vector<hsize_t> offset(total.size(), 0);
    offset[0] = start;
    const hid_t set = datasets_[k];
    check(H5Dset_extent(set, total.data()), "extend dataset " + s.name, "flush");
    const Hid file_space(H5Dget_space(set), H5Sclose);
    const Hid memory_space(H5Screate_simple(static_cast<int>(rows.size()), rows.data(), nullptr), H5Sclose);
    check(H5Sselect_hyperslab(file_space, H5S_SELECT_SET, offset.data(), nullptr, rows.data(), nullptr),
          "select the new rows of " + s.name, "flush");
    check(H5Dwrite(set, H5T_NATIVE_DOUBLE, memory_space, file_space, H5P_DEFAULT, b.rows[k].data()),
          "write dataset " + s.name, "flush");
  }
  check(H5Fflush(file_, H5F_SCOPE_GLOBAL), "flush", "flush");
}

void ResultsCopy::write_attribute(const RootAttribute& attribute) {
  herr_t status = 0;
  if (const auto* number = std::get_if<double>(&attribute.value))
    status = write_scalar_attribute(file_, attribute.name, H5T_NATIVE_DOUBLE, number);
  else if (const auto* count = std::get_if<std::int64_t>(&attribute.value))
    status = write_scalar_attribute(file_, attribute.name, H5T_NATIVE_INT64, count);
  else
    status = write_string_attribute(file_, attribute.name, std::get<std::string>(attribute.value));
  check(status, "write attribute " + attribute.name, "write_attribute");
  check(H5Fflush(file_, H5F_SCOPE_GLOBAL), "flush", "write_attribute");
}

void ResultsCopy::write_options(const RunOptions& options) {
  check(detail::write_options(file_, options), "write the options", "write_options");
  check(H5Fflush(file_, H5F_SCOPE_GLOBAL), "flush", "write_options");
}

bool ResultsCopy::holds(const std::string& name) const { return H5Lexists(file_, name.c_str(), H5P_DEFAULT) > 0; }

void ResultsCopy::write_constant(const std::string& name, const Eigen::MatrixXd& data, const std::string& unit,
                                 const std::string& description) {
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> row_major = data;
  const hsize_t dims[2] = {static_cast<hsize_t>(data.rows()), static_cast<hsize_t>(data.cols())};
  const Hid space(H5Screate_simple(data.cols() == 1 ? 1 : 2, dims, nullptr), H5Sclose);
  const Hid links(intermediate_groups(), H5Pclose);
  const Hid set(H5Dcreate2(file_, name.c_str(), H5T_IEEE_F64LE, space, links, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
  check(set.valid() ? H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, row_major.data()) : -1,
        "write dataset " + name, "write_constant");
  check(describe_dataset(set, unit, description), "describe dataset " + name, "write_constant");
  check(H5Fflush(file_, H5F_SCOPE_GLOBAL), "flush", "write_constant");
}

bool ResultsCopy::close() {
  bool ok = true;
  for (hid_t& set : datasets_)
    if (set >= 0) {
      ok = H5Dclose(set) >= 0 && ok;
      set = H5I_INVALID_HID;
    }
  if (file_ >= 0) ok = H5Fclose(file_) >= 0 && ok;
  file_ = H5I_INVALID_HID;
  return ok;
}

}  // namespace spar::output::detail
