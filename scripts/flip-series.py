#!/usr/bin/env python3
"""Pairs gFlip3D's large flip iterations with their steps' times (bench/RESULTS.md, session 60).

Input: the stderr of one run with GDEL_FLIP_TRACE=2, GDEL_PROFILE=1 and
GDEL_PROFILE_SERIES naming at least "flip: records + write tets" (the k-th interval of a
large-iteration step belongs to the k-th "large" iteration line). Prints, per insertion
round, each large iteration's flips and its steps' nanoseconds per flip, then the sums
over the rounds' first large iteration and over the later ones.

    python3 scripts/flip-series.py LOG [STEP ...]
"""
import re
import sys

STEPS = ["flip: propose", "flip: records + write tets", "flip: adjacency", "flip: next active set"]


def main():
    path = sys.argv[1]
    steps = sys.argv[2:] or STEPS
    iters, series = [], {}
    for line in open(path, errors="replace"):
        m = re.match(r"gflip3d flip iteration: active (\d+), flips (\d+) \(2-3 (\d+)\), (\w+)", line)
        if m:
            iters.append({"active": int(m[1]), "flips": int(m[2]), "large": m[4] == "large", "round": None})
            continue
        m = re.match(r"gflip3d round (\d+):", line)
        if m:
            for it in iters:
                if it["round"] is None:
                    it["round"] = int(m[1])
            continue
        m = re.match(r"profile series (\d+) (.+) ([0-9.]+)$", line.strip())
        if m:
            series.setdefault(m[2], []).append(float(m[3]))
    large = [it for it in iters if it["large"]]
    for s in steps:
        n = len(series.get(s, []))
        if n != len(large):
            print(f"# {s}: {n} intervals for {len(large)} large iterations (not paired)")
    steps = [s for s in steps if len(series.get(s, [])) == len(large)]
    for k, it in enumerate(large):
        it["ms"] = {s: series[s][k] for s in steps}
    print("round  iter  active      flips  " + "  ".join(f"{s.replace('flip: ', '')[:14]:>14}" for s in steps) + "   (ns a flip)")
    first, later = {s: [0.0, 0] for s in steps}, {s: [0.0, 0] for s in steps}
    for r in sorted({it["round"] for it in large if it["round"] is not None}):
        its = [it for it in large if it["round"] == r]
        for i, it in enumerate(its):
            f = max(it["flips"], 1)
            print(f"{r:5d} {i:5d} {it['active']:8d} {it['flips']:10d}  " +
                  "  ".join(f"{1e6 * it['ms'][s] / f:14.2f}" for s in steps))
            acc = first if i == 0 else later
            for s in steps:
                acc[s][0] += it["ms"][s]
                acc[s][1] += it["flips"]
    for name, acc in (("first large iteration of a round", first), ("later large iterations", later)):
        print(f"# {name}: " + ", ".join(
            f"{s} {acc[s][0]:.1f} ms / {acc[s][1]} flips = {1e6 * acc[s][0] / max(acc[s][1], 1):.2f} ns" for s in steps))


if __name__ == "__main__":
    main()
