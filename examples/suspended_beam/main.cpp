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

#include <memory_use.hpp>
#include <sliding_mass.hpp>

using namespace spar;

int main(int argc, char** argv) try {
  // 1. Parse options.
  study::CommandLine cli(argc, argv, "suspended_beam: a lumped mass sliding on a pinned-pinned beam (000 §6.2)");
  const examples::SlidingMassOptions o = examples::sliding_mass_options(
      cli, {.example = "suspended_beam", .elements = 3, .t_end = 2.0, .memory = examples::memory_use::suspended_beam});
  const std::string slopes = cli.text("--slopes", "continuous",
                                      "at the sliding node (000 eq. (40)): continuous (one slope) or discontinuous "
                                      "(a slope per side, equal magnitudes: a hinge)",
                                      {"continuous", "discontinuous"});
  if (!cli.finish()) return 0;

  // 2. The beam and the sliding mass; with --slopes discontinuous a slope per side of the sliding
  //    node, of equal magnitudes (000 eqs. (39)–(40)).
  core::Model model;
  core::SlidingCable<2> cable(model, {.length = 1.0, .elements = o.elements,
                                      .section = core::RancfSection::circular(0.01, 20e6, 7200),
                                      .slider_position = 0.1, .slider_mass = 5.0,
                                      .rational = o.kind == "ale-rancf",
                                      .two_sided_slider = slopes == "discontinuous"});
  solvers::ConstraintList constraints;
  if (slopes == "discontinuous")
    constraints.push_back(std::make_unique<joints::SlidingNodeSlopes>(cable.chain()[cable.slider()],
                                                                      cable.right_slider_node(), 2,
                                                                      joints::SlopeCondition::discontinuous,
                                                                      model.state()));

  // 3. Integrate from rest with both ends pinned (positions fixed, slopes free), control the
  //    lengths, record, report (examples/common/sliding_mass.hpp).
  examples::run_sliding_mass(model, cable, std::move(constraints),
                             {.options = o, .supports = {.left = 2, .right = 2}});
  return 0;
} catch (const std::exception& error) {
  return study::exit_failure(error);
}
