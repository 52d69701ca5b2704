#include "model_case.hpp"

#include <spar/core/core.hpp>
#include <spar/elements/elements.hpp>
#include <spar/iga/iga.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/solvers/static_solver.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>
#include <spar/elements/loads/loads.hpp>
#include <spar/elements/beam/beam.hpp>

#include <cmath>

namespace spar::fuzz {

namespace {

/// The nodes a solve starts from: the beam's tip (for the initial velocity).
struct Built {
  int tip = -1;
};

/// Builds the random model; a spar::Error on the way is an accepted outcome.
Built build(FuzzSource& f, CaseLog& log, core::Model& model) {
  const core::Material material{.young_modulus = log.note("E", f.value(f.uniform(1e8, 3e11))),
                                .poisson_ratio = log.note("nu", f.value(f.uniform(-0.5, 0.49))),
                                .density = log.note("rho", f.value(f.uniform(1e3, 1e4)))};
  const double width = log.note("width", f.value(f.uniform(0.005, 0.05)));
  const double height = log.note("height", f.value(f.uniform(0.005, 0.05)));
  const core::CrossSection section = core::CrossSection::rectangle(width, height, material.poisson_ratio);
  const Eigen::Vector3d start = log.note("start", f.vector(1.0, 0.02));
  // The end as the start plus a span whose x is positive away from hostile values: a source that
  // has run out of decisions (every range at its low end) still draws a beam of nonzero length,
  // not parallel to the section axis hint.
  const Eigen::Vector3d span = log.note(
      "span", Eigen::Vector3d{f.value(f.uniform(0.5, 2.0)), f.value(f.uniform(-2.0, 2.0)), f.value(f.uniform(-2.0, 2.0))});
  const Eigen::Vector3d end = start + span;
  const int elements = log.note("elements", f.count(f.integer(1, 4)));
  const int degree = log.note("degree", f.count(f.integer(1, 3)));
  const Eigen::Vector3d hint = log.note("section axis hint", f.vector(1.0, 0.02));
  const int quadrature = log.note("quadrature points", f.chance(0.1) ? f.count(3, 1.0) : 0);
  const int b = core::add_beam(model, {.centerline = iga::straight_line<3>(start, end, elements, degree),
                                .stiffness = core::SectionStiffness::from(material, section),
                                .inertia = core::SectionInertia::from(material, section),
                                .section_axis_hint = hint,
                                .quadrature_points = quadrature});
  const core::GeometricallyExactBeam& beam = core::beam(model, b);
  model.fix(beam.node(0));
  const Built built{.tip = beam.node(beam.control_point_count() - 1)};
  core::add_load(model, core::NodalForce{.node = built.tip, .force = log.note("tip force", f.vector(1.0))});
  if (f.chance(0.5)) {
    const bool follower = log.note("follower moment", f.chance(0.5));
    core::add_load(model, core::NodalMoment{.node = built.tip, .moment = log.note("tip moment", f.vector(0.1)),
                                     .frame = follower ? core::MomentFrame::material : core::MomentFrame::inertial});
  }
  model.set_gravity(log.note("gravity", f.vector(10.0)));
  if (f.chance(0.3)) {
    const Eigen::Vector3d moments = log.note(
        "body inertia", Eigen::Vector3d{f.value(f.uniform(0.1, 1.0)), f.value(f.uniform(0.1, 1.0)),
                                        f.value(f.uniform(0.1, 1.0))});
    const int body = core::rigid_body(model, core::add_rigid_body(model, {.center_of_mass = log.note("body centre", f.vector(1.0)),
                                                            .mass = log.note("body mass", f.value(f.uniform(0.1, 10.0))),
                                                            .inertia = moments.asDiagonal()}))
                         .node;
    model.fix(body);
  }
  return built;
}

}  // namespace

ModelOutcome model_case(FuzzSource& f, CaseLog& log) {
  ModelOutcome outcome;
  core::Model model;
  Built built;
  outcome.built = accepted([&] { built = build(f, log, model); }, "building the model", log);
  if (!outcome.built) return outcome;

  const bool dynamic = log.note("dynamic", f.chance(0.5));
  const solvers::DynamicOptions options{.time_step = log.note("h", f.value(1e-3)),
                                        .spectral_radius = log.note("rho_inf", f.value(0.9)),
                                        .tolerance = log.note("tolerance", f.value(1e-12)),
                                        .max_cutbacks = 3};
  const Eigen::Vector3d tip_velocity = log.note("tip velocity", f.vector(0.1));
  const Eigen::Vector3d tip_angular_velocity = log.note("tip angular velocity", f.vector(0.1));
  const int load_steps = log.note("load steps", f.chance(0.05) ? f.integer(-1, 0) : f.integer(1, 3));
  const double residual_tolerance = log.note("static residual tolerance", f.value(1e-9));
  outcome.solved = accepted(
      [&] {
        if (dynamic) {
          solvers::GeneralizedAlpha integrator(model, {}, options);
          integrator.set_velocity(built.tip, tip_velocity, tip_angular_velocity);
          integrator.initialize();
          for (int i = 0; i < 2; ++i) integrator.step();
          const solvers::Energies e = integrator.energies();
          log.check(std::isfinite(e.total() + e.external_work + e.numerical_dissipation),
                    "a dynamic run returned non-finite energies");
          log.check(integrator.velocity().allFinite(), "a dynamic run returned a non-finite velocity");
        } else {
          solvers::solve_static(model, {.load_steps = load_steps, .residual_tolerance = residual_tolerance,
                                        .max_cutbacks = 3});
        }
      },
      dynamic ? "a dynamic run" : "a static solve", log);
  if (outcome.solved) {
    for (const Eigen::Vector3d& x : model.state().position)
      log.check(x.allFinite(), "a solve returned a non-finite position");
    for (const Eigen::Matrix3d& R : model.state().rotation)
      log.check(R.allFinite(), "a solve returned a non-finite rotation");
  }
  return outcome;
}

}  // namespace spar::fuzz
