#!/usr/bin/env python3
"""Alternates two builds' benchmarks (old, new) and compares their minima and medians: the check
that a refactoring costs no speed (docs/performance.md, "The platform split, timed").
    scripts/compare_bench.py OLD_BENCH_DIR NEW_BENCH_DIR [ROUNDS]
Serial (OMP_NUM_THREADS=1), 6 repetitions per benchmark and round; on a machine whose speed
drifts, the alternation puts old and new under the same drift."""
import subprocess, statistics, sys, os
env = dict(os.environ, OMP_NUM_THREADS="1")
bins = {"old": sys.argv[1], "new": sys.argv[2]}
tests = [("bench_dynamics", "slider_crank_run/0$"), ("bench_dynamics", "slider_crank_run/2$"), ("bench_truss", "truss_deployment_first_second/0/0$")]
res = {}
for rnd in range(int(sys.argv[3]) if len(sys.argv) > 3 else 3):
    for which in ("old", "new"):
        for exe, flt in tests:
            out = subprocess.run([f"{bins[which]}/{exe}", f"--benchmark_filter={flt}", "--benchmark_repetitions=6", "--benchmark_format=csv"],
                                 capture_output=True, text=True, env=env).stdout
            vals = [float(l.split(",")[3]) for l in out.splitlines() if l.startswith('"') and "_mean" not in l and "_median" not in l and "_stddev" not in l and "_cv" not in l]
            res.setdefault((exe, flt, which), []).extend(vals)
            print(which, rnd, flt, "min %.1f median %.1f" % (min(vals), statistics.median(vals)), flush=True)
for (exe, flt) in [(e, f) for e, f in tests]:
    o, n = res[(exe, flt, "old")], res[(exe, flt, "new")]
    print("%-40s old min %.1f med %.1f | new min %.1f med %.1f | new/old min %.3f med %.3f" % (flt, min(o), statistics.median(o), min(n), statistics.median(n), min(n)/min(o), statistics.median(n)/statistics.median(o)))
