#!/usr/bin/env bash
# The test command: sets up, builds and runs every test.
#   1. install the Debian packages, with those of the tests (scripts/setup.sh --test: ParaView),
#   2. Release build of everything (library, tests, examples, benchmarks), all CTest tests,
#   3. clang build with AddressSanitizer + UndefinedBehaviorSanitizer of the unit tests, run
#      under them, and of the libFuzzer targets (fuzz/), each run briefly on a fixed seed.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)

scripts/setup.sh --test

echo "== release build"
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release
cmake --build build/release -j"$jobs"
ctest --test-dir build/release --output-on-failure -j"$jobs"

echo "== sanitizer build (clang; address, undefined; libFuzzer targets) of the unit tests"
# clang, because libFuzzer is part of it: the fuzz targets link the same instrumented libraries.
cmake -S . -B build/clang-sanitize -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" \
  -DSPAR_SANITIZE=ON -DSPAR_BUILD_FUZZERS=ON -DSPAR_BUILD_EXAMPLES=OFF -DSPAR_BUILD_BENCH=OFF
cmake --build build/clang-sanitize -j"$jobs"
ctest --test-dir build/clang-sanitize --output-on-failure -j"$jobs" -L unit
ctest --test-dir build/clang-sanitize --output-on-failure -L libfuzzer
