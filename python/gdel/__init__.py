"""gdel: exact 3-D Delaunay triangulation on NVIDIA GPUs and multi-core CPUs.

The API follows ``scipy.spatial.Delaunay``: replace ``from scipy.spatial import
Delaunay`` with ``from gdel import Delaunay``.

>>> import numpy as np, gdel
>>> tri = gdel.Delaunay(np.random.default_rng(0).random((1000, 3)))
>>> tri.simplices.shape[1], tri.simplices.dtype
(4, dtype('int32'))
>>> gdel.check(tri.points, tri.simplices).delaunay
True

Exceptions: ValueError for malformed input (shape, dtype, NaN/Inf);
:class:`DegenerateInputError` (a ValueError) when the points have no 3-D
triangulation; MemoryError when device memory runs out (attributes ``needed`` and
``available`` in bytes); :class:`BackendUnavailableError` (a :class:`GdelError`) when
``device="cuda"`` cannot be honoured; :class:`GdelError` (a RuntimeError) otherwise.
See docs/python.md for the output contract.
"""

import operator

from . import _core
from ._check import CheckReport, check
from ._core import BackendUnavailableError, DegenerateInputError, GdelError
from ._delaunay import Delaunay, delaunay
from ._regular import Regular, regular

__version__: str = _core.version()

#: Names accepted by ``algorithm=``.
ALGORITHMS: tuple[str, ...] = _core.ALGORITHMS
#: Names accepted by ``device=`` (and "cuda:N").
DEVICES: tuple[str, ...] = _core.DEVICES + ("cuda:N",)

for _cls in (GdelError, DegenerateInputError, BackendUnavailableError):
    _cls.__module__ = "gdel"  # shown as gdel.<Name> in tracebacks
del _cls


def built_with_cuda() -> bool:
    """True when this build of gdel contains the CUDA backend (a GPU may still be absent)."""
    return _core.built_with_cuda()


def cuda_available() -> bool:
    """True when this build has the CUDA backend and a CUDA device is visible."""
    return _core.cuda_device_available()


def keep_device_memory(nbytes: int) -> None:
    """Keep up to ``nbytes`` of the device memory gdel's GPU calls free, for later calls.

    By default (``0``) every GPU call maps the memory it needs and gives all of it back
    when it returns. With ``nbytes > 0`` the calls on a device share one memory pool that
    keeps up to ``nbytes`` of it after each call, so that the next call finds it mapped
    (uniform 10^7 points on an H100: 5-19 ms of 0.44 s). Other users of the GPU (PyTorch,
    CuPy) see the kept memory as taken, as gdel sees their caches. Arrays returned to
    you never come from the pool. Process-wide. Without CUDA the setting is only recorded.
    """
    try:
        n = None if isinstance(nbytes, bool) else operator.index(nbytes)  # numpy ints too
    except TypeError:
        n = None
    if n is None or n < 0:
        raise ValueError(f"keep_device_memory: nbytes must be an int >= 0, got {nbytes!r}")
    _core.keep_device_memory(min(n, 2**64 - 1))


def release_device_memory() -> None:
    """Give the device memory kept between calls (``keep_device_memory``) back now."""
    _core.release_device_memory()


def kept_device_memory_bound() -> int:
    """The ``keep_device_memory`` setting: bytes kept between calls at most (0: none)."""
    return int(_core.kept_device_memory_bound())


__all__ = [
    "ALGORITHMS",
    "DEVICES",
    "BackendUnavailableError",
    "CheckReport",
    "DegenerateInputError",
    "Delaunay",
    "GdelError",
    "Regular",
    "built_with_cuda",
    "check",
    "cuda_available",
    "delaunay",
    "keep_device_memory",
    "kept_device_memory_bound",
    "regular",
    "release_device_memory",
]
