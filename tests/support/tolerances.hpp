#pragma once
// Tolerances shared by the test suites, each with the reason for its size.

namespace spar::test {

/// Round-off of a 3×3 result with O(1) entries computed in a few dozen flops: each entry carries
/// a few ulps (≤ 5e-16), and the Frobenius norm of nine of them stays below 4e-15.
inline constexpr double round_off_3x3 = 4e-15;

}  // namespace spar::test
