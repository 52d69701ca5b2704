#pragma once
/// \file
/// The umbrella header: everything public in spar.

#include <spar/core/core.hpp>
#include <spar/elements/elements.hpp>
#include <spar/error.hpp>
#include <spar/iga/iga.hpp>
#include <spar/joints/joints.hpp>
#include <spar/lie/lie.hpp>
#include <spar/output/output.hpp>
#include <spar/solvers/solvers.hpp>
#include <spar/study/study.hpp>
