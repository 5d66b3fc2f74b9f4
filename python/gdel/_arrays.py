"""Array interop: what gdel accepts, where it computes, and how results go back.

* Host arrays (numpy, or any DLPack producer whose memory the CPU can read: torch and
  jax CPU arrays, ...) go to the compiled layer as they are. It reads C-contiguous
  float64 in place and converts anything else (float32, integers, any strides) to
  contiguous float64 exactly once. Results are numpy arrays.
* torch and cupy CUDA arrays take the zero-copy path (:func:`_delaunay_on_device`):
  the compiled layer hands their device pointer to ``gdel::delaunay_device``, which
  triangulates them on their own GPU without a host copy, and the results come back
  as int32 arrays of the same framework on the same device, owning gdel's device
  memory. Only a float32 input (converted on the device), a non-contiguous one (made
  contiguous on the device by the framework) or an integer one (converted on the
  device) is copied, and only device-to-device.
* Other CUDA inputs take an explicit host round trip (:func:`_delaunay_via_host`):
  jax arrays, ``device="cpu"`` or a ``device="cuda:N"`` other than the array's,
  ``algorithm="gstar4d"`` (its exact certificate runs on host arrays), and builds
  or machines without CUDA. Results are still arrays of the input's framework on its
  device.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass
from typing import Any, Callable, Optional

import numpy as np

from . import _core

# DLPack device types (dlpack.h, DLDeviceType).
_DL_CPU = 1
_DL_CUDA = 2
_DL_CUDA_HOST = 3  # pinned host memory: readable by the CPU
_DL_CUDA_MANAGED = 13

_HOST_DEVICE_TYPES = (_DL_CPU, _DL_CUDA_HOST)
_CUDA_DEVICE_TYPES = (_DL_CUDA, _DL_CUDA_MANAGED)


# ---------------------------------------------------------------------------
# Frameworks whose CUDA arrays gdel accepts: a copy to the host, and a copy of a
# host (numpy) result back to the device of a given array of that framework. Each is
# imported only when one of its arrays is seen (none is a dependency).
# ---------------------------------------------------------------------------


def _torch_to_host(x: Any) -> Any:
    return x.detach().cpu()


def _torch_to_numpy(x: Any) -> np.ndarray:
    return x.detach().cpu().numpy()


def _torch_from_host(a: np.ndarray, like: Any) -> Any:
    torch = importlib.import_module("torch")
    return torch.from_numpy(np.ascontiguousarray(a)).to(like.device)


def _cupy_to_host(x: Any) -> Any:
    cupy = importlib.import_module("cupy")
    return cupy.asnumpy(x)


def _cupy_to_numpy(x: Any) -> np.ndarray:
    cupy = importlib.import_module("cupy")
    return cupy.asnumpy(x)


def _cupy_from_host(a: np.ndarray, like: Any) -> Any:
    cupy = importlib.import_module("cupy")
    with like.device:
        return cupy.asarray(a)


def _jax_to_host(x: Any) -> Any:
    return np.asarray(x)


def _jax_from_host(a: np.ndarray, like: Any) -> Any:
    jax = importlib.import_module("jax")
    return jax.device_put(a, next(iter(like.devices())))


@dataclass(frozen=True)
class _Framework:
    to_host: Callable[[Any], Any]
    from_host: Callable[[np.ndarray, Any], Any]
    # A device array of this framework as a numpy array (a device -> host copy).
    to_numpy: Callable[[Any], np.ndarray] = np.asarray


_FRAMEWORKS = {
    "torch": _Framework(_torch_to_host, _torch_from_host, _torch_to_numpy),
    "cupy": _Framework(_cupy_to_host, _cupy_from_host, _cupy_to_numpy),
    "jax": _Framework(_jax_to_host, _jax_from_host),
    "jaxlib": _Framework(_jax_to_host, _jax_from_host),
}


def _framework_name(obj: Any) -> str:
    return type(obj).__module__.split(".")[0]


def _dlpack_device(obj: Any) -> Optional[tuple[int, int]]:
    """(device type, device id) of a DLPack producer; None for anything else."""
    if isinstance(obj, np.ndarray) or not hasattr(obj, "__dlpack_device__"):
        return None
    dev = obj.__dlpack_device__()
    return int(dev[0]), int(dev[1])


@dataclass(frozen=True)
class Origin:
    """Where an input array lives, and so where its results go.

    ``framework`` is ``"numpy"`` for every host input (results are numpy arrays) or
    the framework of a CUDA input (``"torch"``, ``"cupy"``, ``"jax"``); ``like`` is
    that input, used to put results on its device.
    """

    framework: str = "numpy"
    device_id: int = 0
    like: Any = None

    @property
    def on_device(self) -> bool:
        return self.framework != "numpy"

    def give(self, a: np.ndarray) -> Any:
        """A host result as an array of the origin's kind (a host-to-device copy for CUDA)."""
        if not self.on_device:
            return a
        return _FRAMEWORKS[self.framework].from_host(a, self.like)

    def to_numpy(self, a: Any) -> np.ndarray:
        """An array of the origin's kind as numpy (a device-to-host copy for CUDA)."""
        if isinstance(a, np.ndarray):
            return a
        return _FRAMEWORKS[self.framework].to_numpy(a)


HOST = Origin()


def origin_of(obj: Any, what: str) -> Origin:
    dev = _dlpack_device(obj)
    if dev is None or dev[0] in _HOST_DEVICE_TYPES:
        return HOST
    if dev[0] in _CUDA_DEVICE_TYPES:
        name = _framework_name(obj)
        if name not in _FRAMEWORKS:
            raise TypeError(
                f"{what}: CUDA arrays of type {type(obj).__module__}.{type(obj).__qualname__} are not "
                "supported (torch, cupy and jax are); copy it to the host first"
            )
        return Origin(name, dev[1], obj)
    raise TypeError(f"{what}: arrays on DLPack device type {dev[0]} are not supported (host and CUDA only)")


def host_array(obj: Any, what: str) -> Any:
    """Something the compiled layer reads directly: a numpy array or a host DLPack
    producer. Lists and other array-likes become numpy arrays here; numpy arrays of
    a dtype gdel cannot take raise ValueError naming it."""
    if isinstance(obj, np.ndarray):
        arr = obj
    elif hasattr(obj, "__dlpack__"):
        if _framework_name(obj) == "torch":
            obj = obj.detach()  # a tensor that requires grad refuses DLPack export
        return obj
    else:
        arr = np.asarray(obj)
    if arr.dtype.kind not in "fiu":
        raise ValueError(f"{what}: expected float32 or float64 values (or integers), got dtype {arr.dtype}")
    if not arr.dtype.isnative:  # DLPack has no byte order: swap once here
        arr = arr.astype(arr.dtype.newbyteorder("="))
    return arr


def as_numpy(obj: Any) -> np.ndarray:
    """A numpy view of a host array from host_array() (no copy)."""
    if isinstance(obj, np.ndarray):
        return obj
    return np.from_dlpack(obj)


def to_host(obj: Any, origin: Origin, what: str) -> Any:
    """host_array() of any accepted input: CUDA inputs are copied to the host first."""
    if origin.on_device:
        obj = _FRAMEWORKS[origin.framework].to_host(obj)
    return host_array(obj, what)


# ---------------------------------------------------------------------------
# device= strings
# ---------------------------------------------------------------------------

DEVICE_CHOICES = ("auto", "cpu", "cuda", "cuda:N")


def resolve_device(device: str, origin: Origin) -> tuple[str, int]:
    """("auto" | "cpu" | "cuda", CUDA ordinal) for the compiled layer.

    "auto" runs on the GPU when this build has CUDA and one is visible (the GPU a CUDA
    input lives on), else on the CPU; "cuda" insists on a GPU; "cuda:N" names one.
    """
    if isinstance(device, str):
        if device == "cpu":
            return "cpu", 0
        if device in ("auto", "cuda"):
            return device, origin.device_id if origin.on_device else 0
        if device.startswith("cuda:") and device[5:].isdigit():
            return "cuda", int(device[5:])
    choices = ", ".join(repr(c) for c in DEVICE_CHOICES)
    raise ValueError(f"unknown device {device!r}; choose one of {choices}")


# ---------------------------------------------------------------------------
# Triangulation entry points
# ---------------------------------------------------------------------------


@dataclass
class RawResult:
    """The compiled layer's output plus where results must go.

    Host path (``on_device`` False): every array is numpy on the host, and
    ``Origin.give`` turns one into an array of the input's kind when it is read. Device
    path (``on_device`` True): ``simplices``, ``neighbors``, ``failed_vertices`` and
    ``representative`` already are arrays of the input's framework on its GPU, and
    ``points`` is the (device) float array that was triangulated.
    """

    points: Any  # host: (n, 3) float64, C-contiguous; device: the input (or its device-side conversion)
    simplices: Any
    neighbors: Any
    failed_vertices: Any
    representative: Any
    stats: dict[str, Any]
    origin: Origin
    on_device: bool = False


def _delaunay_on_host(host: Any, algorithm: str, backend: str, ordinal: int, origin: Origin) -> RawResult:
    r = _core.delaunay(host, algorithm, backend, ordinal)
    # The float64 copy the library made when it converted the input; otherwise the
    # input itself already was contiguous float64 and is viewed, not copied.
    pts = r["points"] if r["points"] is not None else as_numpy(host)
    r["stats"]["device_input"] = None  # the C++ side read host memory
    return RawResult(
        pts, r["simplices"], r["neighbors"], r["failed_vertices"], r["representative"], r["stats"], origin
    )


def _delaunay_via_host(points: Any, algorithm: str, backend: str, ordinal: int, origin: Origin) -> RawResult:
    """A CUDA input through the host: an explicit device -> host copy of the points here,
    and a host -> device copy of each result when it is read (Origin.give)."""
    host = to_host(points, origin, "points")
    return _delaunay_on_host(host, algorithm, backend, ordinal, origin)


# ---------------------------------------------------------------------------
# The zero-copy path: torch / cupy CUDA arrays read in place by gdel::delaunay_device
# ---------------------------------------------------------------------------

_EXACT_INT_LIMIT = 2**53  # integers beyond it may round when made float64
_INEXACT_INT = "points: an integer value is not exactly representable as float64 (|x| must be below 2^53)"


def _torch_prepare(x: Any) -> tuple[Any, int]:
    """(C-contiguous float32/float64 tensor on x's device, its current stream)."""
    torch = importlib.import_module("torch")
    x = x.detach()
    if x.dtype not in (torch.float32, torch.float64):
        if x.dtype.is_floating_point or x.dtype.is_complex or x.dtype == torch.bool:
            raise ValueError(f"points: expected float32 or float64 values (or integers), got dtype {x.dtype}")
        x = x.to(torch.float64)  # on the device; rounding is monotonic, so the check below is exact
        if x.numel() and bool((x.abs() >= _EXACT_INT_LIMIT).any()):
            raise ValueError(_INEXACT_INT)
    x = x.contiguous()  # the same tensor when it already is
    return x, int(torch.cuda.current_stream(x.device).cuda_stream)


def _cupy_prepare(x: Any) -> tuple[Any, int]:
    """(C-contiguous float32/float64 cupy array on x's device, its current stream)."""
    cupy = importlib.import_module("cupy")
    with x.device:
        if x.dtype not in (cupy.float32, cupy.float64):
            if x.dtype.kind not in "iu":
                raise ValueError(f"points: expected float32 or float64 values (or integers), got dtype {x.dtype}")
            x = x.astype(cupy.float64)
            if x.size and bool((cupy.abs(x) >= _EXACT_INT_LIMIT).any()):
                raise ValueError(_INEXACT_INT)
        x = cupy.ascontiguousarray(x)  # the same array when it already is
        return x, int(cupy.cuda.get_current_stream().ptr)


_DEVICE_PREPARE: dict[str, Callable[[Any], tuple[Any, int]]] = {"torch": _torch_prepare, "cupy": _cupy_prepare}


def _empty_like(framework: str, like: Any) -> Any:
    if framework == "torch":
        torch = importlib.import_module("torch")
        return torch.empty((0,), dtype=torch.int32, device=like.device)
    cupy = importlib.import_module("cupy")
    with like.device:
        return cupy.empty((0,), dtype=cupy.int32)


def zero_copy_possible(origin: Origin, algorithm: str, backend: str, ordinal: int) -> bool:
    """Whether a CUDA input goes to gdel::delaunay_device (else: the host round trip)."""
    return (
        origin.framework in _DEVICE_PREPARE
        and backend in ("auto", "cuda")
        and ordinal == origin.device_id
        and algorithm != "gstar4d"  # its certificate runs on host arrays (docs/python.md)
        and _core.cuda_device_available()
    )


def _delaunay_on_device(points: Any, algorithm: str, backend: str, ordinal: int, origin: Origin) -> RawResult:
    """torch / cupy CUDA arrays: no host copy. The compiled layer passes the array's
    device pointer (and the framework's current stream, which gdel waits for) to
    gdel::delaunay_device; the results are int32 arrays of the same framework on the
    same device that own gdel's device memory. Anything else takes the host round trip."""
    if not zero_copy_possible(origin, algorithm, backend, ordinal):
        return _delaunay_via_host(points, algorithm, backend, ordinal, origin)
    x, stream = _DEVICE_PREPARE[origin.framework](points)
    r = _core.delaunay_device(x, origin.framework, algorithm, stream)

    def arr(name: str, empty_shape: tuple[int, ...]) -> Any:
        a = r[name]
        if a is None:
            a = _empty_like(origin.framework, x).reshape(empty_shape)
        return a

    return RawResult(
        x,
        arr("simplices", (0, 4)),
        arr("neighbors", (0, 4)),
        arr("failed_vertices", (0,)),
        arr("representative", (0,)),
        r["stats"],
        origin,
        on_device=True,
    )


def delaunay(points: Any, algorithm: str, device: str) -> RawResult:
    origin = origin_of(points, "points")
    backend, ordinal = resolve_device(device, origin)
    if origin.on_device:
        return _delaunay_on_device(points, algorithm, backend, ordinal, origin)
    return _delaunay_on_host(host_array(points, "points"), algorithm, backend, ordinal, origin)


@dataclass
class RawRegular(RawResult):
    """RawResult of gdel::regular (always through the host: see docs/python.md)."""

    weights: Any = None  # (n,) float64 on the host
    redundant: Any = None
    certificates: Any = None


def regular(points: Any, weights: Any, device: str, certificates: bool) -> RawRegular:
    """gdel::regular on host copies of the inputs (CUDA inputs are copied to the host and
    the results given back on their device when read)."""
    origin = origin_of(points, "points")
    backend, ordinal = resolve_device(device, origin)
    host = to_host(points, origin, "points")
    worigin = origin_of(weights, "weights")
    whost = to_host(weights, worigin, "weights")
    r = _core.regular(host, whost, "auto", backend, ordinal, certificates)
    pts = r["points"] if r["points"] is not None else as_numpy(host)
    w = r["weights"] if r["weights"] is not None else as_numpy(whost)
    r["stats"]["device_input"] = None
    empty = np.zeros(0, dtype=np.int32)
    return RawRegular(
        pts,
        r["simplices"],
        r["neighbors"],
        empty,
        r["representative"],
        r["stats"],
        origin,
        weights=w,
        redundant=r["redundant"],
        certificates=r["certificates"],
    )
