#!/usr/bin/env python3
"""Render gdel-bench JSON (``gdel-bench --json F``, ``gdel bench --json F``, or the merged
``bench.json`` of scripts/gpu-run.sh) as a PNG: time against the number of points, one panel
per distribution, one line per method, log-log axes.

    python3 scripts/plot-bench.py bench/data/2026-11-24-s5auto.json -o docs/img/bench.png
    python3 scripts/plot-bench.py A.json B.json --methods gdel3d-cuda,cgal,cgal-par -o out.png

Several files are merged; a (dist, n, method) measured twice keeps the last file's row.
Rows whose output the verifier rejected (``"valid": false``) are drawn hollow and named in
the legend so that a wrong-but-fast result never passes for a good one. Needs only
matplotlib (Agg backend).
"""
import argparse
import json
import math
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# Stable colours and markers per method family, so that figures are comparable.
STYLE = {
    "gdel3d": ("tab:blue", "o"),
    "auto": ("tab:cyan", "v"),
    "gflip3d": ("tab:green", "s"),
    "gstar4d": ("tab:purple", "D"),
    "greg3d": ("tab:olive", "P"),
    "cgal-par": ("tab:red", "^"),
    "cgal-regular-par": ("tab:red", "^"),
    "cgal": ("tab:orange", "x"),
    "cgal-regular": ("tab:orange", "x"),
    "scipy": ("tab:gray", "*"),
}


def style(method):
    if method in STYLE:
        return STYLE[method]
    for key in sorted(STYLE, key=len, reverse=True):
        if method.startswith(key):
            colour, marker = STYLE[key]
            return colour, marker
    return "black", "."


def load(paths):
    rows = {}
    for p in paths:
        try:
            data = json.loads(pathlib.Path(p).read_text())
        except (OSError, ValueError) as e:
            sys.exit(f"plot-bench: cannot read {p}: {e}")
        if not isinstance(data, list):
            sys.exit(f"plot-bench: {p}: expected a JSON list of gdel-bench rows")
        for r in data:
            try:
                key = (str(r["dist"]), int(r["n"]), str(r["method"]))
                t = float(r["median_s"])
            except (KeyError, TypeError, ValueError):
                sys.exit(f"plot-bench: {p}: a row lacks dist / n / method / median_s: {r}")
            if t > 0 and math.isfinite(t):
                rows[key] = (t, bool(r.get("valid", True)))
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("json", nargs="+", help="gdel-bench JSON files")
    ap.add_argument("-o", "--output", required=True, help="PNG to write")
    ap.add_argument("--methods", help="comma-separated methods to draw (default: all)")
    ap.add_argument("--title", default="", help="figure title (e.g. the device and the date)")
    args = ap.parse_args()

    rows = load(args.json)
    if args.methods:
        keep = set(args.methods.split(","))
        rows = {k: v for k, v in rows.items() if k[2] in keep}
    if not rows:
        sys.exit("plot-bench: no rows to draw")
    dists = sorted({k[0] for k in rows})
    methods = sorted({k[2] for k in rows})
    cols = min(3, len(dists))
    nrows = (len(dists) + cols - 1) // cols
    fig, axes = plt.subplots(nrows, cols, figsize=(4.6 * cols, 3.6 * nrows), squeeze=False)
    for i, d in enumerate(dists):
        ax = axes[i // cols][i % cols]
        for m in methods:
            pts = sorted((k[1], v) for k, v in rows.items() if k[0] == d and k[2] == m)
            if not pts:
                continue
            colour, marker = style(m)
            xs = [n for n, _ in pts]
            ys = [t for _, (t, _) in pts]
            ax.plot(xs, ys, color=colour, marker=marker, label=m, linewidth=1.2)
            bad = [(n, t) for n, (t, ok) in pts if not ok]
            if bad:
                ax.scatter([n for n, _ in bad], [t for _, t in bad], s=90, facecolors="none", edgecolors="k",
                           label=f"{m}: output rejected by the verifier")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(d)
        ax.set_xlabel("points")
        ax.set_ylabel("time (s), median")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    for j in range(len(dists), nrows * cols):
        axes[j // cols][j % cols].axis("off")
    if args.title:
        fig.suptitle(args.title)
    fig.tight_layout()
    out = pathlib.Path(args.output)
    tmp = out.with_name(out.name + ".tmp.png")
    fig.savefig(tmp, dpi=110)
    tmp.replace(out)  # never leave a half-written PNG under the final name
    print(f"plot-bench: {len(rows)} rows, {len(dists)} distributions, {len(methods)} methods -> {out}")


if __name__ == "__main__":
    main()
