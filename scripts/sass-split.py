#!/usr/bin/env python3
"""Where a kernel's warps diverge: ncu source counters mapped onto the kernel's SASS.

  python3 scripts/sass-split.py SASS CSV.gz KERNEL [--windows N] [--flow FUNCTION]

SASS: `nvdisasm -c` of the cubin that holds the kernel (cuobjdump -xelf all OBJECT, then
nvdisasm; both ship in NVIDIA's nvidia-cuda-cuobjdump / nvidia-cuda-nvdisasm wheels).
CSV.gz: `ncu -i REPORT --page source --csv --print-source sass` of one launch of it with the
SourceCounters section (scripts/gpu-run.sh plan s44a writes it). KERNEL: a substring of the
kernel's mangled name. Prints, per function of the kernel's section (the kernel's own code and
each out-of-line callee), its share of warp and thread instructions, threads per warp
instruction and stall samples; --windows N the hottest windows of N instructions; --flow F the
control-flow instructions (BSSY, BSYNC, BRA, CALL, VOTE, ...) of functions matching F ("body":
the kernel's own code) with their execution counts and threads per execution.
"""
import argparse
import collections
import csv
import gzip
import re
import subprocess


def demangle(name):
    return subprocess.run(["c++filt"], input=name, capture_output=True, text=True).stdout.strip()


def kernel_sass(path, kernel):
    """(offset, function, instruction) for the kernel's section, function = the label above."""
    lines = open(path).read().split("\n")
    start = next(i for i, l in enumerate(lines) if l.startswith(".text.") and kernel in l)
    cur, body = "kernel body", []
    for l in lines[start + 1:]:
        if l.startswith(".text.") or l.strip().startswith(".section"):
            break
        m = re.match(r"^\$(\S+?)\$(\S+):", l)
        if m:
            cur = m.group(2)
        m = re.search(r"/\*([0-9a-f]{4,})\*/\s+(.*?);", l)
        if m:
            body.append((int(m.group(1), 16), cur, m.group(2)))
    return body


def counters(path):
    """offset -> (warp instructions, thread instructions, samples), offsets from the first row."""
    with gzip.open(path, "rt") as f:
        rows = list(csv.reader(l for l in f if l.startswith('"')))
    h = next(i for i, x in enumerate(rows) if x and x[0] == "Address")
    hdr = rows[h]
    data = [dict(zip(hdr, x)) for x in rows[h + 1:] if x and x[0].startswith("0x")]
    base = int(data[0]["Address"], 16)
    num = lambda s: float(s.replace(",", "") or 0)
    return {int(d["Address"], 16) - base: (num(d["Instructions Executed"]), num(d["Thread Instructions Executed"]),
                                           num(d["# Samples"])) for d in data}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("sass")
    ap.add_argument("csv")
    ap.add_argument("kernel")
    ap.add_argument("--windows", type=int, default=0)
    ap.add_argument("--flow", default="")
    a = ap.parse_args()
    body = kernel_sass(a.sass, a.kernel)
    cnt = counters(a.csv)
    if len(cnt) != len(body):
        print(f"warning: {len(cnt)} counted instructions, {len(body)} in the SASS (another build?)")
    agg = collections.defaultdict(lambda: [0.0, 0.0, 0.0, 0])
    for o, f, _ in body:
        w, t, s = cnt.get(o, (0, 0, 0))
        x = agg[f]
        x[0] += w
        x[1] += t
        x[2] += s
        x[3] += 1
    W = sum(x[0] for x in agg.values()) or 1
    T = sum(x[1] for x in agg.values()) or 1
    S = sum(x[2] for x in agg.values()) or 1
    print(f"all: warp instructions {W / 1e9:.2f} G, thread instructions {T / 1e9:.2f} G, {T / W:.2f} threads each")
    for f, x in sorted(agg.items(), key=lambda kv: -kv[1][0]):
        name = f if f == "kernel body" else demangle(f)
        print(f"  {x[0] / W * 100:5.1f}% warp {x[1] / T * 100:5.1f}% thread {x[1] / max(x[0], 1):5.2f} thr/inst "
              f"{x[2] / S * 100:5.1f}% samples  n={x[3]:5d}  {name[:100]}")
    if a.windows:
        win = collections.defaultdict(lambda: [0.0, 0.0, 0.0, None])
        for o, f, _ in body:
            w, t, s = cnt.get(o, (0, 0, 0))
            x = win[(f, o // (16 * a.windows))]
            x[0] += w
            x[1] += t
            x[2] += s
            x[3] = o if x[3] is None else x[3]
        print(f"hottest windows of {a.windows} instructions:")
        for (f, _), x in sorted(win.items(), key=lambda kv: -kv[1][0])[:25]:
            name = f if f == "kernel body" else demangle(f)
            print(f"  {x[0] / W * 100:5.1f}% warp {x[1] / max(x[0], 1):5.2f} thr/inst {x[2] / S * 100:5.1f}% samples"
                  f"  @{x[3]:#x} {name[:60]}")
    if a.flow:
        pat = re.compile(r"\b(BSSY|BSYNC|BRA|BRX|CALL|RET|BREAK|BMOV|WARPSYNC|EXIT|YIELD|VOTE)\b")
        for o, f, t in body:
            if (a.flow == "body" and f == "kernel body") or (a.flow != "body" and a.flow in f):
                if pat.search(t):
                    w, th, _ = cnt.get(o, (0, 0, 0))
                    print(f"{o:#08x} {w:12.0f} {th / max(w, 1):5.2f}  {re.sub(r'[$]_ZN4gdel3par6detail14scratch_kernel[^$]*[$]', '', t)[:110]}")


if __name__ == "__main__":
    main()
