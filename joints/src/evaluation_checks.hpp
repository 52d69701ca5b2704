#pragma once
// The boundary checks of the Constraint interface's public evaluations (constraint.hpp; called by
// constraint.cpp before a joint's compute_*): the configuration holds the constraint's blocks, the
// time is finite, the caller-sized outputs have the interface's shapes m, m × n and n × n (n = the
// tangent size of blocks() in q: 6 per frame block, its size per vector block), the velocity has
// the configuration's size and finite entries at the constraint's blocks, the multipliers have m
// finite entries. Each raises spar::InputError — spar::Error for a non-finite velocity or
// multiplier, which inside a solver comes from an iteration — whose `where` names the evaluation
// and the constraint's type. Nothing allocates unless an error is raised.
#include <spar/core/configuration.hpp>
#include <spar/joints/constraint.hpp>

#include <Eigen/Core>

#include <string>

namespace spar::joints::detail {

/// The constraint's C++ type, demangled ("spar::joints::SphericalJoint"): the interface has no name
/// of its own, and a user's joint is named this way too.
std::string type_name(const Constraint& constraint);

/// Checks that q holds every block of the constraint and that t is finite; returns n, the tangent
/// size of the blocks in q. `evaluation` names the public function ("jacobian").
Eigen::Index check_configuration(const Constraint& constraint, const core::Configuration& q, double t,
                                 const char* evaluation);

/// Checks that a vector output or input (`field`, e.g. "the output vector") has `expected` entries.
void check_size(const Constraint& constraint, Eigen::Index size, Eigen::Index expected, const char* field,
                const char* evaluation);

/// Checks that the matrix output `field` ("the Jacobian B") is expected_rows × expected_cols.
void check_shape(const Constraint& constraint, const Eigen::Ref<const Eigen::MatrixXd>& matrix,
                 Eigen::Index expected_rows, Eigen::Index expected_cols, const char* field, const char* evaluation);

/// Checks that λ has equation_count() entries, all finite.
void check_multipliers(const Constraint& constraint, const Eigen::Ref<const Eigen::VectorXd>& lambda,
                       const char* evaluation);

/// Checks that the global velocity has q.dof_count() entries, finite at the constraint's blocks
/// (which check_configuration has found in q).
void check_velocity(const Constraint& constraint, const core::Configuration& q, const Eigen::VectorXd& velocity,
                    const char* evaluation);

}  // namespace spar::joints::detail
