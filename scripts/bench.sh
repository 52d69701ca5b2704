#!/usr/bin/env bash
# Builds and runs every Google Benchmark suite (Release), 5 repetitions each, and prints the
# medians; docs/performance.md quotes them. Run it on an otherwise idle machine.
#   scripts/bench.sh            all suites
#   scripts/bench.sh beam lie   some suites
set -euo pipefail
cd "$(dirname "$0")/.."
suites=("$@")
[ ${#suites[@]} -gt 0 ] || suites=(lie iga solvers beam dynamics ancf rancf truss)

scripts/setup.sh
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release
targets=()
for suite in "${suites[@]}"; do targets+=("bench_$suite"); done
cmake --build build/release -j"$(nproc)" --target "${targets[@]}"

mkdir -p results/bench
for suite in "${suites[@]}"; do
  echo "== bench_$suite"
  build/release/bench/bench_"$suite" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
    --benchmark_out=results/bench/"$suite".json --benchmark_out_format=json | grep -E "median|Benchmark|^-"
done
