#!/usr/bin/env python3
"""Pictures of docs/example.md: a cut-away of the Delaunay tetrahedralization of the
Stanford bunny coloured by tet quality, and a histogram of that quality.

    bash scripts/fetch-models.sh                        # .deps/models/bunny00.off
    cmake --preset cpu && cmake --build --preset cpu --target gdel_cli
    python3 -m venv /tmp/venv-render && /tmp/venv-render/bin/pip install numpy matplotlib
    /tmp/venv-render/bin/python scripts/render-example.py

It runs `build/cpu/gdel delaunay MODEL -o WORK/bunny.npz --check --stats --device cpu`
(printing what the command prints), loads the .npz with numpy (points, tets, neighbors),
prints quality statistics and writes docs/img/bunny-cutaway.png and
docs/img/bunny-quality-hist.png. Only numpy and matplotlib (Agg backend) are needed.
Options: --model, --gdel, --npz (use an existing .npz instead of running gdel),
--out-dir, --work-dir, --dpi.

Quality measure: the radius ratio rho = 3 r_in / R_circ (in-radius over circumradius,
scaled so that the regular tetrahedron has rho = 1; rho -> 0 for flat tets, slivers
included). r_in = 3 V / (sum of the four face areas); R_circ = |circumcentre - p0|.
It is the inverse of what ParaView's Mesh Quality filter calls "Radius Ratio" for tets
(R / (3 r), 1 at best).

Cut-away: the tets whose centroid lies on the -z side of the plane z = (z_min + z_max) / 2
(in bunny00.off y is up, the bunny faces -x and z runs across it from flank to flank, so
the plane is a vertical section through body and head). Drawn are the boundary faces of
that set: faces on the convex hull (neighbour -1) and faces whose neighbour was cut away;
every one of them (10,140 for the bunny: no subsampling), coloured by the quality of the
kept tet it belongs to, on a logarithmic colour scale. Rendering: an orthographic
projection computed here and the painter's algorithm (faces drawn far to near by mean
depth) with a 2-D matplotlib PolyCollection, which gives exact control of the camera and
lets the surface samples near the plane be drawn on top (Poly3DCollection sorts the same
way). Two views: oblique, and facing the cut. At the default 90 dpi the PNG is ~350 KB.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent

# Face k of a tet is the one opposite vertex k (the neighbour convention of gdel's
# `neighbors`); these vertex orders keep each face's normal pointing out of the tet
# (gdel's tets are positively oriented).
FACES = np.array([[1, 2, 3], [0, 3, 2], [0, 1, 3], [0, 2, 1]])


def radius_ratio(points: np.ndarray, tets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """rho = 3 r_in / R_circ per tet, and the tets' volumes."""
    p0, p1, p2, p3 = (points[tets[:, k]] for k in range(4))
    a, b, c = p1 - p0, p2 - p0, p3 - p0
    bc, ca, ab = np.cross(b, c), np.cross(c, a), np.cross(a, b)
    det = np.einsum("ij,ij->i", a, bc)  # 6 V, > 0 for gdel's tets
    vol = det / 6.0
    # circumcentre - p0 = (|a|^2 (b x c) + |b|^2 (c x a) + |c|^2 (a x b)) / (2 det)
    num = (a * a).sum(1)[:, None] * bc + (b * b).sum(1)[:, None] * ca + (c * c).sum(1)[:, None] * ab
    circ = np.linalg.norm(num, axis=1) / (2.0 * det)

    def area(u: np.ndarray, v: np.ndarray, w: np.ndarray) -> np.ndarray:
        return 0.5 * np.linalg.norm(np.cross(v - u, w - u), axis=1)

    surface = area(p1, p2, p3) + area(p0, p2, p3) + area(p0, p1, p3) + area(p0, p1, p2)
    inr = 3.0 * vol / surface
    return 3.0 * inr / circ, vol


def edge_extremes(points: np.ndarray, tets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Longest and shortest edge of each tet."""
    pairs = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)]
    e = np.stack([np.linalg.norm(points[tets[:, i]] - points[tets[:, j]], axis=1) for i, j in pairs], axis=1)
    return e.max(1), e.min(1)


def nearest_neighbour_spacing(points: np.ndarray, tets: np.ndarray) -> float:
    """Median nearest-neighbour distance of the used points. Each point's nearest
    neighbour is joined to it by a Delaunay edge, so the shortest incident edge is it."""
    pairs = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)]
    e = np.concatenate([tets[:, [i, j]] for i, j in pairs])
    length = np.linalg.norm(points[e[:, 0]] - points[e[:, 1]], axis=1)
    nn = np.full(len(points), np.inf)
    np.minimum.at(nn, e[:, 0], length)
    np.minimum.at(nn, e[:, 1], length)
    return float(np.median(nn[np.isfinite(nn)]))


def run_gdel(gdel: Path, model: Path, npz: Path) -> None:
    cmd = [str(gdel), "delaunay", str(model), "-o", str(npz), "--check", "--stats", "--device", "cpu"]
    print("$ " + " ".join(cmd), flush=True)
    env = dict(os.environ)
    env.setdefault("OMP_WAIT_POLICY", "PASSIVE")  # shared cores: see scripts/test-python.sh
    subprocess.run(cmd, check=True, env=env)


def report(q: np.ndarray, vol: np.ndarray, rel: np.ndarray, shortest: np.ndarray, h: float, hull: np.ndarray) -> None:
    print(f"\nradius ratio rho = 3 r_in / R_circ over {len(q)} tets")
    print(f"  min {q.min():.3g}, max {q.max():.3f}, mean {q.mean():.4f}")
    pct = [1, 10, 25, 50, 75, 90, 99]
    print("  percentiles " + ", ".join(f"p{p} {v:.3g}" for p, v in zip(pct, np.percentile(q, pct))))
    for t in (0.01, 0.1, 0.2, 0.5):
        print(f"  rho < {t}: {np.mean(q < t):6.1%} of tets, {vol[q < t].sum() / vol.sum():6.1%} of the volume")
    print(f"  convex-hull tets (a neighbour -1): {hull.sum()}, median rho {np.median(q[hull]):.3g}")
    print(f"median nearest-neighbour spacing h = {h:.5g}; by longest edge L:")
    for lo, hi in ((0, 2), (2, 5), (5, 20), (20, np.inf)):
        s = (rel >= lo) & (rel < hi)
        name = f"L/h in [{lo}, {hi})" if np.isfinite(hi) else f"L/h >= {lo}"
        print(
            f"  {name:17s} {s.sum():7d} tets ({s.mean():5.1%}), {vol[s].sum() / vol.sum():5.1%} of the volume, "
            f"median rho {np.median(q[s]):.3g}, rho < 0.1: {np.mean(q[s] < 0.1):5.1%}"
        )
    # Slivers (flat, no short edge) versus needles and caps (flat because of a short edge).
    s = (rel < 2) & (q < 0.1)
    ratio = shortest[s] / (rel[s] * h)
    print(
        f"  of the {s.sum()} tets with L < 2h and rho < 0.1: shortest/longest edge median {np.median(ratio):.2f}, "
        f"> 0.3 for {np.mean(ratio > 0.3):.1%}"
    )


def camera(azimuth: float, elevation: float) -> np.ndarray:
    """Rows: screen right, screen up, towards the camera. y is up; azimuth 0 and
    elevation 0 put the camera on the +z axis, looking at the cut face."""
    a, e = np.radians(azimuth), np.radians(elevation)
    back = np.array([np.sin(a) * np.cos(e), np.sin(e), np.cos(a) * np.cos(e)])
    right = np.cross([0.0, 1.0, 0.0], back)
    right /= np.linalg.norm(right)
    return np.stack([right, np.cross(back, right), back])


def render_cutaway(points, tets, neighbors, q, h, out: Path, dpi: int) -> None:
    lo, hi = points.min(0), points.max(0)
    zc = 0.5 * (lo[2] + hi[2])
    keep = points[tets].mean(1)[:, 2] < zc
    nb_kept = np.where(neighbors >= 0, keep[np.maximum(neighbors, 0)], False)
    boundary = keep[:, None] & ~nb_kept  # (m, 4): face k of tet t is drawn
    t_idx, f_idx = np.nonzero(boundary)
    tris = points[tets[t_idx[:, None], FACES[f_idx]]]  # (k, 3, 3)
    fq = q[t_idx]
    slab = np.abs(points[:, 2] - zc) < 0.75 * h  # surface samples next to the cut plane
    print(
        f"\ncut-away: plane z = {zc:.4g}, {keep.sum()} of {len(tets)} tets kept, {len(tris)} boundary faces drawn "
        f"({np.sum(boundary & (neighbors < 0))} on the convex hull); {slab.sum()} samples within 0.75 h of the plane"
    )

    norm = LogNorm(vmin=1e-3, vmax=1.0, clip=True)
    cmap = plt.get_cmap("viridis")
    fig, axes = plt.subplots(1, 2, figsize=(11.0, 5.4), layout="constrained")
    views = (
        (axes[0], 35.0, 20.0, "(a) oblique (35° about y, 20° up)"),
        (axes[1], 0.0, 0.0, "(b) facing the cut; red: samples within 0.75 h of the plane"),
    )
    for ax, azimuth, elevation, title in views:
        # Orthographic projection, painter's algorithm: faces drawn far to near by mean depth.
        xyz = tris @ camera(azimuth, elevation).T
        order = np.argsort(xyz[:, :, 2].mean(1))
        ax.add_collection(
            PolyCollection(
                xyz[order, :, :2], facecolors=cmap(norm(fq[order])), edgecolors=(0, 0, 0, 0.25), linewidths=0.1
            )
        )
        if azimuth == 0.0 and elevation == 0.0:
            ax.plot(points[slab, 0], points[slab, 1], ".", color="red", markersize=2.5, markeredgewidth=0)
        ax.autoscale_view()
        ax.set_aspect("equal")
        ax.set_axis_off()
        ax.set_title(title, fontsize=9)
    cb = fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap=cmap), ax=axes, shrink=0.8)
    cb.set_label(r"radius ratio $\rho = 3\,r_{in}/R_{circ}$ (log scale, clipped at $10^{-3}$)")
    fig.suptitle(
        f"Delaunay tetrahedralization of the Stanford bunny ({len(points)} points, {len(tets)} tets):\n"
        f"the {keep.sum()} tets with centroid z < {zc:.2g}, {len(tris)} boundary faces coloured by quality",
        fontsize=9,
    )
    fig.savefig(out, dpi=dpi)
    plt.close(fig)


def render_histogram(q: np.ndarray, rel: np.ndarray, out: Path, dpi: int) -> None:
    bins = np.logspace(np.log10(max(q.min(), 1e-12)), 0, 61)
    fig, ax = plt.subplots(figsize=(7.2, 4.0))
    ax.hist(q, bins=bins, color="0.75", label=f"all tets ({len(q)})")
    for s, label, color in (
        (rel < 2, "longest edge < 2h (neighbouring surface samples)", "tab:blue"),
        (rel >= 20, "longest edge >= 20h (spanning the inside)", "tab:red"),
    ):
        ax.hist(q[s], bins=bins, histtype="step", linewidth=1.4, color=color, label=f"{label}: {s.sum()}")
    ax.set_xscale("log")
    ax.axvline(np.median(q), color="k", linestyle="--", linewidth=0.8, label=f"median of all: {np.median(q):.3g}")
    ax.set_xlabel(r"radius ratio $\rho = 3\,r_{in}/R_{circ}$ (1 = regular tetrahedron)")
    ax.set_ylabel("tets per bin")
    ax.set_title("Tet quality of the bunny's Delaunay tetrahedralization (h = median nearest-neighbour spacing)", fontsize=9)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(out, dpi=dpi)
    plt.close(fig)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--model", type=Path, default=ROOT / ".deps/models/bunny00.off")
    ap.add_argument("--gdel", type=Path, default=ROOT / "build/cpu/gdel")
    ap.add_argument("--npz", type=Path, help="an existing gdel .npz (skips running gdel)")
    ap.add_argument("--out-dir", type=Path, default=ROOT / "docs/img")
    ap.add_argument("--work-dir", type=Path, help="where bunny.npz goes (default: a temporary folder)")
    ap.add_argument("--dpi", type=int, default=90)
    args = ap.parse_args()

    with tempfile.TemporaryDirectory() as tmp:
        npz = args.npz
        if npz is None:
            work = args.work_dir or Path(tmp)
            work.mkdir(parents=True, exist_ok=True)
            npz = work / "bunny.npz"
            run_gdel(args.gdel, args.model, npz)
        with np.load(npz) as d:
            points, tets, neighbors = d["points"], d["tets"].astype(np.int64), d["neighbors"].astype(np.int64)

    q, vol = radius_ratio(points, tets)
    h = nearest_neighbour_spacing(points, tets)
    longest, shortest = edge_extremes(points, tets)
    rel = longest / h
    report(q, vol, rel, shortest, h, (neighbors < 0).any(1))

    args.out_dir.mkdir(parents=True, exist_ok=True)
    cut, hist = args.out_dir / "bunny-cutaway.png", args.out_dir / "bunny-quality-hist.png"
    render_cutaway(points, tets, neighbors, q, h, cut, args.dpi)
    render_histogram(q, rel, hist, args.dpi)
    for p in (cut, hist):
        print(f"wrote {p} ({p.stat().st_size / 1024:.0f} KiB)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
