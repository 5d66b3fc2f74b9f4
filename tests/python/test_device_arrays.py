"""CUDA-resident inputs: results come back as arrays of the same framework on the same
device. torch and cupy CUDA arrays are read in place by gdel::delaunay_device (no host
copy; docs/python.md says what is copied where); other frameworks go through the host.
The GPU tests run where torch/cupy see a GPU and gdel was built with CUDA
(scripts/gpu-python.sh), and are skipped elsewhere. Stand-in frameworks check the
routing and the result assembly on any machine."""

import gc
import json
import os
import time
from itertools import permutations

import numpy as np
import pytest

import gdel
from gdel import _arrays
from helpers import sorted_rows, uniform

# ---------------------------------------------------------------------------
# A stand-in "GPU framework": its arrays say they live on CUDA device 1.
# ---------------------------------------------------------------------------


class FakeGpuArray:
    def __init__(self, a):
        self.host = np.asarray(a)

    @property
    def shape(self):
        return self.host.shape

    def reshape(self, *shape):
        return FakeGpuArray(self.host.reshape(*shape))

    def __dlpack_device__(self):
        return (2, 1)  # kDLCUDA, device 1

    def __dlpack__(self, **kwargs):
        raise AssertionError("the device path must not hand a device array to the host reader")


FakeGpuArray.__module__ = "fakegpu"


@pytest.fixture
def fake_framework(monkeypatch):
    calls = {"to_host": 0, "from_host": 0}

    def to_host(x):
        calls["to_host"] += 1
        return x.host

    def from_host(a, like):
        assert isinstance(like, FakeGpuArray)
        calls["from_host"] += 1
        return FakeGpuArray(a)

    def to_numpy(x):
        calls["to_numpy"] += 1
        return x.host

    calls["to_numpy"] = 0
    monkeypatch.setitem(_arrays._FRAMEWORKS, "fakegpu", _arrays._Framework(to_host, from_host, to_numpy))
    return calls


def test_device_input_round_trip_gives_arrays_of_the_same_kind(fake_framework):
    p = uniform(120, 1)
    ref = gdel.Delaunay(p)
    tri = gdel.Delaunay(FakeGpuArray(p), device="cpu")
    assert fake_framework["to_host"] == 1  # the points crossed to the host once
    for name in ("simplices", "neighbors", "vertex_to_simplex", "representative", "convex_hull"):
        a = getattr(tri, name)
        assert isinstance(a, FakeGpuArray), name
        assert a.host.dtype == np.int32
    np.testing.assert_array_equal(tri.simplices.host, ref.simplices)
    indptr, indices = tri.vertex_neighbor_vertices
    assert isinstance(indptr, FakeGpuArray) and isinstance(indices, FakeGpuArray)
    assert isinstance(tri.points, FakeGpuArray)  # the input itself
    loc = tri.find_simplex(FakeGpuArray(p[:7]))
    assert isinstance(loc, FakeGpuArray) and (loc.host >= 0).all()
    loc_host = tri.find_simplex(p[:7])
    assert isinstance(loc_host, np.ndarray)  # a host query gives a host answer
    report = gdel.check(FakeGpuArray(p), FakeGpuArray(ref.simplices))
    assert report.delaunay


def test_device_input_picks_its_gpu(fake_framework):
    origin = _arrays.origin_of(FakeGpuArray(np.zeros((4, 3))), "points")
    assert origin.on_device and origin.framework == "fakegpu" and origin.device_id == 1
    assert _arrays.resolve_device("auto", origin) == ("auto", 1)
    assert _arrays.resolve_device("cuda", origin) == ("cuda", 1)
    assert _arrays.resolve_device("cuda:0", origin) == ("cuda", 0)
    assert _arrays.resolve_device("cpu", origin) == ("cpu", 0)
    assert _arrays.resolve_device("auto", _arrays.HOST) == ("auto", 0)


def test_unknown_cuda_framework_is_refused():
    class Opaque:
        def __dlpack_device__(self):
            return (2, 0)

        def __dlpack__(self, **kwargs):
            raise AssertionError("not reached")

    with pytest.raises(TypeError, match="CUDA arrays of type .* are not supported"):
        gdel.Delaunay(Opaque())


def test_other_device_types_are_refused():
    class Rocm:
        def __dlpack_device__(self):
            return (10, 0)  # kDLROCM

        def __dlpack__(self, **kwargs):
            raise AssertionError("not reached")

    with pytest.raises(TypeError, match="DLPack device type 10"):
        gdel.Delaunay(Rocm())


def test_zero_copy_is_for_torch_and_cupy_on_their_own_gpu(monkeypatch):
    monkeypatch.setattr(_arrays._core, "cuda_device_available", lambda: True)
    torch_on_1 = _arrays.Origin("torch", 1, None)
    assert _arrays.zero_copy_possible(torch_on_1, "auto", "auto", 1)
    assert _arrays.zero_copy_possible(torch_on_1, "gdel3d", "cuda", 1)
    assert _arrays.zero_copy_possible(_arrays.Origin("cupy", 0, None), "gflip3d", "auto", 0)
    assert not _arrays.zero_copy_possible(torch_on_1, "auto", "cuda", 0)  # another GPU: host round trip
    assert not _arrays.zero_copy_possible(torch_on_1, "auto", "cpu", 0)
    assert not _arrays.zero_copy_possible(torch_on_1, "gstar4d", "auto", 1)  # certificate on host arrays
    assert not _arrays.zero_copy_possible(_arrays.Origin("jax", 0, None), "auto", "auto", 0)
    monkeypatch.setattr(_arrays._core, "cuda_device_available", lambda: False)
    assert not _arrays.zero_copy_possible(torch_on_1, "auto", "auto", 1)


def test_device_entry_point_refuses_host_arrays():
    with pytest.raises(TypeError, match="takes CUDA arrays"):
        gdel._core.delaunay_device(uniform(10, 0), "torch")


@pytest.fixture
def fake_zero_copy(monkeypatch, fake_framework):
    """The zero-copy path with the stand-in framework: _core.delaunay_device is replaced
    by one that returns FakeGpuArrays (as the real one returns device arrays)."""
    seen = {}

    def prepare(x):
        seen["prepared"] = x
        return x, 1234

    def delaunay_device(x, framework, algorithm, stream):
        assert framework == "fakegpu" and stream == 1234
        r = gdel._core.delaunay(x.host, algorithm, "cpu", 0)
        out = {k: (FakeGpuArray(r[k]) if len(r[k]) else None) for k in ("simplices", "neighbors", "failed_vertices", "representative")}
        out["nsimplex"] = len(r["simplices"])
        out["stats"] = dict(r["stats"], device_input={"received": 1, "points_read": 1, "converted": False})
        return out

    monkeypatch.setattr(_arrays._core, "cuda_device_available", lambda: True)
    monkeypatch.setattr(_arrays._core, "delaunay_device", delaunay_device, raising=False)
    monkeypatch.setitem(_arrays._DEVICE_PREPARE, "fakegpu", prepare)
    monkeypatch.setattr(_arrays, "_empty_like", lambda framework, like: FakeGpuArray(np.zeros(0, np.int32)))
    fake_framework["seen"] = seen
    return fake_framework


def test_zero_copy_results_are_used_as_they_are(fake_zero_copy, monkeypatch):
    p = np.vstack([uniform(150, 5), uniform(3, 5)])  # 3 duplicates
    ref = gdel.Delaunay(p, device="cpu")
    tri = gdel.Delaunay(FakeGpuArray(p), device="cuda:1")
    assert fake_zero_copy["to_host"] == 0  # the points never went to the host
    assert tri.stats["device_input"]["points_read"] == 1
    simplices = tri.simplices
    assert isinstance(simplices, FakeGpuArray) and simplices is tri._raw.simplices  # no copy, no re-upload
    assert fake_zero_copy["from_host"] == 0 and fake_zero_copy["to_numpy"] == 0
    np.testing.assert_array_equal(simplices.host, ref.simplices)
    np.testing.assert_array_equal(tri.neighbors.host, ref.neighbors)
    np.testing.assert_array_equal(tri.representative.host, ref.representative)
    assert tri.failed_vertices.host.shape == (0,)  # made by _empty_like
    assert tri.npoints == len(p) and tri.nsimplex == ref.nsimplex
    # derived attributes: computed on the host (one copy of the results), given back
    for name in ("convex_hull", "vertex_to_simplex", "coplanar", "transform"):
        a = getattr(tri, name)
        assert isinstance(a, FakeGpuArray), name
        np.testing.assert_array_equal(a.host, getattr(ref, name), err_msg=name)
    loc = tri.find_simplex(FakeGpuArray(p[:9]))
    assert isinstance(loc, FakeGpuArray)
    np.testing.assert_array_equal(loc.host, ref.find_simplex(p[:9]))
    # check=True verifies host copies (the verifier takes host arrays), here on the CPU
    verify = gdel._core.verify
    monkeypatch.setattr(gdel._core, "verify", lambda pts, s, w, backend: verify(pts, s, w, "cpu"))
    assert gdel.Delaunay(FakeGpuArray(p), device="cuda:1", check=True).check_report.delaunay


def test_zero_copy_stand_in_gflip3d_failed_vertices(fake_zero_copy):
    p = uniform(400, 6)
    ref = gdel.Delaunay(p, algorithm="gflip3d", device="cpu")
    tri = gdel.Delaunay(FakeGpuArray(p), algorithm="gflip3d", device="cuda:1")
    np.testing.assert_array_equal(tri.failed_vertices.host, ref.failed_vertices)


# ---------------------------------------------------------------------------
# Real GPUs
# ---------------------------------------------------------------------------


def canonical(simplices, neighbors):
    """Each tet as its lexicographically smallest even permutation (neighbours permuted
    alike), tets sorted, neighbour ids renumbered: equal iff the same oriented
    triangulation with the same adjacency (mesh/canonical.hpp's order)."""
    s = np.asarray(simplices, dtype=np.int64)
    nb = np.asarray(neighbors, dtype=np.int64)
    even = np.array([p for p in permutations(range(4)) if _parity(p) == 0])
    cand = s[:, even]  # (m, 12, 4)
    key = cand[:, :, 0] * (int(s.max(initial=0)) + 1) + cand[:, :, 1]
    perm = even[np.argmin(key, axis=1)]
    tets = np.take_along_axis(s, perm, axis=1)
    nbs = np.take_along_axis(nb, perm, axis=1)
    order = np.lexsort(tets[:, ::-1].T)
    newid = np.empty(len(order), dtype=np.int64)
    newid[order] = np.arange(len(order))
    tets, nbs = tets[order], nbs[order]
    return tets, np.where(nbs >= 0, newid[np.maximum(nbs, 0)], -1)


def _parity(p):
    p = list(p)
    swaps = 0
    for i in range(len(p)):
        while p[i] != i:
            j = p[i]
            p[i], p[j] = p[j], p[i]
            swaps += 1
    return swaps % 2


def assert_same_triangulation(tri, ref):
    a = canonical(_host(tri.simplices), _host(tri.neighbors))
    b = canonical(ref.simplices, ref.neighbors)
    np.testing.assert_array_equal(a[0], b[0])
    np.testing.assert_array_equal(a[1], b[1])
    np.testing.assert_array_equal(_host(tri.representative), ref.representative)


def _host(a):
    if hasattr(a, "cpu"):
        return a.cpu().numpy()
    if hasattr(a, "get"):
        return a.get()
    return np.asarray(a)


def _torch_cuda():
    torch = pytest.importorskip("torch")
    if not torch.cuda.is_available():
        pytest.skip("torch sees no CUDA device")
    return torch


def _cupy_cuda():
    cupy = pytest.importorskip("cupy")
    try:
        if cupy.cuda.runtime.getDeviceCount() == 0:
            pytest.skip("cupy sees no CUDA device")
    except cupy.cuda.runtime.CUDARuntimeError:
        pytest.skip("cupy sees no CUDA device")
    return cupy


needs_gdel_cuda = pytest.mark.skipif(not gdel.cuda_available(), reason="gdel has no CUDA backend or sees no device")


def test_torch_cuda_tensor():
    torch = _torch_cuda()
    p = uniform(2000, 2)
    x = torch.tensor(p, device="cuda", dtype=torch.float32)
    tri = gdel.Delaunay(x)
    for name in ("simplices", "neighbors", "convex_hull", "vertex_to_simplex"):
        t = getattr(tri, name)
        assert isinstance(t, torch.Tensor) and t.device == x.device and t.dtype == torch.int32, name
    host = tri.simplices.cpu().numpy()
    assert gdel.check(p.astype(np.float32), host).delaunay
    if gdel.cuda_available():
        assert tri.stats["backend"] == "cuda"
    p32 = gdel.Delaunay(p.astype(np.float32), device="cpu")
    assert sorted_rows(host) == sorted_rows(p32.simplices)
    loc = tri.find_simplex(x[:10])
    assert isinstance(loc, torch.Tensor) and loc.device == x.device and bool((loc >= 0).all())


def test_cupy_array():
    cupy = _cupy_cuda()
    p = uniform(2000, 3)
    x = cupy.asarray(p)
    tri = gdel.Delaunay(x)
    assert isinstance(tri.simplices, cupy.ndarray) and tri.simplices.dtype == cupy.int32
    assert tri.simplices.device.id == x.device.id
    ref = gdel.Delaunay(p, device="cpu")
    assert sorted_rows(cupy.asnumpy(tri.simplices)) == sorted_rows(ref.simplices)


@needs_gdel_cuda
def test_cuda_backend_matches_cpu_backend():
    p = uniform(5000, 4)
    gpu = gdel.Delaunay(p, device="cuda", check=True)
    cpu = gdel.Delaunay(p, device="cpu")
    assert gpu.stats["backend"] == "cuda" and cpu.stats["backend"] == "cpu"
    assert sorted_rows(gpu.simplices) == sorted_rows(cpu.simplices)
    assert gdel.check(p, gpu.simplices, device="cuda").delaunay


# -- the zero-copy path on a real GPU ------------------------------------------------


@needs_gdel_cuda
@pytest.mark.parametrize("dtype", ["float64", "float32"])
def test_torch_zero_copy_same_device_same_result(dtype):
    torch = _torch_cuda()
    p = np.vstack([uniform(3000, 7), uniform(3000, 7)[:5]])  # with exact duplicates
    x = torch.tensor(p, device="cuda", dtype=getattr(torch, dtype))
    tri = gdel.Delaunay(x)
    d = tri.stats["device_input"]
    assert d is not None, "the device path was not taken"
    assert d["received"] == x.data_ptr()  # the C++ side got the tensor's own memory
    if dtype == "float64":
        assert d["points_read"] == x.data_ptr() and not d["converted"]  # and the algorithm read it there
    else:
        assert d["converted"] and d["points_read"] != x.data_ptr()  # a float64 copy, made on the device
    assert tri.stats["backend"] == "cuda"
    for name in ("simplices", "neighbors", "representative", "failed_vertices"):
        t = getattr(tri, name)
        assert isinstance(t, torch.Tensor) and t.is_cuda and t.device == x.device and t.dtype == torch.int32, name
        assert t.is_contiguous()
    assert tri.simplices.shape == (tri.nsimplex, 4) and tri.representative.shape == (len(p),)
    ref = gdel.Delaunay(p.astype(dtype), device="cpu")
    assert_same_triangulation(tri, ref)
    assert tri.failed_vertices.numel() == 0
    assert gdel.check(p.astype(dtype), _host(tri.simplices)).delaunay


@needs_gdel_cuda
@pytest.mark.parametrize("dtype", ["float64", "float32"])
def test_cupy_zero_copy_same_device_same_result(dtype):
    cupy = _cupy_cuda()
    p = uniform(3000, 8)
    x = cupy.asarray(p, dtype=dtype)
    tri = gdel.Delaunay(x)
    d = tri.stats["device_input"]
    assert d is not None and d["received"] == x.data.ptr
    assert (d["points_read"] == x.data.ptr) == (dtype == "float64")
    for name in ("simplices", "neighbors", "representative", "failed_vertices"):
        a = getattr(tri, name)
        assert isinstance(a, cupy.ndarray) and a.dtype == cupy.int32 and a.device.id == x.device.id, name
    assert_same_triangulation(tri, gdel.Delaunay(p.astype(dtype), device="cpu"))


@needs_gdel_cuda
def test_torch_zero_copy_gflip3d_strided_integer_and_scaled_inputs():
    torch = _torch_cuda()
    p = uniform(2500, 9)
    # gflip3d: failed vertices on the device, as the CPU backend gives them
    x = torch.tensor(p, device="cuda")
    tri = gdel.Delaunay(x, algorithm="gflip3d")
    ref = gdel.Delaunay(p, algorithm="gflip3d", device="cpu")
    np.testing.assert_array_equal(_host(tri.failed_vertices), ref.failed_vertices)
    assert sorted_rows(_host(tri.simplices)) == sorted_rows(ref.simplices)
    # a non-contiguous tensor: made contiguous on the device by torch, then read in place
    xt = torch.tensor(np.asfortranarray(p), device="cuda").t().contiguous().t()
    assert not xt.is_contiguous()
    assert_same_triangulation(gdel.Delaunay(xt), gdel.Delaunay(p, device="cpu"))
    # integers: converted to float64 on the device
    q = np.random.default_rng(3).integers(-1000, 1000, size=(800, 3))
    assert_same_triangulation(gdel.Delaunay(torch.tensor(q, device="cuda")), gdel.Delaunay(q, device="cpu"))
    # magnitudes outside the predicates' range: scaled by a power of two on the device
    big = p * 1e300
    tb = gdel.Delaunay(torch.tensor(big, device="cuda"))
    assert tb.stats["device_input"]["converted"]
    assert_same_triangulation(tb, gdel.Delaunay(big, device="cpu"))


@needs_gdel_cuda
def test_torch_zero_copy_errors_match_the_host_path():
    torch = _torch_cuda()
    p = uniform(100, 10)
    p[37, 1] = np.nan
    with pytest.raises(ValueError, match="row 37 has a non-finite coordinate"):
        gdel.Delaunay(torch.tensor(p, device="cuda"))
    p[37, 1] = np.inf
    with pytest.raises(ValueError, match="row 37 has a non-finite coordinate"):
        gdel.Delaunay(torch.tensor(p, device="cuda", dtype=torch.float32))
    flat = uniform(50, 11)
    flat[:, 2] = 0.5
    with pytest.raises(gdel.DegenerateInputError):
        gdel.Delaunay(torch.tensor(flat, device="cuda"))
    with pytest.raises(gdel.DegenerateInputError):
        gdel.Delaunay(torch.zeros((10, 3), device="cuda", dtype=torch.float64))
    with pytest.raises(ValueError, match="expected an array of shape"):
        gdel.Delaunay(torch.zeros((10, 2), device="cuda", dtype=torch.float64))
    with pytest.raises(ValueError, match="float16"):
        gdel.Delaunay(torch.zeros((10, 3), device="cuda", dtype=torch.float16))


@needs_gdel_cuda
def test_torch_zero_copy_waits_for_the_producer_stream():
    torch = _torch_cuda()
    p = uniform(200_000, 12)
    side = torch.cuda.Stream()
    src = torch.tensor(p, device="cuda")
    side.wait_stream(torch.cuda.current_stream())  # src is complete before the side stream copies it
    with torch.cuda.stream(side):
        torch.cuda._sleep(50_000_000)  # keep the side stream busy, then write the points
        x = torch.empty_like(src)
        x.copy_(src)
        tri = gdel.Delaunay(x)  # gdel must wait for `side`, the current stream here
    assert_same_triangulation(tri, gdel.Delaunay(p, device="cpu"))


@needs_gdel_cuda
def test_device_results_own_their_memory_and_free_it():
    torch = _torch_cuda()
    p = uniform(300_000, 13)
    x = torch.tensor(p, device="cuda")
    tri = gdel.Delaunay(x)
    s, nb, rep = tri.simplices, tri.neighbors, tri.representative
    nbytes = 4 * (s.numel() + nb.numel() + rep.numel())
    expect = s.cpu().numpy().copy()
    del tri
    gc.collect()
    np.testing.assert_array_equal(s.cpu().numpy(), expect)  # the tensors keep gdel's memory alive
    torch.cuda.synchronize()
    free_before = torch.cuda.mem_get_info(x.device)[0]
    del s, nb, rep
    gc.collect()
    torch.cuda.synchronize()
    free_after = torch.cuda.mem_get_info(x.device)[0]
    assert free_after - free_before >= 0.9 * nbytes  # the capsules freed it (cudaFree)


# -- proof that no host copy happens --------------------------------------------------
#
# 1. Pointers: stats["device_input"] reports the device pointer the C++ entry point
#    received and the one its algorithm read the coordinates from; both are the
#    tensor's data_ptr() (float64 input). The results are tensors on that GPU wrapping
#    gdel's cudaMalloc'd memory.
# 2. Traffic: CUPTI (through torch.profiler) records every memcpy of the process,
#    gdel's included. The zero-copy call moves only a few scalars (counts, reduction
#    results) between host and device, independent of n; the forced host round trip
#    moves the points and every result, and the same measurement sees it (which shows
#    that the measurement works).
# 3. Time: the zero-copy call is faster than the forced round trip at 10^6 points
#    (GDEL_DEVICE_BENCH_N for more), min of 3 runs each, results read as device tensors.


_MEMCPY_NAMES: set = set()


def _host_device_bytes(fn):
    """(bytes copied host->device, device->host) while fn runs, from the CUPTI trace."""
    torch = _torch_cuda()
    from torch.profiler import ProfilerActivity, profile

    torch.cuda.synchronize()
    with profile(activities=[ProfilerActivity.CUDA]) as prof:
        fn()
        torch.cuda.synchronize()
    path = os.path.join(os.environ.get("TMPDIR", "/tmp"), f"gdel-trace-{os.getpid()}.json")
    prof.export_chrome_trace(path)
    with open(path) as f:
        trace = json.load(f)
    os.unlink(path)
    h2d = d2h = 0
    for ev in trace.get("traceEvents", []):
        name = str(ev.get("name", ""))
        if "memcpy" not in name.lower():
            continue
        _MEMCPY_NAMES.add(f"{name} [{ev.get('cat')}]")
        if ev.get("cat") != "gpu_memcpy":  # not the runtime API calls (cudaMemcpyAsync): the copies
            continue
        nbytes = int(ev.get("args", {}).get("bytes", 0))
        if "HtoD" in name:
            h2d += nbytes
        elif "DtoH" in name:
            d2h += nbytes
    return h2d, d2h


def _round_trip(monkeypatch, x):
    """gdel.Delaunay(x) forced through the host, results read as device tensors."""
    with monkeypatch.context() as m:
        m.setattr(_arrays, "zero_copy_possible", lambda *a: False)
        tri = gdel.Delaunay(x)
        assert tri.stats["device_input"] is None
        return tri, (tri.simplices, tri.neighbors, tri.representative)


def _zero_copy(x):
    tri = gdel.Delaunay(x)
    assert tri.stats["device_input"]["points_read"] == x.data_ptr()
    return tri, (tri.simplices, tri.neighbors, tri.representative)


@needs_gdel_cuda
def test_no_host_copy_by_cupti_memcpy_trace(monkeypatch):
    torch = _torch_cuda()
    n = 1_000_000
    x = torch.rand((n, 3), device="cuda", dtype=torch.float64, generator=torch.Generator("cuda").manual_seed(1))
    _zero_copy(x)  # warm-up (context, module loading)
    rt_h2d, rt_d2h = _host_device_bytes(lambda: _round_trip(monkeypatch, x))
    if rt_d2h < 24 * n:
        pytest.skip(
            f"the profiler recorded too little memcpy traffic for the host round trip (H2D {rt_h2d}, "
            f"D2H {rt_d2h} bytes; events {sorted(_MEMCPY_NAMES)}): no CUPTI memcpy records"
        )
    zc_h2d, zc_d2h = _host_device_bytes(lambda: _zero_copy(x))
    print(f"\nhost<->device bytes at n={n}: zero-copy H2D {zc_h2d} D2H {zc_d2h}; round trip H2D {rt_h2d} D2H {rt_d2h}")
    assert rt_h2d >= 24 * n  # the round trip uploads the points (and the results)
    assert zc_h2d + zc_d2h < 1 << 20  # scalars only: < 1 MiB against 24 MB of points
    assert zc_h2d + zc_d2h < (rt_h2d + rt_d2h) / 100


@needs_gdel_cuda
def test_zero_copy_is_faster_than_a_host_round_trip(monkeypatch):
    torch = _torch_cuda()
    n = int(os.environ.get("GDEL_DEVICE_BENCH_N", "1000000"))
    x = torch.rand((n, 3), device="cuda", dtype=torch.float64, generator=torch.Generator("cuda").manual_seed(2))

    def timed(fn):
        best = float("inf")
        for _ in range(3):
            torch.cuda.synchronize()
            t0 = time.perf_counter()
            out = fn()
            torch.cuda.synchronize()
            best = min(best, time.perf_counter() - t0)
            del out
            gc.collect()
        return best

    _zero_copy(x)  # warm-up
    zc = timed(lambda: _zero_copy(x))
    rt = timed(lambda: _round_trip(monkeypatch, x))
    print(f"\nn={n}: zero-copy {zc:.3f} s, forced host round trip {rt:.3f} s ({rt / zc:.2f}x)")
    assert zc < rt
