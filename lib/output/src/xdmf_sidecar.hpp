#pragma once
/// \file
/// The XDMF sidecar of a results file (docs/output.md, "XDMF sidecar"): an XDMF 3 temporal
/// collection that ParaView's default reader (XDMF3) plays as an animation of the beams'
/// centerlines, the rigid bodies' shapes and the nodes. Every array is a hyperslab of the HDF5 file written in XDMF 3's
/// own syntax, `file.h5:/dataset|start:stride:count:dimensions`, with its full Dimensions,
/// NumberType, Precision and Format.
///
/// The document is appended in place: the writer remembers where the closing tags begin and, at
/// each flush, writes the new steps' grids followed by the closing tags there in one pwrite. A
/// flush therefore costs O(steps since the last flush), whatever the length of the run, and the
/// file is complete XML after every flush. A kill can cut that write short, so ResultsWriter
/// keeps two sidecars and writes only the one that is not the published file (spare_copy.hpp).

#include <spar/output/results_writer.hpp>

#include <sys/types.h>

#include <string>
#include <vector>

namespace spar::output::detail {

class XdmfSidecar {
public:
  /// Creates (truncates) `xmf_path` as an empty temporal collection whose heavy data are in the
  /// HDF5 file `h5_name` (its name relative to the sidecar). Throws spar::Error if the file
  /// cannot be created or if check_names refuses the names.
  XdmfSidecar(std::string xmf_path, const std::string& h5_name, ResultsLayout layout);
  /// Throws spar::Error naming the sidecar `xmf_path` if `h5_name` holds a character the XDMF
  /// reference syntax reserves, or it or a centerline field's name a character XML refuses: what
  /// the constructor checks first, for a caller that makes the sidecar later on another thread.
  static void check_names(const std::string& xmf_path, const std::string& h5_name, const ResultsLayout& layout);
  /// Closes the file descriptor; what was written stays.
  ~XdmfSidecar();
  XdmfSidecar(const XdmfSidecar&) = delete;
  XdmfSidecar& operator=(const XdmfSidecar&) = delete;

  /// Appends the grids of steps first_step, first_step + 1, … (one per entry of `times`), whose
  /// data are on disk in datasets of `rows` steps, then the closing tags, in one write at the
  /// offset of the previous closing tags.
  void append(int first_step, const std::vector<double>& times, int rows);

private:
  /// The grid of one step, with the texts of its step number, time and row count.
  std::string step_grid(const std::string& step, const std::string& time, const std::string& rows) const;
  std::string beam_grid(const std::string& step, std::size_t beam, const std::string& rows) const;
  /// Shape `body` of layout.rigid_bodies: a Hexahedron (box) or 3 two-point Polyline cells (axes).
  std::string rigid_body_grid(const std::string& step, std::size_t body, const std::string& rows) const;
  std::string nodes_grid(const std::string& step, const std::string& rows) const;
  /// A DataItem reading step `step` of `dataset` (rows × shape, doubles): the first `taken`
  /// entries of its last dimension.
  std::string step_item(const std::string& dataset, const std::string& step, const std::string& rows,
                        std::vector<int> shape, int taken, const std::string& indent) const;
  /// Writes `text` at `offset`, all of it; throws spar::Error naming the sidecar on failure.
  void write_at(const std::string& text, off_t offset);

  std::string path_;
  std::string h5_name_;  ///< XML-escaped
  ResultsLayout layout_;
  int fd_ = -1;
  off_t body_end_ = 0;  ///< where the closing tags begin
  /// step_grid cut at its placeholders for the step, time and row count (xdmf_sidecar.cpp): a
  /// step's grid is pieces[0], its value of placeholders[0], pieces[1], …, pieces.back().
  std::vector<std::string> grid_pieces_;
  std::vector<char> grid_placeholders_;
};

}  // namespace spar::output::detail
