#include <spar/core/frame_inertia.hpp>
#include <spar/lie/hat.hpp>

#include <Eigen/Geometry>

namespace spar::core {

FrameInertia::FrameInertia(const Coefficients& coefficients, double translational,
                           const Eigen::Matrix3d& rotational)
    : coefficients_(coefficients), translational_(translational), rotational_(rotational) {}

Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::ColMajor, 3, max_inertia_frames>
FrameInertia::weighted_angular_velocities(const Eigen::Ref<const Eigen::VectorXd>& velocity) const {
  const int k = frame_count();
  Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::ColMajor, 3, max_inertia_frames> sums =
      Eigen::Matrix3Xd::Zero(3, k);
  for (int I = 0; I < k; ++I)
    for (int J = 0; J < k; ++J) sums.col(I) += coefficients_(I, J) * velocity.segment<3>(6 * J + 3);
  return sums;
}

// 003 eq. 32: (M v̇)_I = Σ_J m_IJ (ρA ẍ_J, ρJ Ω̇_J); docs/dynamics.md eq. D2 for f_gyr. One pass
// over J gathers Σ_J m_IJ v̇_J (all six entries) and Σ_J m_IJ Ω_J.
void FrameInertia::add_force(const Eigen::Ref<const Eigen::VectorXd>& velocity,
                             const Eigen::Ref<const Eigen::VectorXd>& acceleration,
                             Eigen::Ref<Eigen::VectorXd> force) const {
  const int k = frame_count();
  for (int I = 0; I < k; ++I) {
    Eigen::Matrix<double, 6, 1> weighted_acceleration = Eigen::Matrix<double, 6, 1>::Zero();
    Eigen::Vector3d weighted_omega = Eigen::Vector3d::Zero();
    for (int J = 0; J < k; ++J) {
      const double m = coefficients_(I, J);
      weighted_acceleration += m * acceleration.segment<6>(6 * J);
      weighted_omega += m * velocity.segment<3>(6 * J + 3);
    }
    const Eigen::Vector3d momentum = rotational_ * weighted_omega;  // Π_I
    force.segment<3>(6 * I) += translational_ * weighted_acceleration.head<3>();
    force.segment<3>(6 * I + 3) += rotational_ * weighted_acceleration.tail<3>() +
                                   Eigen::Vector3d(velocity.segment<3>(6 * I + 3)).cross(momentum);
  }
}

void FrameInertia::add_mass(Eigen::Ref<Eigen::MatrixXd> mass) const {
  const int k = frame_count();
  for (int I = 0; I < k; ++I)
    for (int J = 0; J < k; ++J) {
      const double m = coefficients_(I, J);
      mass.block<3, 3>(6 * I, 6 * J).diagonal().array() += m * translational_;
      mass.block<3, 3>(6 * I + 3, 6 * J + 3) += m * rotational_;
    }
}

// docs/dynamics.md eq. D2.
void FrameInertia::add_gyroscopic_tangent(const Eigen::Ref<const Eigen::VectorXd>& velocity,
                                          Eigen::Ref<Eigen::MatrixXd> tangent) const {
  const int k = frame_count();
  const auto omega_sums = weighted_angular_velocities(velocity);
  for (int I = 0; I < k; ++I) {
    const Eigen::Matrix3d hat_omega_J = lie::hat(Eigen::Vector3d(velocity.segment<3>(6 * I + 3))) * rotational_;
    for (int K = 0; K < k; ++K) tangent.block<3, 3>(6 * I + 3, 6 * K + 3) += coefficients_(I, K) * hat_omega_J;
    tangent.block<3, 3>(6 * I + 3, 6 * I + 3) -= lie::hat(Eigen::Vector3d(rotational_ * omega_sums.col(I)));
  }
}

double FrameInertia::kinetic_energy(const Eigen::Ref<const Eigen::VectorXd>& velocity) const {
  const int k = frame_count();
  const auto omega_sums = weighted_angular_velocities(velocity);
  double twice = 0.0;
  for (int I = 0; I < k; ++I) {
    Eigen::Vector3d linear = Eigen::Vector3d::Zero();
    for (int J = 0; J < k; ++J) linear += coefficients_(I, J) * velocity.segment<3>(6 * J);
    twice += translational_ * velocity.segment<3>(6 * I).dot(linear) +
             velocity.segment<3>(6 * I + 3).dot(rotational_ * omega_sums.col(I));
  }
  return 0.5 * twice;
}

}  // namespace spar::core
