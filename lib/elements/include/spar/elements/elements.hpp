#pragma once
/// \file
/// The element families: the geometrically exact beam on NURBS, 3D ANCF beams, RANCF and
/// ALE-RANCF cables, rigid bodies and point masses, loads — each with its builders.

#include <spar/elements/ancf/ancf_beam.hpp>
#include <spar/elements/ancf/ancf_beam_element.hpp>
#include <spar/elements/ancf/ancf_points.hpp>
#include <spar/elements/beam/beam.hpp>
#include <spar/elements/beam/beam_centerline.hpp>
#include <spar/elements/beam/beam_element.hpp>
#include <spar/elements/beam/beam_inertia.hpp>
#include <spar/elements/beam/centerline_sampler.hpp>
#include <spar/elements/beam/distributed_moment.hpp>
#include <spar/elements/beam/geometrically_exact_beam_element.hpp>
#include <spar/elements/beam/section_resultants.hpp>
#include <spar/elements/cable/cable_centerline.hpp>
#include <spar/elements/cable/cable.hpp>
#include <spar/elements/cable/cable_reference.hpp>
#include <spar/elements/cable/length_control_log.hpp>
#include <spar/elements/cable/rancf_cable_element.hpp>
#include <spar/elements/cable/rancf_merging.hpp>
#include <spar/elements/cable/rancf_segmentation.hpp>
#include <spar/elements/cable/sliding_cable.hpp>
#include <spar/elements/loads/load_elements.hpp>
#include <spar/elements/loads/loads.hpp>
#include <spar/elements/loads/vector_load_element.hpp>
#include <spar/elements/rigid_body/point_mass_element.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>
#include <spar/elements/rigid_body/rigid_body_element.hpp>
#include <spar/elements/rigid_body/rigid_rail.hpp>
