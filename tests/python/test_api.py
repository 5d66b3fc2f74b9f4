"""gdel's Python API: result types, accepted inputs, errors, the verifier, packaging."""

import importlib.metadata
import importlib.resources
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import gdel
from gdel import _core
from helpers import check_neighbors, orient_exact, sorted_rows, uniform

# ---------------------------------------------------------------------------
# Result arrays
# ---------------------------------------------------------------------------


def test_result_types_and_shapes():
    p = uniform(200, 1)
    tri = gdel.Delaunay(p)
    m = tri.nsimplex
    assert m > 0 and tri.npoints == 200 and tri.ndim == 3
    for name, shape in [
        ("simplices", (m, 4)),
        ("neighbors", (m, 4)),
        ("vertex_to_simplex", (200,)),
        ("representative", (200,)),
        ("failed_vertices", (0,)),
        ("coplanar", (0, 3)),
    ]:
        a = getattr(tri, name)
        assert isinstance(a, np.ndarray), name
        assert a.dtype == np.int32, name
        assert a.shape == shape, name
    assert tri.convex_hull.dtype == np.int32 and tri.convex_hull.shape[1] == 3
    indptr, indices = tri.vertex_neighbor_vertices
    assert indptr.dtype == np.int32 and indices.dtype == np.int32 and indptr.shape == (201,)
    assert tri.transform.shape == (m, 4, 3) and tri.transform.dtype == np.float64
    np.testing.assert_array_equal(tri.representative, np.arange(200))
    # Every input point is a vertex, every vertex id in range.
    assert set(np.unique(tri.simplices).tolist()) == set(range(200))
    s = tri.stats
    assert s["algorithm"] == "gdel3d" and s["backend"] in ("cpu", "cuda")
    assert s["points"] == 200 and s["distinct_points"] == 200 and s["seconds"] > 0
    assert isinstance(s["stages"], dict) and len(s["stages"]) > 0
    assert "gdel3d" in s["summary"]
    assert tri.check_report is None
    assert "200 points" in repr(tri)


def test_simplices_are_positively_oriented_exactly():
    p = uniform(60, 2)
    tri = gdel.Delaunay(p)
    for t in tri.simplices:
        assert orient_exact(*p[t]) == 1


def test_result_arrays_own_their_memory():
    tri = gdel.Delaunay(uniform(50, 3))
    for a in (tri.simplices, tri.neighbors, tri.representative):
        # numpy view over a capsule-owned buffer: not a copy of another numpy array,
        # and it stays valid after the triangulation object is gone.
        assert a.base is not None and not isinstance(a.base, np.ndarray)
    s = tri.simplices.copy()
    keep = tri.simplices
    del tri
    np.testing.assert_array_equal(keep, s)


def test_neighbors_and_vertex_to_simplex_consistent():
    tri = gdel.Delaunay(uniform(150, 4))
    check_neighbors(tri.simplices, tri.neighbors)
    for v, s in enumerate(tri.vertex_to_simplex):
        assert v in tri.simplices[s]


def test_convex_hull_faces_point_outward():
    p = uniform(300, 5)
    tri = gdel.Delaunay(p)
    inside = p.mean(axis=0)
    hull = tri.convex_hull
    assert len(hull) == int((tri.neighbors < 0).sum())
    for a, b, c in hull:
        normal = np.cross(p[b] - p[a], p[c] - p[a])
        assert np.dot(normal, p[a] - inside) > 0
        # and every input point is on the inner side (or on the plane)
        assert (np.array([orient_exact(p[a], p[b], p[c], q) for q in p[::15]]) <= 0).all()


def test_functional_form_matches_class():
    p = uniform(100, 6)
    a = gdel.delaunay(p)
    b = gdel.Delaunay(p)
    assert isinstance(a, gdel.Delaunay)
    np.testing.assert_array_equal(a.simplices, b.simplices)  # deterministic (100 points: one thread)


# ---------------------------------------------------------------------------
# Inputs: dtypes, layouts, array kinds
# ---------------------------------------------------------------------------


def _layouts(p):
    n = len(p)
    wide = np.zeros((n, 6))
    wide[:, ::2] = p
    tall = np.zeros((2 * n, 3))
    tall[::2] = p
    ro = p.copy()
    ro.flags.writeable = False
    return {
        "fortran": np.asfortranarray(p),
        "column-strided": wide[:, ::2],
        "row-strided": tall[::2],
        "negative-stride": p[::-1].copy()[::-1],
        "read-only": ro,
        "big-endian": p.astype(">f8"),
        "list": p.tolist(),
        "tuple-of-tuples": tuple(map(tuple, p.tolist())),
    }


@pytest.mark.parametrize("layout", list(_layouts(uniform(4, 0)).keys()))
def test_layouts_give_the_same_triangulation(layout):
    p = uniform(120, 7)
    ref = gdel.Delaunay(p)
    tri = gdel.Delaunay(_layouts(p)[layout])
    np.testing.assert_array_equal(tri.simplices, ref.simplices)
    np.testing.assert_array_equal(tri.points, p)
    assert tri.points.dtype == np.float64 and tri.points.flags.c_contiguous


def test_contiguous_float64_input_is_not_copied():
    p = uniform(80, 8)
    tri = gdel.Delaunay(p)
    assert tri.points is p


def test_float32_input_converted_once_to_float64():
    p32 = uniform(150, 9).astype(np.float32)
    tri = gdel.Delaunay(p32)
    assert tri.points.dtype == np.float64
    np.testing.assert_array_equal(tri.points, p32.astype(np.float64))
    assert not np.shares_memory(tri.points, p32)
    ref = gdel.Delaunay(p32.astype(np.float64))
    assert sorted_rows(tri.simplices) == sorted_rows(ref.simplices)
    assert gdel.check(p32, tri.simplices).delaunay


def test_integer_input():
    p = np.random.default_rng(10).integers(-1000, 1000, size=(100, 3))
    tri = gdel.Delaunay(p)
    np.testing.assert_array_equal(tri.points, p.astype(np.float64))
    assert gdel.check(p, tri.simplices).delaunay
    with pytest.raises(ValueError, match="2\\^53"):
        gdel.Delaunay(np.full((5, 3), 2**60, dtype=np.int64))


class _DLPackOnly:
    """A minimal DLPack producer: no buffer protocol, no __array__."""

    def __init__(self, a):
        self._a = a

    def __dlpack__(self, **kwargs):
        return self._a.__dlpack__(**kwargs)

    def __dlpack_device__(self):
        return self._a.__dlpack_device__()


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_dlpack_producer(dtype):
    p = uniform(90, 12).astype(dtype)
    tri = gdel.Delaunay(_DLPackOnly(p))
    ref = gdel.Delaunay(p)
    assert isinstance(tri.simplices, np.ndarray)
    np.testing.assert_array_equal(tri.simplices, ref.simplices)
    np.testing.assert_array_equal(tri.points, p.astype(np.float64))
    loc = tri.find_simplex(_DLPackOnly(p[:10].astype(np.float64)))
    assert isinstance(loc, np.ndarray) and (loc >= 0).all()


def test_torch_cpu_tensors():
    torch = pytest.importorskip("torch")
    p = uniform(90, 13)
    ref = gdel.Delaunay(p)
    t = torch.tensor(p, requires_grad=True)
    tri = gdel.Delaunay(t)
    assert isinstance(tri.simplices, np.ndarray)  # CPU inputs give numpy outputs
    np.testing.assert_array_equal(tri.simplices, ref.simplices)
    tri32 = gdel.Delaunay(torch.tensor(p, dtype=torch.float32).t().contiguous().t())  # strided float32
    np.testing.assert_array_equal(tri32.points, p.astype(np.float32).astype(np.float64))
    assert gdel.check(tri32.points, tri32.simplices).delaunay


def test_jax_cpu_arrays():
    jax = pytest.importorskip("jax")
    jnp = pytest.importorskip("jax.numpy")
    cpu = jax.devices("cpu")[0]  # explicitly: jax puts arrays on a GPU by default where it has one
    p = uniform(90, 14)
    tri = gdel.Delaunay(jax.device_put(jnp.asarray(p.astype(np.float32)), cpu))
    assert isinstance(tri.simplices, np.ndarray)
    np.testing.assert_array_equal(tri.points, p.astype(np.float32).astype(np.float64))
    assert sorted_rows(tri.simplices) == sorted_rows(gdel.Delaunay(p.astype(np.float32)).simplices)
    assert gdel.check(tri.points, tri.simplices).delaunay
    loc = tri.find_simplex(jax.device_put(jnp.asarray(p[:5].astype(np.float32)), cpu))
    assert isinstance(loc, np.ndarray) and (loc >= 0).all()


# ---------------------------------------------------------------------------
# Errors
# ---------------------------------------------------------------------------


@pytest.mark.parametrize(
    "shape",
    [(10, 2), (10, 4), (30,), (2, 5, 3), (3, 10)],
)
def test_wrong_shape_is_value_error(shape):
    a = np.zeros(shape)
    with pytest.raises(ValueError, match=r"expected an array of shape \(n, 3\), got shape") as e:
        gdel.Delaunay(a)
    got = "(" + ", ".join(map(str, shape)) + ("," if len(shape) == 1 else "") + ")"
    assert got in str(e.value)


def test_scalar_is_value_error():
    with pytest.raises(ValueError, match=r"\(n, 3\)"):
        gdel.Delaunay(np.float64(1.0))


@pytest.mark.parametrize("dtype", [np.complex128, np.bool_, object, "U3", np.float16])
def test_wrong_dtype_is_value_error(dtype):
    a = np.ones((10, 3), dtype=dtype)
    with pytest.raises(ValueError, match="dtype") as e:
        gdel.Delaunay(a)
    assert "float32 or float64" in str(e.value)


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_is_value_error_naming_the_row(bad):
    p = uniform(10, 14)
    p[7, 1] = bad
    with pytest.raises(ValueError, match="row 7"):
        gdel.Delaunay(p)


@pytest.mark.parametrize(
    "points",
    [
        np.zeros((0, 3)),
        uniform(3, 15),
        np.ones((20, 3)),  # one distinct point
        np.c_[uniform(20, 16)[:, :2], np.zeros(20)],  # coplanar
        np.outer(np.arange(10.0), [1.0, 2.0, 3.0]),  # collinear
    ],
    ids=["empty", "three", "all-equal", "coplanar", "collinear"],
)
def test_degenerate_input(points):
    with pytest.raises(gdel.DegenerateInputError) as e:
        gdel.Delaunay(points)
    assert isinstance(e.value, ValueError)
    assert type(e.value).__module__ == "gdel"


def test_unknown_algorithm_lists_choices():
    with pytest.raises(ValueError, match="unknown algorithm 'qhull'") as e:
        gdel.Delaunay(uniform(10, 17), algorithm="qhull")
    for name in ("'auto'", "'gdel3d'", "'gflip3d'"):
        assert name in str(e.value)


@pytest.mark.parametrize("device", ["gpu", "cuda:x", "CPU", ""])
def test_unknown_device_lists_choices(device):
    with pytest.raises(ValueError, match="unknown device") as e:
        gdel.Delaunay(uniform(10, 18), device=device)
    for name in ("'auto'", "'cpu'", "'cuda'"):
        assert name in str(e.value)


@pytest.mark.skipif(gdel.cuda_available(), reason="a CUDA device is visible")
def test_cuda_device_unavailable():
    with pytest.raises(gdel.BackendUnavailableError) as e:
        gdel.Delaunay(uniform(10, 19), device="cuda")
    assert isinstance(e.value, gdel.GdelError) and isinstance(e.value, RuntimeError)
    assert "CUDA" in str(e.value)


@pytest.mark.parametrize(
    "kind, expected",
    [
        ("InvalidInput", ValueError),
        ("DegenerateInput", gdel.DegenerateInputError),
        ("OutOfDeviceMemory", MemoryError),
        ("BackendUnavailable", gdel.BackendUnavailableError),
        ("CudaError", gdel.GdelError),
        ("Error", gdel.GdelError),
    ],
)
def test_exception_translation(kind, expected):
    with pytest.raises(expected, match="the message") as e:
        _core._raise(kind, "the message")
    if kind == "InvalidInput":
        assert type(e.value) is ValueError
    if kind in ("CudaError", "Error"):
        assert type(e.value) is gdel.GdelError


def test_out_of_memory_carries_byte_counts():
    with pytest.raises(MemoryError) as e:
        _core._raise("OutOfDeviceMemory", "out of device memory")
    assert e.value.needed == 1234 and e.value.available == 56
    assert "needed 1234 bytes" in str(e.value) and "56 bytes free" in str(e.value)


def test_exception_hierarchy():
    assert issubclass(gdel.DegenerateInputError, ValueError)
    assert issubclass(gdel.BackendUnavailableError, gdel.GdelError)
    assert issubclass(gdel.GdelError, RuntimeError)
    assert not issubclass(gdel.DegenerateInputError, gdel.GdelError)


# ---------------------------------------------------------------------------
# Duplicates, algorithms, check
# ---------------------------------------------------------------------------


def test_duplicates_are_represented_by_the_smallest_index():
    base = uniform(40, 20)
    p = np.concatenate([base, base[[3, 17, 3]]])  # 40, 41, 42 duplicate 3, 17, 3
    tri = gdel.Delaunay(p)
    rep = tri.representative
    np.testing.assert_array_equal(rep[:40], np.arange(40))
    np.testing.assert_array_equal(rep[40:], [3, 17, 3])
    used = set(np.unique(tri.simplices).tolist())
    assert used == set(range(40))
    np.testing.assert_array_equal(tri.vertex_to_simplex[40:], [-1, -1, -1])
    cop = tri.coplanar
    np.testing.assert_array_equal(cop[:, 0], [40, 41, 42])
    np.testing.assert_array_equal(cop[:, 2], [3, 17, 3])
    for point, simplex, vertex in cop:
        assert vertex in tri.simplices[simplex]
    indptr, _ = tri.vertex_neighbor_vertices
    assert (np.diff(indptr)[40:] == 0).all()
    assert tri.stats["distinct_points"] == 40
    assert gdel.check(p, tri.simplices).delaunay
    ref = gdel.Delaunay(base)
    assert sorted_rows(ref.simplices) == sorted_rows(tri.simplices)


def test_gflip3d_gives_a_valid_triangulation():
    p = uniform(400, 21)
    tri = gdel.Delaunay(p, algorithm="gflip3d", check=True)
    assert tri.stats["algorithm"] == "gflip3d"
    r = tri.check_report
    assert r.valid
    failed = tri.failed_vertices
    assert failed.dtype == np.int32 and len(failed) == tri.stats["failed_vertices"]
    assert (np.diff(failed) > 0).all()  # ascending, distinct
    # failed vertices are reported exactly when some facet is not locally Delaunay
    assert (len(failed) == 0) == (r.non_delaunay_facets == 0)
    check_neighbors(tri.simplices, tri.neighbors)


def test_check_flag_attaches_report():
    tri = gdel.Delaunay(uniform(200, 22), check=True)
    r = tri.check_report
    assert isinstance(r, gdel.CheckReport)
    assert r.delaunay and r.valid and r.tets == tri.nsimplex and r.points == 200
    assert r.euler == 1 and r.euler_ok


def test_check_detects_broken_triangulations():
    p = uniform(100, 23)
    tri = gdel.Delaunay(p)
    s = tri.simplices
    good = gdel.check(p, s)
    assert good.valid and good.delaunay and str(good) == good.summary and good.summary.startswith("OK")
    assert good.hull_facets == len(tri.convex_hull)
    flipped = gdel.check(p, s[:, [1, 0, 2, 3]])
    assert not flipped.valid and flipped.inverted_tets == len(s)
    missing = gdel.check(p, s[1:])
    assert not missing.valid
    bad = s.copy()
    bad[0, 0] = 100  # out of range
    assert gdel.check(p, bad).bad_index == 1
    # int64 ids and strided arrays are accepted
    assert gdel.check(p, s.astype(np.int64)).delaunay
    assert gdel.check(np.asfortranarray(p), np.asfortranarray(s)).delaunay
    # equal weights: the regular test is the Delaunay test
    assert gdel.check(p, s, np.full(100, 0.5)).delaunay


def test_check_detects_non_delaunay():
    # Two tets sharing a face vs the three around the edge: exactly one is Delaunay.
    # The segment 3-4 pierces triangle 012: the hull has a 2-tet and a 3-tet
    # triangulation, both valid, and (no 5 points cospherical) exactly one Delaunay.
    p = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.3, 0.3, 1], [0.3, 0.3, -1]], dtype=float)
    tri = gdel.Delaunay(p)
    assert gdel.check(p, tri.simplices).delaunay
    two = [[0, 1, 2, 3], [0, 1, 2, 4]]
    three = [[0, 1, 3, 4], [1, 2, 3, 4], [2, 0, 3, 4]]
    verdicts = []
    for cand in (two, three):
        c = np.array(cand)
        c = np.array([t if orient_exact(*p[t]) > 0 else t[[1, 0, 2, 3]] for t in c])
        r = gdel.check(p, c)
        assert r.valid and r.inverted_tets == 0
        assert r.delaunay == (sorted_rows(c) == sorted_rows(tri.simplices))
        verdicts.append(r.delaunay)
    assert sorted(verdicts) == [False, True]


def test_check_argument_errors():
    p = uniform(20, 24)
    s = gdel.Delaunay(p).simplices
    with pytest.raises(ValueError, match=r"shape \(m, 4\)"):
        gdel.check(p, s[:, :3])
    with pytest.raises(ValueError, match=r"weights: expected an array of shape \(20,\)"):
        gdel.check(p, s, np.zeros(19))
    with pytest.raises(ValueError, match="integer"):
        gdel.check(p, s.astype(np.float64))
    with pytest.raises(ValueError, match="int32"):
        gdel.check(p, s.astype(np.int64) + 2**40)


# ---------------------------------------------------------------------------
# Threads, packaging
# ---------------------------------------------------------------------------


def test_gil_released_while_computing():
    # A Python thread that stamps the time every millisecond can only run while the
    # main thread's C++ call has released the GIL.
    p = uniform(40000, 25)
    stamps = []
    stop = threading.Event()

    def ticker():
        while not stop.is_set():
            stamps.append(time.perf_counter())
            time.sleep(0.001)

    th = threading.Thread(target=ticker)
    th.start()
    time.sleep(0.02)
    t0 = time.perf_counter()
    gdel.Delaunay(p)
    t1 = time.perf_counter()
    stop.set()
    th.join()
    lo, hi = t0 + 0.1 * (t1 - t0), t1 - 0.1 * (t1 - t0)
    during = [t for t in stamps if lo < t < hi]
    assert len(during) >= 5, f"no Python progress during a {t1 - t0:.2f} s call"


def test_version_matches_package_metadata():
    assert gdel.__version__ == importlib.metadata.version("gdel")


def test_typing_files_are_installed():
    root = importlib.resources.files("gdel")
    assert root.joinpath("py.typed").is_file()
    stub = root.joinpath("_core.pyi").read_text()
    assert "class DegenerateInputError(ValueError)" in stub
    assert "class BackendUnavailableError(GdelError)" in stub
    assert "def delaunay(" in stub and "def verify(" in stub


def test_public_names():
    assert set(gdel.ALGORITHMS) >= {"auto", "gdel3d", "gflip3d"}  # grows with the C++ API
    assert gdel.DEVICES[:3] == ("auto", "cpu", "cuda")
    for name in gdel.__all__:
        assert hasattr(gdel, name), name
    assert isinstance(gdel.built_with_cuda(), bool)
    assert gdel.cuda_available() in (False, True)
    if not gdel.built_with_cuda():
        assert not gdel.cuda_available()


def test_kept_device_memory_setting():
    before = gdel.kept_device_memory_bound()
    p = uniform(3000, 5)
    ref = gdel.delaunay(p, device="cpu")
    try:
        gdel.keep_device_memory(1 << 30)
        assert gdel.kept_device_memory_bound() == 1 << 30
        gdel.keep_device_memory(np.int64(1 << 20))
        assert gdel.kept_device_memory_bound() == 1 << 20
        gdel.keep_device_memory(2**70)  # no bound (clamped to the largest size_t)
        assert gdel.kept_device_memory_bound() == 2**64 - 1
        for bad in (-1, 1.5, True, "1"):
            with pytest.raises(ValueError, match="nbytes"):
                gdel.keep_device_memory(bad)
        assert gdel.kept_device_memory_bound() == 2**64 - 1
        # the same triangulation with memory kept (on the GPU where there is one), twice
        for _ in range(2):
            tri = gdel.delaunay(p)
            assert sorted_rows(tri.simplices) == sorted_rows(ref.simplices)
        gdel.release_device_memory()
        assert gdel.kept_device_memory_bound() == 2**64 - 1  # the setting stays
        gdel.keep_device_memory(0)
        assert gdel.kept_device_memory_bound() == 0
    finally:
        gdel.keep_device_memory(before)


def test_readme_python_example_runs(capsys):
    readme = (Path(__file__).resolve().parents[2] / "README.md").read_text()
    section = readme.split("\n## Python\n", 1)[1]
    code = section.split("```python\n", 1)[1].split("```", 1)[0]
    exec(compile(code, "README.md", "exec"), {})
    out = capsys.readouterr().out.splitlines()
    assert out[0].endswith("int32 cpu") or out[0].endswith("int32 cuda")
    assert out[1].startswith("True [")
