// check_results FILE.h5 — the properties every dynamic run's results file must have, whatever the
// model (issue 9: a run once stored angular velocities of 50 400 rad/s for a node that the stored
// quaternions turned at 377 rad/s, and a kinetic energy jumping from 7.2 J to 9632 J in a step):
//
// 1. The stored velocities are the rate of the stored configuration: for every node and step,
//    the secant rate s = (x_{n+1} − x_n)/h (translations) and s = log(R_nᵀ R_{n+1})/h (rotations,
//    material, as Ω is) agrees with the mean m = ½(v_n + v_{n+1}):
//        |s − m| ≤ max(|v_n − v_{n−1}|, |v_{n+1} − v_n|, |v_{n+2} − v_{n+1}|) + 0.05 |m| + 0.01 V,
//    V the largest stored speed of that kind (translation or rotation) in the run. Generalized-α
//    gives s − m = h(γ/2 − β)(a_n − a_{n+1}) exactly (|γ/2 − β| = 1.3e-3 at ρ∞ = 0.9), small
//    against h|a|, which the velocity changes measure. Where a mode the step cannot resolve rings
//    (ωh ≫ 1: the slider-crank's root section, its tiny rotary inertia hit by the drive at t = 0),
//    the stored velocity alternates from step to step while the secant averages the ringing out;
//    the neighbouring changes are then as large as the mismatch, and the bound admits it. An
//    aliased rotation increment (2πk added to h|Ω|) shifts the velocity for good, with small
//    changes between steps, and breaks the bound by 2πk/h ≫ V.
// 2. The energy balance holds step by step: the numerical dissipation D (docs/dynamics.md D8)
//    changes in one step by at most 1 % of the run's energy scale max(T + |Π| + |V_g| + |W_ext|).
// 3. Every profile (profiles/<name>, docs/output.md) has a row per step, as many points as its
//    arc lengths profiles/<name>_arc_length, which increase, and finite values.
//
// Exit 0 and one line "results consistent: …" when all hold; exit 1 naming the first violation.
// A file without frame nodes (ANCF models, whose nodes are vector blocks, or a model whose sliding
// coordinate keeps the writer from storing velocities) is checked for the balance only.
#include <spar/lie/exp.hpp>
#include <spar/lie/log.hpp>
#include <spar/lie/quaternion.hpp>

#include <hdf5.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

/// A whole double dataset and its dimensions.
struct Dataset {
  std::vector<double> values;
  std::vector<hsize_t> dims;
};

Dataset read(hid_t file, const std::string& name) {
  if (H5Lexists(file, name.c_str(), H5P_DEFAULT) <= 0) throw std::runtime_error("no dataset " + name);
  const hid_t dataset = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  const hid_t space = H5Dget_space(dataset);
  Dataset d;
  d.dims.resize(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
  H5Sget_simple_extent_dims(space, d.dims.data(), nullptr);
  hsize_t count = 1;
  for (const hsize_t n : d.dims) count *= n;
  d.values.resize(count);
  if (count > 0) H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, d.values.data());
  H5Sclose(space);
  H5Dclose(dataset);
  return d;
}

int fail(const std::string& what) {
  std::printf("results inconsistent: %s\n", what.c_str());
  return 1;
}

/// The names of the links in group `name` (none if it does not exist).
std::vector<std::string> members(hid_t file, const std::string& name) {
  std::vector<std::string> names;
  if (H5Lexists(file, name.c_str(), H5P_DEFAULT) <= 0) return names;
  const hid_t group = H5Gopen2(file, name.c_str(), H5P_DEFAULT);
  H5G_info_t info;
  H5Gget_info(group, &info);
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t size = H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    std::string link(static_cast<std::size_t>(size), '\0');
    H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, link.data(), link.size() + 1, H5P_DEFAULT);
    names.push_back(link);
  }
  H5Gclose(group);
  return names;
}

/// Check 3 for profile `name`: "" if it holds, else what is wrong.
std::string check_profile(hid_t file, const std::string& name, std::size_t steps) {
  const Dataset values = read(file, "profiles/" + name), arc = read(file, "profiles/" + name + "_arc_length");
  if (values.dims.size() != 3 || values.dims[0] != steps || values.dims[1] != arc.values.size())
    return "profiles/" + name + " is not steps × " + std::to_string(arc.values.size()) + " points × components";
  for (std::size_t i = 1; i < arc.values.size(); ++i)
    if (!(arc.values[i] > arc.values[i - 1])) return "profiles/" + name + "_arc_length does not increase";
  if (!std::all_of(values.values.begin(), values.values.end(), [](double x) { return std::isfinite(x); }))
    return "profiles/" + name + " holds a value that is not finite";
  return "";
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc != 2) {
    std::printf("usage: check_results FILE.h5\n");
    return 2;
  }
  const hid_t file = H5Fopen(argv[1], H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) return fail(std::string("cannot open ") + argv[1]);
  const Dataset time = read(file, "time");
  const std::size_t steps = time.values.size();
  if (steps < 3) return fail("fewer than 3 steps");
  const bool with_nodes = H5Lexists(file, "velocities", H5P_DEFAULT) > 0;
  double worst_ratio = 0.0;
  std::size_t nodes = 0;
  if (with_nodes) {
    const Dataset positions = read(file, "positions");
    const Dataset quaternions = read(file, "quaternions");
    const Dataset velocities = read(file, "velocities");
    nodes = positions.dims[1];
    // 1. Velocities against the rate of the configuration.
    double speed_scale[2] = {0.0, 0.0};  // largest stored |ẋ| and |Ω|
    for (std::size_t k = 0; k < steps * nodes; ++k)
      for (int part = 0; part < 2; ++part)
        speed_scale[part] = std::max(speed_scale[part],
                                     Eigen::Vector3d(&velocities.values[6 * k + 3 * part]).norm());
    for (std::size_t s = 0; s + 1 < steps; ++s) {
      const double h = time.values[s + 1] - time.values[s];
      for (std::size_t i = 0; i < nodes; ++i) {
        const auto x = [&](std::size_t step) { return Eigen::Vector3d(&positions.values[(step * nodes + i) * 3]); };
        const auto v = [&](std::size_t step) {
          return Eigen::Matrix<double, 6, 1>(&velocities.values[(step * nodes + i) * 6]);
        };
        const auto R = [&](std::size_t step) {
          const double* q = &quaternions.values[(step * nodes + i) * 4];
          return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
        };
        Eigen::Matrix<double, 6, 1> secant;
        secant.head<3>() = (x(s + 1) - x(s)) / h;
        secant.tail<3>() = spar::lie::log(Eigen::Matrix3d(R(s).transpose() * R(s + 1))) / h;
        const Eigen::Matrix<double, 6, 1> mean = 0.5 * (v(s) + v(s + 1));
        for (int part = 0; part < 2; ++part) {
          double change = 0.0;  // the largest velocity change of the three steps around this one
          for (std::size_t a = (s > 0 ? s - 1 : s); a <= std::min(s + 1, steps - 2); ++a)
            change = std::max(change, (v(a + 1) - v(a)).segment<3>(3 * part).norm());
          const double error = (secant - mean).segment<3>(3 * part).norm();
          const double allowed = change + 0.05 * mean.segment<3>(3 * part).norm() + 0.01 * speed_scale[part];
          worst_ratio = std::max(worst_ratio, error / allowed);
          if (error > allowed) {
            char what[256];
            std::snprintf(what, sizeof what,
                          "node %zu, step %zu (t = %.6g s): stored %s %.6g, rate of the configuration %.6g",
                          i, s + 1, time.values[s + 1], part ? "angular velocity" : "velocity",
                          mean.segment<3>(3 * part).norm(), secant.segment<3>(3 * part).norm());
            return fail(what);
          }
        }
      }
    }
  }

  // 2. The energy balance, step by step.
  const Dataset kinetic = read(file, "scalars/kinetic_energy");
  const Dataset strain = read(file, "scalars/strain_energy");
  const Dataset gravity = read(file, "scalars/gravity_potential");
  const Dataset work = read(file, "scalars/external_work");
  const Dataset dissipation = read(file, "scalars/numerical_dissipation");
  double scale = 0.0, worst_jump = 0.0;
  for (std::size_t s = 0; s < steps; ++s)
    scale = std::max(scale, kinetic.values[s] + std::abs(strain.values[s]) + std::abs(gravity.values[s]) +
                                std::abs(work.values[s]));
  for (std::size_t s = 0; s + 1 < steps; ++s) {
    const double jump = std::abs(dissipation.values[s + 1] - dissipation.values[s]);
    worst_jump = std::max(worst_jump, jump);
    if (jump > 1e-2 * scale) {
      char what[256];
      std::snprintf(what, sizeof what,
                    "step %zu (t = %.6g s): the energy balance moved by %.6g J in one step (scale %.6g J; "
                    "kinetic energy %.6g -> %.6g J)",
                    s + 1, time.values[s + 1], jump, scale, kinetic.values[s], kinetic.values[s + 1]);
      return fail(what);
    }
  }
  // 3. The profiles.
  std::size_t profiles = 0;
  for (const std::string& name : members(file, "profiles")) {
    if (name.size() > 11 && name.ends_with("_arc_length")) continue;
    if (const std::string wrong = check_profile(file, name, steps); !wrong.empty()) return fail(wrong);
    ++profiles;
  }
  H5Fclose(file);
  std::printf("results consistent: %zu steps, %zu frame nodes, %zu profiles; velocity mismatch at most %.3g of its bound; "
              "largest one-step change of the energy balance %.3g J of %.3g J\n",
              steps, nodes, profiles, worst_ratio, worst_jump, scale);
  return 0;
} catch (const std::exception& error) {
  return fail(error.what());
}
