"""Array interop: what gdel accepts, where it computes, and how results go back.

* Host arrays (numpy, or any DLPack producer whose memory the CPU can read: torch and
  jax CPU arrays, ...) go to the compiled layer as they are. It reads C-contiguous
  float64 in place and converts anything else (float32, integers, any strides) to
  contiguous float64 exactly once. Results are numpy arrays.
* CUDA arrays (torch, cupy, jax) are NOT zero-copy yet: the C++ API takes host
  memory only, so :func:`_delaunay_on_device` copies the points to the host through
  the array's own framework, triangulates (on the GPU the array lives on, unless
  ``device`` says otherwise), and each result is copied back to that GPU as an array
  of the same framework. When the C++ API gains a device-pointer entry point, that
  function is the one place to change.
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


def _torch_from_host(a: np.ndarray, like: Any) -> Any:
    torch = importlib.import_module("torch")
    return torch.from_numpy(np.ascontiguousarray(a)).to(like.device)


def _cupy_to_host(x: Any) -> Any:
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


_FRAMEWORKS = {
    "torch": _Framework(_torch_to_host, _torch_from_host),
    "cupy": _Framework(_cupy_to_host, _cupy_from_host),
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
    """The compiled layer's output, on the host, plus where results must go."""

    points: np.ndarray  # (n, 3) float64, C-contiguous
    simplices: np.ndarray
    neighbors: np.ndarray
    failed_vertices: np.ndarray
    representative: np.ndarray
    stats: dict[str, Any]
    origin: Origin


def _delaunay_on_host(host: Any, algorithm: str, backend: str, ordinal: int, origin: Origin) -> RawResult:
    r = _core.delaunay(host, algorithm, backend, ordinal)
    # The float64 copy the library made when it converted the input; otherwise the
    # input itself already was contiguous float64 and is viewed, not copied.
    pts = r["points"] if r["points"] is not None else as_numpy(host)
    return RawResult(
        pts, r["simplices"], r["neighbors"], r["failed_vertices"], r["representative"], r["stats"], origin
    )


def _delaunay_on_device(points: Any, algorithm: str, backend: str, ordinal: int, origin: Origin) -> RawResult:
    # NOT zero-copy yet. The C++ API (gdel::delaunay) takes host memory only, so the
    # points make an explicit device -> host copy here and every result a host ->
    # device copy when it is read (Origin.give). A device-pointer C++ entry point will
    # replace this body: pass the CUDA pointer and stream, get device arrays back.
    host = to_host(points, origin, "points")
    return _delaunay_on_host(host, algorithm, backend, ordinal, origin)


def delaunay(points: Any, algorithm: str, device: str) -> RawResult:
    origin = origin_of(points, "points")
    backend, ordinal = resolve_device(device, origin)
    if origin.on_device:
        return _delaunay_on_device(points, algorithm, backend, ordinal, origin)
    return _delaunay_on_host(host_array(points, "points"), algorithm, backend, ordinal, origin)
