#pragma once
/// \file
/// The umbrella header: everything public in spar.

#include <spar/error.hpp>
#include <spar/lie/lie.hpp>
