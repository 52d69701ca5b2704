// The hot path of SparsePattern allocates nothing: every global operator new in this test
// executable is counted, and a batch of add_block and set_zero calls must leave the counter
// unchanged.
#include <spar/core/sparse_assembly.hpp>

#include <catch2/catch.hpp>

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long> allocations{0};
}

void* operator new(std::size_t size) {
  ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
// Catch2 allocates with the nothrow form; replacing it too keeps every new paired with this
// file's delete (AddressSanitizer reports a mismatch otherwise).
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  ++allocations;
  return std::malloc(size == 0 ? 1 : size);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

TEST_CASE("add_block and set_zero do not allocate", "[core][sparse_pattern][allocation]") {
  using spar::core::PatternBlock;
  spar::core::SparsePattern pattern(
      6, {PatternBlock::element({0, 1, 2, 3}), PatternBlock::coupling({5}, {1, 2})});
  const Eigen::MatrixXd K = Eigen::MatrixXd::Ones(4, 4);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Ones(1, 2);
  const Eigen::MatrixXd B_transpose_position = Eigen::MatrixXd::Ones(2, 1);
  const long before = allocations.load();
  for (int i = 0; i < 100; ++i) {
    pattern.set_zero();
    pattern.add_block(0, K);
    pattern.add_block(1, B);
    pattern.add_block(1, B, B_transpose_position);
  }
  const long after = allocations.load();
  CHECK(after == before);
  CHECK(pattern.matrix().coeff(1, 1) == 1.0);
  CHECK(pattern.matrix().coeff(5, 1) == 2.0);
}
