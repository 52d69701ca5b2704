#pragma once
/// \file
/// What a driver's options may ask of a run, checked before it starts (docs/errors.md, "Command
/// line"): the ranges of numeric options, a time span of too many steps, a time the run never
/// reaches, a beam that is no slender beam, more elements than the memory holds. Each check throws
/// a spar::Error naming the options, the value and what to give instead.

#include <spar/error.hpp>

#include <cmath>
#include <limits>
#include <string>

namespace spar::study {

/// The values a numeric option accepts: an interval with open or closed ends. The default accepts
/// every finite number.
struct Range {
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();
  bool low_open = false;
  bool high_open = false;

  /// (0, high], or (0, inf) without a bound: step sizes, lengths, tolerances.
  static Range positive(double high = std::numeric_limits<double>::infinity()) {
    return {0.0, high, true, std::isinf(high)};
  }
  /// [low, high].
  static Range between(double low, double high) { return {low, high, false, false}; }

  bool contains(double value) const {
    return (low_open ? value > low : value >= low) && (high_open ? value < high : value <= high);
  }
  /// The interval as a message shows it, e.g. "(0, 1]" or "[-0.999, 0.5)".
  std::string text() const;
};

/// The Newton tolerances a driver accepts (|[dq, h²β dλ]|², |Φ|_∞ in m): a tolerance above 10⁻²
/// accepts increments of decimetres and makes the result meaningless (1e300 gave an 8660 %
/// deformation).
inline constexpr Range newton_tolerances{0.0, 1e-2, true, false};

/// The most steps a time span may take (t_end/h): far above the examples' runs (400 to 3·10⁴ steps
/// by default, 10⁵ RK4 steps for heavy_top's reference), low enough that a mistyped step ends at
/// once instead of running for days.
inline constexpr double max_time_steps = 1e7;

/// The number of steps of size h that reach t_end, or a spar::Error naming the options when h and
/// t_end are not positive finite times with h ≤ t_end and t_end/h ≤ max_time_steps.
long time_steps(double h, double t_end, const std::string& h_name = "--h", const std::string& t_end_name = "--t-end");

/// A time the run must reach to mean anything (an output interval, a deployment time): a
/// spar::Error naming both options when `time` = `name` is later than the end time `t_end`
/// (four_bar --output-interval 1e300 wrote the state at t = 0 only; truss_deployment --t-f 1e300
/// deployed nothing).
void require_within_run(double time, const std::string& name, const std::string& what, double t_end,
                        const std::string& t_end_name = "--t-end");

/// The slenderness (length over the section's side in the plane of bending) a beam accepts,
/// [3, 10⁴]:
/// - at least 3: a member shorter than 3 times its section's depth is a deep beam, not a beam
///   (EN 1992-1-1 §5.3.1(3)), whose sections do not stay plane; modal_beam --length 1e-6 --width 1
///   --height 1 (10⁻⁶) compared a cube's "modes" with Timoshenko's beam;
/// - at most 10⁴: the tangent's axial stiffness EA/L_e over its bending stiffness EI/L³ grows as
///   12 n (L/t)², 10¹⁰ at L/t = 10⁴ with 16 elements, and as digits are lost the Newton test at
///   10⁻⁹ of the forces can no longer be met: cantilever_statics on its default mesh (16 cubic
///   elements, load 6) converges in both cases for L = 10⁻³, 1 and 10³ m up to L/t = 10⁴ and fails
///   from 3·10⁴ at L = 10³ m (at 10⁹, --length 1e3 --width 1e-6, at load factor 0). A mesh too
///   coarse for the load (one element rolled up) fails at any slenderness: that is no input error.
inline constexpr double min_slenderness = 3.0;
inline constexpr double max_slenderness = 1e4;

/// A spar::Error naming the options when a beam of length `length` (option `length_name`) with
/// section sides `thin` (`thin_name`) ≤ `thick` (`thick_name`) is no slender beam: L/thick <
/// min_slenderness or L/thin > `most` (max_slenderness, or a driver's tighter bound).
void require_slender_beam(double length, const std::string& length_name, double thin, const std::string& thin_name,
                          double thick, const std::string& thick_name, double most = max_slenderness);

/// The peak memory of a run as a function of n, its element count: per_element · n +
/// per_element_squared · n² bytes (measured per driver: examples/common/memory_use.hpp).
struct MemoryUse {
  double per_element = 0.0;
  /// A dense matrix of the model's size (a dense eigenproblem, a dense transfer matrix).
  double per_element_squared = 0.0;

  double bytes(double elements) const { return (per_element + per_element_squared * elements) * elements; }
};

/// The physical memory of this machine in bytes (sysconf; 4 GB if it cannot say).
double physical_memory();
/// The memory a run may use: half the physical memory, so a run leaves room for the system and
/// for a second run beside it.
double memory_budget();
/// The most elements whose memory (MemoryUse::bytes) fits in memory_budget(), capped at the int
/// range: the upper end of an --elements option, so a run that would end in std::bad_alloc after
/// minutes is refused at once.
int element_limit(const MemoryUse& memory);
/// A spar::Error naming `names` when `elements` elements (as given: `given`) need more than
/// memory_budget().
void require_memory(double elements, const MemoryUse& memory, const std::string& names, const std::string& given = "");

}  // namespace spar::study
