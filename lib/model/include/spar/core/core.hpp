#pragma once
/// \file
/// spar::core — the model: the configuration space (frame and vector blocks), the Element
/// interface, the Model container, sections and materials, the frames' inertia.

#include <spar/core/check_element.hpp>
#include <spar/core/configuration.hpp>
#include <spar/core/converged_chart.hpp>
#include <spar/core/cross_section.hpp>
#include <spar/core/curve.hpp>
#include <spar/core/derivative_check.hpp>
#include <spar/core/dual.hpp>
#include <spar/core/element.hpp>
#include <spar/core/frame_inertia.hpp>
#include <spar/core/linear_point.hpp>
#include <spar/core/material_point.hpp>
#include <spar/core/model.hpp>
#include <spar/core/section_integrals.hpp>
