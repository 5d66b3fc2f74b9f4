"""Helpers shared by the gdel Python tests."""

from fractions import Fraction

import numpy as np


def sorted_rows(a):
    """The rows of an integer array as a set of sorted tuples (orientation-free)."""
    return set(map(tuple, np.sort(np.asarray(a), axis=1).tolist()))


def uniform(n, seed):
    """n points uniform in the unit cube: general position with probability 1."""
    return np.random.default_rng(seed).random((n, 3))


def orient_exact(a, b, c, d):
    """Sign of det[b-a, c-a, d-a] in exact rational arithmetic (floats convert exactly)."""
    a, b, c, d = ([Fraction(float(v)) for v in p] for p in (a, b, c, d))
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    w = [d[i] - a[i] for i in range(3)]
    det = (
        u[0] * (v[1] * w[2] - v[2] * w[1])
        - u[1] * (v[0] * w[2] - v[2] * w[0])
        + u[2] * (v[0] * w[1] - v[1] * w[0])
    )
    return (det > 0) - (det < 0)


def check_neighbors(simplices, neighbors):
    """Asserts scipy's neighbour convention: neighbors[s, i] shares the face opposite
    vertex i of s, and points back to s across the face opposite its own apex; -1
    exactly on faces that belong to one simplex."""
    simplices = np.asarray(simplices)
    neighbors = np.asarray(neighbors)
    face_count = {}
    for s in simplices:
        for i in range(4):
            key = tuple(sorted(np.delete(s, i).tolist()))
            face_count[key] = face_count.get(key, 0) + 1
    for s, (tet, nbs) in enumerate(zip(simplices, neighbors)):
        for i in range(4):
            face = set(np.delete(tet, i).tolist())
            t = nbs[i]
            if t < 0:
                assert face_count[tuple(sorted(face))] == 1, f"simplex {s} face {i}: -1 on an interior face"
                continue
            other = set(simplices[t].tolist())
            assert face <= other, f"simplex {s} face {i}: neighbour {t} does not contain the face"
            apex = (other - face).pop()
            j = simplices[t].tolist().index(apex)
            assert neighbors[t, j] == s, f"simplex {s} face {i}: neighbour {t} does not point back"
