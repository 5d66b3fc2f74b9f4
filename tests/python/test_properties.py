"""Property tests (hypothesis) on small random and degenerate point sets: every result
passes the exact verifier, and on general position it is scipy's triangulation."""

import itertools
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import example, given
from hypothesis import strategies as st
from scipy.spatial import Delaunay as ScipyDelaunay

import gdel
from helpers import check_neighbors, orient_exact, sorted_rows

ALGORITHMS = ["gdel3d", "gflip3d"]




def _affine_rank(p):
    """Exact affine rank (rational Gaussian elimination; floats convert exactly)."""
    rows = [[Fraction(float(v)) for v in r] for r in np.asarray(p)]
    m = [[a - b for a, b in zip(r, rows[0])] for r in rows[1:]]
    rank = 0
    for col in range(3):
        pivot = next((i for i in range(rank, len(m)) if m[i][col] != 0), None)
        if pivot is None:
            continue
        m[rank], m[pivot] = m[pivot], m[rank]
        for i in range(len(m)):
            if i != rank and m[i][col] != 0:
                f = m[i][col] / m[rank][col]
                m[i] = [a - f * b for a, b in zip(m[i], m[rank])]
        rank += 1
    return rank


def _expected_representative(p):
    first = {}
    return np.array([first.setdefault(tuple(row), i) for i, row in enumerate(np.asarray(p).tolist())])


def _assert_full_contract(p, tri, algorithm):
    report = gdel.check(p, tri.simplices)
    assert report.meets_contract(algorithm), report.summary
    assert report.inverted_tets == 0 and report.unused_points == 0 and report.euler_ok
    np.testing.assert_array_equal(tri.representative, _expected_representative(p))
    check_neighbors(tri.simplices, tri.neighbors)
    if algorithm == "gdel3d":
        assert report.delaunay and report.degenerate_tets == 0  # no flat tets, even on degenerate input
    return report


# -- general position: random coordinates from a seed ------------------------------


@given(n=st.integers(4, 80), seed=st.integers(0, 2**32 - 1), scale=st.sampled_from([1.0, 2.0**-80, 2.0**90]))
def test_random_sets_match_scipy(n, seed, scale):
    p = np.random.default_rng(seed).random((n, 3)) * scale
    tri = gdel.Delaunay(p)
    _assert_full_contract(p, tri, "gdel3d")
    ref = ScipyDelaunay(p)
    assert tri.nsimplex == ref.nsimplex
    assert sorted_rows(tri.simplices) == sorted_rows(ref.simplices)
    assert sorted_rows(tri.convex_hull) == sorted_rows(ref.convex_hull)


@given(n=st.integers(4, 60), seed=st.integers(0, 2**32 - 1))
def test_random_sets_gflip3d_valid(n, seed):
    p = np.random.default_rng(seed).normal(size=(n, 3))
    tri = gdel.Delaunay(p, algorithm="gflip3d")
    _assert_full_contract(p, tri, "gflip3d")


@given(
    n=st.integers(4, 40),
    seed=st.integers(0, 2**32 - 1),
    k=st.integers(-300, 300),
)
def test_power_of_two_scaling_does_not_change_the_triangulation(n, seed, k):
    # Scaling by 2^k is exact and preserves every predicate: the same triangulation,
    # including outside the predicates' direct range (the library rescales exactly).
    p = np.random.default_rng(seed).random((n, 3)) + 0.5
    a = gdel.Delaunay(p)
    b = gdel.Delaunay(np.ldexp(p, k))
    assert sorted_rows(a.simplices) == sorted_rows(b.simplices)


# -- degenerate sets: small integer grids (many coplanar and cospherical subsets) ----

grid_point = st.tuples(st.integers(0, 3), st.integers(0, 3), st.integers(0, 3))


@pytest.mark.parametrize("algorithm", ALGORITHMS)
@given(pts=st.lists(grid_point, min_size=4, max_size=40))
def test_grid_subsets(algorithm, pts):
    p = np.array(pts, dtype=np.float64)
    if _affine_rank(p) < 3:
        with pytest.raises(gdel.DegenerateInputError):
            gdel.Delaunay(p, algorithm=algorithm)
        return
    tri = gdel.Delaunay(p, algorithm=algorithm)
    _assert_full_contract(p, tri, algorithm)
    # every input point is located, also among gflip3d's flat tets (NaN transforms)
    assert (tri.find_simplex(p) >= 0).all()


# Integer points on the sphere of radius 3: all cospherical.
SPHERE3 = sorted(
    {
        tuple(s * v for s, v in zip(signs, perm))
        for base in ((3, 0, 0), (1, 2, 2))
        for perm in itertools.permutations(base)
        for signs in itertools.product((1, -1), repeat=3)
    }
)


@pytest.mark.parametrize("algorithm", ALGORITHMS)
@given(
    idx=st.lists(st.integers(0, len(SPHERE3) - 1), min_size=4, max_size=40),
    center=st.booleans(),
)
def test_cospherical_sets(algorithm, idx, center):
    p = np.array([SPHERE3[i] for i in idx], dtype=np.float64)
    if center:
        p = np.concatenate([p, [[0.0, 0.0, 0.0]]])
    if _affine_rank(p) < 3:
        with pytest.raises(gdel.DegenerateInputError):
            gdel.Delaunay(p, algorithm=algorithm)
        return
    tri = gdel.Delaunay(p, algorithm=algorithm)
    _assert_full_contract(p, tri, algorithm)
    # Exact orientation: positive; gflip3d may leave flat tets on such input.
    allowed = {1} if algorithm == "gdel3d" else {0, 1}
    for t in tri.simplices[:20]:
        assert orient_exact(*p[t]) in allowed


@given(
    base=st.lists(st.tuples(*[st.floats(-1e3, 1e3, allow_nan=False, width=32)] * 3), min_size=4, max_size=25),
    dup=st.lists(st.integers(0, 24), max_size=10),
)
# a sliver whose rounded centroid misses its interior (found by this test, 2026-11-29:
# "no interior point of the first tetrahedron is representable")
@example(base=[(0.0, 0.0, 0.0), (0.0, 0.0, 1.1754943508222875e-38), (0.0, 1.0, 0.0), (1.0, 0.0, 1.0)], dup=[])
def test_float32_sets_with_duplicates(base, dup):
    b = np.array(base, dtype=np.float32)
    p = np.concatenate([b, b[[d % len(b) for d in dup]]]) if dup else b
    if _affine_rank(p) < 3:
        with pytest.raises(gdel.DegenerateInputError):
            gdel.Delaunay(p)
        return
    tri = gdel.Delaunay(p)
    _assert_full_contract(p.astype(np.float64), tri, "gdel3d")
    assert (tri.vertex_to_simplex[tri.representative != np.arange(len(p))] == -1).all()


# Found by test_float32_sets_with_duplicates (2026-12-05): a sliver with a short edge of
# length 2^-126 whose interior holds doubles (e.g. (2^-53 - 2^-106, 1 - 2^-53, 2^-106 -
# 2^-140)) that the kernel point's first search (weights 2^-e) missed ("tetrahedron too
# thin"); geom::interior_point (a coordinate-by-coordinate search) finds one.
def test_thin_first_tetrahedron_with_interior_doubles():
    p = np.array([(0.0, 0.0, 1.0), (0.0, 1.0, 0.0), (0.0, 1.0, -1.1754943508222875e-38), (1.0, 0.0, 0.0)])
    assert orient_exact(*p) != 0
    _assert_full_contract(p, gdel.Delaunay(p), "gdel3d")


# Found by a stress run of float32 sets like the test above (session 55): four points
# nearly on the plane x = y, 2^-149 off it at most, so the tet is 2^-149 thick across
# that plane where its coordinates are about 1 (doubles 2^-52 apart) and reaches
# coordinates below 2^-97 (where doubles are fine enough) only at heights no double
# represents: no double lies strictly inside it. The kernel point that stands for infinity
# is then the exact centroid of the tet (docs/gflip3d.md); CGAL triangulates it too (one
# tet). With more points on the same two planes one ulp apart, every insertion is
# located and flipped with orientations against that centroid.
def test_first_tetrahedron_without_a_kernel_point():
    p = np.array([(1.5, 1.5, 2.0), (0.0, 1.401298464324817e-45, -504.2170104980469),
                  (0.5, 0.5, -1.1754943508222875e-38), (2.0, 2.0, 2.350988701644575e-38)])
    assert orient_exact(*p) != 0
    tri = gdel.Delaunay(p)
    _assert_full_contract(p, tri, "gdel3d")
    assert tri.stats["kernel_point_centroid"] == 1
    rng = np.random.default_rng(55)
    q = np.column_stack([1 + np.ldexp(1.0, -52) * (np.arange(500) % 2), rng.random(500), rng.random(500)])
    tri = gdel.Delaunay(q)
    _assert_full_contract(q, tri, "gdel3d")
    assert tri.stats["kernel_point_centroid"] == 1


@given(
    pts=st.lists(grid_point, min_size=4, max_size=30),
    queries=st.lists(st.tuples(*[st.integers(-1, 7)] * 3), min_size=1, max_size=30),
)
def test_find_simplex_on_grid_sets(pts, queries):
    # Half-integer queries over an integer grid: exactly on faces, edges and vertices
    # as often as strictly inside or outside. A query is outside the hull exactly when
    # it lies strictly beyond some (outward) hull face; otherwise find_simplex returns
    # a simplex whose barycentric coordinates are all >= -tol.
    p = np.array(pts, dtype=np.float64)
    if _affine_rank(p) < 3:
        return
    tri = gdel.Delaunay(p)
    x = np.array(queries, dtype=np.float64) / 2
    found = tri.find_simplex(x)
    hull = tri.convex_hull
    for q, s in zip(x, found):
        outside = any(orient_exact(p[a], p[b], p[c], q) > 0 for a, b, c in hull)
        assert (s < 0) == outside, (q, s)
        if s >= 0:
            t = tri.transform[s]
            c3 = t[:3] @ (q - t[3])
            assert min(c3.min(), 1 - c3.sum()) >= -100 * np.finfo(float).eps
    # every input point lies in (the closure of) some simplex
    assert (tri.find_simplex(p) >= 0).all()
