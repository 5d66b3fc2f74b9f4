"""gdel.Regular / gdel.regular: the exact regular triangulation from Python."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import gdel
from helpers import check_neighbors, sorted_rows, uniform


def _weights(n, scale, seed, lo=0.0):
    h = 1.0 / np.cbrt(n)
    return scale * h * h * np.random.default_rng(seed).uniform(lo, 1.0, n)


def test_regular_is_certified_and_lists_the_hidden_points():
    p = uniform(3000, 1)
    w = _weights(3000, 3.0, 2)
    r = gdel.Regular(p, w, device="cpu", check=True, certificates=True)
    assert r.stats["algorithm"] == "greg3d"
    assert r.check_report.delaunay and r.check_report.redundant_points == len(r.redundant)
    assert r.simplices.dtype == np.int32 and r.simplices.shape[1] == 4
    used = np.zeros(3000, dtype=bool)
    used[r.simplices.ravel()] = True
    np.testing.assert_array_equal(r.redundant, np.flatnonzero(~used))
    assert 0.2 * 3000 < len(r.redundant) < 0.8 * 3000  # this weight scale hides a good share
    assert r.certificates.shape == (len(r.redundant), 5)
    assert (r.vertex_to_simplex[r.redundant] == -1).all()
    check_neighbors(r.simplices, r.neighbors)
    np.testing.assert_array_equal(r.weights, w)
    assert gdel.check(p, r.simplices, w).delaunay
    assert not gdel.check(p, gdel.Delaunay(p, device="cpu").simplices, w).delaunay


def test_equal_weights_give_the_delaunay_triangulation():
    p = uniform(2000, 3)
    r = gdel.regular(p, np.full(2000, 0.25), device="cpu")
    d = gdel.Delaunay(p, device="cpu")
    assert len(r.redundant) == 0
    assert sorted_rows(r.simplices) == sorted_rows(d.simplices)


def test_duplicates_keep_the_heaviest_copy():
    p = uniform(200, 4)
    p = np.vstack([p, p[[5, 7]]])
    w = np.zeros(202)
    w[200], w[201] = 1e-12, -1e-12
    r = gdel.Regular(p, w, device="cpu", certificates=True)
    np.testing.assert_array_equal(r.redundant, [5, 201])
    assert r.representative[5] == 200 and r.representative[201] == 7
    np.testing.assert_array_equal(r.certificates[0], [200, -1, -1, -1, -1])


def test_bad_input_raises_value_error():
    p = uniform(50, 5)
    with pytest.raises(ValueError, match="weights"):
        gdel.Regular(p, np.zeros(49), device="cpu")
    w = np.zeros(50)
    w[3] = np.nan
    with pytest.raises(ValueError, match="row 3"):
        gdel.Regular(p, w, device="cpu")
    with pytest.raises(gdel.DegenerateInputError):
        gdel.Regular(np.zeros((10, 3)), np.zeros(10), device="cpu")


def test_torch_cpu_tensors_are_accepted():
    torch = pytest.importorskip("torch")
    p = uniform(500, 6)
    w = _weights(500, 3.0, 7)
    a = gdel.Regular(p, w, device="cpu")
    b = gdel.Regular(torch.from_numpy(p), torch.from_numpy(w), device="cpu")
    assert isinstance(b.simplices, np.ndarray)  # CPU inputs give numpy outputs, as for Delaunay
    np.testing.assert_array_equal(b.simplices, a.simplices)
    np.testing.assert_array_equal(b.redundant, a.redundant)


@given(
    st.integers(min_value=5, max_value=40).flatmap(
        lambda n: st.tuples(
            st.lists(st.tuples(*[st.integers(-4, 4)] * 3), min_size=n, max_size=n),
            st.lists(st.sampled_from([0.0, 0.5, 1.0, 2.0, -1.0]), min_size=n, max_size=n),
        )
    )
)
def test_small_degenerate_weighted_sets_pass_the_exact_check(data):
    pts, w = np.array(data[0], dtype=np.float64), np.array(data[1])
    try:
        r = gdel.Regular(pts, w, device="cpu", check=True, certificates=True)
    except gdel.DegenerateInputError:
        return  # coplanar or fewer than 4 distinct points
    assert r.check_report.delaunay
    assert r.check_report.unused_points == 0
