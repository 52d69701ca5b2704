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

#include <cli.hpp>
#include <sliding_mass_run.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>

using namespace spar;

int main(int argc, char** argv) try {
  // 1. Parse options.
  examples::CommandLine cli(argc, argv, "semicircular_beam: a lumped mass sliding on a suspended semicircular beam (000 §6.3)");
  const examples::SlidingMassOptions o = examples::sliding_mass_options(cli, 16, 3.0, examples::memory_use::semicircular_beam);
  const std::string out = cli.output_folder("--out", "results/semicircular_beam", "output folder");
  if (!cli.finish()) return 0;
  examples::time_steps(o.h, o.t_end);  // a span of no steps or of too many is refused

  // 2. The stress-free shape: the lower semicircle, cut at the first mesh's material coordinates.
  const double R = 2.0, length = std::numbers::pi * R;
  iga::CircularArc<2> arc;
  arc.center = Eigen::Vector2d(R, 0.0);
  arc.radius = R;
  arc.start_angle = std::numbers::pi;  // from (0, 0) counter-clockwise through (R, −R) to (2R, 0)
  arc.sweep = std::numbers::pi;
  const auto exact_arc = [&](const std::vector<double>& x) { return core::CableReference::circular_arc(arc, x); };
  // ALE-ANCF: each span the cubic Bézier with unit weights and the arc's end points and unit
  // tangents at a third of its length (000 eq. (10): the ANCF cable with |r_x| = 1 at the nodes).
  const auto hermite_arc = [&](const std::vector<double>& x) {
    const core::CableReference exact = core::CableReference::circular_arc(arc, x);
    std::vector<iga::RationalBezier<2>> pieces;
    for (std::size_t k = 0; k + 1 < x.size(); ++k) {
      const Eigen::Vector4d a = exact.node(static_cast<int>(k)), b = exact.node(static_cast<int>(k) + 1);
      const double third = (x[k + 1] - x[k]) / 3;
      iga::RationalBezier<2> piece{iga::RationalBezier<2>::Points(2, 4), Eigen::Vector4d::Ones()};
      piece.points << a.head<2>(), a.head<2>() + third * a.tail<2>().normalized(),
          b.head<2>() - third * b.tail<2>().normalized(), b.head<2>();
      pieces.push_back(piece);
    }
    return core::CableReference(pieces, x);
  };

  // 3. The beam, the sliding mass and the supports.
  const double radius = 0.02, young = 200e6, density = 7200;
  const double area = std::numbers::pi * radius * radius, inertia = area * radius * radius / 4;
  core::Model model;
  const bool rational = o.kind == "ale-rancf";
  core::SlidingCable<2> cable(model, {.length = length, .elements = o.elements,
                                      .section = {.axial_stiffness = young * area,
                                                  .bending_stiffness = young * inertia,
                                                  .mass_per_length = density * area},
                                      .slider_position = length / 16, .slider_mass = 0.8,
                                      .rational = rational,
                                      .shape = rational ? std::function<core::CableReference(const std::vector<double>&)>(exact_arc)
                                                        : std::function<core::CableReference(const std::vector<double>&)>(hermite_arc)});
  model.set_gravity(Eigen::Vector3d(0.0, -9.81, 0.0));
  examples::pin_both_ends(cable, model);

  // 4. The integrator, from rest.
  solvers::GeneralizedAlpha integrator(model, {}, {.time_step = o.h, .spectral_radius = o.rho_infinity,
                                                   .iteration_matrix = solvers::iteration_matrix_from_string(o.strategy),
                                                   .tolerance = 1e-16, .residual_tolerance = 1e-9});
  integrator.initialize();

  // 5. Integrate, control the lengths, record, report (examples/common/sliding_mass_run.hpp).
  examples::run_sliding_mass(cable, model, integrator,
                             {.example = "semicircular_beam", .out = out, .options = o});
  return 0;
} catch (const std::exception& error) {
  std::fprintf(stderr, "%s\n", error.what());
  return 1;
}
