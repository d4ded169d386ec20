#!/usr/bin/env python3
"""Write the summary of every bundled example, by each method, with wall times removed, so that
two builds can be compared digit for digit (`diff -r BEFORE AFTER`): a restructuring that
changes no mechanics must leave every file equal.

usage: tools/example-summaries.py OUT_DIR [LIFTOFF_BIN]   (default: target/release/liftoff)
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


def main():
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
