// semicircular_beam — a suspended semicircular beam, pinned at both ends, with a lumped mass
// sliding along it without friction under gravity, on exact-arc ALE-RANCF elements with element
// length control (paper 000, Ding & Ouyang 2022, §6.3, eq. (43), Figures 15–16).
//
// Sample runs:
//   semicircular_beam                                 (ALE-RANCF, 16 elements, h = 1e-3 s, 3 s)
//   semicircular_beam --elements 32 --out results/semicircular_beam_32
//   semicircular_beam --element ale-ancf              (unit weights: a cubic Hermite near-circle)
//
// Description:
//   A semicircle of radius R = 2 m hangs below its two pinned ends (0, 0) and (2R, 0): the lower
//   half of the circle about (R, 0), so the beam is a U in the X–Y plane with gravity along −Y.
//   Circular section r = 0.02 m, ρ = 7200 kg/m³, E = 200 MPa, no damping; a 0.8 kg mass starts
//   at rest at 1/16 of the length from the left end. Each element is the exact circular arc of
//   000 eq. (43) (iga: A7.1's rational quadratic, raised to a cubic), and the semicircle is the
//   beam's stress-free shape: 000 eq. (19) has no reference strains, under which the arc would
//   start prestressed by κ = 1/R and an axial strain of up to −1.6 %; spar subtracts the strains
//   of the initial shape at every material point (core::CableReference, docs/rancf.md "Curved
//   cables"). With --element ale-ancf the elements have unit weights and the stress-free shape is
//   the cubic Hermite interpolant of the arc with unit nodal slopes (not exactly circular).
//   The sliding node carries the mass; the two elements next to it are ALE, the others fixed
//   length; length control as in suspended_beam (000 §5). ρ∞ = 1 by default. The last line of
//   stdout is a JSON summary.
#include <spar/spar.hpp>

#include <memory_use.hpp>
#include <sliding_mass.hpp>

#include <numbers>

using namespace spar;

int main(int argc, char** argv) try {
  // 1. Parse options.
  study::CommandLine cli(argc, argv, "semicircular_beam: a lumped mass sliding on a suspended semicircular beam (000 §6.3)");
  const examples::SlidingMassOptions o = examples::sliding_mass_options(
      cli, {.example = "semicircular_beam", .elements = 16, .t_end = 3.0, .memory = examples::memory_use::semicircular_beam});
  if (!cli.finish()) return 0;

  // 2. The stress-free shape: the lower semicircle, cut at the first mesh's material coordinates.
  const double R = 2.0, length = std::numbers::pi * R;
  //    From (0, 0) counter-clockwise through (R, −R) to (2R, 0).
  const iga::CircularArc<2> arc{.center = Eigen::Vector2d(R, 0.0), .radius = R, .start_angle = std::numbers::pi,
                                .sweep = std::numbers::pi};
  //    ALE-ANCF: each span the cubic Bézier with unit weights and the arc's end points and unit
  //    tangents at a third of its length (000 eq. (10): the ANCF cable with |r_x| = 1 at the nodes).
  const bool rational = o.kind == "ale-rancf";
  const auto shape = [&](const std::vector<double>& x) {
    const core::CableReference exact = core::CableReference::circular_arc(arc, x);
    return rational ? exact : exact.polynomial_interpolant();
  };

  // 3. The beam and the sliding mass.
  core::Model model;
  core::SlidingCable<2> cable(model, {.length = length, .elements = o.elements,
                                      .section = core::RancfSection::circular(0.02, 200e6, 7200),
                                      .slider_position = length / 16, .slider_mass = 0.8,
                                      .rational = rational, .shape = shape});

  // 4. Integrate from rest with both ends pinned (positions fixed, slopes free), control the
  //    lengths, record, report (examples/common/sliding_mass.hpp).
  examples::run_sliding_mass(model, cable, {},
                             {.options = o, .supports = {.left = 2, .right = 2}});
  return 0;
} catch (const std::exception& error) {
  return study::exit_failure(error);
}
