// Modal analysis (solvers::modal_analysis, docs/dynamics.md D11) against closed-form frequencies:
// a pinned–pinned beam held by two spherical joints (the null-space form of the constraints)
// against the Timoshenko beam's exact frequencies, and a clamped cantilever against
// Euler–Bernoulli's.
#include <spar/iga/straight_line.hpp>
#include <spar/joints/spherical_joint.hpp>
#include <spar/solvers/modal_analysis.hpp>
#include <spar/elements/beam/beam.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace spar;

namespace {

const core::Material steel{.young_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850};
constexpr double length = 1.0;

/// A steel beam along X from the origin, `elements` cubic elements, section width × height.
int add_beam(core::Model& model, int elements, double width, double height) {
  const core::CrossSection section = core::CrossSection::rectangle(width, height, steel.poisson_ratio);
  return core::add_beam(model, {.centerline = iga::straight_line<3>(Eigen::Vector3d::Zero(), Eigen::Vector3d(length, 0, 0),
                                                             elements, 3),
                         .stiffness = core::SectionStiffness::from(steel, section),
                         .inertia = core::SectionInertia::from(steel, section)});
}

/// The k-th bending frequency of a simply supported Timoshenko beam with rotary inertia: with
/// α = kπ/L, w = W sin αx, ψ = Ψ cos αx in κGA(w″ − ψ′) = ρA ẅ, EIψ″ + κGA(w′ − ψ) = ρI ψ̈,
/// ρAρI s² − (ρI κGA α² + ρA EI α² + ρA κGA) s + κGA EI α⁴ = 0 for s = ω²: the lower root.
double timoshenko_pinned(int k, double EI, double kGA, double rhoA, double rhoI) {
  const double alpha = k * std::numbers::pi / length;
  const double a = rhoA * rhoI, b = rhoI * kGA * alpha * alpha + rhoA * EI * alpha * alpha + rhoA * kGA,
               c = kGA * EI * std::pow(alpha, 4);
  return std::sqrt(2 * c / (b + std::sqrt(b * b - 4 * a * c)));  // the lower root, without cancellation
}

/// The computed ω nearest to `omega`, relative difference.
double nearest(const solvers::Modes& modes, double omega) {
  double best = INFINITY;
  for (int i = 0; i < modes.angular_frequencies.size(); ++i)
    best = std::min(best, std::abs(modes.angular_frequencies(i) - omega) / omega);
  return best;
}

}  // namespace

TEST_CASE("modal analysis: a pinned-pinned beam held by joints has the Timoshenko frequencies", "[dynamics][validation]") {
  // 20 × 10 mm, L/h = 100 in the weak plane: the Timoshenko terms are 1e-4 of ω₁ there, well above
  // the 1e-6 asked. 64 cubic elements: the discretization error of mode 3 is ~(3π/64)⁶ ≈ 1e-8.
  core::Model model;
  const int b = add_beam(model, 64, 0.02, 0.01);
  const core::GeometricallyExactBeam& beam = core::beam(model, b);
  const core::Configuration& q = model.state();
  std::vector<std::unique_ptr<joints::Constraint>> owned;
  owned.push_back(std::make_unique<joints::SphericalJoint>(joints::Attachment{beam.node(0)}, joints::Attachment{-1},
                                                           q));
  owned.push_back(std::make_unique<joints::SphericalJoint>(
      joints::Attachment{beam.node(beam.control_point_count() - 1)}, joints::Attachment{-1, Eigen::Vector3d(length, 0, 0)},
      q));
  const solvers::Modes modes = solvers::modal_analysis(model, {owned[0].get(), owned[1].get()}, {.modes = 12});
  // The rigid turn about the beam's axis (both pins on it) is free: ω = 0, up to the dense
  // eigensolver's round-off on ω², ε λ_max with λ_max ≈ 4e11 s⁻² (the element-scale shear
  // modes): √(ε λ_max) ≈ 6e-3 rad/s (measured 4.9e-3), against ω₁ = 147 rad/s. Bound 0.05.
  CHECK(std::abs(modes.angular_frequencies(0)) <= 0.05);
  const core::SectionStiffness& C = beam.stiffness();
  const core::SectionInertia& J = beam.inertia();
  // Bending about section axis 2 (deflection along 3, shear τ₃GA, rotary ρI₂) and about axis 3.
  for (int k = 1; k <= 3; ++k) {
    const double weak = timoshenko_pinned(k, C.bending_2, C.shear_3, J.mass_per_length, J.rotary(1, 1));
    const double strong = timoshenko_pinned(k, C.bending_3, C.shear_2, J.mass_per_length, J.rotary(2, 2));
    INFO("mode " << k << ": " << weak << " and " << strong << " rad/s; nearest computed off by "
                 << nearest(modes, weak) << ", " << nearest(modes, strong));
    CHECK(nearest(modes, weak) <= 1e-6);
    CHECK(nearest(modes, strong) <= 1e-6);
  }
  // Mass-normalized shapes that satisfy the joints.
  for (int i = 0; i < modes.shapes.cols(); ++i) {
    CHECK(modes.shapes.col(i).segment<3>(q.blocks[beam.node(0)].offset).norm() <= 1e-12);
  }
}

TEST_CASE("modal analysis: a slender clamped cantilever has Euler-Bernoulli's frequencies", "[dynamics][validation]") {
  // 5 × 5 mm, L/h = 200. The beam is a Timoshenko beam with rotary inertia, whose frequencies lie
  // below Euler–Bernoulli's ω_k = (β_k L)² √(EI/(ρA L⁴)) by a relative amount of the order of
  // (β_k r)²(1 + E/κG), r = h/√12 the radius of gyration: 3.0e-5, 1.9e-4, 5.2e-4 for k = 1, 2, 3
  // (measured: 2.0e-5, 1.4e-4, 3.3e-4, i.e. 0.63–0.74 of it; for a pinned–pinned beam the factor
  // is ½). So: below Euler–Bernoulli, by less than that estimate.
  core::Model model;
  const int b = add_beam(model, 64, 0.005, 0.005);
  const core::GeometricallyExactBeam& beam = core::beam(model, b);
  model.fix(beam.node(0));
  const solvers::Modes modes = solvers::modal_analysis(model, {}, {.modes = 8});
  const double EI = beam.stiffness().bending_2, rhoA = beam.inertia().mass_per_length;
  const double kGA = beam.stiffness().shear_3, EA = beam.stiffness().axial;
  const double r2 = EI / EA;  // r², the squared radius of gyration
  const double beta_l[] = {1.8751040687119611, 4.6940911329741746, 7.8547574382376126};
  for (int k = 0; k < 3; ++k) {
    const double omega_eb = beta_l[k] * beta_l[k] * std::sqrt(EI / (rhoA * std::pow(length, 4)));
    double omega = 0.0;  // the computed ω nearest to Euler–Bernoulli's
    for (int i = 0; i < modes.angular_frequencies.size(); ++i)
      if (std::abs(modes.angular_frequencies(i) - omega_eb) < std::abs(omega - omega_eb)) omega = modes.angular_frequencies(i);
    const double shift = (omega_eb - omega) / omega_eb;
    const double estimate = beta_l[k] * beta_l[k] / (length * length) * r2 * (1 + EA / kGA);
    INFO("mode " << k + 1 << ": Euler-Bernoulli " << omega_eb << " rad/s, computed " << omega << ", below by " << shift
                 << " (estimate " << estimate << ")");
    CHECK(shift > 0.0);
    CHECK(shift <= estimate);
  }
}
