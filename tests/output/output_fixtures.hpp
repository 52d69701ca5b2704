#pragma once
/// \file
/// Shared by the output tests: a small deterministic run (3 nodes, 2 multipliers, 2 scalars,
/// 1 probe, 2 beams with 2 centerline fields, a box and axes drawn at two nodes), a scratch folder, and readers for what
/// ResultsWriter wrote.

#include <spar/core/configuration.hpp>
#include <spar/output/results_writer.hpp>

#include <Eigen/Geometry>
#include <hdf5.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
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

inline output::ResultsLayout sample_layout() {
  output::ResultsLayout layout;
  layout.node_count = 3;
  layout.multiplier_count = 2;
  layout.scalars = {{.name = "kinetic_energy", .unit = "J", .description = "kinetic energy"},
                    {.name = "newton_iterations", .unit = "1", .description = "Newton iterations", .integer = true}};
  layout.probes = {{.name = "tip", .unit = "m", .description = "tip position"}};
  layout.centerline_points = {4, 5};
  layout.centerline_fields = {{.name = "arc_length", .unit = "m", .description = "arc length"},
                              {.name = "velocity", .unit = "m/s", .description = "velocity", .components = 3}};
  // A box off its node's origin, and the axes at their default length (a tenth of the model's extent).
  layout.rigid_bodies = {{.node = 1, .kind = output::RigidBodyShape::Kind::box, .size = {0.4, 0.2, 0.1},
                          .offset = {0.05, -0.1, 0.2}},
                         {.node = 2}};
  return layout;
}

/// Step k of the sample run, every value distinct and a known function of (k, index).
struct SampleStep {
  core::Configuration configuration;
  Eigen::VectorXd velocity;
  Eigen::VectorXd multipliers;
  output::ResultsStep step;

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
      const Eigen::MatrixXd arc_length = Eigen::VectorXd::LinSpaced(points, 0.0, 1.0);
      step.centerline_fields.push_back({arc_length, -centerline - Eigen::MatrixXd::Constant(points, 3, k)});
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

  /// The HDF5 type class (H5T_FLOAT, H5T_INTEGER, ...) and size in bytes of dataset `name`.
  std::pair<H5T_class_t, std::size_t> dataset_type(const std::string& name) const {
    const hid_t set = H5Dopen2(id_, name.c_str(), H5P_DEFAULT);
    if (set < 0) throw std::runtime_error("no dataset " + name);
    const hid_t type = H5Dget_type(set);
    const std::pair<H5T_class_t, std::size_t> result{H5Tget_class(type), H5Tget_size(type)};
    H5Tclose(type);
    H5Dclose(set);
    return result;
  }

  /// The absolute names of every dataset in the file.
  std::vector<std::string> datasets() const {
    std::vector<std::string> names;
    // Generic, so it converts to the link callback of HDF5 1.10 (H5L_info_t) and 1.12 (H5L_info2_t).
    auto visit = [](hid_t group, const char* name, const auto*, void* data) -> herr_t {
      const hid_t object = H5Oopen(group, name, H5P_DEFAULT);
      if (object >= 0 && H5Iget_type(object) == H5I_DATASET)
        static_cast<std::vector<std::string>*>(data)->push_back(std::string("/") + name);
      if (object >= 0) H5Oclose(object);
      return 0;
    };
    H5Lvisit(id_, H5_INDEX_NAME, H5_ITER_NATIVE, visit, &names);
    return names;
  }

  double double_attribute(const std::string& name) const {
    double value = 0;
    const hid_t attribute = H5Aopen(id_, name.c_str(), H5P_DEFAULT);
    if (attribute < 0) throw std::runtime_error("no attribute " + name);
    H5Aread(attribute, H5T_NATIVE_DOUBLE, &value);
    H5Aclose(attribute);
    return value;
  }

  /// A 64-bit integer attribute of the root group; throws if it is stored as anything else.
  long long integer_attribute(const std::string& name) const {
    long long value = 0;
    const hid_t attribute = H5Aopen(id_, name.c_str(), H5P_DEFAULT);
    if (attribute < 0) throw std::runtime_error("no attribute " + name);
    const hid_t type = H5Aget_type(attribute);
    const bool int64 = H5Tget_class(type) == H5T_INTEGER && H5Tget_size(type) == 8;
    H5Aread(attribute, H5T_NATIVE_LLONG, &value);
    H5Tclose(type);
    H5Aclose(attribute);
    if (!int64) throw std::runtime_error("attribute " + name + " is not a 64-bit integer");
    return value;
  }

  /// A string attribute and how it is stored.
  struct StringAttribute {
    std::string value;
    bool variable_length = false;
    bool utf8 = false;
  };

  /// String attribute `name` of `object` (a group or dataset path), fixed or variable length.
  StringAttribute string_attribute_of(const std::string& object, const std::string& name) const {
    const hid_t attribute = H5Aopen_by_name(id_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    if (attribute < 0) throw std::runtime_error("no attribute " + name + " on " + object);
    const hid_t type = H5Aget_type(attribute);
    StringAttribute result;
    result.utf8 = H5Tget_cset(type) == H5T_CSET_UTF8;
    result.variable_length = H5Tis_variable_str(type) > 0;
    if (result.variable_length) {
      char* text = nullptr;
      H5Aread(attribute, type, &text);
      result.value = text == nullptr ? "" : text;
      H5free_memory(text);
    } else {
      std::string value(H5Tget_size(type), '\0');
      H5Aread(attribute, type, value.data());
      result.value = value.substr(0, value.find('\0'));
    }
    H5Tclose(type);
    H5Aclose(attribute);
    return result;
  }

  std::string string_attribute(const std::string& name) const { return string_attribute_of("/", name).value; }

  /// The names of the attributes of `object` (a group or dataset path), in name order.
  std::vector<std::string> attribute_names(const std::string& object) const {
    std::vector<std::string> names;
    auto collect = [](hid_t, const char* name, const H5A_info_t*, void* data) -> herr_t {
      static_cast<std::vector<std::string>*>(data)->push_back(name);
      return 0;
    };
    if (H5Aiterate_by_name(id_, object.c_str(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names, H5P_DEFAULT) < 0)
      throw std::runtime_error("cannot list the attributes of " + object);
    return names;
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
