#!/usr/bin/env bash
# Scaling with the element count (docs/performance.md, "Scaling"): runs bench_scaling (a
# cantilevered cubic beam, 100 steps with output) once per element count and assembly, each in its
# own process so that /usr/bin/time's peak resident memory is that run's, and fits the exponent of
# time per step and of peak memory against N over N = 100 … 10 000 (log-log least squares).
# Run it on an otherwise idle machine.
#   scripts/scaling.sh                 3 repetitions (medians)
#   scripts/scaling.sh 5               5 repetitions
set -euo pipefail
cd "$(dirname "$0")/.."
repetitions=${1:-3}

cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DSPAR_BUILD_BENCH=ON > /dev/null
cmake --build build/release -j2 --target bench_scaling > /dev/null

out=results/scaling
mkdir -p "$out"
for n in 10 100 1000 10000; do
  for parallel in 0 1; do
    name="$out/n${n}_p${parallel}"
    /usr/bin/time -f "%M" -o "$name.rss" build/release/bench/bench_scaling \
      --benchmark_filter="cantilever/elements:$n/parallel:$parallel/" \
      --benchmark_repetitions="$repetitions" --benchmark_format=json > "$name.json"
  done
done

/usr/bin/python3 - "$out" <<'PY'
import json, math, statistics, sys
out = sys.argv[1]
rows = {}
for n in (10, 100, 1000, 10000):
    for p in (0, 1):
        runs = [b for b in json.load(open(f"{out}/n{n}_p{p}.json"))["benchmarks"]
                if b.get("run_type") == "iteration"]
        rows[n, p] = dict(ms=statistics.median(b["ms_per_step"] for b in runs),
                          us=statistics.median(b["us_per_element_iteration"] for b in runs),
                          it=statistics.median(b["iterations_per_step"] for b in runs),
                          rss=int(open(f"{out}/n{n}_p{p}.rss").read().split()[-1]) / 1024)
print("| elements | iterations/step | ms/step serial | parallel | speed-up | µs/(element·iteration) serial | parallel | peak MB serial | parallel |")
print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
for n in (10, 100, 1000, 10000):
    s, q = rows[n, 0], rows[n, 1]
    print(f"| {n} | {s['it']:.2f} | {s['ms']:.3g} | {q['ms']:.3g} | {s['ms'] / q['ms']:.2f} | "
          f"{s['us']:.3g} | {q['us']:.3g} | {s['rss']:.0f} | {q['rss']:.0f} |")
for row in rows.values(): row["ms_per_iteration"] = row["ms"] / row["it"]
def slope(key, p):
    xs = [math.log(n) for n in (100, 1000, 10000)]
    ys = [math.log(rows[n, p][key]) for n in (100, 1000, 10000)]
    mx, my = sum(xs) / 3, sum(ys) / 3
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
for p, label in ((0, "serial"), (1, "parallel")):
    print(f"{label}: time per step ~ N^{slope('ms', p):.3f}, per Newton iteration ~ N^{slope('ms_per_iteration', p):.3f}, peak memory ~ N^{slope('rss', p):.3f} (N = 100 … 10 000), "
          f"{(rows[10000, p]['rss'] - rows[1000, p]['rss']) * 1024 / 9000:.1f} KB per element from 1 000 to 10 000")
PY
