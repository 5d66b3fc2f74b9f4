"""gdel.Delaunay: the exact 3-D Delaunay triangulation with scipy.spatial.Delaunay's shape."""

from __future__ import annotations

from functools import cached_property
from typing import Any, Optional

import numpy as np

from . import _arrays, _check, _core, _locate

# Hull face of simplex s opposite its vertex i, listed so that its normal (right-hand
# rule) points out of s, i.e. out of the hull. docs/conventions.md: face_vertex(i, .)
# = (1,3,2) (0,2,3) (0,3,1) (0,1,2) turns counter-clockwise seen from vertex i (normal
# towards the inside); these are the same faces reversed.
_OUTWARD_FACE = np.array([[1, 2, 3], [0, 3, 2], [0, 1, 3], [0, 2, 1]], dtype=np.intp)

# The 6 edges of a simplex, as pairs of local vertex indices.
_EDGES = np.array([[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]], dtype=np.intp)


class Delaunay:
    """Exact Delaunay triangulation of 3-D points, shaped like ``scipy.spatial.Delaunay``.

    ``from gdel import Delaunay`` in place of ``from scipy.spatial import Delaunay`` gives
    the same attributes for 3-D input, computed with exact predicates (no joggling, no
    tolerance in any combinatorial decision), on the GPU when one is available.

    Parameters
    ----------
    points : array (n, 3)
        float32 or float64 coordinates (integers are accepted when exactly representable),
        any strides. numpy arrays, nested sequences, and DLPack producers (torch, cupy,
        jax, ...) are accepted. Host arrays are read in place when C-contiguous float64
        and converted to contiguous float64 once otherwise. torch and cupy CUDA arrays
        are triangulated on their GPU without a host copy (float32 is converted on the
        device) and the results are int32 arrays of the same framework on the same
        device; jax CUDA arrays (and ``device="cpu"``, another ``cuda:N``, or gstar4d)
        go through the host, with results copied back to the input's device.
    algorithm : "auto" | "gdel3d" | "gflip3d" | ...
        "auto" is "gdel3d": the exact Delaunay triangulation (every facet locally
        Delaunay, no zero-volume simplex, cospherical ties broken by a symbolic
        perturbation). "gflip3d" is the unrepaired flip algorithm: a valid triangulation
        in which a few facets may not be locally Delaunay (``failed_vertices``).
        ``gdel.ALGORITHMS`` lists every name this build knows (the C++ library's).
    device : "auto" | "cpu" | "cuda" | "cuda:N"
        Where to compute. "auto": the GPU when this build has CUDA and a device is
        visible (for a CUDA input, the GPU it is on), else the CPU (OpenMP threads).
    check : bool
        Run the exact verifier on the result (``check_report``) and raise
        :class:`gdel.GdelError` unless it meets the algorithm's contract
        (:meth:`CheckReport.meets_contract`; gdel3d: Delaunay; gflip3d: a valid
        triangulation, flat tets allowed on degenerate input).

    Attributes
    ----------
    points : ndarray (n, 3) float64
        The input as C-contiguous float64 (the input itself when it already was). For
        CUDA input: the array that was passed in.

    For a CUDA input, ``simplices``, ``neighbors``, ``representative`` and
    ``failed_vertices`` are the device arrays the C++ library returned; the derived
    attributes (``convex_hull``, ``vertex_to_simplex``, ``vertex_neighbor_vertices``,
    ``transform``, ``coplanar``) and ``find_simplex`` are computed on the host from a
    copy made on first use, and returned on the input's device.
    simplices : ndarray (m, 4) int32
        Vertex ids of each tetrahedron, positively oriented: ``orient3d(p0,p1,p2,p3) =
        det[p1-p0, p2-p0, p3-p0] > 0``. Duplicate points (exactly equal) appear once,
        as the smallest index of each group (see ``representative``).
    neighbors : ndarray (m, 4) int32
        ``neighbors[s, i]`` is the simplex across the face opposite vertex ``i`` of
        ``s``; -1 on the convex hull (scipy's convention).
    convex_hull : ndarray (h, 3) int32
        Hull triangles, each oriented with its normal (right-hand rule) pointing out
        of the hull.
    vertex_to_simplex : ndarray (n,) int32
        A simplex containing each vertex; -1 for points in no simplex (duplicates).
    vertex_neighbor_vertices : (ndarray (n+1,), ndarray) int32
        ``(indptr, indices)``: the vertices joined to vertex k by an edge are
        ``indices[indptr[k]:indptr[k+1]]`` (ascending).
    transform : ndarray (m, 4, 3) float64
        Affine maps to barycentric coordinates, as scipy defines them.
    representative : ndarray (n,) int32
        For each input point, the point that stands for it in ``simplices``: itself,
        or the smallest index of an exactly equal point.
    coplanar : ndarray (k, 3) int32
        scipy's layout for points left out of the triangulation (here: exact
        duplicates): ``[point, a simplex of its representative, representative]``.
    failed_vertices : ndarray (k,) int32
        gflip3d only: vertices of facets left not locally Delaunay (empty for gdel3d).
    stats : dict
        Algorithm, backend, seconds in total and per stage, counts, peak memory.
    check_report : CheckReport or None
        With ``check=True``, the exact verifier's report.
    npoints, nsimplex, ndim : int

    Differences from scipy: 3-D only; no ``incremental``/``qhull_options``/
    ``furthest_site``; points that are not exact duplicates are never dropped (no
    "coplanar" points in Qhull's sense).
    """

    ndim = 3

    def __init__(
        self,
        points: Any,
        *,
        algorithm: str = "auto",
        device: str = "auto",
        check: bool = False,
    ) -> None:
        self._adopt(_arrays.delaunay(points, algorithm, device), points, device, check, None)

    def _adopt(self, raw: Any, points: Any, device: str, check: bool, weights: Any) -> None:
        """Takes the compiled layer's result; with ``check``, runs the exact verifier
        (regular mode when ``weights`` is given) and raises unless the result meets the
        algorithm's contract."""
        self._raw = raw
        self._origin = raw.origin
        self._input = points
        self.stats: dict[str, Any] = raw.stats
        self.check_report: Optional[_check.CheckReport] = None
        if check:
            backend, _ = _arrays.resolve_device(device, raw.origin)
            report = _check.CheckReport(**_core.verify(self._points, self._simplices, weights, backend))
            self.check_report = report
            if not report.meets_contract(self.stats["algorithm"]):
                raise _core.GdelError(
                    f"the {self.stats['algorithm']} result failed the exact check:\n{report.summary}"
                )

    # -- sizes -----------------------------------------------------------------

    @property
    def npoints(self) -> int:
        return int(self._raw.points.shape[0])

    @property
    def nsimplex(self) -> int:
        return int(self._raw.simplices.shape[0])

    # -- host views: numpy arrays the derived attributes and queries compute with. On the
    # -- device path (torch/cupy CUDA input) each is a device -> host copy made on first
    # -- use only; the triangulation itself never needs them.

    def _host(self, name: str) -> np.ndarray:
        return self._origin.to_numpy(getattr(self._raw, name)) if self._raw.on_device else getattr(self._raw, name)

    @cached_property
    def _points(self) -> np.ndarray:
        return np.ascontiguousarray(self._host("points"), dtype=np.float64)

    @cached_property
    def _simplices(self) -> np.ndarray:
        return self._host("simplices")

    @cached_property
    def _neighbors(self) -> np.ndarray:
        return self._host("neighbors")

    @cached_property
    def _representative(self) -> np.ndarray:
        return self._host("representative")

    # -- arrays (host numpy for host input; the input's framework and device else) --

    def _result(self, name: str) -> Any:
        a = getattr(self._raw, name)
        return a if self._raw.on_device else self._origin.give(a)

    @cached_property
    def points(self) -> Any:
        return self._input if self._origin.on_device else self._raw.points

    @cached_property
    def simplices(self) -> Any:
        return self._result("simplices")

    @cached_property
    def neighbors(self) -> Any:
        return self._result("neighbors")

    @cached_property
    def failed_vertices(self) -> Any:
        return self._result("failed_vertices")

    @cached_property
    def representative(self) -> Any:
        return self._result("representative")

    @cached_property
    def _vertex_to_simplex(self) -> np.ndarray:
        vts = np.full(self.npoints, -1, dtype=np.int32)
        vts[self._simplices.ravel()] = np.repeat(np.arange(self.nsimplex, dtype=np.int32), 4)
        return vts

    @cached_property
    def vertex_to_simplex(self) -> Any:
        return self._origin.give(self._vertex_to_simplex)

    @cached_property
    def convex_hull(self) -> Any:
        s, i = np.nonzero(self._neighbors < 0)
        hull = self._simplices[s[:, None], _OUTWARD_FACE[i]]
        return self._origin.give(np.ascontiguousarray(hull, dtype=np.int32))

    @cached_property
    def vertex_neighbor_vertices(self) -> tuple[Any, Any]:
        n = self.npoints
        e = self._simplices[:, _EDGES].reshape(-1, 2).astype(np.int64)
        key = np.unique(np.concatenate([e[:, 0] * n + e[:, 1], e[:, 1] * n + e[:, 0]]))
        src, dst = np.divmod(key, n)
        indptr = np.zeros(n + 1, dtype=np.int64)
        np.cumsum(np.bincount(src, minlength=n), out=indptr[1:])
        itype = np.int32 if len(key) <= np.iinfo(np.int32).max else np.int64
        return self._origin.give(indptr.astype(itype)), self._origin.give(dst.astype(np.int32))

    @cached_property
    def _transform(self) -> np.ndarray:
        return _locate.affine_transform(self._points, self._simplices)

    @cached_property
    def transform(self) -> Any:
        return self._origin.give(self._transform)

    @cached_property
    def coplanar(self) -> Any:
        rep = self._representative
        dup = np.flatnonzero(rep != np.arange(self.npoints, dtype=rep.dtype))
        kept = rep[dup]
        c = np.stack([dup, self._vertex_to_simplex[kept], kept], axis=1).astype(np.int32)
        return self._origin.give(c.reshape(-1, 3))

    # -- queries ---------------------------------------------------------------

    def find_simplex(self, xi: Any, bruteforce: bool = False, tol: Optional[float] = None) -> Any:
        """The simplex containing each point of ``xi`` (shape (..., 3)), -1 outside the hull.

        scipy's semantics: a point is in simplex s when all four of its barycentric
        coordinates in s are >= -tol (default ``100 * eps`` of float64). Coordinates are
        computed in floating point, so a point within tol of a face shared by two
        simplices may be reported in either; the result is exact for points strictly
        inside a simplex by more than that margin. Returns int32 of shape
        ``xi.shape[:-1]``, as an array of ``xi``'s kind (a CUDA ``xi`` goes through the
        host, like the points).
        """
        origin = _arrays.origin_of(xi, "xi")
        x = np.asarray(_arrays.as_numpy(_arrays.to_host(xi, origin, "xi")), dtype=np.float64)
        if x.ndim == 0 or x.shape[-1] != 3:
            raise ValueError(f"xi: expected an array of shape (..., 3), got shape {x.shape}")
        shape = x.shape[:-1]
        x = np.ascontiguousarray(x.reshape(-1, 3))
        eps = 100 * np.finfo(np.float64).eps if tol is None else float(tol)
        s = _locate.find_simplex(
            self._points,
            self._simplices,
            self._neighbors,
            self._transform,
            self._vertex_to_simplex,
            x,
            eps,
            bruteforce,
        )
        return origin.give(s.reshape(shape))

    def __repr__(self) -> str:
        return (
            f"<gdel.Delaunay: {self.npoints} points, {self.nsimplex} simplices, "
            f"{self.stats['algorithm']} on {self.stats['backend']}>"
        )


def delaunay(points: Any, *, algorithm: str = "auto", device: str = "auto", check: bool = False) -> Delaunay:
    """Functional form of :class:`Delaunay` (same arguments, same object)."""
    return Delaunay(points, algorithm=algorithm, device=device, check=check)
