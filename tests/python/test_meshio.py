"""meshio reads the .vtu and .mesh files that gdel writes (issue 7).

The Python package has no mesh writer, so the files come from the `gdel` command: the
path in the environment variable GDEL_CLI, else build/cpu/gdel in the repository
(scripts/test.sh builds it before running the Python tests). Skipped when meshio is not
installed or the command is missing.

Reference: the same input written as .npz by the same command, read with numpy alone.
At 300 points the CPU backend inserts on one thread, so every run gives the same tets in
the same order (larger inputs run on several threads: the same tets, possibly in another
order unless Options::canonical_order is set).
"""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

meshio = pytest.importorskip("meshio")

ROOT = Path(__file__).resolve().parents[2]


def _gdel_cli() -> Path:
    path = Path(os.environ.get("GDEL_CLI", ROOT / "build" / "cpu" / "gdel"))
    if not (path.is_file() and os.access(path, os.X_OK)):
        pytest.skip(f"gdel command not found at {path} (cmake --build --preset cpu --target gdel_cli, or set GDEL_CLI)")
    return path


@pytest.fixture(scope="module")
def written(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """One input, triangulated by the command into .npz, .vtu and .mesh."""
    gdel = _gdel_cli()
    d = tmp_path_factory.mktemp("meshio")
    rng = np.random.default_rng(7)
    # Coordinates with full 53-bit mantissas (no short decimal form), mixed signs and
    # magnitudes, plus an exact duplicate: every input point is written, duplicates too.
    pts = (rng.random((300, 3)) - 0.5) * np.array([1.0, 3e-3, 7e4])
    pts[5] = [0.1, 1.0 / 3.0, -2.0 / 3.0]
    pts[6] = pts[17]
    np.save(d / "pts.npy", pts)
    env = dict(os.environ, OMP_WAIT_POLICY=os.environ.get("OMP_WAIT_POLICY", "PASSIVE"))
    out = {"input": d / "pts.npy"}
    for ext in ("npz", "vtu", "mesh"):
        out[ext] = d / f"m.{ext}"
        subprocess.run(
            [str(gdel), "delaunay", str(out["input"]), "-o", str(out[ext]), "--device", "cpu", "--quiet"],
            check=True,
            env=env,
            timeout=120,
        )
    return out


@pytest.fixture(scope="module")
def reference(written: dict[str, Path]) -> dict[str, np.ndarray]:
    with np.load(written["npz"]) as z:
        ref = {k: z[k] for k in ("points", "tets", "neighbors")}
    assert np.array_equal(ref["points"], np.load(written["input"]))
    assert ref["tets"].shape[0] > 0
    return ref


def _tetra(mesh) -> np.ndarray:
    blocks = [c for c in mesh.cells if c.type == "tetra"]
    assert len(blocks) == 1, [c.type for c in mesh.cells]
    assert len(mesh.cells) == 1, [c.type for c in mesh.cells]
    return blocks[0].data


def test_vtu(written: dict[str, Path], reference: dict[str, np.ndarray]) -> None:
    mesh = meshio.read(written["vtu"])
    # Float64 binary: bit-exact points, all of them (the duplicate included).
    assert mesh.points.dtype == np.float64
    assert np.array_equal(mesh.points, reference["points"])
    tets = _tetra(mesh)
    assert np.array_equal(tets, reference["tets"])
    # Cell data: neighbors (4 components, -1 on the hull) and tet_id (the row).
    neighbors = mesh.cell_data["neighbors"]
    assert len(neighbors) == 1
    assert np.array_equal(neighbors[0], reference["neighbors"])
    assert (neighbors[0] == -1).any()
    tet_id = mesh.cell_data["tet_id"]
    assert np.array_equal(tet_id[0], np.arange(len(tets)))


def test_mesh(written: dict[str, Path], reference: dict[str, np.ndarray]) -> None:
    mesh = meshio.read(written["mesh"])
    # ASCII, each coordinate in its shortest round-trip form: read back exactly.
    assert mesh.points.dtype == np.float64
    assert np.array_equal(mesh.points, reference["points"])
    # 1-based in the file; meshio returns 0-based ids.
    assert np.array_equal(_tetra(mesh), reference["tets"])


def test_orientation(written: dict[str, Path]) -> None:
    """The tets meshio hands on are positively oriented (VTK_TETRA's order)."""
    mesh = meshio.read(written["vtu"])
    p = mesh.points[_tetra(mesh)]
    det = np.linalg.det(p[:, 1:] - p[:, :1])
    assert (det > 0).all()
