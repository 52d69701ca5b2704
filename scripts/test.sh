#!/usr/bin/env bash
# The test command: sets up, builds and runs every test.
#   1. install the Debian packages, with those of the tests (scripts/setup.sh --test: ParaView),
#   2. Release build of everything (library, tests, examples, benchmarks), all CTest tests,
#   3. AddressSanitizer + UndefinedBehaviorSanitizer build of the unit tests, run under them.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)

scripts/setup.sh --test

echo "== release build"
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release
cmake --build build/release -j"$jobs"
ctest --test-dir build/release --output-on-failure -j"$jobs"

echo "== sanitizer build (address, undefined) of the unit tests"
cmake -S . -B build/sanitize -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" \
  -DSPAR_SANITIZE=ON -DSPAR_BUILD_EXAMPLES=OFF -DSPAR_BUILD_BENCH=OFF
cmake --build build/sanitize -j"$jobs"
ctest --test-dir build/sanitize --output-on-failure -j"$jobs" -L unit
