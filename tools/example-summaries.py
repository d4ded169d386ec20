#!/usr/bin/env python3
"""Write the summary of every bundled example, by each method, with wall times removed, so that
two builds can be compared digit for digit (`diff -r BEFORE AFTER`): a restructuring that
changes no mechanics must leave every file equal.

usage: tools/example-summaries.py OUT_DIR [LIFTOFF_BIN]   (default: target/release/liftoff)
       tools/example-summaries.py --compare BEFORE AFTER [REL_TOL]

The second form compares two such folders on the answers only: every number of every file to
REL_TOL (default 1e-9) relative to the larger magnitude of its kind, keys that only one side has
listed once, and the path of a solver's own account skipped (the steps it took, its residuals,
its notes — a different start changes those, never the answer).
"""
import json
import pathlib
import subprocess
import sys

LARGE = [("paper-halfspace", "96,96"), ("slab-pasternak", "72,48"), ("slab-clay-layer", "72,48"),
         ("slab-on-grade", "180,120")]
TIMED = ("time_s", "method_time_s", "time", "elapsed")


def strip(value):
    """The value without wall-clock fields (at any depth)."""
    if isinstance(value, dict):
        return {k: strip(v) for k, v in value.items() if k not in TIMED and not k.endswith("_s")}
    if isinstance(value, list):
        return [strip(v) for v in value]
    return value


ACCOUNT = ("history", "iterations", "solver_info", "penalty_stages", "notes", "status")


def compare(before, after, tol):
    """Differences of the answers in two folders of summaries."""
    problems, added = [], set()

    def walk(a, b, path):
        if isinstance(a, dict) and isinstance(b, dict):
            for k in sorted(set(a) | set(b)):
                if k in ACCOUNT:
                    continue
                if k not in a or k not in b:
                    added.add(k)
                    continue
                walk(a[k], b[k], f"{path}.{k}")
        elif isinstance(a, list) and isinstance(b, list):
            if len(a) != len(b):
                problems.append(f"{path}: {len(a)} against {len(b)} entries")
            for i, (x, y) in enumerate(zip(a, b)):
                walk(x, y, f"{path}[{i}]")
        elif isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
            scale = max(abs(a), abs(b), 1e-300)
            if abs(a - b) > tol * scale and abs(a - b) > 1e-12:
                problems.append(f"{path}: {a!r} against {b!r}")
        elif a != b:
            problems.append(f"{path}: {a!r} against {b!r}")

    for f in sorted(pathlib.Path(before).glob("*.json")):
        g = pathlib.Path(after) / f.name
        if not g.exists():
            problems.append(f"{f.name}: missing after")
            continue
        walk(json.loads(f.read_text()), json.loads(g.read_text()), f.name)
    for p in problems:
        print(p)
    print(f"{len(problems)} difference(s) beyond {tol:g}; keys only one side has: {sorted(added)}")
    return not problems


def main():
    if sys.argv[1] == "--compare":
        tol = float(sys.argv[4]) if len(sys.argv) > 4 else 1e-9
        sys.exit(0 if compare(sys.argv[2], sys.argv[3], tol) else 1)
    out = pathlib.Path(sys.argv[1])
    binary = sys.argv[2] if len(sys.argv) > 2 else "target/release/liftoff"
    out.mkdir(parents=True, exist_ok=True)
    listing = subprocess.run([binary, "example"], capture_output=True, text=True, check=True).stdout
    names = [line.split()[0] for line in listing.splitlines()[1:] if line.strip()]
    for name in names:
        for method in ("scene", "penalty", "qp", "bonded"):
            args = [binary, "solve", f"example:{name}", "--json"]
            if method in ("penalty", "qp"):
                args += ["--method", method, "--contact", "unbonded"]
            elif method == "bonded":
                args += ["--contact", "bonded"]
            run = subprocess.run(args, capture_output=True, text=True)
            try:
                doc = strip(json.loads(run.stdout))
            except json.JSONDecodeError:
                doc = {"exit": run.returncode, "stderr": run.stderr.strip().splitlines()[-1:]}
            (out / f"{name}--{method}.json").write_text(json.dumps(doc, indent=1, sort_keys=True) + "\n")
            print(f"{name:22} {method:8} exit {run.returncode}", flush=True)
    # Larger grids, where the iterative route, the FFT T and the nested start of the QP run.
    for name, mesh in LARGE:
        for method in ("penalty", "qp"):
            args = [binary, "solve", f"example:{name}", "--json", "--mesh", mesh, "--method", method]
            run = subprocess.run(args, capture_output=True, text=True)
            try:
                doc = strip(json.loads(run.stdout))
            except json.JSONDecodeError:
                doc = {"exit": run.returncode, "stderr": run.stderr.strip().splitlines()[-1:]}
            (out / f"{name}--{mesh}--{method}.json").write_text(json.dumps(doc, indent=1, sort_keys=True) + "\n")
            print(f"{name:22} {mesh:8} {method:8} exit {run.returncode}", flush=True)


if __name__ == "__main__":
    main()
