"""CUDA-resident inputs: results come back as arrays of the same framework on the same
device. Today this is an explicit host round trip (docs/python.md); the GPU tests run
where torch/cupy see a GPU and are skipped elsewhere. A stand-in framework checks the
routing on any machine."""

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

    monkeypatch.setitem(_arrays._FRAMEWORKS, "fakegpu", _arrays._Framework(to_host, from_host))
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


# ---------------------------------------------------------------------------
# Real GPUs
# ---------------------------------------------------------------------------


def _torch_cuda():
    torch = pytest.importorskip("torch")
    if not torch.cuda.is_available():
        pytest.skip("torch sees no CUDA device")
    return torch


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
    cupy = pytest.importorskip("cupy")
    try:
        if cupy.cuda.runtime.getDeviceCount() == 0:
            pytest.skip("cupy sees no CUDA device")
    except cupy.cuda.runtime.CUDARuntimeError:
        pytest.skip("cupy sees no CUDA device")
    p = uniform(2000, 3)
    x = cupy.asarray(p)
    tri = gdel.Delaunay(x)
    assert isinstance(tri.simplices, cupy.ndarray) and tri.simplices.dtype == cupy.int32
    assert tri.simplices.device.id == x.device.id
    ref = gdel.Delaunay(p, device="cpu")
    assert sorted_rows(cupy.asnumpy(tri.simplices)) == sorted_rows(ref.simplices)


@pytest.mark.skipif(not gdel.cuda_available(), reason="no CUDA device for gdel")
def test_cuda_backend_matches_cpu_backend():
    p = uniform(5000, 4)
    gpu = gdel.Delaunay(p, device="cuda", check=True)
    cpu = gdel.Delaunay(p, device="cpu")
    assert gpu.stats["backend"] == "cuda" and cpu.stats["backend"] == "cpu"
    assert sorted_rows(gpu.simplices) == sorted_rows(cpu.simplices)
    assert gdel.check(p, gpu.simplices, device="cuda").delaunay
