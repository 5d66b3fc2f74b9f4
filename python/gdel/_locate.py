"""Point location in a triangulation with barycentric coordinates (scipy's semantics).

A point x lies in simplex s when all four barycentric coordinates of x with respect to
s are >= -tol. Coordinates come from scipy's affine ``transform``: for simplex s with
vertices r0..r3, ``c[:3] = transform[s, :3] @ (x - transform[s, 3])`` and
``c[3] = 1 - sum(c[:3])``; coordinate j belongs to vertex j, so a negative c[j] means x
is beyond the face opposite vertex j, which is where ``neighbors[s, j]`` lies.

The search is a vectorised visibility walk (from a simplex near each query, step to the
neighbour across the most negative coordinate), which terminates on a Delaunay
triangulation; leaving through a hull face whose coordinate is below -tol proves the
point is outside the convex hull (the face's plane separates it from every point).
Queries that have not settled after a bounded number of steps, or meet a degenerate
simplex, are resolved by brute force over all simplices, which returns the first
simplex (lowest index) containing the point.
"""

from __future__ import annotations

import numpy as np

# Work per vectorised block: queries x simplices x 4 doubles.
_BLOCK = 1 << 20


def affine_transform(points: np.ndarray, simplices: np.ndarray) -> np.ndarray:
    """scipy's ``Delaunay.transform``: (m, 4, 3); NaN rows for zero-volume simplices."""
    p = points[simplices]  # (m, 4, 3)
    r = p[:, 3, :]
    a, b, c = p[:, 0, :] - r, p[:, 1, :] - r, p[:, 2, :] - r
    # Inverse of the matrix with columns a, b, c: rows (b x c, c x a, a x b) / det.
    bc, ca, ab = np.cross(b, c), np.cross(c, a), np.cross(a, b)
    det = np.einsum("ij,ij->i", a, bc)
    t = np.empty((len(simplices), 4, 3), dtype=np.float64)
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / det
        t[:, 0, :] = bc * inv[:, None]
        t[:, 1, :] = ca * inv[:, None]
        t[:, 2, :] = ab * inv[:, None]
    t[:, 3, :] = r
    t[det == 0] = np.nan
    return t


def _barycentric(transform: np.ndarray, s: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Coordinates (k, 4) of queries x (k, 3) in simplices s (k,)."""
    t = transform[s]
    c3 = np.einsum("kij,kj->ki", t[:, :3, :], x - t[:, 3, :])
    return np.concatenate([c3, 1.0 - c3.sum(axis=1, keepdims=True)], axis=1)


def _start_simplices(points: np.ndarray, vertex_to_simplex: np.ndarray, x: np.ndarray) -> np.ndarray:
    """For each query, a simplex of the nearest of up to 256 evenly spread vertices."""
    used = np.flatnonzero(vertex_to_simplex >= 0)
    k = min(len(used), 256)
    sample = used[np.linspace(0, len(used) - 1, k).astype(np.int64)]
    sp = points[sample]
    start = np.empty(len(x), dtype=np.int64)
    step = max(1, _BLOCK // (3 * k))
    for i in range(0, len(x), step):
        d = ((x[i : i + step, None, :] - sp[None, :, :]) ** 2).sum(axis=2)
        start[i : i + step] = vertex_to_simplex[sample[np.argmin(d, axis=1)]]
    return start


def _walk(
    transform: np.ndarray,
    neighbors: np.ndarray,
    x: np.ndarray,
    start: np.ndarray,
    tol: float,
    max_steps: int,
) -> np.ndarray:
    """Result per query: simplex, -1 (outside), or -2 (unsettled: brute force)."""
    result = np.full(len(x), -2, dtype=np.int64)
    cur = start.copy()
    active = np.arange(len(x))
    for _ in range(max_steps):
        if active.size == 0:
            break
        s = cur[active]
        c = _barycentric(transform, s, x[active])
        j = np.argmin(c, axis=1)
        cmin = c[np.arange(len(s)), j]
        degenerate = np.any(np.isnan(c), axis=1)
        inside = (cmin >= -tol) & ~degenerate
        result[active[inside]] = s[inside]
        nxt = neighbors[s, j]
        outside = ~inside & ~degenerate & (nxt < 0)
        result[active[outside]] = -1
        move = ~inside & ~outside & ~degenerate
        cur[active[move]] = nxt[move]
        active = active[move]
    return result


def _brute_force(transform: np.ndarray, x: np.ndarray, tol: float) -> np.ndarray:
    """First simplex (lowest index) containing each query within tol, else -1."""
    m = len(transform)
    found = np.full(len(x), -1, dtype=np.int64)
    tchunk = min(m, 1 << 16)
    for t0 in range(0, m, tchunk):
        t = transform[t0 : t0 + tchunk]
        todo = np.flatnonzero(found < 0)
        qchunk = max(1, _BLOCK // (4 * len(t)))
        for q0 in range(0, len(todo), qchunk):
            q = todo[q0 : q0 + qchunk]
            c3 = np.einsum("tij,qtj->qti", t[:, :3, :], x[q][:, None, :] - t[None, :, 3, :])
            c = np.concatenate([c3, 1.0 - c3.sum(axis=2, keepdims=True)], axis=2)
            ok = np.all(c >= -tol, axis=2)  # NaN (degenerate simplex) compares False
            has = np.any(ok, axis=1)
            found[q[has]] = t0 + np.argmax(ok[has], axis=1)
    return found


def find_simplex(
    points: np.ndarray,
    simplices: np.ndarray,
    neighbors: np.ndarray,
    transform: np.ndarray,
    vertex_to_simplex: np.ndarray,
    x: np.ndarray,
    tol: float,
    bruteforce: bool,
) -> np.ndarray:
    """Simplex index per query row of x (k, 3), -1 outside; int32."""
    m = len(simplices)
    if len(x) == 0 or m == 0:
        return np.full(len(x), -1, dtype=np.int32)
    if bruteforce:
        return _brute_force(transform, x, tol).astype(np.int32)
    start = _start_simplices(points, vertex_to_simplex, x)
    max_steps = 64 + 16 * int(round(m ** (1.0 / 3.0)))
    result = _walk(transform, neighbors, x, start, tol, max_steps)
    left = np.flatnonzero(result == -2)
    if left.size:
        result[left] = _brute_force(transform, x[left], tol)
    return result.astype(np.int32)
