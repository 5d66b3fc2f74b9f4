"""gdel.check: the exact verifier (C++ gdel::verify) on any points and simplices."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional

from . import _arrays, _core


@dataclass(frozen=True)
class CheckReport:
    """What :func:`gdel.check` found. Every decision is an exact predicate (no symbolic
    perturbation: a cospherical tie is a tie, allowed and counted).

    ``valid``: the simplices triangulate the convex hull of the distinct points
    (every failure count below is 0 and the Euler characteristic is that of a ball).
    ``delaunay``: valid and every interior facet locally Delaunay (regular with weights).
    ``str(report)`` is the same text as ``gdel check`` prints.
    """

    # sizes
    points: int
    distinct_points: int
    tets: int
    vertices_used: int
    edges: int
    facets: int
    hull_facets: int
    euler: int
    # validity failures (each 0 in a valid triangulation)
    bad_index: int
    degenerate_tets: int
    inverted_tets: int
    overshared_facets: int
    same_side_facets: int
    hull_open_edges: int
    hull_reflex_edges: int
    unused_points: int
    duplicate_vertices: int
    locate_failures: int
    euler_ok: bool
    # the Delaunay / regular property
    non_delaunay_facets: int
    cospherical_facets: int
    redundant_points: int
    # work
    exact_evaluations: int
    seconds: float
    # verdicts
    valid: bool
    delaunay: bool
    summary: str

    def __str__(self) -> str:
        return self.summary

    def meets_contract(self, algorithm: str) -> bool:
        """Whether this is what ``algorithm`` promises (the rule of ``gdel delaunay --check``).

        gdel3d ("auto"): the Delaunay triangulation. gflip3d: a valid triangulation in
        which some facets may not be locally Delaunay and, on degenerate input, some
        tets may be flat (zero volume; only gdel3d's repair removes them).
        """
        if algorithm == "gflip3d":
            return self.valid or (self.degenerate_tets > 0 and _valid_ignoring_flat(self))
        return self.delaunay


def _valid_ignoring_flat(r: CheckReport) -> bool:
    failures = (
        r.bad_index,
        r.inverted_tets,
        r.overshared_facets,
        r.same_side_facets,
        r.hull_open_edges,
        r.hull_reflex_edges,
        r.unused_points,
        r.duplicate_vertices,
        r.locate_failures,
    )
    return r.euler_ok and not any(failures)


def check(points: Any, simplices: Any, weights: Optional[Any] = None, *, device: str = "auto") -> CheckReport:
    """Exactly verify that ``simplices`` is a (Delaunay / regular) triangulation of ``points``.

    Parameters
    ----------
    points : array (n, 3)
        float32/float64 (or integer) coordinates; numpy, any DLPack producer, or a CUDA
        array (copied to the host: not zero-copy yet).
    simplices : array (m, 4)
        Vertex ids (any integer dtype that fits int32). Orientation matters: a
        negatively oriented simplex is counted in ``inverted_tets``.
    weights : array (n,), optional
        Point weights: the regular (power) test replaces the Delaunay test, and points
        in no simplex must be proven redundant.
    device : "auto" | "cpu" | "cuda"
        Where the verifier runs ("cuda:0" is accepted; other ordinals are not yet).

    Returns
    -------
    CheckReport
    """
    origin = _arrays.origin_of(points, "points")
    backend, ordinal = _arrays.resolve_device(device, origin)
    if device.startswith("cuda:") and ordinal != 0:
        raise ValueError(
            f"device {device!r}: gdel.check runs on the default CUDA device only "
            "(the C++ gdel::verify takes no device ordinal yet)"
        )
    pts = _arrays.to_host(points, origin, "points")
    tets = _arrays.to_host(simplices, _arrays.origin_of(simplices, "simplices"), "simplices")
    w = None
    if weights is not None:
        w = _arrays.to_host(weights, _arrays.origin_of(weights, "weights"), "weights")
    return CheckReport(**_core.verify(pts, tets, w, backend))
