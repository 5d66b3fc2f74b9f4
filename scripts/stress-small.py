#!/usr/bin/env python3
"""Stress run: many small hostile point sets through the `gdel` command, each checked exactly.

Every set is written as .xyz and triangulated with `gdel delaunay --check` by gdel3d (and
on the CPU also by gdel3d with the GPU's rounds, --cpu-rounds) and gstar4d. A run passes
when every result is verified ("check: OK") or the set is reported degenerate (fewer than
four distinct points, all coplanar). The generators aim at the first tetrahedron and its
kernel point (docs/gflip3d.md): clusters a few ulps wide, points on two planes one ulp
apart (no double inside any tetrahedron), tiny and subnormal coordinates, and mixtures.

    scripts/stress-small.py --gdel build/cpu/gdel [--device cpu|cuda] [--sets 1000] [--seed 1]
                            [--seconds S]   (no new set after S seconds)

Failing sets are kept under --keep (default build/stress-small/) with the command's output.
Exit status 0 when none failed. Standard library only (runs on the device machine too).
"""
import argparse
import pathlib
import random
import subprocess
import sys
import tempfile
import time

U = 2.0 ** -52  # one ulp of the doubles in [1, 2)


def ulp_cluster(rng, n):
    base = [rng.choice([1.0, 0.75, 3.0, -2.0]) for _ in range(3)]
    k = rng.choice([1, 2, 3])
    return [tuple(b + abs(b) * U * rng.randint(0, k) for b in base) for _ in range(n)]


def planes(rng, n):
    return [(1 + U * rng.randint(0, 1), rng.random(), rng.random()) for _ in range(n)]


def planes_lattice(rng, n):
    return [(1 + U * rng.randint(0, 1), rng.randint(0, 3) / 4, rng.randint(0, 3) / 4) for _ in range(n)]


def tiny(rng, n):
    e = rng.choice([-149, -126, -100])
    vals = [0.0, 2.0 ** e, -(2.0 ** e), 1.0, 0.5, 2.0 ** (e + 1)]
    return [tuple(rng.choice(vals) for _ in range(3)) for _ in range(n)]


def mixed(rng, n):
    near = [(1 + rng.uniform(-1, 1) * 1e-3, 1 + rng.uniform(-1, 1) * 1e-3, 1 + U * rng.randint(0, 1))
            for _ in range(n - n // 2)]
    return ulp_cluster(rng, n // 2) + near


GENERATORS = [ulp_cluster, planes, planes_lattice, tiny, mixed]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--gdel", required=True, help="the gdel command to run")
    ap.add_argument("--device", default="cpu", choices=["cpu", "cuda"])
    ap.add_argument("--sets", type=int, default=1000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--keep", default="build/stress-small")
    ap.add_argument("--seconds", type=float, default=0, help="start no new set after this long (0: no limit)")
    a = ap.parse_args()
    rng = random.Random(a.seed)
    algorithms = [["gdel3d"], ["gstar4d"]] + ([["gdel3d", "--cpu-rounds"]] if a.device == "cpu" else [])
    tally, failed, done = {}, 0, 0
    t0 = time.monotonic()
    keep = pathlib.Path(a.keep)
    with tempfile.TemporaryDirectory() as tmp:
        src, dst = pathlib.Path(tmp, "in.xyz"), pathlib.Path(tmp, "out.npz")
        for it in range(a.sets):
            if a.seconds and time.monotonic() - t0 > a.seconds:
                break
            done += 1
            gen = rng.choice(GENERATORS)
            pts = gen(rng, rng.randint(4, 40))
            src.write_text("".join("%r %r %r\n" % p for p in pts))
            for alg in algorithms:
                cmd = [a.gdel, "delaunay", str(src), "-o", str(dst), "--check", "--stats", "--device", a.device,
                       "--algorithm"] + alg
                try:
                    r = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
                    out, rc = r.stdout + r.stderr, r.returncode
                except subprocess.TimeoutExpired:
                    out, rc = "timed out after 120 s", -1
                ok = rc == 0 and "check: OK" in out
                degenerate = rc != 0 and ("coplanar" in out or "need at least 4" in out)
                centroid = "kernel point: the exact centroid" in out
                key = (gen.__name__, "ok" if ok else "degenerate" if degenerate else "FAILED", centroid)
                tally[key] = tally.get(key, 0) + 1
                if not ok and not degenerate:
                    failed += 1
                    keep.mkdir(parents=True, exist_ok=True)
                    name = "%s-%d-%s" % (gen.__name__, it, "-".join(x.strip("-") for x in alg))
                    (keep / (name + ".xyz")).write_text(src.read_text())
                    (keep / (name + ".log")).write_text(" ".join(cmd) + "\n" + out)
                    print("FAILED", name, "rc", rc, out[-300:], flush=True)
    print("generator, outcome, kernel point an exact centroid: runs")
    for k in sorted(tally):
        print("  %-15s %-10s %-5s %d" % (*k, tally[k]))
    print("%d sets, %d runs, %d failed (%.0f s)" % (done, sum(tally.values()), failed, time.monotonic() - t0))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
