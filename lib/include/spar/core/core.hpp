#pragma once
/// \file
/// spar::core — the model: configuration space, sections, the beam element, loads, assembly and
/// results files.

#include <spar/core/ancf_beam.hpp>
#include <spar/core/beam.hpp>
#include <spar/core/beam_element.hpp>
#include <spar/core/centerline_sampler.hpp>
#include <spar/core/configuration.hpp>
#include <spar/core/converged_chart.hpp>
#include <spar/core/cross_section.hpp>
#include <spar/core/distributed_moment.hpp>
#include <spar/core/element.hpp>
#include <spar/core/elements/ancf_beam_element.hpp>
#include <spar/core/elements/geometrically_exact_beam_element.hpp>
#include <spar/core/elements/load_elements.hpp>
#include <spar/core/elements/point_mass_element.hpp>
#include <spar/core/elements/rancf_cable_element.hpp>
#include <spar/core/elements/rancf_merging.hpp>
#include <spar/core/elements/rancf_segmentation.hpp>
#include <spar/core/elements/rigid_body_element.hpp>
#include <spar/core/elements/vector_load_element.hpp>
#include <spar/core/hdf5_file.hpp>
#include <spar/core/inertia.hpp>
#include <spar/core/loads.hpp>
#include <spar/core/model.hpp>
#include <spar/core/progress_bar.hpp>
#include <spar/core/results_writer.hpp>
#include <spar/core/section_integrals.hpp>
#include <spar/core/cable_reference.hpp>
#include <spar/core/sliding_cable.hpp>
#include <spar/core/sparse_assembly.hpp>
#include <spar/core/work_sharing.hpp>
