#!/usr/bin/env bash
# Long libFuzzer runs of the fuzz targets (fuzz/, docs/errors.md "Fuzzing"): builds them with clang
# at -O2 under AddressSanitizer + UndefinedBehaviorSanitizer, assertions on, in build/fuzz, and runs
# each for the given number of inputs on a fixed seed (default 10⁶), one after the other.
#   scripts/fuzz.sh [runs] [target...]     e.g. scripts/fuzz.sh 1000000 model_fuzzer
# SPAR_FUZZ_ASAN=0 builds without AddressSanitizer (UBSan only, in build/fuzz-ubsan): several times
# faster for the model target, whose Eigen kernels ASan instruments at every access.
# A broken property or a crash stops the target and leaves the input as <build>/fuzz/<target>-crash-*;
# replay it with <build>/fuzz/<target> <file>, and add it to fuzz/regressions.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-1000000}
[ $# -gt 0 ] && shift
if [ $# -gt 0 ]; then targets=("$@"); else targets=(spline_fuzzer model_fuzzer); fi

scripts/setup.sh --test
if [ "${SPAR_FUZZ_ASAN:-1}" = 0 ]; then
  build=build/fuzz-ubsan
  sanitizers=(-DSPAR_SANITIZE=OFF -DCMAKE_CXX_FLAGS="-fsanitize=undefined -fno-sanitize-recover=all"
              -DCMAKE_EXE_LINKER_FLAGS=-fsanitize=undefined)
else
  build=build/fuzz
  sanitizers=(-DSPAR_SANITIZE=ON)
fi
cmake -S . -B "$build" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O2 -g" "${sanitizers[@]}" \
  -DSPAR_BUILD_FUZZERS=ON -DSPAR_BUILD_TESTS=OFF -DSPAR_BUILD_EXAMPLES=OFF -DSPAR_BUILD_BENCH=OFF
cmake --build "$build" -j"$(nproc)" --target "${targets[@]}"
for target in "${targets[@]}"; do
  echo "== $target: $runs runs (log: $build/fuzz/$target.log)"
  status=0
  "$build"/fuzz/"$target" -runs="$runs" -seed=1 -max_len=512 -len_control=0 -timeout=20 \
    -print_final_stats=1 -artifact_prefix="$build"/fuzz/"$target"- > "$build"/fuzz/"$target".log 2>&1 ||
    status=$?
  grep -E '^(stat::|Done)|VIOLATED|ERROR|SUMMARY|broke a property' "$build"/fuzz/"$target".log || true
  [ "$status" -eq 0 ] || { echo "fuzz: $target failed (exit $status; see its log)" >&2; exit 1; }
done
