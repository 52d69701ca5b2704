// suspended_beam — a beam pinned at both ends with a lumped mass sliding along it without
// friction under gravity, modelled with a sliding node on ALE-RANCF or ALE-ANCF elements and
// element length control (paper 000, Ding & Ouyang 2022, §6.2, Figures 13–14).
//
// Sample runs:
//   suspended_beam                                   (ALE-RANCF, 3 elements, h = 1e-3 s, 2 s)
//   suspended_beam --element ale-ancf
//   suspended_beam --elements 6 --h 5e-4 --out results/suspended_beam_6
//   suspended_beam --slopes discontinuous             (a hinge at the mass, 000 eq. (40))
//
// Description:
//   L = 1 m, circular section r = 0.01 m, ρ = 7200 kg/m³, E = 20 MPa, no damping (000 §6.1–6.2);
//   both ends pinned (positions fixed, slopes free); a 5 kg mass starts at rest 0.1 m from the
//   left end and slides towards the sag's bottom and beyond. The beam is straight at t = 0, so it
//   first falls and the mass slides as it sags. The sliding node carries the mass; the two
//   elements next to it are ALE, the others fixed length; when one of them passes 1.5 L_std a
//   node is inserted (exact) and the node beyond the other one deleted (merge: least-squares
//   weights for ALE-RANCF, unit weights for ALE-ANCF). After each event the integrator restarts
//   its accelerations. Written at every step: the energies, the deformed beam length, the slider's
//   material coordinate and position, and the centreline; at the end, the event log. ρ∞ = 1 by
//   default, so between events the total energy is conserved to the integrator's accuracy and the
//   jumps at the events are the merges'. The last line of stdout is a JSON summary.
#include <spar/spar.hpp>

#include <cli.hpp>
#include <sliding_mass_run.hpp>

#include <cstdio>
#include <numbers>

using namespace spar;

int main(int argc, char** argv) try {
  // 1. Parse options.
  examples::CommandLine cli(argc, argv, "suspended_beam: a lumped mass sliding on a pinned-pinned beam (000 §6.2)");
  const examples::SlidingMassOptions o = examples::sliding_mass_options(cli, 3, 2.0, examples::memory_use::suspended_beam);
  const std::string slopes = cli.text("--slopes", "continuous",
                                      "at the sliding node (000 eq. (40)): continuous (one slope) or discontinuous "
                                      "(a slope per side, equal magnitudes: a hinge)",
                                      {"continuous", "discontinuous"});
  const std::string out = cli.output_folder("--out", "results/suspended_beam", "output folder");
  if (!cli.finish()) return 0;
  examples::time_steps(o.h, o.t_end);  // a span of no steps or of too many is refused

  // 2. The beam, the sliding mass and the supports.
  const double radius = 0.01, young = 20e6, density = 7200;
  const double area = std::numbers::pi * radius * radius, inertia = area * radius * radius / 4;
  core::Model model;
  core::SlidingCable<2> cable(model, {.length = 1.0, .elements = o.elements,
                                      .section = {.axial_stiffness = young * area,
                                                  .bending_stiffness = young * inertia,
                                                  .mass_per_length = density * area},
                                      .slider_position = 0.1, .slider_mass = 5.0,
                                      .rational = o.kind == "ale-rancf",
                                      .two_sided_slider = slopes == "discontinuous"});
  model.set_gravity(Eigen::Vector3d(0.0, -9.81, 0.0));
  examples::pin_both_ends(cable, model);
  // A slope per side of the sliding node, of equal magnitudes (000 eqs. (39)–(40)).
  solvers::ConstraintList constraints;
  if (slopes == "discontinuous")
    constraints.push_back(std::make_unique<joints::SlidingNodeSlopes>(cable.chain()[cable.slider()],
                                                                      cable.right_slider_node(), 2,
                                                                      joints::SlopeCondition::discontinuous,
                                                                      model.state()));

  // 3. The integrator, from rest.
  solvers::GeneralizedAlpha integrator(model, std::move(constraints), {.time_step = o.h, .spectral_radius = o.rho_infinity,
                                                   .iteration_matrix = solvers::iteration_matrix_from_string(o.strategy),
                                                   .tolerance = 1e-16, .residual_tolerance = 1e-9});
  integrator.initialize();

  // 4. Integrate, control the lengths, record, report (examples/common/sliding_mass_run.hpp).
  examples::run_sliding_mass(cable, model, integrator,
                             {.example = "suspended_beam", .out = out, .options = o});
  return 0;
} catch (const std::exception& error) {
  std::fprintf(stderr, "%s\n", error.what());
  return 1;
}
