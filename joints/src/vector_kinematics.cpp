#include <spar/joints/vector_kinematics.hpp>
#include <spar/lie/hat.hpp>

#include <Eigen/Geometry>

namespace spar::joints {

AttachedVector AttachedVector::from_inertial(JointFrame frame, const Eigen::Vector3d& inertial,
                                             const core::Configuration& q0) {
  if (frame.on_ground()) return {frame, inertial};
  return {frame, q0.rotation[frame.node].transpose() * inertial};
}

Eigen::Vector3d AttachedVector::direction(const core::Configuration& q) const {
  if (frame_.on_ground()) return vector_;
  return q.rotation[frame_.node] * vector_;
}

void AttachedVector::add_jacobian_along(const core::Configuration& q, const Eigen::Vector3d& w,
                                        Eigen::Ref<Eigen::MatrixXd> B, int row) const {
  if (frame_.on_ground()) return;
  // ∂(R exp(δ) v)/∂δ = −R ṽ, so ∂(w·R v)/∂δ = −wᵀ R ṽ = (v × Rᵀw)ᵀ (eq. J10).
  B.block<1, 3>(row, frame_.rotation_column()) +=
      vector_.cross(q.rotation[frame_.node].transpose() * w).transpose();
}

void AttachedVector::add_multiplier_tangent_along(const core::Configuration& q,
                                                  const Eigen::Vector3d& w, double lambda,
                                                  Eigen::Ref<Eigen::MatrixXd> K) const {
  if (frame_.on_ground()) return;
  // ṽ Rᵀw with R ← R exp(δ): Rᵀw ← Rᵀw + (Rᵀw)~ δ (eq. J11).
  const int column = frame_.rotation_column();
  K.block<3, 3>(column, column) +=
      lambda * lie::hat(vector_) * lie::hat(q.rotation[frame_.node].transpose() * w);
}

Eigen::Vector3d AttachedVector::rate(const core::Configuration& q,
                                     const Eigen::VectorXd& velocity) const {
  if (frame_.on_ground()) return Eigen::Vector3d::Zero();
  return q.rotation[frame_.node] * frame_.angular_velocity(q, velocity).cross(vector_);
}

Eigen::Vector3d AttachedVector::acceleration_terms(const core::Configuration& q,
                                                   const Eigen::VectorXd& velocity) const {
  if (frame_.on_ground()) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d omega = frame_.angular_velocity(q, velocity);
  return q.rotation[frame_.node] * omega.cross(omega.cross(vector_));
}

double DotProduct::value(const core::Configuration& q) const {
  return a_.direction(q).dot(b_.direction(q));
}

void DotProduct::add_jacobian(const core::Configuration& q, Eigen::Ref<Eigen::MatrixXd> B,
                              int row) const {
  a_.add_jacobian_along(q, b_.direction(q), B, row);
  b_.add_jacobian_along(q, a_.direction(q), B, row);
}

void DotProduct::add_multiplier_tangent(const core::Configuration& q, double lambda,
                                        Eigen::Ref<Eigen::MatrixXd> K) const {
  a_.add_multiplier_tangent_along(q, b_.direction(q), lambda, K);
  b_.add_multiplier_tangent_along(q, a_.direction(q), lambda, K);
  if (a_.frame().on_ground() || b_.frame().on_ground()) return;
  // ∂(ṽ_a R_aᵀ R_b v_b)/∂δ_b = −ṽ_a R_aᵀ R_b ṽ_b; the (b, a) block is its transpose (eq. J14).
  const Eigen::Matrix3d coupling = -lambda * lie::hat(a_.vector()) *
                                   q.rotation[a_.frame().node].transpose() *
                                   q.rotation[b_.frame().node] * lie::hat(b_.vector());
  K.block<3, 3>(a_.frame().rotation_column(), b_.frame().rotation_column()) += coupling;
  K.block<3, 3>(b_.frame().rotation_column(), a_.frame().rotation_column()) += coupling.transpose();
}

double DotProduct::acceleration_terms(const core::Configuration& q,
                                      const Eigen::VectorXd& velocity) const {
  return a_.acceleration_terms(q, velocity).dot(b_.direction(q)) +
         2 * a_.rate(q, velocity).dot(b_.rate(q, velocity)) +
         a_.direction(q).dot(b_.acceleration_terms(q, velocity));
}

RelativeRotationLock::RelativeRotationLock(JointFrame a, JointFrame b,
                                           const core::Configuration& q0) {
  // Row i pairs e_{i+1} of a with e_{i+2} of b (indices mod 3): (e₂, e₃), (e₃, e₁), (e₁, e₂).
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d e_a = Eigen::Vector3d::Unit((i + 1) % 3);
    const Eigen::Vector3d e_b = Eigen::Vector3d::Unit((i + 2) % 3);
    products_[i] = DotProduct(AttachedVector::from_inertial(a, e_a, q0),
                              AttachedVector::from_inertial(b, e_b, q0));
  }
}

Eigen::Vector3d RelativeRotationLock::value(const core::Configuration& q) const {
  return {products_[0].value(q), products_[1].value(q), products_[2].value(q)};
}

void RelativeRotationLock::add_jacobian(const core::Configuration& q, Eigen::Ref<Eigen::MatrixXd> B,
                                        int first_row) const {
  for (int i = 0; i < 3; ++i) products_[i].add_jacobian(q, B, first_row + i);
}

void RelativeRotationLock::add_multiplier_tangent(const core::Configuration& q,
                                                  const Eigen::Vector3d& lambda,
                                                  Eigen::Ref<Eigen::MatrixXd> K) const {
  for (int i = 0; i < 3; ++i) products_[i].add_multiplier_tangent(q, lambda(i), K);
}

Eigen::Vector3d RelativeRotationLock::acceleration_terms(const core::Configuration& q,
                                                         const Eigen::VectorXd& velocity) const {
  return {products_[0].acceleration_terms(q, velocity),
          products_[1].acceleration_terms(q, velocity),
          products_[2].acceleration_terms(q, velocity)};
}

}  // namespace spar::joints
