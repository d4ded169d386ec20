"""Chart and table of docs/examples/slab-clay-layer.md from three `liftoff solve` runs.

Usage (from the repository root, after `cargo build --release`):
    python3 docs/examples/slab-clay-layer.py OUT_DIR
where OUT_DIR holds layer-qp/, layer-penalty/, winkler-qp/ and halfspace-qp/ written by
`liftoff solve ... --out OUT_DIR/NAME` (see the .md for the scenes). Writes the SVG beside
this script and prints the markdown table."""
import csv, json, os, sys

out = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
runs = [("layer-qp", "3 m clay layer on rock", "#1f77b4"),
        ("winkler-qp", "Winkler, k = E_oed/h", "#2ca02c"),
        ("halfspace-qp", "clay as a half-space", "#d62728")]

def load(name):
    s = json.load(open(os.path.join(out, name, "summary.json")))
    ph = s["physical"]; mu = s["dimensionless"]["mu"]
    L, P, D = ph["half_length"], ph["force"], ph["rigidity"]
    wscale = P * L * L / D * 1e3            # mm per unit V
    pscale = P / (mu * L * L) * 1e-3        # kPa per unit σ
    # Headers carry their unit (`V [-]`): keyed by the name alone.
    rows = [{k.split(" [")[0]: v for k, v in r.items()}
            for r in csv.DictReader(open(os.path.join(out, name, "profiles.csv")))]
    rows = [r for r in rows if r["line"] == "diagonal"]
    # distance from the centre along the diagonal, m (coord is s along it, −1 … 1)
    half_diag = (L * L + (mu * L) ** 2) ** 0.5
    d = [float(r["coord"]) * half_diag for r in rows]
    w = [float(r["V"]) * wscale for r in rows]
    p = [float(r["sigma"]) * pscale for r in rows]
    return s, d, w, p

data = [(n, lab, col) + load(n) for n, lab, col in runs]
for n, lab, col, s, d, w, p in data:
    print(f"<!-- {n}: profile max p {max(p):.1f} kPa, max w {max(w):.2f} mm -->")

W, H = 900, 660
def panel(y0, h, key, label, fmt):
    xs = [x for *_, d, w, p in data for x in d]
    vals = [v for *_, d, w, p in data for v in (w if key == "w" else p)]
    lo, hi = min(min(vals), 0.0), max(vals) * 1.08
    x0, x1 = 80, W - 30
    X = lambda x: x0 + (x - min(xs)) / (max(xs) - min(xs)) * (x1 - x0)
    Y = lambda v: y0 + h - (v - lo) / (hi - lo) * h
    g = [f'<rect x="{x0}" y="{y0}" width="{x1-x0}" height="{h}" fill="none" stroke="#444"/>']
    for k in range(6):
        v = lo + (hi - lo) * k / 5
        g.append(f'<line x1="{x0}" x2="{x1}" y1="{Y(v):.1f}" y2="{Y(v):.1f}" stroke="#ddd"/>')
        g.append(f'<text x="{x0-6}" y="{Y(v)+4:.1f}" text-anchor="end" font-size="12">{fmt(v)}</text>')
    if lo < 0:
        g.append(f'<line x1="{x0}" x2="{x1}" y1="{Y(0):.1f}" y2="{Y(0):.1f}" stroke="#888" stroke-dasharray="4 3"/>')
    for k in range(-3, 4):
        x = k * 2.0
        if min(xs) <= x <= max(xs):
            g.append(f'<text x="{X(x):.1f}" y="{y0+h+16}" text-anchor="middle" font-size="12">{x:g}</text>')
    for c in (-3.6056, 3.6056):  # the columns at (±3, ±2) lie on the diagonal
        g.append(f'<line x1="{X(c):.1f}" x2="{X(c):.1f}" y1="{y0}" y2="{y0+h}" stroke="#999" stroke-dasharray="2 4"/>')
    for n, lab, col, s, d, w, p in data:
        v = w if key == "w" else p
        pts = " ".join(f"{X(a):.1f},{Y(b):.1f}" for a, b in zip(d, v))
        g.append(f'<polyline points="{pts}" fill="none" stroke="{col}" stroke-width="2"/>')
    g.append(f'<text x="{x0}" y="{y0-8}" font-size="14">{label}</text>')
    return "\n".join(g)

svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif">',
       '<rect width="100%" height="100%" fill="white"/>',
       '<text x="450" y="24" text-anchor="middle" font-size="16">12 m × 8 m slab, four 300 kN columns + self-weight, unbonded: along the diagonal</text>',
       panel(60, 220, "w", "settlement w, mm (negative: the slab lifts off)", lambda v: f"{v:.1f}"),
       panel(340, 220, "p", "contact pressure, kPa", lambda v: f"{v:.0f}"),
       f'<text x="450" y="{H-62}" text-anchor="middle" font-size="12">distance from the centre along the diagonal, m (dotted: the columns)</text>']
for k, (n, lab, col, *_r) in enumerate(data):
    svg.append(f'<line x1="{100+k*260}" x2="{130+k*260}" y1="{H-24}" y2="{H-24}" stroke="{col}" stroke-width="3"/>')
    svg.append(f'<text x="{136+k*260}" y="{H-20}" font-size="13">{lab}</text>')
svg.append("</svg>")
open(os.path.join(here, "slab-clay-layer.svg"), "w").write("\n".join(svg))

print("| soil | method | contact (% of plate) | max pressure (kPa) | max settlement (mm) | corner (mm) | solve time (s) |")
print("|---|---|---|---|---|---|---|")
for name, lab in [("layer-penalty", "3 m clay layer on rock"), ("layer-qp", "3 m clay layer on rock"),
                  ("winkler-qp", "Winkler, k = E_oed/h = 8.97 MN/m³"), ("halfspace-qp", "clay as a half-space")]:
    s = json.load(open(os.path.join(out, name, "summary.json")))
    ph = s["physical"]; wscale = ph["force"] * ph["half_length"] ** 2 / ph["rigidity"] * 1e3
    mu = s["dimensionless"]["mu"]; pscale = ph["force"] / (mu * ph["half_length"] ** 2) * 1e-3
    meth = s["method"] + (f" ({s['qp_solver']})" if s.get("qp_solver") else "")
    print(f"| {lab} | {meth} | {100*s['contact_fraction']:.1f} | {s['pressure_max']*1e-3:.1f} | "
          f"{s['w_max']*1e3:.2f} | {s['V_corner']*wscale:.3f} | {s['time_s']['total']:.2f} |")
