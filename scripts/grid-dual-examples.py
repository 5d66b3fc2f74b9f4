#!/usr/bin/env python3
"""Pictures of docs/grid.md ("Negative results"): the digital Voronoi colourings of
examples/grid_dual_examples.hpp, their raw duals under the grid perturbation, and which
site tets are bad.

    cmake --preset cpu && cmake --build --preset cpu --target grid_dual_examples
    python3 scripts/grid-dual-examples.py            # needs numpy and matplotlib

It builds nothing: it runs the example program (--program, default
build/cpu/grid_dual_examples), which writes one JSON file per example and
grid-summary.json into a work folder (--json-dir, default a temporary one) and exits 1 when
a figure differs from the documented one; then it draws docs/img/grid-<name>.png per
example (--out-dir). Only numpy and matplotlib (Agg backend) are needed.

Each picture: left, the colouring in 3-D (voxel centres as dots coloured by their site, the
sites as large labelled markers) with the 4-coloured grid tets (Kuhn tets between voxel
centres) that dualize a site tet; middle, the raw dual: the distinct site tets; right, the
colouring slice by slice (z = 0 .. W-1, site ids written on the sites' voxels, hatched:
voxels cut off from their site's own voxel, i.e. a region in pieces). Colours of
tets: red = invalid (flat, inverted, folded, or holding a facet in three or more tets or in
two on the same side), orange = valid but in a non-Delaunay pair, blue = neither; dashed
green edges: Delaunay tets of the sites that no grid tet dualizes.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection  # noqa: E402

INVALID = {"flat", "inverted", "folded", "overshared_facet", "overlapping_facet"}
RED, ORANGE, BLUE, GREEN = "#d62728", "#ff7f0e", "#4a78a8", "#2ca02c"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def category(tet: dict) -> str:
    flags = set(tet["flags"])
    if flags & INVALID:
        return RED
    if "non_delaunay_pair" in flags:
        return ORANGE
    return BLUE


def site_colours(n: int):
    cmap = plt.get_cmap("tab10")
    return [cmap(i % 10) for i in range(n)]


def voxel_coords(W: int):
    """Coordinates (x, y, z) of the voxel centres in index order (x fastest)."""
    z, y, x = np.meshgrid(np.arange(W), np.arange(W), np.arange(W), indexing="ij")
    return np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1) + 0.5


def tet_edges(p):
    return [(p[a], p[b]) for a in range(4) for b in range(a + 1, 4)]


def tet_faces(p):
    return [[p[a], p[b], p[c]] for a, b, c in ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3))]


def setup_3d(ax, W: int, title: str):
    ax.set_xlim(0, W)
    ax.set_ylim(0, W)
    ax.set_zlim(0, W)
    ax.set_box_aspect((1, 1, 1))
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    ax.view_init(elev=22, azim=-58)
    ax.set_title(title, fontsize=10)
    ticks = list(range(0, W + 1, max(1, W // 4)))
    ax.set_xticks(ticks)
    ax.set_yticks(ticks)
    ax.set_zticks(ticks)


def draw_sites(ax, sites, colours):
    ax.scatter(sites[:, 0], sites[:, 1], sites[:, 2], s=70, c=colours, edgecolors="black", depthshade=False, zorder=5)
    for i, p in enumerate(sites):
        ax.text(p[0], p[1], p[2], f" {i}", fontsize=9, fontweight="bold", zorder=6)


def draw_colouring(ax, ex, kuhn, colours):
    W = ex["W"]
    sites = np.array(ex["sites"])
    centres = voxel_coords(W)
    col = np.array(ex["colouring"])
    ax.scatter(centres[:, 0], centres[:, 1], centres[:, 2], s=14 if W <= 4 else 5,
               c=[colours[c] for c in col], alpha=0.55, depthshade=False)
    segs, segc = [], []
    for tet in ex["tets"]:
        for x, y, z, j in tet["grid_tets"]:
            corner = [np.array([x + (k & 1), y + ((k >> 1) & 1), z + ((k >> 2) & 1)]) + 0.5 for k in kuhn[j]]
            for e in tet_edges(corner):
                segs.append(e)
                segc.append(category(tet))
    if segs:
        ax.add_collection3d(Line3DCollection(segs, colors=segc, linewidths=1.2, alpha=0.9))
    draw_sites(ax, sites, colours)
    setup_3d(ax, W, "colouring and its 4-coloured grid tets")


def draw_dual(ax, ex, colours):
    W = ex["W"]
    sites = np.array(ex["sites"])
    for tet in ex["tets"]:
        p = sites[tet["sites"]]
        c = category(tet)
        ax.add_collection3d(Poly3DCollection(tet_faces(p), facecolors=c, edgecolors=c, linewidths=1.0,
                                             alpha=0.18 if c == BLUE else 0.32))
    dual = {tuple(t["sites"]) for t in ex["tets"]}
    if ex["delaunay_unique"]:
        missed = [tuple(t) for t in ex["empty_sphere_tets"] if tuple(t) not in dual]
        segs = [e for t in missed for e in tet_edges(sites[list(t)])]
        if segs:
            ax.add_collection3d(Line3DCollection(segs, colors=GREEN, linewidths=1.6, linestyles="dashed"))
    draw_sites(ax, sites, colours)
    setup_3d(ax, W, "raw dual: distinct site tets")


def draw_slices(fig, spec, ex, colours):
    W = ex["W"]
    col = np.array(ex["colouring"]).reshape(W, W, W)  # [z][y][x]
    sites = np.array(ex["sites"])
    own = {tuple(int(c) for c in np.floor(p)): i for i, p in enumerate(sites)}
    per_row = 2 if W == 4 else min(W, 3)
    rows = (W + per_row - 1) // per_row
    sub = spec.subgridspec(rows, per_row, wspace=0.06, hspace=0.18)
    rgba = np.array(colours)
    detached = [(v % W, (v // W) % W, v // (W * W)) for v in ex["detached_voxels"]]
    for z in range(W):
        ax = fig.add_subplot(sub[z // per_row, z % per_row])
        ax.imshow(rgba[col[z]], origin="lower", extent=(0, W, 0, W), alpha=0.85)
        for x, y, zz in detached:
            if zz == z:
                ax.add_patch(plt.Rectangle((x + 0.08, y + 0.08), 0.84, 0.84, fill=False, hatch="xxx",
                                           edgecolor="black", linewidth=1.2))
        for (x, y, zz), i in own.items():
            if zz == z:
                ax.text(x + 0.5, y + 0.5, str(i), ha="center", va="center", fontsize=9, fontweight="bold")
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title(f"z = {z}", fontsize=8)


def caption(ex) -> str:
    f = ex["figures"]
    names = [("tets", "site tet"), ("inverted", "inverted"), ("folded", "folded"), ("flat", "flat"),
             ("overshared_facets", "facet{} in >2 tets"), ("overlapping_facets", "overlapping facet pair"),
             ("non_delaunay_pairs", "non-Delaunay pair"), ("cospherical_pairs", "cospherical pair"),
             ("off_hull_facets", "open facet{} off the hull"), ("split_regions", "region{} in pieces"),
             ("vertex_blocks", "block{} with >=5 colours")]

    def counted(n: int, label: str) -> str:
        plural = "" if n == 1 else "s"
        if "{}" in label:
            return f"{n} " + label.format(plural)
        return f"{n} {label}" + (plural if label.endswith(("tet", "pair")) else "")

    parts = [counted(f[k], label) for k, label in names if f[k] > 0 or k == "tets"]
    if ex["delaunay_unique"]:
        parts.append(f"{f['dual_empty_sphere']} of the {f['empty_sphere_tets']} Delaunay tets in the dual")
    else:
        parts.append(f"{f['empty_sphere_tets']} tets with an empty sphere (Delaunay not unique)")
    return ", ".join(parts)


def draw(ex, kuhn, path: str, dpi: int):
    colours = site_colours(len(ex["sites"]))
    fig = plt.figure(figsize=(16, 6))
    spec = fig.add_gridspec(1, 3, width_ratios=[1, 1, 1.15], wspace=0.08)
    draw_colouring(fig.add_subplot(spec[0], projection="3d"), ex, kuhn, colours)
    draw_dual(fig.add_subplot(spec[1], projection="3d"), ex, colours)
    draw_slices(fig, spec[2], ex, colours)
    fig.suptitle(f"grid-{ex['name']}: {ex['title']}", fontsize=11)
    fig.text(0.5, 0.025, caption(ex), ha="center", fontsize=9)
    fig.text(0.5, 0.0, "red: invalid site tet, orange: non-Delaunay pair, blue: neither; "
             "dashed green: Delaunay tet missing from the dual; hatched voxels: a region's detached piece",
             ha="center", fontsize=8, color="#444444")
    fig.savefig(path, dpi=dpi, bbox_inches="tight")
    plt.close(fig)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--program", default=os.path.join(ROOT, "build", "cpu", "grid_dual_examples"))
    ap.add_argument("--out-dir", default=os.path.join(ROOT, "docs", "img"))
    ap.add_argument("--json-dir", default=None, help="where the program writes its JSON (default: a temporary folder)")
    ap.add_argument("--dpi", type=int, default=80)
    args = ap.parse_args()
    if not os.path.exists(args.program):
        print(f"{args.program} not found: cmake --build --preset cpu --target grid_dual_examples", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory() as tmp:
        jdir = args.json_dir or tmp
        os.makedirs(jdir, exist_ok=True)
        run = subprocess.run([args.program, jdir], capture_output=True, text=True,
                             env=dict(os.environ, OMP_WAIT_POLICY="PASSIVE"))
        print(run.stdout, end="")
        if run.returncode != 0:
            print(run.stderr, end="", file=sys.stderr)
            print("the example program failed: fix the examples or their documented figures first", file=sys.stderr)
            return 1
        with open(os.path.join(jdir, "grid-summary.json")) as f:
            summary = json.load(f)
        os.makedirs(args.out_dir, exist_ok=True)
        for item in summary["examples"]:
            with open(os.path.join(jdir, f"grid-{item['name']}.json")) as f:
                ex = json.load(f)
            path = os.path.join(args.out_dir, f"grid-{ex['name']}.png")
            draw(ex, summary["kuhn_corners"], path, args.dpi)
            print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
