#include <spar/joints/coordinate_driver.hpp>

#include <spar/error.hpp>

#include <algorithm>
#include <string>
#include <utility>

namespace spar::joints {

namespace {
constexpr const char* name = "joints::CoordinateDriver";
}

CoordinateDriver::CoordinateDriver(int block, std::vector<int> coordinates, std::vector<TimeFunction> f,
                                   const core::Configuration& q0)
    : blocks_{block}, coordinates_(std::move(coordinates)), f_(std::move(f)) {
  if (block < 0 || block >= q0.block_count() || q0.is_frame(block))
    throw Error("block " + std::to_string(block) + " is not a vector block of the configuration", name,
                "drive coordinates of a vector block (an ANCF or cable node); drive a frame with "
                "PositionDriver or AngleDriver");
  if (coordinates_.empty()) throw Error("no coordinate to drive", name, "give at least one coordinate");
  const int size = q0.blocks[block].size;
  std::vector<int> sorted = coordinates_;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 0; k < sorted.size(); ++k) {
    if (sorted[k] < 0 || sorted[k] >= size)
      throw Error("coordinate " + std::to_string(sorted[k]) + " is outside block " + std::to_string(block) + " of " +
                      std::to_string(size) + " coordinates",
                  name, "give coordinates 0 … " + std::to_string(size - 1));
    if (k > 0 && sorted[k] == sorted[k - 1])
      throw Error("coordinate " + std::to_string(sorted[k]) + " is given twice", name, "give each coordinate once");
  }
  if (f_.size() != 1 && f_.size() != coordinates_.size())
    throw Error(std::to_string(f_.size()) + " time functions for " + std::to_string(coordinates_.size()) +
                    " coordinates",
                name, "give one function for all coordinates or one per coordinate");
  for (const TimeFunction& function : f_) check_time_function(function, name);
  const auto p0 = q0.vector(block);
  for (const int c : coordinates_) reference_.push_back(p0(c));
}

// docs/joints.md eq. J30.
void CoordinateDriver::compute_value(const core::Configuration& q, double t, Eigen::Ref<Eigen::VectorXd> phi) const {
  const auto p = q.vector(blocks_[0]);
  for (int k = 0; k < equation_count(); ++k) phi(k) = p(coordinates_[k]) - reference_[k] - function(k).value(t);
}

void CoordinateDriver::compute_jacobian(const core::Configuration& /*q*/, double /*t*/,
                                        Eigen::Ref<Eigen::MatrixXd> B) const {
  for (int k = 0; k < equation_count(); ++k) B(k, coordinates_[k]) = 1.0;
}

void CoordinateDriver::compute_multiplier_tangent(const core::Configuration& /*q*/, double /*t*/,
                                                  const Eigen::Ref<const Eigen::VectorXd>& /*lambda*/,
                                                  Eigen::Ref<Eigen::MatrixXd> /*K*/) const {}

void CoordinateDriver::compute_acceleration_terms(const core::Configuration& /*q*/,
                                                  const Eigen::VectorXd& /*velocity*/, double t,
                                                  Eigen::Ref<Eigen::VectorXd> c) const {
  for (int k = 0; k < equation_count(); ++k) c(k) = -function(k).second_derivative(t);
}

void CoordinateDriver::compute_time_derivative(const core::Configuration& /*q*/, double t,
                                               Eigen::Ref<Eigen::VectorXd> phi_t) const {
  for (int k = 0; k < equation_count(); ++k) phi_t(k) = -function(k).first_derivative(t);
}

}  // namespace spar::joints
