// Property fuzzing of the spline and model inputs (issue 15): random, mostly plausible inputs with
// random mutations (NaN, infinities, huge and tiny values, wrong sizes, unsorted knots, weights
// <= 0, out-of-range counts) go through the public API, which must end each call in a spar::Error
// or a finite result — never another exception, a crash or a hang — and where it succeeds the
// result must keep its defining property (a refined curve is the same curve; a solved model has a
// finite state and finite energies). Deterministic: SPAR_FUZZ_SEED, SPAR_FUZZ_RUNS (spline runs;
// the model target runs a fiftieth of them) and SPAR_FUZZ_MODEL_RUNS change the seed and the
// lengths (docs/errors.md); the defaults keep the suite at about a second.
#include <spar/core/core.hpp>
#include <spar/iga/iga.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/solvers/static_solver.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace spar;

namespace {

long environment_number(const char* name, long fallback) {
  const char* text = std::getenv(name);
  return text == nullptr ? fallback : std::strtol(text, nullptr, 10);
}

/// Random inputs: a plausible value most of the time, a hostile one otherwise.
class Fuzzer {
public:
  explicit Fuzzer(unsigned seed) : random_(seed) {}

  bool chance(double p) { return std::bernoulli_distribution(p)(random_); }
  int integer(int low, int high) { return std::uniform_int_distribution<int>(low, high)(random_); }
  double uniform(double low, double high) { return std::uniform_real_distribution<double>(low, high)(random_); }

  /// `plausible` most of the time; else NaN, ±inf, 0, a negative, a huge or a tiny value.
  double value(double plausible, double hostility = 0.05) {
    if (!chance(hostility)) return plausible;
    constexpr double hostile[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                                  -std::numeric_limits<double>::infinity(), 0.0, -1.0, 1e300, -1e300, 1e-300,
                                  std::numeric_limits<double>::denorm_min()};
    return hostile[integer(0, static_cast<int>(std::size(hostile)) - 1)];
  }
  /// `plausible` most of the time; else an out-of-range count.
  int count(int plausible, double hostility = 0.05) {
    if (!chance(hostility)) return plausible;
    constexpr int hostile[] = {-1, 0, 1, 100, std::numeric_limits<int>::max(), std::numeric_limits<int>::min()};
    return hostile[integer(0, static_cast<int>(std::size(hostile)) - 1)];
  }
  Eigen::Vector3d vector(double scale, double hostility = 0.05) {
    return {value(uniform(-scale, scale), hostility), value(uniform(-scale, scale), hostility),
            value(uniform(-scale, scale), hostility)};
  }

private:
  std::mt19937 random_;
};

/// A clamped knot vector of degree p, sometimes broken (unsorted, wrong end multiplicity, NaN).
std::vector<double> fuzz_knots(Fuzzer& f, int p) {
  const int interior = f.integer(0, 6);
  std::vector<double> knots(std::max(p, 0) + 1, 0.0);
  for (int i = 0; i < interior; ++i) {
    const double u = f.uniform(0.0, 1.0);
    const int repeat = f.integer(1, std::max(p, 1) + (f.chance(0.05) ? 1 : 0));
    knots.insert(knots.end(), repeat, u);
  }
  knots.insert(knots.end(), std::max(p, 0) + 1, 1.0);
  if (!f.chance(0.1)) std::sort(knots.begin(), knots.end());
  for (double& u : knots) u = f.value(u, 0.02);
  if (f.chance(0.05) && !knots.empty()) knots.pop_back();
  if (f.chance(0.05)) knots.push_back(f.value(1.0, 0.5));
  return knots;
}

/// Runs `call`: a spar::Error is an accepted outcome; any other exception fails the test.
template <class Call>
bool accepted(Call&& call, const std::string& what) {
  try {
    call();
    return true;
  } catch (const Error&) {
    return false;
  } catch (const std::exception& other) {
    FAIL(what << " threw a " << typeid(other).name() << " instead of a spar::Error: " << other.what());
  }
  return false;
}

/// The largest distance between two curves at `samples` parameters over the knot range,
/// relative to the size of the control net; parameters where either curve's evaluation overflows
/// (a spar::Error) are skipped.
double curve_difference(const iga::NurbsCurve<3>& a, const iga::NurbsCurve<3>& b, int samples) {
  const double scale = std::max(1.0, a.control_points().cwiseAbs().maxCoeff());
  double difference = 0.0;
  for (int i = 0; i <= samples; ++i) {
    const double u = a.knots().first() + (a.knots().last() - a.knots().first()) * i / samples;
    try {
      difference = std::max(difference, (a.point(u) - b.point(u)).cwiseAbs().maxCoeff() / scale);
    } catch (const Error&) {
    }
  }
  return difference;
}

}  // namespace

TEST_CASE("fuzzed spline inputs end in a spar::Error or a finite, unchanged curve", "[fuzz]") {
  const auto seed = static_cast<unsigned>(environment_number("SPAR_FUZZ_SEED", 15));
  const long runs = environment_number("SPAR_FUZZ_RUNS", 20000);
  Fuzzer f(seed);
  long curves = 0, refinements = 0;
  for (long run = 0; run < runs; ++run) {
    const int p = f.chance(0.05) ? f.integer(-2, 10) : f.integer(1, 4);
    const std::vector<double> knots = fuzz_knots(f, p);
    INFO("seed " << seed << ", run " << run << ", degree " << p << ", knots " << Catch::Detail::stringify(knots));
    std::optional<iga::KnotVector> U;
    if (!accepted([&] { U.emplace(knots, p); }, "KnotVector")) continue;
    const int n = U->basis_count() + (f.chance(0.03) ? f.integer(-1, 1) : 0);
    Eigen::Matrix3Xd points(3, std::max(n, 0));
    Eigen::VectorXd weights(std::max(n, 0) + (f.chance(0.03) ? 1 : 0));
    for (int i = 0; i < points.cols(); ++i) points.col(i) = f.vector(10.0, 0.01);
    for (int i = 0; i < weights.size(); ++i) weights(i) = f.value(f.uniform(0.2, 5.0), 0.01);
    INFO("control points\n" << points << "\nweights " << weights.transpose());
    std::optional<iga::NurbsCurve<3>> curve;
    if (!accepted([&] { curve.emplace(*U, points, weights); }, "NurbsCurve")) continue;
    ++curves;

    // Evaluation: inside, at the ends, outside the knot range and at NaN.
    for (int k = 0; k < 3; ++k) {
      const double u = f.value(f.uniform(U->first(), U->last()), 0.1);
      const int order = f.chance(0.05) ? f.integer(-1, 12) : f.integer(0, 2);
      iga::NurbsCurve<3>::Derivatives d;
      if (accepted([&] { d = curve->derivatives(u, order); }, "NurbsCurve::derivatives"))
        CHECK(d.allFinite());
    }
    // Insertion, refinement and elevation keep the curve (to round-off of the weights' range
    // 0.2 … 5: 1e-10 of the control net's size).
    const double u = f.value(f.uniform(U->first(), U->last()), 0.05);
    const int times = f.chance(0.05) ? f.count(1, 1.0) : f.integer(1, p + 1);
    std::optional<iga::RefinedCurve<3>> refined;
    INFO("insert " << u << " " << times << " times");
    if (accepted([&] { refined.emplace(iga::insert_knot(*curve, u, times)); }, "insert_knot")) {
      ++refinements;
      CHECK(curve_difference(*curve, refined->curve, 20) <= 1e-10);
    }
    std::vector<double> X(f.integer(0, 4));
    for (double& x : X) x = f.value(f.uniform(U->first(), U->last()), 0.03);
    if (!f.chance(0.05)) std::sort(X.begin(), X.end());
    INFO("refine with " << Catch::Detail::stringify(X));
    if (accepted([&] { refined.emplace(iga::refine_knots(*curve, X)); }, "refine_knots"))
      CHECK(curve_difference(*curve, refined->curve, 20) <= 1e-10);
    const int t = f.chance(0.05) ? f.count(1, 1.0) : f.integer(0, 2);
    INFO("elevate by " << t);
    if (accepted([&] { refined.emplace(iga::elevate_degree(*curve, t)); }, "elevate_degree"))
      CHECK(curve_difference(*curve, refined->curve, 20) <= 1e-10);
    const int per_span = f.chance(0.05) ? f.count(2, 1.0) : f.integer(1, 3);
    INFO("h-refine by " << per_span);
    if (accepted([&] { refined.emplace(iga::h_refine(*curve, per_span)); }, "h_refine"))
      CHECK(curve_difference(*curve, refined->curve, 20) <= 1e-10);
    // Extraction: Σ_a N_a = 1 = Σ_b B_b, so every column of every operator sums to 1.
    std::vector<Eigen::MatrixXd> C;
    if (accepted([&] { C = iga::bezier_extraction(*U); }, "bezier_extraction"))
      for (const Eigen::MatrixXd& Ce : C) CHECK((Ce.colwise().sum().array() - 1.0).abs().maxCoeff() <= 1e-12);
  }
  // The mutations are rare enough that most runs reach the properties.
  CHECK(curves > runs / 2);
  CHECK(refinements > runs / 4);
  // Open-uniform vectors of any requested size, degree and continuity.
  for (long run = 0; run < runs / 10; ++run) {
    const int elements = f.count(f.integer(1, 20)), degree = f.count(f.integer(0, 5)), continuity = f.integer(-2, 5);
    const double first = f.value(0.0), last = f.value(1.0);
    INFO("open_uniform(" << elements << ", " << degree << ", " << continuity << ", " << first << ", " << last << ")");
    accepted([&] { iga::KnotVector::open_uniform(elements, degree, continuity, first, last); }, "open_uniform");
  }
}

TEST_CASE("fuzzed models end in a spar::Error or a finite solved state", "[fuzz]") {
  const auto seed = static_cast<unsigned>(environment_number("SPAR_FUZZ_SEED", 15));
  const long runs = environment_number("SPAR_FUZZ_MODEL_RUNS", environment_number("SPAR_FUZZ_RUNS", 20000) / 50);
  Fuzzer f(seed);
  long solved = 0;
  for (long run = 0; run < runs; ++run) {
    INFO("seed " << seed << ", run " << run);
    core::Model model;
    int tip = -1, body = -1;
    std::ostringstream drawn;  // every random input, for the failure message
    const auto note = [&drawn](const char* name, const auto& value) -> const auto& {
      drawn << name << " = " << value << "\n";
      return value;
    };
    const auto note_vector = [&drawn](const char* name, const Eigen::Vector3d& v) -> Eigen::Vector3d {
      drawn << name << " = " << v.transpose() << "\n";
      return v;
    };
    const bool built = accepted(
        [&] {
          const core::Material material{.young_modulus = note("E", f.value(f.uniform(1e8, 3e11))),
                                        .poisson_ratio = note("nu", f.value(f.uniform(-0.5, 0.49))),
                                        .density = note("rho", f.value(f.uniform(1e3, 1e4)))};
          const double width = note("width", f.value(f.uniform(0.005, 0.05)));
          const double height = note("height", f.value(f.uniform(0.005, 0.05)));
          const core::CrossSection section = core::CrossSection::rectangle(width, height, material.poisson_ratio);
          const Eigen::Vector3d start = note_vector("start", f.vector(1.0, 0.02));
          const Eigen::Vector3d end = note_vector("end", f.vector(2.0));
          const int elements = note("elements", f.count(f.integer(1, 4)));
          const int degree = note("degree", f.count(f.integer(1, 3)));
          const Eigen::Vector3d hint = note_vector("section axis hint", f.vector(1.0, 0.02));
          const int quadrature = note("quadrature points", f.chance(0.1) ? f.count(3, 1.0) : 0);
          const int b = model.add_beam({.centerline = iga::straight_line<3>(start, end, elements, degree),
                                        .stiffness = core::SectionStiffness::from(material, section),
                                        .inertia = core::SectionInertia::from(material, section),
                                        .section_axis_hint = hint,
                                        .quadrature_points = quadrature});
          const core::GeometricallyExactBeam& beam = model.beam(b);
          model.fix(beam.node(0));
          tip = beam.node(beam.control_point_count() - 1);
          model.add_load(core::NodalForce{.node = tip, .force = note_vector("tip force", f.vector(1.0))});
          if (f.chance(0.5)) {
            const bool follower = note("follower moment", f.chance(0.5));
            model.add_load(core::NodalMoment{.node = tip, .moment = note_vector("tip moment", f.vector(0.1)),
                                             .frame = follower ? core::MomentFrame::material : core::MomentFrame::inertial});
          }
          model.set_gravity(note_vector("gravity", f.vector(10.0)));
          if (f.chance(0.3)) {
            const Eigen::Vector3d moments = note_vector(
                "body inertia", {f.value(f.uniform(0.1, 1.0)), f.value(f.uniform(0.1, 1.0)), f.value(f.uniform(0.1, 1.0))});
            body = model.rigid_body(model.add_rigid_body({.center_of_mass = note_vector("body centre", f.vector(1.0)),
                                                          .mass = note("body mass", f.value(f.uniform(0.1, 10.0))),
                                                          .inertia = moments.asDiagonal()}))
                       .node;
            model.fix(body);
          }
        },
        "building the model");
    if (!built) continue;
    const bool dynamic = f.chance(0.5);
    const solvers::DynamicOptions options{.time_step = note("h", f.value(1e-3)),
                                          .spectral_radius = note("rho_inf", f.value(0.9)),
                                          .tolerance = note("tolerance", f.value(1e-12)), .max_cutbacks = 3};
    const Eigen::Vector3d tip_velocity = note_vector("tip velocity", f.vector(0.1));
    const Eigen::Vector3d tip_angular_velocity = note_vector("tip angular velocity", f.vector(0.1));
    const int load_steps = note("load steps", f.chance(0.05) ? f.integer(-1, 0) : f.integer(1, 3));
    const double residual_tolerance = note("static residual tolerance", f.value(1e-9));
    INFO(drawn.str());
    const bool ok = accepted(
        [&] {
          if (dynamic) {
            solvers::GeneralizedAlpha integrator(model, {}, options);
            integrator.set_velocity(tip, tip_velocity, tip_angular_velocity);
            integrator.initialize();
            for (int i = 0; i < 2; ++i) integrator.step();
            const solvers::Energies e = integrator.energies();
            CHECK(std::isfinite(e.total() + e.external_work + e.numerical_dissipation));
            CHECK(integrator.velocity().allFinite());
          } else {
            solvers::solve_static(model, {.load_steps = load_steps, .residual_tolerance = residual_tolerance,
                                          .max_cutbacks = 3});
          }
        },
        dynamic ? "a dynamic run" : "a static solve");
    if (!ok) continue;
    ++solved;
    for (const Eigen::Vector3d& x : model.state().position) CHECK(x.allFinite());
    for (const Eigen::Matrix3d& R : model.state().rotation) CHECK(R.allFinite());
  }
  CHECK(solved > runs / 4);
}
