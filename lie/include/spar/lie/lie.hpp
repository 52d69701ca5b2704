#pragma once
/// \file
/// spar::lie — the SO(3) toolkit: hat/vee, exp/log, quaternions, the tangent operator T, its
/// inverse and their derivatives. Conventions and equations: docs/conventions.md.

#include <spar/lie/coefficients.hpp>
#include <spar/lie/exp.hpp>
#include <spar/lie/hat.hpp>
#include <spar/lie/log.hpp>
#include <spar/lie/quaternion.hpp>
#include <spar/lie/tangent.hpp>
