#include <spar/core/results_writer.hpp>

#include "fresh_file.hpp"
#include "hdf5_attributes.hpp"
#include "hdf5_lifetime.hpp"
#include "spare_copy.hpp"
#include "written_files.hpp"
#include "xdmf_sidecar.hpp"

#include <spar/error.hpp>
#include <spar/lie/quaternion.hpp>

#include <Eigen/Geometry>

#include <fcntl.h>
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <deque>
#include <exception>
#include <filesystem>
#include <functional>
#include <limits>
#include <mutex>
#include <set>
#include <thread>
#include <utility>
#include <variant>

namespace spar::core {

namespace {

/// Closes an HDF5 identifier when it goes out of scope (also on a throw).
class Hid {
public:
  Hid(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Hid() {
    if (id_ >= 0) close_(id_);
  }
  Hid(const Hid&) = delete;
  Hid& operator=(const Hid&) = delete;
  operator hid_t() const { return id_; }
  bool valid() const { return id_ >= 0; }

private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

/// One time-history dataset of `steps × shape` values, extended by every block write.
struct Series {
  std::string name;            ///< absolute path in the file, e.g. "/positions"
  std::string unit;            ///< stored as the dataset's `units` attribute
  std::string description;     ///< stored as the dataset's `description` attribute
  std::vector<hsize_t> shape;  ///< per-step shape, {} for one scalar per step
  bool integer = false;        ///< stored as int32 (counters), else as doubles
  std::array<hid_t, 2> datasets{H5I_INVALID_HID, H5I_INVALID_HID};  ///< in either copy of the file
  std::vector<double> buffer;  ///< steps not yet handed to the writer thread, row-major

  hsize_t values_per_step() const {
    hsize_t count = 1;
    for (hsize_t extent : shape) count *= extent;
    return count;
  }
  /// {steps, shape...}: the dimensions of `steps` rows.
  std::vector<hsize_t> dims(hsize_t steps) const {
    std::vector<hsize_t> result{steps};
    result.insert(result.end(), shape.begin(), shape.end());
    return result;
  }
  void push(const double* values, std::size_t count) { buffer.insert(buffer.end(), values, values + count); }
  /// Appends `values` row by row (the datasets are row-major, Eigen's matrices column-major),
  /// without a temporary.
  void push_rows(const Eigen::MatrixXd& values) {
    const std::size_t at = buffer.size();
    buffer.resize(at + static_cast<std::size_t>(values.size()));
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(buffer.data() + at, values.rows(),
                                                                                      values.cols()) = values;
  }
};

/// Steps per chunk: one block (flush_every steps), capped at about 64 KiB per chunk, so a block
/// write fills whole chunks and a chunk stays small enough for the default chunk cache.
hsize_t chunk_steps(hsize_t values_per_step, int flush_every) {
  const hsize_t cap = std::max<hsize_t>(1, 65536 / (sizeof(double) * values_per_step));
  return std::min<hsize_t>(cap, static_cast<hsize_t>(flush_every));
}

/// The shortest decimal text that reads back as the same double.
std::string format_double(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

/// Why `path` cannot be created, as far as the file system tells, else `otherwise`.
std::string creation_failure_reason(const std::string& path, const std::string& otherwise) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path folder = fs::absolute(path, ec).parent_path();
  if (!fs::exists(folder, ec)) return "its folder " + folder.string() + " does not exist";
  if (!fs::is_directory(folder, ec)) return folder.string() + " is not a folder";
  if (access(folder.c_str(), W_OK) != 0) return "its folder " + folder.string() + " is not writable";
  if (fs::is_directory(path, ec)) return "it is a folder";
  return otherwise;
}

/// Opens the spare copy of `target` (the file `path` names, spare_copy.hpp) for writing as the
/// writer thread will, creating it (empty, with the permissions HDF5 or the sidecar would give
/// it) if it does not exist, so that a path which cannot be written is reported by the
/// constructor; the writer thread then makes the file itself. `target` itself is not touched:
/// until the writer thread replaces it, it stays whatever it was (an earlier run's results), so a
/// kill leaves no empty file under its name. Throws spar::Error naming `path` and the reason.
void check_writable(const std::string& path, const std::string& target, mode_t mode, const std::string& what,
                    const std::string& where) {
  std::error_code ec;
  if (std::filesystem::is_directory(target, ec))
    throw Error("cannot create " + what + " " + path + ": it is a folder", where, "pass the path of a file");
  const std::string spare = detail::spare_path(target);
  const int fd = ::open(spare.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, mode);
  if (fd < 0) {
    const std::string system_reason = std::strerror(errno);
    throw Error("cannot create " + what + " " + path + ": " + creation_failure_reason(spare, system_reason), where,
                "pass a path in an existing, writable folder");
  }
  ::close(fd);
}

/// A quantity of layout.`field`: a name that is non-empty, has no '/' (it becomes a dataset name)
/// and is unique within `seen`; a unit and a description.
void check_quantity(const ResultsQuantity& quantity, const std::string& field, std::set<std::string>& seen,
                    const std::string& where) {
  const std::string& name = quantity.name;
  if (name.empty() || name.find('/') != std::string::npos)
    throw Error("layout." + field + " holds the name \"" + name + "\", which is empty or contains '/'", where,
                "use plain names such as kinetic_energy");
  if (!seen.insert(name).second)
    throw Error("layout." + field + " holds \"" + name + "\" twice", where,
                "give every " + field + " entry a distinct name");
  if (quantity.unit.empty() || quantity.description.empty())
    throw Error("layout." + field + " entry \"" + name + "\" has no " + (quantity.unit.empty() ? "unit" : "description"),
                where, "state its SI unit (\"1\" for ratios and counts) and what it is: the file carries both");
}

/// Shapes drawn at nodes that exist, of sizes a shape can have: a box's edges and given axis
/// lengths positive, unset axis lengths all zero; every number finite.
void check_rigid_bodies(const ResultsLayout& layout, const std::string& where) {
  for (std::size_t k = 0; k < layout.rigid_bodies.size(); ++k) {
    const RigidBodyShape& shape = layout.rigid_bodies[k];
    const std::string entry = "layout.rigid_bodies[" + std::to_string(k) + "]";
    if (shape.node < 0 || shape.node >= layout.node_count)
      throw Error(entry + ".node = " + std::to_string(shape.node) + " is not a node of the layout (node_count = " +
                      std::to_string(layout.node_count) + ")",
                  where, "pass the body's node, e.g. model.rigid_body(b).node, and the model's node count");
    const bool box = shape.kind == RigidBodyShape::Kind::box;
    const bool positive = (shape.size.array() > 0.0).all() && shape.size.allFinite();
    if (!shape.offset.allFinite() || !(positive || (!box && shape.size.isZero(0.0))))
      throw Error(entry + " has size (" + format_double(shape.size.x()) + ", " + format_double(shape.size.y()) + ", " +
                      format_double(shape.size.z()) + ") m or an offset that is not finite",
                  where,
                  box ? "give the box's three edge lengths in m, all positive"
                      : "give the three axis lengths in m, all positive, or leave them all zero for a tenth of the "
                        "model's extent");
  }
}

/// Checks the layout's counts and names; throws spar::Error naming the field.
void check_layout(const ResultsLayout& layout, int flush_every, const std::string& where) {
  if (layout.node_count < 0 || layout.multiplier_count < 0)
    throw Error("layout.node_count = " + std::to_string(layout.node_count) + " and layout.multiplier_count = " +
                    std::to_string(layout.multiplier_count) + " must not be negative",
                where, "pass the model's node and multiplier counts");
  if (flush_every < 1)
    throw Error("flush_every = " + std::to_string(flush_every) + " must be at least 1", where,
                "pass the number of steps per block write, e.g. 100");
  std::set<std::string> scalars, probes;
  for (const ResultsQuantity& scalar : layout.scalars) check_quantity(scalar, "scalars", scalars, where);
  for (const ResultsQuantity& probe : layout.probes) {
    check_quantity(probe, "probes", probes, where);
    if (probe.integer)
      throw Error("layout.probes entry \"" + probe.name + "\" is marked integer", where,
                  "probes are 3-vectors of doubles; declare counters as scalars");
  }
  for (std::size_t k = 0; k < layout.centerline_points.size(); ++k)
    if (layout.centerline_points[k] < 2)
      throw Error("layout.centerline_points[" + std::to_string(k) + "] = " + std::to_string(layout.centerline_points[k]) +
                      " is below 2",
                  where, "sample each beam's centerline at 2 points or more (e.g. 10 per element + 1)");
  std::set<std::string> fields;
  for (const CenterlineField& field : layout.centerline_fields) {
    check_quantity({.name = field.name, .unit = field.unit, .description = field.description}, "centerline_fields",
                   fields, where);
    if (field.name.find_first_of(":|") != std::string::npos)
      throw Error("layout.centerline_fields entry \"" + field.name + "\" contains ':' or '|'", where,
                  "name the field without the characters XDMF references reserve, e.g. axial_strain");
    if (field.components != 1 && field.components != 3)
      throw Error("layout.centerline_fields entry \"" + field.name + "\" has " + std::to_string(field.components) +
                      " components",
                  where, "give a scalar (1 component) or a vector (3 components) per point");
  }
  check_rigid_bodies(layout, where);
}

/// The vertices of `shape` in its body's material frame (columns), `length` the axes' length
/// where the shape leaves it to the model: a box's 8 corners in VTK's hexahedron order (the face
/// z = −½ counterclockwise seen from +z, then the face z = +½), or the axes as 3 segments
/// (origin, end) along X, Y, Z.
Eigen::Matrix3Xd shape_vertices(const RigidBodyShape& shape, double length) {
  if (shape.kind == RigidBodyShape::Kind::box) {
    Eigen::Matrix<double, 3, 8> corners;
    corners << -1, 1, 1, -1, -1, 1, 1, -1,  //
        -1, -1, 1, 1, -1, -1, 1, 1,         //
        -1, -1, -1, -1, 1, 1, 1, 1;
    return (0.5 * shape.size.asDiagonal() * corners).colwise() + shape.offset;
  }
  const Eigen::Vector3d lengths = shape.size.isZero(0.0) ? Eigen::Vector3d::Constant(length) : shape.size;
  Eigen::Matrix3Xd ends = Eigen::Matrix3Xd::Zero(3, 6);
  for (int axis = 0; axis < 3; ++axis) ends(axis, 2 * axis + 1) = lengths(axis);
  return ends.colwise() + shape.offset;
}

/// `path` with its extension replaced by `.xmf`.
std::string sidecar_path(const std::string& path) {
  return std::filesystem::path(path).replace_extension(".xmf").string();
}

}  // namespace

struct ResultsWriter::Impl {
  std::string path;       ///< as the caller gave it
  std::string xdmf_path;  ///< as xdmf_path() returns it
  /// The files written: `path` and `xdmf_path`, or the files they link to (write_target).
  std::string target, xdmf_target;
  ResultsLayout layout;
  int flush_every;
  bool closed = false;  ///< close() has run or an error closed the file (the caller's thread only)
  std::string claim;    ///< the key of the HDF5 file in detail::written_files, until it is closed
  /// The two copies of the HDF5 file (spare_copy.hpp): made by the writer thread's first job;
  /// the caller uses them only with the writer thread idle or joined. Copy `h5_spare` is named
  /// spare_path(target), the other `target`; likewise the sidecars.
  std::array<hid_t, 2> files{H5I_INVALID_HID, H5I_INVALID_HID};
  int h5_spare = 0;
  std::vector<Series> series;  ///< /time first; the others in append order
  int positions = -1, quaternions = -1, velocities = -1, multipliers = -1;
  int first_scalar = 0, first_probe = 0, first_centerline = 0;
  int first_field = 0;  ///< field f of beam k is series first_field + f × beams + k
  int first_rigid_body = 0;           ///< the vertices of shape k are series first_rigid_body + k
  int first_rigid_body_velocity = -1;  ///< their velocities series first_rigid_body_velocity + k, if any
  /// Per shape, its vertices in the body's frame: set at the first append, where an axes' default
  /// length takes the model's extent.
  std::vector<Eigen::Matrix3Xd> shape_corners;
  double last_time = 0;        ///< the last appended step's time
  /// The two copies of the sidecar: used by the writer thread only, once it runs.
  std::array<std::unique_ptr<detail::XdmfSidecar>, 2> sidecars;
  int xmf_spare = 0;
  int appended = 0;
  int handed = 0;              ///< steps handed to the writer thread (the next block's first row)

  // ---- the writer thread (one for the writer's lifetime) and what it shares with the caller ----

  /// A block of steps handed to the writer thread: the rows of every series and where they go.
  struct Block {
    int first = 0;                          ///< the row of its first step
    int count = 0;                          ///< its steps
    std::vector<std::vector<double>> rows;  ///< per series, `count` steps row-major (series[k].buffer's layout)
  };
  /// The block in flight. The caller fills it only while `block_queued` is false; the writer
  /// thread reads it only while `block_queued` is true.
  Block block;

  /// The writer thread's jobs, done in the order queued: the creation of the file (the first),
  /// a root attribute, the block in flight.
  struct CreateFile {};
  struct WriteAttribute {
    std::string name;
    std::variant<double, std::int64_t, std::string> value;
  };
  struct WriteBlock {};
  using Job = std::variant<CreateFile, WriteAttribute, WriteBlock>;

  std::thread worker;
  mutable std::mutex mutex;                  ///< guards the fields below
  mutable std::condition_variable changed;   ///< signals a job queued, a job done, a stop
  std::deque<Job> jobs;                      ///< queued, not yet taken by the writer thread
  bool working = false;                      ///< the writer thread is doing a job taken from `jobs`
  bool block_queued = false;                 ///< `block` holds steps the writer thread has not finished
  bool stopping = false;                     ///< the writer thread returns once `jobs` is empty
  bool failed = false;                       ///< the writer thread met an error: it does no more jobs
  std::exception_ptr failure;                ///< the writer thread's error, not yet rethrown to the caller
  int flushed = 0;                           ///< steps on disk: written, H5Fflush-ed and in the sidecar

  std::string where(const std::string& function) const { return "core::ResultsWriter::" + function + "(" + path + ")"; }

  void check(herr_t status, const std::string& what, const std::string& function) const {
    detail::check_hdf5(status, what, where(function), "check that the output folder is writable and the disk is not full");
  }

  void require_open(const std::string& function) const {
    if (closed)
      throw Error("the results file is closed", where(function), "call " + function + " before close()");
  }

  /// Queues the root attribute `attribute` for the writer thread, after the jobs queued before
  /// it. A name HDF5 would refuse is refused here; an HDF5 failure of the write is rethrown
  /// like any error of the writer thread.
  void queue_attribute(WriteAttribute attribute) {
    require_open("write_attribute");
    report_failure();
    // HDF5 keeps an attribute in one header message of at most 64 KiB (a double's name may
    // have 65 479 bytes in HDF5 1.10); 65 000 leaves the type and the value room.
    if (attribute.name.empty() || attribute.name.size() > 65000)
      throw Error("the attribute name has " + std::to_string(attribute.name.size()) + " characters", where("write_attribute"),
                  "give a name of 1 to 65 000 characters, e.g. time_step");
    queue(std::move(attribute));
  }

  /// Hands `job` to the writer thread.
  void queue(Job job) {
    {
      const std::lock_guard<std::mutex> lock(mutex);
      jobs.push_back(std::move(job));
    }
    changed.notify_all();
  }

  /// Adds a series of `shape` per step and returns its index.
  int add_series(std::string name, std::string unit, std::string description, std::vector<hsize_t> shape,
                 bool integer = false) {
    series.push_back(Series{std::move(name), std::move(unit), std::move(description), std::move(shape), integer});
    return static_cast<int>(series.size()) - 1;
  }

  /// The series of the layout, in the order append() fills them.
  void plan_series() {
    const auto n = static_cast<hsize_t>(layout.node_count);
    add_series("/time", "s", "time of each step", {});
    if (n > 0) {
      positions = add_series("/positions", "m", "node positions x (inertial frame), node by node", {n, 3});
      quaternions = add_series("/quaternions", "1",
                               "node rotations R (material to inertial) as unit quaternions (w, x, y, z), w >= 0",
                               {n, 4});
      if (layout.velocities)
        velocities = add_series("/velocities", "m/s, rad/s",
                                "node velocities: x dot (inertial, m/s) in columns 0-2, then the angular velocity "
                                "Omega (material frame, rad/s) in columns 3-5",
                                {n, 6});
    }
    if (layout.multiplier_count > 0)
      multipliers = add_series("/multipliers", "N, N m",
                               "Lagrange multipliers of the constraints, constraint by constraint: forces (N) for "
                               "position constraints, moments (N m) for rotation constraints",
                               {static_cast<hsize_t>(layout.multiplier_count)});
    first_scalar = static_cast<int>(series.size());
    for (const ResultsQuantity& scalar : layout.scalars)
      add_series("/scalars/" + scalar.name, scalar.unit, scalar.description, {}, scalar.integer);
    first_probe = static_cast<int>(series.size());
    for (const ResultsQuantity& probe : layout.probes) add_series("/probes/" + probe.name, probe.unit, probe.description, {3});
    first_centerline = static_cast<int>(series.size());
    for (std::size_t k = 0; k < layout.centerline_points.size(); ++k)
      add_series("/centerlines/beam" + std::to_string(k), "m",
                 "beam " + std::to_string(k) +
                     "'s centerline (inertial frame) at points equally spaced in its knot parameter, root to tip",
                 {static_cast<hsize_t>(layout.centerline_points[k]), 3});
    first_field = static_cast<int>(series.size());
    for (const CenterlineField& field : layout.centerline_fields)
      for (std::size_t k = 0; k < layout.centerline_points.size(); ++k) {
        std::vector<hsize_t> shape{static_cast<hsize_t>(layout.centerline_points[k])};
        if (field.components > 1) shape.push_back(static_cast<hsize_t>(field.components));
        add_series("/centerline_fields/" + field.name + "/beam" + std::to_string(k), field.unit,
                   field.description + " (beam " + std::to_string(k) + ", at its centerline points)", shape);
      }
    first_rigid_body = static_cast<int>(series.size());
    for (std::size_t k = 0; k < layout.rigid_bodies.size(); ++k)
      add_series("/rigid_bodies/body" + std::to_string(k), "m",
                 "vertices x + R c of shape " + std::to_string(k) + " (layout.rigid_bodies) at node " +
                     std::to_string(layout.rigid_bodies[k].node) +
                     " (inertial frame): a box's 8 corners in VTK hexahedron order, or the axes' 3 segments "
                     "(origin, end) along material X, Y, Z",
                 {static_cast<hsize_t>(vertex_count(layout.rigid_bodies[k])), 3});
    if (layout.velocities && !layout.rigid_bodies.empty()) {
      first_rigid_body_velocity = static_cast<int>(series.size());
      for (std::size_t k = 0; k < layout.rigid_bodies.size(); ++k)
        add_series("/rigid_body_fields/velocity/body" + std::to_string(k), "m/s",
                   "velocity x dot + R (Omega x c) of each vertex of shape " + std::to_string(k) + " (inertial frame)",
                   {static_cast<hsize_t>(vertex_count(layout.rigid_bodies[k])), 3});
    }
  }

  static int vertex_count(const RigidBodyShape& shape) { return shape.kind == RigidBodyShape::Kind::box ? 8 : 6; }

  /// Copy `c` of the HDF5 file, under the spare's name: every dataset of the layout with zero
  /// steps, the sidecar's topologies and the schema, flushed.
  void create_copy(int c) {
    const Hid access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
#if H5_VERSION_GE(1, 10, 7)
    // No lock: the file can be read (after a flush) while the run goes on.
    H5Pset_file_locking(access, false, true);
#endif
    const std::string spare = detail::spare_path(target);
    detail::remove_for_rewrite(spare);  // a new file: its close does not start ext4's write-back
    files[c] = H5Fcreate(spare.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access);
    if (files[c] < 0)
      throw Error("cannot create the results file " + path + ": " +
                      creation_failure_reason(spare, "HDF5 refused to create it (the file may be open in another "
                                                     "program, or the disk full)"),
                  "core::ResultsWriter(" + path + ")", "pass a path in an existing, writable folder");
    for (Series& s : series) create_dataset(s, c);
    write_topologies(files[c]);
    check(detail::write_string_attribute(files[c], "schema", "spar.results/2"), "write attribute schema", "ResultsWriter");
    check(H5Fflush(files[c], H5F_SCOPE_GLOBAL), "flush", "ResultsWriter");
  }

  /// The writer thread's first job: both copies of the HDF5 file and of the sidecar. The first
  /// replaces the files of an earlier run (the sidecar first, so that it never lists steps the
  /// HDF5 file does not hold), the second stays the spare.
  void create_files() {
    const std::string h5_name = std::filesystem::path(path).filename().string();
    for (int c = 0; c < 2; ++c) {
      {
        const auto hdf5 = detail::hdf5_calls();
        create_copy(c);
      }
      sidecars[c] = std::make_unique<detail::XdmfSidecar>(detail::spare_path(xdmf_target), h5_name, layout);
      if (c == 1) continue;
      detail::replace_file(detail::spare_path(xdmf_target), xdmf_target, where("ResultsWriter"));
      detail::replace_file(detail::spare_path(target), target, where("ResultsWriter"));
    }
    h5_spare = xmf_spare = 1;
  }

  /// Gives the spare HDF5 copy, just changed and flushed, the file's name (spare_copy.hpp).
  void publish_h5() {
    detail::exchange_names(detail::spare_path(target), target, where("flush"));
    h5_spare = 1 - h5_spare;
  }

  void publish_xmf() {
    detail::exchange_names(detail::spare_path(xdmf_target), xdmf_target, where("flush"));
    xmf_spare = 1 - xmf_spare;
  }

  /// The writer thread's job for a root attribute: writes it to the spare, replacing one of the
  /// same name, flushes, publishes the spare and does the same to the other copy.
  void write_root_attribute(const WriteAttribute& attribute) {
    const auto hdf5 = detail::hdf5_calls();
    write_root_attribute(attribute, files[h5_spare]);
    publish_h5();
    write_root_attribute(attribute, files[h5_spare]);
  }

  void write_root_attribute(const WriteAttribute& attribute, hid_t file) {
    herr_t status = 0;
    if (const auto* number = std::get_if<double>(&attribute.value))
      status = detail::write_scalar_attribute(file, attribute.name, H5T_NATIVE_DOUBLE, number);
    else if (const auto* count = std::get_if<std::int64_t>(&attribute.value))
      status = detail::write_scalar_attribute(file, attribute.name, H5T_NATIVE_INT64, count);
    else
      status = detail::write_string_attribute(file, attribute.name, std::get<std::string>(attribute.value));
    check(status, "write attribute " + attribute.name, "write_attribute");
    check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush", "write_attribute");
  }

  /// A link-creation property list that creates missing intermediate groups.
  static hid_t intermediate_groups() {
    const hid_t properties = H5Pcreate(H5P_LINK_CREATE);
    H5Pset_create_intermediate_group(properties, 1);
    return properties;
  }

  void create_dataset(Series& s, int c) {
    const std::vector<hsize_t> dims = s.dims(0);
    std::vector<hsize_t> max_dims = dims, chunk = s.dims(chunk_steps(s.values_per_step(), flush_every));
    max_dims[0] = H5S_UNLIMITED;
    const int rank = static_cast<int>(dims.size());
    const Hid space(H5Screate_simple(rank, dims.data(), max_dims.data()), H5Sclose);
    const Hid creation(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    H5Pset_chunk(creation, rank, chunk.data());
    const Hid links(intermediate_groups(), H5Pclose);
    hid_t& set = s.datasets[static_cast<std::size_t>(c)];
    set = H5Dcreate2(files[c], s.name.c_str(), s.integer ? H5T_STD_I32LE : H5T_IEEE_F64LE, space, links, creation,
                     H5P_DEFAULT);
    check(set < 0 ? -1 : 0, "create dataset " + s.name, "ResultsWriter");
    check(detail::describe_dataset(set, s.unit, s.description), "describe dataset " + s.name, "ResultsWriter");
  }

  /// An int dataset (`dims`) for the sidecar's topologies.
  void write_ints(hid_t file, const std::string& name, const std::vector<int>& values, const std::vector<hsize_t>& dims,
                  const std::string& description) {
    const Hid space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
    const Hid links(intermediate_groups(), H5Pclose);
    const Hid set(H5Dcreate2(file, name.c_str(), H5T_STD_I32LE, space, links, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
    check(set.valid() ? H5Dwrite(set, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) : -1,
          "write dataset " + name, "ResultsWriter");
    check(detail::describe_dataset(set, "1", description), "describe dataset " + name, "ResultsWriter");
  }

  /// Point indices 0 … count−1 of each sidecar topology: one polyline per beam, the nodes.
  void write_topologies(hid_t file) {
    auto indices = [](int count) {
      std::vector<int> result(static_cast<std::size_t>(count));
      for (int i = 0; i < count; ++i) result[static_cast<std::size_t>(i)] = i;
      return result;
    };
    for (std::size_t k = 0; k < layout.centerline_points.size(); ++k) {
      const int p = layout.centerline_points[k];
      write_ints(file, "/xdmf/polyline" + std::to_string(k), indices(p), {1, static_cast<hsize_t>(p)},
                 "point indices 0 ... P-1 of beam " + std::to_string(k) + "'s polyline in the XDMF sidecar");
    }
    const auto drawn = [&](RigidBodyShape::Kind kind) {
      return std::any_of(layout.rigid_bodies.begin(), layout.rigid_bodies.end(),
                         [kind](const RigidBodyShape& shape) { return shape.kind == kind; });
    };
    if (drawn(RigidBodyShape::Kind::box))
      write_ints(file, "/xdmf/hexahedron", indices(8), {1, 8}, "vertex indices 0 ... 7 of a box's hexahedron in the XDMF sidecar");
    if (drawn(RigidBodyShape::Kind::axes))
      write_ints(file, "/xdmf/axes", indices(6), {3, 2},
                 "vertex indices of the axes' three segments (0 1, 2 3, 4 5: X, Y, Z) in the XDMF sidecar");
    if (layout.node_count > 0)
      write_ints(file, "/xdmf/polyvertex", indices(layout.node_count), {static_cast<hsize_t>(layout.node_count)},
                 "point indices 0 ... n-1 of the nodes' point cloud in the XDMF sidecar");
  }

  /// Appends the steps of `b` to every dataset of copy `c` and flushes it (writer thread,
  /// holding the HDF5 lock).
  void write_block(const Block& b, int c) {
    const auto start = static_cast<hsize_t>(b.first);
    const auto count = static_cast<hsize_t>(b.count);
    for (std::size_t k = 0; k < series.size(); ++k) {
      const Series& s = series[k];
      const std::vector<hsize_t> total = s.dims(start + count), rows = s.dims(count);
      std::vector<hsize_t> offset(total.size(), 0);
      offset[0] = start;
      const hid_t set = s.datasets[static_cast<std::size_t>(c)];
      check(H5Dset_extent(set, total.data()), "extend dataset " + s.name, "flush");
      const Hid file_space(H5Dget_space(set), H5Sclose);
      const Hid memory_space(H5Screate_simple(static_cast<int>(rows.size()), rows.data(), nullptr), H5Sclose);
      check(H5Sselect_hyperslab(file_space, H5S_SELECT_SET, offset.data(), nullptr, rows.data(), nullptr),
            "select the new rows of " + s.name, "flush");
      check(H5Dwrite(set, H5T_NATIVE_DOUBLE, memory_space, file_space, H5P_DEFAULT, b.rows[k].data()),
            "write dataset " + s.name, "flush");
    }
    check(H5Fflush(files[c], H5F_SCOPE_GLOBAL), "flush", "flush");
  }

  /// The writer thread's job for one block: its rows and its steps in the sidecar (series 0
  /// holds their times) to the spares, the spares published (the HDF5 file first, so that the
  /// sidecar never lists steps it does not hold), then the same to the new spares; both files
  /// are complete up to the block when it returns, and a kill at any moment leaves them whole
  /// (spare_copy.hpp).
  void write_and_flush(const Block& b) {
    for (int pass = 0; pass < 2; ++pass) {
      {
        const auto hdf5 = detail::hdf5_calls();
        write_block(b, h5_spare);
      }
      sidecars[static_cast<std::size_t>(xmf_spare)]->append(b.first, b.rows[0], b.first + b.count);
      if (pass > 0) continue;
      publish_h5();
      publish_xmf();
    }
  }

  /// The writer thread: does the jobs queued, in order, until told to stop. After an error it
  /// keeps the error for the caller and does no more jobs (no HDF5 call).
  void run_writer() {
    std::unique_lock<std::mutex> lock(mutex);
    while (true) {
      changed.wait(lock, [this] { return !jobs.empty() || stopping; });
      if (jobs.empty()) return;
      const Job job = std::move(jobs.front());
      jobs.pop_front();
      const bool writes_block = std::holds_alternative<WriteBlock>(job);
      if (!failed) {
        working = true;
        lock.unlock();
        std::exception_ptr error;
        try {
          do_job(job);
        } catch (...) {
          error = std::current_exception();
        }
        lock.lock();
        working = false;
        failed = error != nullptr;
        failure = error;
        if (!failed && writes_block) flushed = block.first + block.count;
      }
      if (writes_block) {
        for (std::vector<double>& rows : block.rows) rows.clear();  // keeps their capacity for the next swap
        block_queued = false;
      }
      changed.notify_all();
    }
  }

  void do_job(const Job& job) {
    if (std::holds_alternative<CreateFile>(job))
      create_files();
    else if (const auto* attribute = std::get_if<WriteAttribute>(&job))
      write_root_attribute(*attribute);
    else
      write_and_flush(block);
  }

  /// Starts the writer thread (the constructor, once the path has proved writable) with the
  /// creation of the files as its first job. Both blocks' buffers are reserved whole, so append
  /// never reallocates.
  void start_writer() {
    block.rows.resize(series.size());
    for (std::size_t k = 0; k < series.size(); ++k) {
      const auto values = static_cast<std::size_t>(flush_every) * series[k].values_per_step();
      series[k].buffer.reserve(values);
      block.rows[k].reserve(values);
    }
    jobs.emplace_back(CreateFile{});
    worker = std::thread([this] { run_writer(); });
  }

  /// Hands the buffered steps to the writer thread as one block, once it has finished the
  /// previous one: the filled buffers and the written block's (emptied) storage swap, so a step
  /// is copied once and, in steady state, nothing is allocated. Rethrows an earlier error of the
  /// writer thread instead (see report_failure).
  void hand_over() {
    if (appended == handed) return;
    {
      std::unique_lock<std::mutex> lock(mutex);
      changed.wait(lock, [this] { return !block_queued; });
    }
    report_failure();
    {
      const std::lock_guard<std::mutex> lock(mutex);
      block.first = handed;
      block.count = appended - handed;
      for (std::size_t k = 0; k < series.size(); ++k) std::swap(block.rows[k], series[k].buffer);
      block_queued = true;
      jobs.emplace_back(WriteBlock{});
    }
    changed.notify_all();
    handed = appended;
  }

  /// Waits until the writer thread has done every job queued (it is then idle: the caller may
  /// make HDF5 calls); returns the steps on disk.
  int await_writer() const {
    std::unique_lock<std::mutex> lock(mutex);
    changed.wait(lock, [this] { return jobs.empty() && !working; });
    return flushed;
  }

  /// await_writer, then: if the writer thread met an error, closes the file and rethrows it.
  void wait_idle() {
    await_writer();
    report_failure();
  }

  /// Rethrows, after closing the file, an error the writer thread has met so far, without
  /// waiting for the job in hand.
  void report_failure() {
    std::exception_ptr error;
    {
      const std::lock_guard<std::mutex> lock(mutex);
      error = std::exchange(failure, nullptr);
    }
    if (error) {
      release();
      std::rethrow_exception(error);
    }
  }

  /// Stops and joins the writer thread once it has done the jobs queued.
  void stop_writer() {
    if (!worker.joinable()) return;
    {
      const std::lock_guard<std::mutex> lock(mutex);
      stopping = true;
    }
    changed.notify_all();
    worker.join();
  }

  /// Stops the writer thread, then closes every dataset, both copies of the file and of the
  /// sidecar (those the writer thread made) and removes the spares; returns false if HDF5
  /// reported a failure.
  bool release() {
    stop_writer();
    closed = true;
    for (auto& sidecar : sidecars) sidecar.reset();
    const auto hdf5 = detail::hdf5_calls();
    bool ok = true;
    for (Series& s : series)
      for (hid_t& set : s.datasets)
        if (set >= 0) {
          ok = H5Dclose(set) >= 0 && ok;
          set = H5I_INVALID_HID;
        }
    for (hid_t& file : files) {
      if (file >= 0) ok = H5Fclose(file) >= 0 && ok;
      file = H5I_INVALID_HID;
    }
    ::unlink(detail::spare_path(target).c_str());
    ::unlink(detail::spare_path(xdmf_target).c_str());
    if (!ok) detail::note_hdf5_failure();
    detail::release_written_file(std::exchange(claim, {}));
    return ok;
  }

  /// A constructor that threw after claiming the file leaves it to other writers.
  ~Impl() { detail::release_written_file(claim); }

  /// A constant's values are finite (issue 29: a NaN constant was written silently).
  void check_constant(const std::string& name, const Eigen::MatrixXd& data) const {
    for (Eigen::Index j = 0; j < data.cols(); ++j)
      for (Eigen::Index i = 0; i < data.rows(); ++i)
        if (!std::isfinite(data(i, j)))
          throw Error("the constant " + name + " holds " + format_double(data(i, j)) + " at row " + std::to_string(i) +
                          ", column " + std::to_string(j) + ", which is not finite",
                      where("write_constant"), "write finite values only");
  }

  // ---- append: checks, then one push per series in plan_series() order ----

  [[noreturn]] void size_error(const std::string& field, std::size_t got, const std::string& expected,
                               const std::string& fix) const {
    throw Error("step." + field + " has " + std::to_string(got) + " entries, expected " + expected,
                where("append") + " at step " + std::to_string(appended), fix);
  }

  void check_step(const ResultsStep& step) const {
    if (!std::isfinite(step.time) || (appended > 0 && !(step.time > last_time)))
      throw Error("step.time = " + format_double(step.time) + " is not finite or not after the previous step's " +
                      (appended > 0 ? format_double(last_time) : std::string("-")),
                  where("append") + " at step " + std::to_string(appended),
                  "append converged steps only, in increasing time");
    const auto n = static_cast<std::size_t>(layout.node_count);
    const Configuration* q = step.configuration;
    if (n > 0 && (q == nullptr || q->position.size() != n || q->rotation.size() != n))
      size_error("configuration nodes", q == nullptr ? 0 : std::min(q->position.size(), q->rotation.size()),
                 std::to_string(n) + " (layout.node_count)", "pass the model's configuration");
    const Eigen::VectorXd* v = step.velocity;
    if (velocities >= 0 && (v == nullptr || static_cast<std::size_t>(v->size()) != 6 * n))
      size_error("velocity", v == nullptr ? 0 : static_cast<std::size_t>(v->size()),
                 "6 per node = " + std::to_string(6 * n), "pass 6 entries per node (x dot, Omega)");
    if (velocities < 0 && v != nullptr)
      size_error("velocity", static_cast<std::size_t>(v->size()), "none (layout.velocities is false or no nodes)",
                 "set layout.velocities, or pass velocity = nullptr");
    const auto m = static_cast<std::size_t>(layout.multiplier_count);
    const Eigen::VectorXd* lambda = step.multipliers;
    const std::size_t lambda_size = lambda == nullptr ? 0 : static_cast<std::size_t>(lambda->size());
    if (lambda_size != m)
      size_error("multipliers", lambda_size, std::to_string(m) + " (layout.multiplier_count)",
                 "pass the multiplier vector of the constraints, or fix layout.multiplier_count");
    if (step.scalars.size() != layout.scalars.size())
      size_error("scalars", step.scalars.size(), std::to_string(layout.scalars.size()) + " (layout.scalars)",
                 "pass one value per layout scalar, in the same order");
    if (step.probes.size() != layout.probes.size())
      size_error("probes", step.probes.size(), std::to_string(layout.probes.size()) + " (layout.probes)",
                 "pass one point per layout probe, in the same order");
    check_counters(step);
    check_centerlines(step);
    check_finite_values(step);
  }

  /// Throws spar::Error naming `field` if `values` hold a NaN or an infinity (issue 29: a NaN
  /// probe or position was written silently): the index of the first such entry, as `entry`
  /// describes it.
  void check_finite(const std::string& field, const double* values, std::size_t count,
                    const std::function<std::string(std::size_t)>& entry, bool may_be_undefined = false) const {
    const double* bad = std::find_if(values, values + count, [may_be_undefined](double x) {
      return !std::isfinite(x) && !(may_be_undefined && std::isnan(x));
    });
    if (bad != values + count)
      throw Error("step." + field + " " + entry(static_cast<std::size_t>(bad - values)) + " = " + format_double(*bad) +
                      " is not finite",
                  where("append") + " at step " + std::to_string(appended),
                  "check the run that computed it; only a scalar or probe declared may_be_undefined may be NaN");
  }

  /// Every value the step holds is finite, but NaN in a probe declared may_be_undefined (the
  /// scalars: check_counters).
  void check_finite_values(const ResultsStep& step) const {
    const auto plain = [](std::size_t i) { return "entry " + std::to_string(i); };
    const auto xyz = [](std::size_t i) { return "component " + std::to_string(i); };
    if (const Configuration* q = step.configuration; positions >= 0) {
      for (std::size_t i = 0; i < q->position.size(); ++i) {
        check_finite("configuration position of node " + std::to_string(i), q->position[i].data(), 3, xyz);
        check_finite("configuration rotation of node " + std::to_string(i), q->rotation[i].data(), 9, plain);
      }
    }
    if (velocities >= 0) check_finite("velocity", step.velocity->data(), static_cast<std::size_t>(step.velocity->size()), plain);
    if (multipliers >= 0)
      check_finite("multipliers", step.multipliers->data(), static_cast<std::size_t>(step.multipliers->size()), plain);
    for (std::size_t i = 0; i < step.probes.size(); ++i)
      check_finite("probes[" + std::to_string(i) + "] (" + layout.probes[i].name + ")", step.probes[i].data(), 3, xyz,
                   layout.probes[i].may_be_undefined);
    for (std::size_t k = 0; k < step.centerlines.size(); ++k)
      check_matrix("centerlines[" + std::to_string(k) + "]", step.centerlines[k]);
    for (std::size_t k = 0; k < step.centerline_fields.size(); ++k)
      for (std::size_t f = 0; f < step.centerline_fields[k].size(); ++f)
        check_matrix("centerline_fields[" + std::to_string(k) + "][" + std::to_string(f) + "] (" +
                         layout.centerline_fields[f].name + ")",
                     step.centerline_fields[k][f]);
  }

  /// check_finite for a matrix of points, its entries named by row and column.
  void check_matrix(const std::string& field, const Eigen::MatrixXd& values) const {
    const auto rows = static_cast<std::size_t>(values.rows());
    check_finite(field, values.data(), static_cast<std::size_t>(values.size()), [rows](std::size_t i) {
      return "row " + std::to_string(i % rows) + ", column " + std::to_string(i / rows);
    });
  }

  /// Scalars are finite (NaN only where declared may_be_undefined); the values of integer
  /// scalars are whole numbers that fit in 32 bits.
  void check_counters(const ResultsStep& step) const {
    for (std::size_t i = 0; i < step.scalars.size(); ++i) {
      const double value = step.scalars[i];
      if (!std::isfinite(value) && !(std::isnan(value) && layout.scalars[i].may_be_undefined))
        throw Error("step.scalars[" + std::to_string(i) + "] (" + layout.scalars[i].name + ") = " + format_double(value) +
                        " is not finite",
                    where("append") + " at step " + std::to_string(appended),
                    "check the run that computed it, or declare the scalar may_be_undefined if NaN marks "
                    "a step where it has no value");
      if (layout.scalars[i].integer &&
          !(value == std::trunc(value) && std::abs(value) <= std::numeric_limits<std::int32_t>::max()))
        throw Error("step.scalars[" + std::to_string(i) + "] = " + format_double(value) + " for the integer scalar " +
                        layout.scalars[i].name + " is not a whole number of 32 bits",
                    where("append") + " at step " + std::to_string(appended),
                    "pass the counter's value, or declare the scalar without `integer`");
    }
  }

  void check_centerlines(const ResultsStep& step) const {
    const std::vector<int>& points = layout.centerline_points;
    if (step.centerlines.size() != points.size())
      size_error("centerlines", step.centerlines.size(), std::to_string(points.size()) + " beams (layout.centerline_points)",
                 "pass one sampled centerline per beam");
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Eigen::MatrixXd& c = step.centerlines[k];
      if (c.rows() != points[k] || c.cols() != 3)
        size_error("centerlines[" + std::to_string(k) + "]", static_cast<std::size_t>(c.size()),
                   std::to_string(points[k]) + " × 3 (layout.centerline_points[" + std::to_string(k) +
                       "] rows of x, y, z), got " + std::to_string(c.rows()) + " × " + std::to_string(c.cols()),
                   "sample the beam at the layout's number of points");
    }
    check_centerline_fields(step);
  }

  void check_centerline_fields(const ResultsStep& step) const {
    const std::vector<CenterlineField>& fields = layout.centerline_fields;
    const std::size_t beams = fields.empty() ? 0 : layout.centerline_points.size();
    if (step.centerline_fields.size() != beams)
      size_error("centerline_fields", step.centerline_fields.size(),
                 fields.empty() ? std::string("none (layout.centerline_fields is empty)")
                                : std::to_string(beams) + " beams (layout.centerline_points)",
                 "pass per beam one matrix per layout.centerline_fields entry");
    for (std::size_t k = 0; k < beams; ++k) {
      const std::string entry = "centerline_fields[" + std::to_string(k) + "]";
      if (step.centerline_fields[k].size() != fields.size())
        size_error(entry, step.centerline_fields[k].size(), std::to_string(fields.size()) + " (layout.centerline_fields)",
                   "pass one matrix per field, in the layout's order");
      for (std::size_t f = 0; f < fields.size(); ++f) {
        const Eigen::MatrixXd& values = step.centerline_fields[k][f];
        if (values.rows() != layout.centerline_points[k] || values.cols() != fields[f].components)
          size_error(entry + "[" + std::to_string(f) + "] (" + fields[f].name + ")", static_cast<std::size_t>(values.size()),
                     std::to_string(layout.centerline_points[k]) + " × " + std::to_string(fields[f].components) +
                         " (a row per centerline point), got " + std::to_string(values.rows()) + " × " +
                         std::to_string(values.cols()),
                     "sample the field at the beam's centerline points");
      }
    }
  }

  void buffer_nodes(const ResultsStep& step) {
    if (positions < 0) return;
    const Configuration& q = *step.configuration;
    for (int i = 0; i < layout.node_count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      series[static_cast<std::size_t>(positions)].push(q.position[k].data(), 3);
      const Eigen::Quaterniond quaternion = lie::quaternion_from_rotation(q.rotation[k]);
      const double wxyz[4] = {quaternion.w(), quaternion.x(), quaternion.y(), quaternion.z()};
      series[static_cast<std::size_t>(quaternions)].push(wxyz, 4);
    }
    if (velocities >= 0)
      series[static_cast<std::size_t>(velocities)].push(step.velocity->data(), static_cast<std::size_t>(step.velocity->size()));
  }

  /// The shapes' vertices in their bodies' frames, at the first step: an axes' default length is
  /// a tenth of the diagonal of the box bounding the step's nodes and centerline points.
  void place_shapes(const ResultsStep& step) {
    if (layout.rigid_bodies.empty() || !shape_corners.empty()) return;
    Eigen::AlignedBox3d extent;
    for (const Eigen::Vector3d& x : step.configuration->position) extent.extend(x);
    for (const Eigen::MatrixXd& centerline : step.centerlines)
      for (Eigen::Index p = 0; p < centerline.rows(); ++p) extent.extend(Eigen::Vector3d(centerline.row(p).transpose()));
    const double length = 0.1 * extent.diagonal().norm();
    for (std::size_t k = 0; k < layout.rigid_bodies.size(); ++k) {
      const RigidBodyShape& shape = layout.rigid_bodies[k];
      if (shape.kind == RigidBodyShape::Kind::axes && shape.size.isZero(0.0) && !(length > 0.0))
        throw Error("layout.rigid_bodies[" + std::to_string(k) + "] leaves its axes' length to the model's extent, "
                        "but the first step's nodes and centerlines are all at one point",
                    where("append") + " at step 0", "give the axes' lengths in size");
    }
    for (const RigidBodyShape& shape : layout.rigid_bodies) shape_corners.push_back(shape_vertices(shape, length));
  }

  /// Each shape's vertices x + R c and, if the layout has velocities, their velocities
  /// ẋ + R (Ω × c) (Ω material).
  void buffer_shapes(const ResultsStep& step) {
    if (shape_corners.empty()) return;  // a layout without shapes may have steps without a configuration
    const Configuration& q = *step.configuration;
    for (std::size_t k = 0; k < shape_corners.size(); ++k) {
      const auto node = static_cast<std::size_t>(layout.rigid_bodies[k].node);
      const Eigen::Matrix3Xd& corners = shape_corners[k];
      const Eigen::Matrix3Xd vertices = (q.rotation[node] * corners).colwise() + q.position[node];
      series[static_cast<std::size_t>(first_rigid_body) + k].push(vertices.data(), static_cast<std::size_t>(vertices.size()));
      if (first_rigid_body_velocity < 0) continue;
      const auto i = static_cast<Eigen::Index>(6 * node);
      const Eigen::Vector3d x_dot = step.velocity->segment<3>(i), omega = step.velocity->segment<3>(i + 3);
      Eigen::Matrix3Xd velocities(3, corners.cols());
      for (Eigen::Index c = 0; c < corners.cols(); ++c)
        velocities.col(c) = x_dot + q.rotation[node] * omega.cross(corners.col(c));
      series[static_cast<std::size_t>(first_rigid_body_velocity) + k].push(velocities.data(),
                                                                          static_cast<std::size_t>(velocities.size()));
    }
  }

  void buffer_step(const ResultsStep& step) {
    series[0].push(&step.time, 1);
    buffer_nodes(step);
    if (multipliers >= 0)
      series[static_cast<std::size_t>(multipliers)].push(step.multipliers->data(),
                                                          static_cast<std::size_t>(step.multipliers->size()));
    for (std::size_t i = 0; i < step.scalars.size(); ++i)
      series[static_cast<std::size_t>(first_scalar) + i].push(&step.scalars[i], 1);
    for (std::size_t i = 0; i < step.probes.size(); ++i)
      series[static_cast<std::size_t>(first_probe) + i].push(step.probes[i].data(), 3);
    for (std::size_t k = 0; k < step.centerlines.size(); ++k)
      series[static_cast<std::size_t>(first_centerline) + k].push_rows(step.centerlines[k]);
    for (std::size_t k = 0; k < step.centerline_fields.size(); ++k)
      for (std::size_t f = 0; f < step.centerline_fields[k].size(); ++f)
        series[static_cast<std::size_t>(first_field) + f * step.centerline_fields.size() + k].push_rows(
            step.centerline_fields[k][f]);
    buffer_shapes(step);
    last_time = step.time;
  }
};

ResultsWriter::ResultsWriter(const std::string& h5_path, ResultsLayout layout, int flush_every)
    : impl_(std::make_unique<Impl>()) {
  Impl& impl = *impl_;
  check_layout(layout, flush_every, "core::ResultsWriter(" + h5_path + ")");
  impl.path = h5_path;
  impl.xdmf_path = sidecar_path(h5_path);
  impl.target = detail::write_target(h5_path);
  impl.xdmf_target = detail::write_target(impl.xdmf_path);
  impl.layout = std::move(layout);
  impl.flush_every = flush_every;
  impl.plan_series();
  // What the caller can get wrong is refused here; the writer thread makes the files.
  const std::string where = "core::ResultsWriter(" + h5_path + ")";
  impl.claim = detail::claim_written_file(h5_path, where);
  detail::XdmfSidecar::check_names(impl.xdmf_path, std::filesystem::path(h5_path).filename().string(), impl.layout);
  check_writable(h5_path, impl.target, 0666, "the results file", where);  // HDF5's own mode for the files it makes
  check_writable(impl.xdmf_path, impl.xdmf_target, 0644, "the XDMF sidecar", where);
  impl.start_writer();
}

ResultsWriter::~ResultsWriter() {
  try {
    close();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
  }
}

ResultsWriter::ResultsWriter(ResultsWriter&&) noexcept = default;
ResultsWriter& ResultsWriter::operator=(ResultsWriter&& other) noexcept {
  if (this != &other) {
    ResultsWriter discarded(std::move(*this));  // closes the file this writer held
    impl_ = std::move(other.impl_);
  }
  return *this;
}

ResultsWriter::Impl& ResultsWriter::live(const std::string& function) const {
  if (!impl_)
    throw Error("this ResultsWriter was moved from and holds no file", "core::ResultsWriter::" + function,
                "call it on the writer it was moved to");
  return *impl_;
}

void ResultsWriter::write_attribute(const std::string& name, double value) {
  live("write_attribute").queue_attribute({name, value});
}

void ResultsWriter::write_attribute(const std::string& name, std::int64_t value) {
  live("write_attribute").queue_attribute({name, value});
}

void ResultsWriter::write_attribute(const std::string& name, const std::string& value) {
  live("write_attribute").queue_attribute({name, value});
}

void ResultsWriter::write_constant(const std::string& name, const Eigen::MatrixXd& data, const std::string& unit,
                                   const std::string& description) {
  Impl& impl = live("write_constant");
  impl.require_open("write_constant");
  impl.check_constant(name, data);
  impl.wait_idle();
  const auto hdf5 = detail::hdf5_calls();
  if (H5Lexists(impl.files[0], name.c_str(), H5P_DEFAULT) > 0)
    throw Error("the file already holds an object named " + name, impl.where("write_constant"),
                "write each constant once, under a name not used by the time histories (docs/output.md)");
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> row_major = data;
  // To the spare, which is then published, then to the other copy (spare_copy.hpp).
  for (int pass = 0; pass < 2; ++pass) {
    const hid_t file = impl.files[static_cast<std::size_t>(impl.h5_spare)];
    const hsize_t dims[2] = {static_cast<hsize_t>(data.rows()), static_cast<hsize_t>(data.cols())};
    const Hid space(H5Screate_simple(data.cols() == 1 ? 1 : 2, dims, nullptr), H5Sclose);
    const Hid links(Impl::intermediate_groups(), H5Pclose);
    const Hid set(H5Dcreate2(file, name.c_str(), H5T_IEEE_F64LE, space, links, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
    impl.check(set.valid() ? H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, row_major.data()) : -1,
               "write dataset " + name, "write_constant");
    impl.check(detail::describe_dataset(set, unit, description), "describe dataset " + name, "write_constant");
    impl.check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush", "write_constant");
    if (pass == 0) impl.publish_h5();
  }
}

void ResultsWriter::append(const ResultsStep& step) {
  Impl& impl = live("append");
  impl.require_open("append");
  impl.report_failure();
  impl.check_step(step);
  impl.place_shapes(step);
  impl.buffer_step(step);
  ++impl.appended;
  if (impl.appended - impl.handed >= impl.flush_every) impl.hand_over();
}

void ResultsWriter::flush() {
  Impl& impl = live("flush");
  impl.require_open("flush");
  impl.hand_over();
  impl.wait_idle();
}

void ResultsWriter::close() {
  if (!impl_ || impl_->closed) return;
  std::exception_ptr failure;
  try {
    flush();
  } catch (...) {
    failure = std::current_exception();
  }
  const bool released = impl_->closed || impl_->release();  // a writer-thread error released it already
  if (failure) std::rethrow_exception(failure);
  impl_->check(released ? 0 : -1, "close the file", "close");
}

int ResultsWriter::steps_written() const { return live("steps_written").appended; }

int ResultsWriter::steps_flushed() const { return live("steps_flushed").await_writer(); }

const std::string& ResultsWriter::xdmf_path() const { return live("xdmf_path").xdmf_path; }

}  // namespace spar::core
