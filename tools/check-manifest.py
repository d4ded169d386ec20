#!/usr/bin/env python3
"""Checks of Cargo.toml that a compiler does not make (run by .ci/run):

1. the solver core without default features depends on no front-end crate (clap, plotters,
   indicatif, quick-xml, image, png, ctrlc): `cargo tree -p liftoff --no-default-features`;
   csv is not one of them since the core reads the deflectometer's basin files (`backcalc`);
2. the Python package's wheel depends on none of them either;
3. `rust-version` of both packages is the true minimum: the highest `rust-version` among the
   locked dependencies (a newer one would be a false promise, an older one needlessly high);
4. no exact pins (`=x.y.z`): liftoff is a library, Cargo.lock pins.
"""
import json
import pathlib
import re
import subprocess
import sys

FRONT_ENDS = ("clap", "plotters", "indicatif", "quick-xml", "image", "png", "tempfile", "ctrlc")
ROOT = pathlib.Path(__file__).resolve().parents[1]


def tree(*args):
    out = subprocess.run(["cargo", "tree", "-e", "normal", "--prefix", "none", *args],
                         cwd=ROOT, capture_output=True, text=True, check=True).stdout
    return {line.split()[0] for line in out.splitlines() if line.strip()}


def version(v):
    return tuple(int(x) for x in v.split(".")) + (0,) * (3 - len(v.split(".")))


def main():
    failures = []
    for what, args in [("the core", ["-p", "liftoff", "--no-default-features"]),
                       ("the Python package", ["-p", "liftoff-python"])]:
        bad = sorted(tree(*args) & set(FRONT_ENDS))
        if bad:
            failures.append(f"{what} depends on front-end crates: {', '.join(bad)}")
    meta = json.loads(subprocess.run(["cargo", "metadata", "--format-version", "1", "--locked"],
                                     cwd=ROOT, capture_output=True, text=True, check=True).stdout)
    used = {n["id"] for n in meta["resolve"]["nodes"]}
    ours = {"liftoff", "liftoff-python"}
    deps = [p for p in meta["packages"] if p["id"] in used and p["name"] not in ours and p.get("rust_version")]
    need = max(deps, key=lambda p: version(p["rust_version"]))
    for p in meta["packages"]:
        if p["name"] in ours:
            if version(p.get("rust_version") or "0") != version(need["rust_version"]):
                failures.append(f"{p['name']}: rust-version {p.get('rust_version')} but {need['name']} "
                                f"{need['version']} needs {need['rust_version']}")
    for manifest in [ROOT / "Cargo.toml", ROOT / "python" / "Cargo.toml"]:
        if re.search(r'"=\s*[0-9]', manifest.read_text()):
            failures.append(f"{manifest.relative_to(ROOT)}: an exact version pin (=x.y.z)")
    for f in failures:
        print(f"check-manifest: {f}")
    if not failures:
        print(f"check-manifest: core and wheel free of front-end crates; rust-version {need['rust_version']} "
              f"(from {need['name']} {need['version']}); no exact pins")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
