"""gdel.Regular: the exact regular (weighted Delaunay) triangulation, shaped like gdel.Delaunay."""

from __future__ import annotations

from functools import cached_property
from typing import Any

import numpy as np

from . import _arrays
from ._delaunay import Delaunay


class Regular(Delaunay):
    """Exact regular (weighted Delaunay) triangulation of weighted 3-D points (gReg3D).

    The points lifted to ``(p, |p|^2 - w)``: the regular triangulation is the projection
    of the lower convex hull. A point whose lifted image is not on that hull is
    *redundant* (hidden): it belongs to no simplex and is listed in ``redundant``. With all
    weights equal this is exactly :class:`gdel.Delaunay`'s triangulation.

    Parameters
    ----------
    points : array (n, 3)
        As for :class:`gdel.Delaunay` (numpy, nested sequences, DLPack producers; CUDA
        arrays are copied to the host and the results returned on their device: the
        regular path has no zero-copy device entry yet).
    weights : array (n,)
        One weight per point: a squared radius (power distance ``|x - p|^2 - w``), any sign.
    device : "auto" | "cpu" | "cuda" | "cuda:N"
        Where to compute, as for :class:`gdel.Delaunay`.
    check : bool
        Run the exact verifier in regular mode (power tests; unused points must be
        redundant) and raise :class:`gdel.GdelError` unless it passes. (gdel::regular
        already certifies its result this way; this keeps the report.)
    certificates : bool
        Also return ``certificates``: per redundant point, 5 point ids proving it
        redundant (docs/greg3d.md): ``(k, e, t0, t1, t2)`` whose lifted simplex holds its
        lifted point; ``(a, b, c, d, -1)`` a simplex holding it with its lifted point not
        below the simplex's; ``(r, -1, -1, -1, -1)`` a duplicate of the heavier point r.

    Attributes
    ----------
    Those of :class:`gdel.Delaunay` (``simplices``, ``neighbors``, ``convex_hull``,
    ``vertex_to_simplex`` (-1 for redundant points), ``vertex_neighbor_vertices``,
    ``transform``, ``find_simplex``, ``stats``, ...), and:
    weights : ndarray (n,) float64
    redundant : ndarray (k,) int32
        Ids of the points that are no vertex, ascending (exact duplicates of a heavier
        point included).
    representative : ndarray (n,) int32
        For each point: itself, or the heaviest point with the same coordinates.
    certificates : ndarray (k, 5) int32 or None
    """

    def __init__(
        self,
        points: Any,
        weights: Any,
        *,
        device: str = "auto",
        check: bool = False,
        certificates: bool = False,
    ) -> None:
        raw = _arrays.regular(points, weights, device, certificates)
        self._adopt(raw, points, device, check, raw.weights)

    @cached_property
    def weights(self) -> Any:
        return self._origin.give(np.ascontiguousarray(self._raw.weights, dtype=np.float64))

    @cached_property
    def redundant(self) -> Any:
        return self._origin.give(self._raw.redundant)

    @cached_property
    def certificates(self) -> Any:
        c = self._raw.certificates
        return None if c is None else self._origin.give(c)

    @cached_property
    def coplanar(self) -> Any:
        # scipy's layout for points left out: [point, a simplex of its representative,
        # representative], here for exact duplicates only (redundant points are in
        # `redundant`).
        return super().coplanar

    def __repr__(self) -> str:
        return (
            f"<gdel.Regular: {self.npoints} points ({len(self._raw.redundant)} redundant), "
            f"{self.nsimplex} simplices, {self.stats['algorithm']} on {self.stats['backend']}>"
        )


def regular(
    points: Any, weights: Any, *, device: str = "auto", check: bool = False, certificates: bool = False
) -> Regular:
    """Functional form of :class:`Regular` (same arguments, same object)."""
    return Regular(points, weights, device=device, check=check, certificates=certificates)
