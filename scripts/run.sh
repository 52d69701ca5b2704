#!/usr/bin/env bash
# The main job: sets up, builds and runs the flagship example — the flexible slider-crank of
# paper 003 (h = 5e-4 s, frozen iteration matrix) — writes its HDF5/XDMF/CSV and a plot, and
# prints a one-paragraph summary. Extra arguments go to the example, e.g. scripts/run.sh --h 1e-4.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/setup.sh
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release
cmake --build build/release -j"$(nproc)" --target slider_crank

out=results/slider_crank
mkdir -p "$out"
build/release/examples/slider_crank --h 5e-4 --strategy frozen --out "$out" "$@" | tee "$out/run.log"
/usr/bin/python3 examples/slider_crank/plot.py "$out"

/usr/bin/python3 - "$(tail -n 1 "$out/run.log")" <<'PY'
import json, sys
r = json.loads(sys.argv[1])
print(f"\nSummary: the flexible slider-crank of Wu et al. (2020, section 5.1) ran {r['steps']} steps of "
      f"h = {r['h']:g} s with the '{r['strategy']}' iteration matrix in {r['wall_s']:.2f} s "
      f"({r['newton_iterations']} Newton iterations, {r['factorizations']} factorizations, "
      f"{r['jtheta_updates']} updates of J_theta, {r['cutbacks']} cut-back steps). Rod I reached "
      f"{r['max_rod1_speed']:.0f} rad/s (paper: over 320) and Rod II's deformation rate peaked at "
      f"{100 * r['max_rod2_deformation_rate']:.2f} % (paper: over 5 % at h = 1e-4); the joints held "
      f"to {r['max_constraint_residual']:.1e} m. The drive did {r['external_work']:.0f} J of work and the "
      f"integrator dissipated {r['numerical_dissipation']:.0f} J of it (rho_inf = 0.9; docs/dynamics.md D8)"
      + (f"; the slider was at x = {r['slider_x_at_0_1']:.4f} m at t = 0.1 s" if r['slider_x_at_0_1'] is not None else "")
      + f". Time histories: results/slider_crank/slider_crank.h5 "
      f"(open slider_crank.xmf in ParaView), slider_crank.csv; figure: slider_crank.png.")
PY
