#include "evaluation_checks.hpp"

#include <spar/error.hpp>

#include <string>

namespace spar::joints::detail {

namespace {

std::string shape(Eigen::Index rows, Eigen::Index cols) {
  return std::to_string(rows) + "×" + std::to_string(cols);
}

void check_blocks(const Constraint& constraint, const core::Configuration& q,
                  std::string_view where) {
  for (const int block : constraint.blocks())
    if (block >= q.block_count())
      throw Error("the configuration has " + std::to_string(q.block_count()) +
                      " blocks but the joint acts on block " + std::to_string(block),
                  where, "evaluate the joint on the configuration of the model it was built for");
}

void check_size(Eigen::Index size, Eigen::Index expected, std::string_view name,
                std::string_view where) {
  if (size != expected)
    throw Error(std::string(name) + " has " + std::to_string(size) + " entries, expected " +
                    std::to_string(expected),
                where, "size it as the Constraint interface documents");
}

void check_shape(Eigen::Index rows, Eigen::Index cols, Eigen::Index expected_rows,
                 Eigen::Index expected_cols, std::string_view name, std::string_view where) {
  if (rows != expected_rows || cols != expected_cols)
    throw Error(std::string(name) + " is " + shape(rows, cols) + ", expected " +
                    shape(expected_rows, expected_cols),
                where, "size it as the Constraint interface documents (m, m×n, n×n)");
}

Eigen::Index columns(const Constraint& constraint, const core::Configuration& q) {
  return core::block_dof_count(q, constraint.blocks());
}

}  // namespace

void begin_vector_output(const Constraint& constraint, const core::Configuration& q,
                         Eigen::Ref<Eigen::VectorXd> out, std::string_view where) {
  check_blocks(constraint, q, where);
  check_size(out.size(), constraint.equation_count(), "the output vector", where);
  out.setZero();
}

void begin_jacobian(const Constraint& constraint, const core::Configuration& q,
                    Eigen::Ref<Eigen::MatrixXd> B, std::string_view where) {
  check_blocks(constraint, q, where);
  check_shape(B.rows(), B.cols(), constraint.equation_count(), columns(constraint, q),
              "the Jacobian B", where);
  B.setZero();
}

void begin_multiplier_tangent(const Constraint& constraint, const core::Configuration& q,
                              const Eigen::Ref<const Eigen::VectorXd>& lambda,
                              Eigen::Ref<Eigen::MatrixXd> K, std::string_view where) {
  check_blocks(constraint, q, where);
  check_size(lambda.size(), constraint.equation_count(), "the multiplier vector", where);
  check_shape(K.rows(), K.cols(), columns(constraint, q), columns(constraint, q),
              "the multiplier tangent K", where);
  K.setZero();
}

void begin_acceleration_terms(const Constraint& constraint, const core::Configuration& q,
                              const Eigen::VectorXd& velocity, Eigen::Ref<Eigen::VectorXd> c,
                              std::string_view where) {
  check_blocks(constraint, q, where);
  check_size(velocity.size(), q.dof_count(), "the velocity vector", where);
  check_size(c.size(), constraint.equation_count(), "the output vector", where);
  c.setZero();
}

}  // namespace spar::joints::detail
