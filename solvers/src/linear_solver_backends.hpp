#pragma once
// The backend factories behind make_linear_solver, one per source file.

#include <spar/solvers/linear_solver.hpp>

#include <memory>

namespace spar::solvers::detail {

/// A new KLU solver (klu_solver.cpp).
std::unique_ptr<LinearSolver> make_klu_solver();
/// A new UMFPACK solver (umfpack_solver.cpp).
std::unique_ptr<LinearSolver> make_umfpack_solver();
/// A new Eigen SparseLU solver (eigen_lu_solver.cpp).
std::unique_ptr<LinearSolver> make_eigen_lu_solver();

}  // namespace spar::solvers::detail
