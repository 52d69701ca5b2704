#pragma once
/// \file
/// Shared by the output tests: a small deterministic run (3 nodes, 2 multipliers, 2 scalars,
/// 1 probe, 2 beams), a scratch folder, and readers for what ResultsWriter wrote.

#include <spar/core/configuration.hpp>
#include <spar/core/results_writer.hpp>

#include <Eigen/Geometry>
#include <hdf5.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace spar::test {

/// A fresh, empty folder under the system's temp dir, removed again at the end of the test.
class ScratchFolder {
public:
  explicit ScratchFolder(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / ("spar_output_" + std::to_string(getpid()) + "_" + name)) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
  std::filesystem::path path_;
};

inline core::ResultsLayout sample_layout() {
  core::ResultsLayout layout;
  layout.node_count = 3;
  layout.multiplier_count = 2;
  layout.scalar_names = {"kinetic_energy", "newton_iterations"};
  layout.probe_names = {"tip"};
  layout.centerline_points = {4, 5};
  return layout;
}

/// Step k of the sample run, every value distinct and a known function of (k, index).
struct SampleStep {
  core::Configuration configuration;
  Eigen::VectorXd velocity;
  Eigen::VectorXd multipliers;
  core::ResultsStep step;

  explicit SampleStep(int k) {
    for (int i = 0; i < 3; ++i) {
      const Eigen::Matrix3d R =
          Eigen::AngleAxisd(0.3 * k + 1.1 * i, Eigen::Vector3d(1, 2 * i - 1, 0.5 + k).normalized()).toRotationMatrix();
      configuration.add_frame(Eigen::Vector3d(k + i, 2.0 * i, -0.5 * k), R);
    }
    velocity = Eigen::VectorXd::LinSpaced(18, 100.0 * k, 100.0 * k + 17);
    multipliers = Eigen::Vector2d(-k, 1e3 * k);
    step.time = 1e-3 * (k + 1);
    step.configuration = &configuration;
    step.velocity = &velocity;
    step.multipliers = &multipliers;
    step.scalars = {0.5 * k, static_cast<double>(k % 3)};
    step.probes = {Eigen::Vector3d(k, -k, 7)};
    for (int points : {4, 5}) {
      Eigen::MatrixXd centerline(points, 3);
      for (int p = 0; p < points; ++p) centerline.row(p) << p, k * 0.1 * p, points + 10.0 * k;
      step.centerlines.push_back(centerline);
    }
  }
};

/// A dataset read back: its shape and its values in row-major order.
struct DatasetContents {
  std::vector<hsize_t> shape;
  std::vector<double> values;
};

/// Opens an HDF5 file read-only; closes it at the end of the scope.
class ReadOnlyFile {
public:
  explicit ReadOnlyFile(const std::string& path) : id_(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT)) {
    if (id_ < 0) throw std::runtime_error("cannot open " + path);
  }
  ~ReadOnlyFile() { H5Fclose(id_); }
  ReadOnlyFile(const ReadOnlyFile&) = delete;
  ReadOnlyFile& operator=(const ReadOnlyFile&) = delete;

  bool has(const std::string& name) const { return H5Lexists(id_, name.c_str(), H5P_DEFAULT) > 0; }

  /// Shape and values (as doubles, whatever the stored type) of dataset `name`.
  DatasetContents read(const std::string& name) const {
    const hid_t set = H5Dopen2(id_, name.c_str(), H5P_DEFAULT);
    if (set < 0) throw std::runtime_error("no dataset " + name);
    const hid_t space = H5Dget_space(set);
    DatasetContents contents;
    contents.shape.resize(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
    H5Sget_simple_extent_dims(space, contents.shape.data(), nullptr);
    contents.values.resize(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
    if (!contents.values.empty()) H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, contents.values.data());
    H5Sclose(space);
    H5Dclose(set);
    return contents;
  }

  double double_attribute(const std::string& name) const {
    double value = 0;
    const hid_t attribute = H5Aopen(id_, name.c_str(), H5P_DEFAULT);
    if (attribute < 0) throw std::runtime_error("no attribute " + name);
    H5Aread(attribute, H5T_NATIVE_DOUBLE, &value);
    H5Aclose(attribute);
    return value;
  }

  std::string string_attribute(const std::string& name) const {
    const hid_t attribute = H5Aopen(id_, name.c_str(), H5P_DEFAULT);
    if (attribute < 0) throw std::runtime_error("no attribute " + name);
    const hid_t type = H5Aget_type(attribute);
    std::string value(H5Tget_size(type), '\0');
    H5Aread(attribute, type, value.data());
    H5Tclose(type);
    H5Aclose(attribute);
    return value.substr(0, value.find('\0'));
  }

private:
  hid_t id_;
};

inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace spar::test
