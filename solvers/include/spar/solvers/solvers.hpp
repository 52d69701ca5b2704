#pragma once
/// \file
/// spar::solvers — the sparse assembly and its work sharing, sparse linear solvers, Newton statics,
/// the generalized-α integrator, modal analysis.

#include <spar/solvers/generalized_alpha.hpp>
#include <spar/solvers/linear_solver.hpp>
#include <spar/solvers/modal_analysis.hpp>
#include <spar/solvers/sparse_assembly.hpp>
#include <spar/solvers/static_solver.hpp>
#include <spar/solvers/time_sampler.hpp>
#include <spar/solvers/work_sharing.hpp>
