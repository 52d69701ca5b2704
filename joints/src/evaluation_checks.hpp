#pragma once
// Shape checks shared by every joint's evaluation functions: the configuration holds the joint's
// nodes and the caller-sized outputs have the shapes of the Constraint interface. Each function
// raises spar::Error naming `where` on a mismatch, and otherwise zeroes the output so the joint can
// accumulate its building blocks into it. Nothing allocates unless an error is raised.
#include <spar/core/configuration.hpp>
#include <spar/joints/constraint.hpp>

#include <Eigen/Core>

#include <string_view>

namespace spar::joints::detail {

/// Checks q and phi (m entries); zeroes phi. Used for value and time_derivative.
void begin_vector_output(const Constraint& constraint, const core::Configuration& q,
                         Eigen::Ref<Eigen::VectorXd> out, std::string_view where);

/// Checks q and B (m × 6k); zeroes B.
void begin_jacobian(const Constraint& constraint, const core::Configuration& q,
                    Eigen::Ref<Eigen::MatrixXd> B, std::string_view where);

/// Checks q, λ (m entries) and K (6k × 6k); zeroes K.
void begin_multiplier_tangent(const Constraint& constraint, const core::Configuration& q,
                              const Eigen::Ref<const Eigen::VectorXd>& lambda,
                              Eigen::Ref<Eigen::MatrixXd> K, std::string_view where);

/// Checks q, the global velocity (6 per node of q) and c (m entries); zeroes c.
void begin_acceleration_terms(const Constraint& constraint, const core::Configuration& q,
                              const Eigen::VectorXd& velocity, Eigen::Ref<Eigen::VectorXd> c,
                              std::string_view where);

}  // namespace spar::joints::detail
