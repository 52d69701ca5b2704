#pragma once
/// \file
/// spar::solvers — sparse linear solvers and the nonlinear statics solver.

#include <spar/solvers/generalized_alpha.hpp>
#include <spar/solvers/time_sampler.hpp>
#include <spar/solvers/linear_solver.hpp>
#include <spar/solvers/modal_analysis.hpp>
#include <spar/solvers/static_solver.hpp>
