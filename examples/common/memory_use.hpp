#pragma once
// The peak memory of each example's run as a function of its --elements, measured with
// `/usr/bin/time -f %M` (the peak resident set) at two or more sizes, so that
// study::element_limit sizes each example's --elements by what its run needs (issue 29: at the
// former common bound, 10⁵ bytes per element, --elements 126380 ended in std::bad_alloc in
// slider_crank, modal_beam and falling_beam and in KLU's "out of memory" in flexible_pendulum).
// The dynamic examples are measured over runs of 260 or more recorded steps: output::ResultsWriter
// holds two blocks of 100 steps (its flush_every) in memory, so the peak grows over the first 200
// recorded steps and then stays (flexible_pendulum, 1000 elements: 67, 136, 199, 199, 200 MiB after
// 1, 100, 200, 400, 800 steps), and a run of a few steps shows a third of it. Each figure is the
// measured increment with a margin of 1.5 (the allocator's fragmentation, other machines' libraries),
// rounded up to 2 digits, at the recording the options allow most often (every step).

#include <spar/study/run_limits.hpp>

namespace spar::examples::memory_use {

// Measured on 2026-11-28 (Release, GCC 12; peak resident sets in MiB, increments in kB = 10³ B).

/// Statics, one record: 1000, 4000, 16000 elements: 41.6, 129.4, 480.2 MiB; 30.7 kB per element.
inline constexpr study::MemoryUse cantilever_statics{.per_element = 4.6e4};
/// Statics, one record: 1000, 4000 elements: 77.2, 270.4 MiB; 67.5 kB.
inline constexpr study::MemoryUse ancf_cantilever{.per_element = 1.1e5};
/// Per --elements (two rods), 0.13 s at h = 5e-4 (every step recorded): 100, 400: 66.3, 178.5 MiB;
/// 392 kB.
inline constexpr study::MemoryUse slider_crank{.per_element = 5.9e5};
/// 0.065 s at h = 2.5e-4: 250, 1000: 68.8, 198.7 MiB; 182 kB.
inline constexpr study::MemoryUse flexible_pendulum{.per_element = 2.8e5};
/// Per --elements (two rods), 0.026 s at h = 1e-4: 250, 1000: 116.5, 376.2 MiB; 363 kB.
inline constexpr study::MemoryUse four_bar{.per_element = 5.5e5};
/// 0.26 s at h = 1e-3: 250, 1000: 47.4, 129.1 MiB; 114 kB.
inline constexpr study::MemoryUse ancf_pendulum{.per_element = 1.8e5};
/// --elements-ab 250, 1000 (--elements-oa 2), 0.026 s at h = 1e-4, --record-every 1: 42.5, 108.9 MiB;
/// 92.8 kB per element of either link.
inline constexpr study::MemoryUse ancf_double_pendulum{.per_element = 1.4e5};
/// Per --elements of the carrier (and of the sliding beam), 0.26 s at h = 1e-3: 50, 200: 25.8, 42.1 MiB;
/// 114 kB.
inline constexpr study::MemoryUse sliding_beam{.per_element = 1.8e5};
/// Per --elements (28 members), 1.3 s at h = 5e-3 with --output-interval 5e-3: 10, 40: 43.2, 96.8 MiB;
/// 1.88 MB.
inline constexpr study::MemoryUse truss_deployment{.per_element = 2.9e6};
/// The dense eigenproblem (solvers::modal_analysis: about 8 dense matrices of 6(n + 3) rows): 100,
/// 200, 400 elements: 36.8, 114.2, 398.4 MiB, fitted by 2.6 MB + 134 kB n + 2260 B n² (a run of 400
/// elements takes 26 s, the time growing as n³).
inline constexpr study::MemoryUse modal_beam{.per_element = 2.0e5, .per_element_squared = 3400};
/// The sliding cable's length-control event builds its transfer matrix P dense, n × n for 5
/// coordinates per element (lib/elements/cable/src/sliding_cable.cpp): 200 B n². falling_beam, two steps of 1 ms,
/// one event: 1000, 1500, 2000 elements: 221.3, 466.3, 806.5 MiB, fitted by 17 MB + 15.2 kB n +
/// 199.5 B n². semicircular_beam over 260 and 1120 steps (12 and 53 events): 250, 1000: 47.8, 272.6
/// MiB, 200 B n² and 64 kB n. The same cable and recording in all three (falling_beam 1000: 240 MiB,
/// suspended_beam 1000: 260 MiB, over 0.26 s until Newton gave up, after 160 s and 128 s).
inline constexpr study::MemoryUse falling_beam{.per_element = 9.6e4, .per_element_squared = 300};
inline constexpr study::MemoryUse suspended_beam{.per_element = 9.6e4, .per_element_squared = 300};
inline constexpr study::MemoryUse semicircular_beam{.per_element = 9.6e4, .per_element_squared = 300};

}  // namespace spar::examples::memory_use
