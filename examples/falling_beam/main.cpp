// falling_beam — a cantilever falling under gravity with a lumped mass sliding along it without
// friction until it leaves the free end, modelled with a sliding node on ALE-RANCF or ALE-ANCF
// elements and element length control (paper 000, Ding & Ouyang 2022, §6.1, Figures 8–12,
// Tables 1–2).
//
// Sample runs:
//   falling_beam                                     (ALE-RANCF, 20 elements, h = 1e-3 s, 1 s)
//   falling_beam --element ale-ancf --elements 5
//   falling_beam --elements 40 --h 5e-4 --out results/falling_beam_40
//
// Description:
//   L = 1 m, circular section r = 0.01 m, ρ = 7200 kg/m³, E = 20 MPa, no damping; left end
//   clamped, right end free; a 0.8 kg mass starts 0.1 m from the left end, sliding at 0.4 m/s
//   along the beam, which is straight and at rest at t = 0. Gravity (0, −9.81) m/s². The sliding
//   node carries the mass; the two elements next to it are ALE, the others fixed length; when one
//   of them passes 1.5 L_std a node is inserted (exact) and the node beyond the other one deleted
//   (merge: least-squares weights for ALE-RANCF, unit weights for ALE-ANCF). When the element
//   between the mass and the free end is shorter than 0.05 L_std (or than four steps of its travel)
//   the mass leaves the beam and flies
//   on as a free particle (core::SlidingCable::release). After each event the integrator restarts
//   its accelerations. Written every step: the energies, the right end, the slider (or the free
//   mass), the centreline; at the end, the event log. The last line of stdout is a JSON summary.
#include <spar/spar.hpp>

#include <memory_use.hpp>
#include <sliding_mass.hpp>

using namespace spar;

int main(int argc, char** argv) try {
  // 1. Parse options.
  study::CommandLine cli(argc, argv, "falling_beam: a lumped mass sliding off a falling cantilever (000 §6.1)");
  const examples::SlidingMassOptions o = examples::sliding_mass_options(
      cli, {.example = "falling_beam", .elements = 20, .t_end = 1.0, .memory = examples::memory_use::falling_beam});
  if (!cli.finish()) return 0;

  // 2. The beam and the sliding mass (with the block it flies off in).
  core::Model model;
  core::SlidingCable<2> cable(model, {.length = 1.0, .elements = o.elements,
                                      .section = core::RancfSection::circular(0.01, 20e6, 7200),
                                      .slider_position = 0.1, .slider_mass = 0.8,
                                      .rational = o.kind == "ale-rancf", .detachable = true});

  // 3. Integrate with the left end clamped (position and slope), from the mass sliding at 0.4 m/s
  //    on the beam at rest; control the lengths, release the mass, record, report
  //    (examples/common/sliding_mass.hpp).
  examples::run_sliding_mass(model, cable, {}, {.options = o, .supports = {.left = 4}, .slider_speed = 0.4});
  return 0;
} catch (const std::exception& error) {
  return study::exit_failure(error);
}
