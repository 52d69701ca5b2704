#!/usr/bin/env bash
# Installs what spar needs from Debian's packages. Idempotent: when everything is present it
# changes nothing and touches no network; otherwise it runs `apt-get update` once and installs
# the missing packages. Needs root (or sudo) only when something is missing.
#   scripts/setup.sh          what building and running spar needs (scripts/run.sh)
#   scripts/setup.sh --test   and what the tests need besides (scripts/test.sh): ParaView's
#                             pvpython under a virtual X server, which opens an example's results,
#                             and clang for the sanitizer build and the libFuzzer targets
set -euo pipefail

packages=(
  cmake g++ make            # toolchain (OpenMP comes with GCC)
  libeigen3-dev             # dense linear algebra
  libsuitesparse-dev        # KLU / UMFPACK / CHOLMOD sparse direct solvers
  libhdf5-dev               # results files
  catch2                    # tests (v2)
  libbenchmark-dev          # bench/
  python3 python3-matplotlib  # the examples' plot scripts
)
case "${1:-}" in
  "") ;;
  --test)
    packages+=(
      paraview python3-paraview  # ParaView and its pvpython (the results-file test, label paraview)
      xvfb                       # Xvfb: the virtual X server pvpython renders on (tests/output/virtual_display.py)
      libxml2-utils              # xmllint: the XDMF sidecars are well-formed XML (tests/output, tests/examples)
      clang libclang-rt-dev libomp-dev  # the sanitizer build and libFuzzer (clang's OpenMP)
    ) ;;
  *) echo "setup: unknown option '$1' (use --test or nothing)" >&2; exit 2 ;;
esac

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: need root or sudo to install ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
