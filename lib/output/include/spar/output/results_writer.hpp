#pragma once
/// \file
/// The time-history results file of a simulation: one HDF5 file of extendible datasets (one row
/// per step) and an XDMF sidecar that lets ParaView play the deforming beams as an animation.
/// Steps are buffered and written in blocks, each followed by H5Fflush and an append of the
/// block's steps to the sidecar, so a run that dies keeps every step up to its last flush and
/// both files still open; a flush costs the same at step 100 and at step 10⁶. The files are
/// made and the blocks written on a thread of the writer's own (see ResultsWriter), so the run
/// does not wait for the disk.
/// The schema (dataset names, shapes, units) is in docs/output.md, "Time histories".

#include <spar/core/configuration.hpp>
#include <spar/output/provenance.hpp>

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace spar::output {

/// A per-step quantity: its dataset name, its unit and its meaning, stored with the dataset as
/// its `units` and `description` attributes.
struct ResultsQuantity {
  std::string name;         ///< dataset name, e.g. kinetic_energy (no '/')
  std::string unit;         ///< SI unit, e.g. "J", "m/s", "rad"; "1" for ratios and counts
  std::string description;  ///< what it is, e.g. "kinetic energy of the rods and the slider"
  /// Stored as 32-bit integers (counters such as newton_iterations); every value appended must
  /// then be a whole number. Scalars only.
  bool integer = false;
  /// NaN marks a step where the quantity is not defined (e.g. the material coordinate of a slider
  /// that has left its beam). Without this flag a NaN or infinite value is refused: a NaN result
  /// is never written silently. Scalars and probes; every other value of a step, and a
  /// constant, must be finite.
  bool may_be_undefined = false;
};

/// A quantity sampled at every centerline point of every beam, e.g. the velocity or the arc
/// length: stored per step beside the centerlines and shown by the XDMF sidecar as point data of
/// the beams, so ParaView can colour them by it.
struct CenterlineField {
  std::string name;         ///< dataset and ParaView array name, e.g. velocity (no '/', ':', '|')
  std::string unit;         ///< SI unit, e.g. "m/s"; "1" for ratios
  std::string description;  ///< what it is
  int components = 1;       ///< 1 (a scalar per point) or 3 (a vector per point, inertial frame)
};

/// A quantity along a line at a fixed number of points, e.g. a beam's section forces at its Gauss
/// points (core::section_resultants): stored per step as the dataset `/profiles/<name>`, points ×
/// components. Not drawn by the XDMF sidecar (its points need not be the centerline's).
struct ResultsProfile {
  ResultsQuantity quantity;  ///< name, unit, description (not integer; may_be_undefined allowed)
  int points = 0;            ///< ≥ 1
  int components = 1;        ///< ≥ 1, e.g. 3 for a force in the inertial frame
};

/// How the XDMF sidecar draws a rigid body (docs/output.md, "Rigid bodies"): a box or the three
/// axes of its frame, both given in the body's material frame and carried by the node's frame, so
/// a vertex c of the shape is at x + R c. The writer stores the vertices of every step (the
/// frames stay in `positions` and `quaternions` as they are): ParaView cannot rotate a shape by
/// a stored quaternion.
struct RigidBodyShape {
  enum class Kind {
    axes,  ///< three line segments from `offset` along the body's material X, Y and Z (cells 0, 1, 2)
    box,   ///< a hexahedron centred at `offset`, its edges along the body's material axes
  };
  int node = 0;  ///< the body's node: a frame of the configuration, 0 ≤ node < layout.node_count
  Kind kind = Kind::axes;
  /// box: its edge lengths along material X, Y, Z (m, all > 0); axes: each axis' length (m, all
  /// > 0), or all zero (the default) for a tenth of the model's extent — the diagonal of the box
  /// that bounds the first appended step's nodes and centerline points.
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  /// The box's centre or the axes' origin in the body's material frame (m), from the node.
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
};

/// What every step of a run holds; fixed when the file is created.
struct ResultsLayout {
  /// Nodes of the configuration: positions n×3, rotations as unit quaternions n×4
  /// (w, x, y, z with w ≥ 0) and, when `velocities` is set, velocities n×6 (ẋ inertial, Ω material).
  int node_count = 0;
  /// Whether steps carry node velocities (6 per node).
  bool velocities = true;
  /// Lagrange multipliers λ per step (0: none).
  int multiplier_count = 0;
  /// Per-step scalars, e.g. {.name = "kinetic_energy", .unit = "J", .description = "kinetic
  /// energy of the rods"}, {.name = "newton_iterations", .unit = "1", .description = "Newton
  /// iterations of the step", .integer = true}.
  std::vector<ResultsQuantity> scalars;
  /// Per-step 3-vectors, e.g. a material point's position in m.
  std::vector<ResultsQuantity> probes;
  /// Per beam, the number of centerline points sampled at every step (≥ 2; the XDMF polylines).
  std::vector<int> centerline_points;
  /// Point data of every beam's centerline points (none: the beams are bare polylines).
  std::vector<CenterlineField> centerline_fields;
  /// Quantities along lines at points of their own (profiles/<name>).
  std::vector<ResultsProfile> profiles;
  /// Shapes drawn at nodes in the XDMF sidecar, one grid each (none: the nodes are points only).
  /// A node may carry several shapes.
  std::vector<RigidBodyShape> rigid_bodies;
};

/// One step's data, borrowed for the duration of ResultsWriter::append.
struct ResultsStep {
  double time = 0;
  const core::Configuration* configuration = nullptr;   ///< node_count nodes, or nullptr if node_count = 0
  const Eigen::VectorXd* velocity = nullptr;      ///< 6 per node, or nullptr if the layout has none
  const Eigen::VectorXd* multipliers = nullptr;   ///< multiplier_count entries, or nullptr if 0
  std::vector<double> scalars;                    ///< in layout.scalars order
  std::vector<Eigen::Vector3d> probes;            ///< in layout.probes order
  std::vector<Eigen::MatrixXd> centerlines;       ///< per beam, centerline_points[k] × 3
  /// Per beam, one matrix per layout.centerline_fields entry (in its order): centerline_points[k]
  /// rows of `components` values, one row per centerline point; empty if the layout has none.
  std::vector<std::vector<Eigen::MatrixXd>> centerline_fields;
  /// One matrix per layout.profiles entry, in its order: points × components.
  std::vector<Eigen::MatrixXd> profiles;
};

/// Writes a run's time histories into `<name>.h5` and its XDMF sidecar `<name>.xmf`.
/// The file is not locked (HDF5 file locking is off), so it can be read while the run goes on:
/// after each flush both files are complete up to the flushed step.
///
/// Threading: the constructor starts one writer thread, which lives until close() or the
/// destructor joins it, and whose jobs run in the order of the calls: first making the files
/// (the HDF5 file, its datasets, the sidecar), then the root attributes of write_attribute, the
/// options of write_options and the blocks of steps. append() copies the step into the buffers
/// of the block being filled; a full block is handed to the writer thread, which writes it,
/// H5Fflush-es and appends it to the sidecar while the caller fills the next one (two blocks in
/// memory at most: append waits only if the writer thread is still writing the previous block).
/// Every HDF5 call of the writer is made on its thread, or on the caller's with the writer
/// thread idle (write_constant, close), under the library's HDF5 lock (HDF5 is not assumed
/// thread-safe: two writers may run side by side). An error of the writer thread (a full disk,
/// an HDF5 failure) is rethrown as its spar::Error by the next append, flush, close or write_*
/// call, which closes the file first: the writer then writes nothing more. A ResultsWriter is
/// used from one thread at a time, like any object without a lock.
class ResultsWriter {
public:
  /// Checks `layout` and that both paths can be written, then has the writer thread make the
  /// HDF5 file with every dataset of `layout` with zero steps, and an empty sidecar, and put them
  /// in the place of an earlier run's files (a kill at any moment leaves both files whole:
  /// docs/output.md, "Surviving a kill"); flush() waits for that. Steps are written in blocks of `flush_every` (≥ 1). Throws
  /// spar::Error naming the path and the reason if the layout is invalid, a file cannot be
  /// opened for writing or another writer of this program (a ResultsWriter not yet closed, an
  /// Hdf5File) is writing it; a later failure of HDF5 making the file (a full disk) is rethrown
  /// by the next call, like any error of the writer thread.
  ResultsWriter(const std::string& h5_path, ResultsLayout layout, int flush_every = 100);
  /// Closes the file (see close()); reports a failure on stderr instead of throwing.
  ~ResultsWriter();
  ResultsWriter(ResultsWriter&&) noexcept;
  ResultsWriter& operator=(ResultsWriter&&) noexcept;
  ResultsWriter(const ResultsWriter&) = delete;
  ResultsWriter& operator=(const ResultsWriter&) = delete;

  /// Run metadata: a scalar attribute of the root group (replaced if it exists): a double, a
  /// 64-bit integer (counters such as steps or factorizations) or a variable-length UTF-8 string
  /// (h5py reads str). State the unit in the name or in docs/output.md. Written and flushed by
  /// the writer thread after the blocks handed over before it, without waiting for them;
  /// spar::Error at once for a name of 0 or more than 65 000 characters, and for the names of
  /// the file's own schema and provenance (`schema`, `spar_version`, `spar_revision`).
  void write_attribute(const std::string& name, double value);
  void write_attribute(const std::string& name, std::int64_t value);
  void write_attribute(const std::string& name, int value) { write_attribute(name, std::int64_t{value}); }
  void write_attribute(const std::string& name, const std::string& value);
  /// The run's options, name → value as text (RunOptions, e.g. every option of the example's
  /// command line with its value as given or its default), as string attributes of the group
  /// `/options`, replacing those of the same names: with the root attributes `schema`,
  /// `spar_version` and `spar_revision`, which every file carries from its creation, the file
  /// says how it was made (docs/output.md, "Schema and provenance"). Written and flushed like
  /// write_attribute, after the jobs before it; spar::Error at once for a name of 0 or more than
  /// 65 000 characters. May be called more than once.
  void write_options(const RunOptions& options);
  /// A constant dataset `name` (rows × cols, row-major; a column vector is stored 1-D) with its
  /// `units` and `description`, e.g. the reference geometry; groups in `name` are created.
  /// Throws spar::Error if `name` already exists (every time-history name is taken from the start).
  void write_constant(const std::string& name, const Eigen::MatrixXd& data, const std::string& unit,
                      const std::string& description);
  /// Buffers one step after checking it against the layout (spar::Error naming the field and the
  /// expected size) and that time increases; hands the block to the writer thread when
  /// flush_every steps are buffered (waiting for it if it is still writing the previous block).
  void append(const ResultsStep& step);
  /// Writes the buffered steps, H5Fflush-es the file and appends them to the sidecar, and waits
  /// for the writer thread to finish, so both are readable now with every appended step.
  void flush();
  /// Flushes, joins the writer thread and closes the file; later calls do nothing, append/write_*
  /// then throw.
  void close();
  /// A writer that was moved from holds nothing: every call but close() (which does nothing) and
  /// the destructor throws spar::Error.
  /// Steps appended so far (written or still buffered).
  int steps_written() const;
  /// Steps on disk (written, H5Fflush-ed and in the sidecar): waits for the writer thread to
  /// finish the blocks handed to it, so call it between blocks, not at every step.
  int steps_flushed() const;
  /// The sidecar's path: the HDF5 path with its extension replaced by `.xmf`.
  const std::string& xdmf_path() const;

private:
  struct Impl;
  /// The writer's state; spar::Error naming `function` if this writer was moved from.
  Impl& live(const std::string& function) const;
  std::unique_ptr<Impl> impl_;
};

}  // namespace spar::output
