#include "evaluation_checks.hpp"

#include <spar/error.hpp>

#include <cxxabi.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>
#include <typeinfo>

namespace spar::joints::detail {

namespace {

/// "joints::Constraint::jacobian (spar::joints::SphericalJoint)": the evaluation and the joint.
std::string where(const Constraint& constraint, const char* evaluation) {
  return std::string("joints::Constraint::") + evaluation + " (" + type_name(constraint) + ")";
}

[[noreturn]] void refuse(const Constraint& constraint, const char* evaluation, const std::string& what,
                         const std::string& fix) {
  throw InputError(what, where(constraint, evaluation), fix);
}

std::string shape(Eigen::Index rows, Eigen::Index cols) { return std::to_string(rows) + "×" + std::to_string(cols); }

}  // namespace

std::string type_name(const Constraint& constraint) {
  const char* mangled = typeid(constraint).name();
  int status = 0;
  const std::unique_ptr<char, void (*)(void*)> demangled(abi::__cxa_demangle(mangled, nullptr, nullptr, &status),
                                                         std::free);
  return status == 0 && demangled ? demangled.get() : mangled;
}

Eigen::Index check_configuration(const Constraint& constraint, const core::Configuration& q, double t,
                                 const char* evaluation) {
  Eigen::Index n = 0;
  for (const int block : constraint.blocks()) {
    if (block < 0 || block >= q.block_count())
      refuse(constraint, evaluation,
             "the configuration has " + std::to_string(q.block_count()) + " blocks but the joint acts on block " +
                 std::to_string(block),
             "evaluate the joint on the configuration of the model it was built for");
    n += q.blocks[block].size;
  }
  if (!std::isfinite(t)) refuse(constraint, evaluation, "the time is " + significant(t), "give a finite time");
  return n;
}

void check_size(const Constraint& constraint, Eigen::Index size, Eigen::Index expected, const char* field,
                const char* evaluation) {
  if (size != expected)
    refuse(constraint, evaluation,
           std::string(field) + " has " + std::to_string(size) + " entries, expected " + std::to_string(expected),
           "size it as the Constraint interface documents (m = equation_count(); the velocity: "
           "q.dof_count())");
}

void check_shape(const Constraint& constraint, const Eigen::Ref<const Eigen::MatrixXd>& matrix,
                 Eigen::Index expected_rows, Eigen::Index expected_cols, const char* field, const char* evaluation) {
  if (matrix.rows() != expected_rows || matrix.cols() != expected_cols)
    refuse(constraint, evaluation,
           std::string(field) + " is " + shape(matrix.rows(), matrix.cols()) + ", expected " +
               shape(expected_rows, expected_cols),
           "size it as the Constraint interface documents (m × n and n × n, n = "
           "core::block_dof_count(q, blocks()))");
}

void check_multipliers(const Constraint& constraint, const Eigen::Ref<const Eigen::VectorXd>& lambda,
                       const char* evaluation) {
  check_size(constraint, lambda.size(), constraint.equation_count(), "the multiplier vector", evaluation);
  for (Eigen::Index i = 0; i < lambda.size(); ++i)
    if (!std::isfinite(lambda(i)))
      throw Error("the multiplier vector has a non-finite entry (" + significant(lambda(i)) + ") at index " +
                      std::to_string(i),
                  where(constraint, evaluation), "give finite multipliers");
}

void check_velocity(const Constraint& constraint, const core::Configuration& q, const Eigen::VectorXd& velocity,
                    const char* evaluation) {
  check_size(constraint, velocity.size(), q.dof_count(), "the velocity vector", evaluation);
  // Only the constraint's own entries: what it reads, at the cost of its size, not the model's.
  for (const int block : constraint.blocks())
    for (int i = q.blocks[block].offset; i < q.blocks[block].offset + q.blocks[block].size; ++i)
      if (!std::isfinite(velocity(i)))
        throw Error("the velocity vector has a non-finite entry (" + significant(velocity(i)) + ") at dof " +
                        std::to_string(i),
                    where(constraint, evaluation), "give a finite velocity");
}

}  // namespace spar::joints::detail
