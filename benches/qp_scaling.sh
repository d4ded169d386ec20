#!/usr/bin/env bash
# Penalty against the QP, one process per run, alternating so that both see the same load on
# a shared machine: wall time and peak RSS (/usr/bin/time), the CLI's own timings, iterations,
# and the two answers' V_max. Prints a markdown table.
#
#   benches/qp_scaling.sh SCENE N [N...]        e.g. benches/qp_scaling.sh example:paper-halfspace 128 256 512
#
# Extra CLI options for both methods go in $OPTS (e.g. OPTS="--symmetry none").
set -euo pipefail
OPTS=${OPTS:-}
bin=${LIFTOFF:-target/release/liftoff}
scene=$1; shift
echo "| elements | method | solver | converged | iterations | inner CG | wall s | solve s | peak RSS MiB | V_max |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for n in "$@"; do
  for method in penalty qp; do
    out=$(mktemp); tim=$(mktemp)
    # shellcheck disable=SC2086
    /usr/bin/time -f "%e %M" -o "$tim" "$bin" solve "$scene" --method "$method" --mesh "$n,$n" $OPTS --json >"$out" 2>/dev/null || true
    read -r wall rss < <(tail -n 1 "$tim")
    python3 - "$out" "$n" "$method" "$wall" "$rss" <<'PY'
import json, sys
path, n, method, wall, rss = sys.argv[1:]
try:
    d = json.load(open(path))
except Exception:
    print(f"| {n}² | {method} | – | failed | | | {wall} | | {int(rss)/1024:.0f} | |"); sys.exit()
info = d.get("solver_info") or {}
cg = info.get("cg_iterations")
print(f"| {n}² | {method} | {d.get('qp_solver') or '–'} | {d['converged']} | {d['iterations']} | "
      f"{'' if cg is None else int(cg)} | {wall} | {d['time_s']['solve']:.2f} | {int(rss)/1024:.0f} | {d['V_max']:.10g} |")
PY
    rm -f "$out" "$tim"
  done
done
