"""Sampled joint trajectories as CSV and JSON (seconds, radians and degrees) that load back.

Exported samples are in the robot controller's joint convention (`JointConvention`: what the
pendant, the project file and every program show): `csv_text(..., convention=c)` writes
`c.to_controller(q)` and says so in the column headers (`J1 controller [rad]`) and in JSON's
`"joints": "controller"`. Without a convention the values are written as given, headed
`q1 [rad]` (`"joints": "as given"`). The loaders return the values as written."""

from __future__ import annotations

import csv
import io
import json
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.atomic_file import atomic_write_text
from workbench.errors import InputError
from workbench.kinematics.joint_convention import JointConvention

FORMAT = "workbench.joint_samples"


def _check(
    times: ArrayLike, positions: ArrayLike
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    t = np.asarray(times, float).reshape(-1)
    q = np.asarray(positions, float)
    if q.ndim != 2 or q.shape[0] != t.shape[0]:
        raise InputError(f"positions must be ({t.shape[0]}, dof) to match times, got {q.shape}")
    if not (np.all(np.isfinite(t)) and np.all(np.isfinite(q))):
        raise InputError("times and positions must be finite numbers")
    return t, q


def _header(dof: int, controller: bool) -> list[str]:
    col = (lambda k, u: f"J{k} controller [{u}]") if controller else (lambda k, u: f"q{k} [{u}]")
    return (
        ["t [s]"]
        + [col(k, "rad") for k in range(1, dof + 1)]
        + [col(k, "deg") for k in range(1, dof + 1)]
    )


def _controller(q: NDArray[np.float64], convention: JointConvention | None) -> NDArray[np.float64]:
    if convention is None:
        return q
    return np.asarray(convention.to_controller(q), float).reshape(q.shape)


def csv_text(
    times: ArrayLike, positions: ArrayLike, *, convention: JointConvention | None = None
) -> str:
    """Return samples as CSV text: t [s], J1..Jn [rad], J1..Jn [deg]; floats round-trip
    exactly. `positions` are model joints; with `convention` they are written as the
    controller's (`J1 controller [rad]` ...), else as given (`q1 [rad]` ...)."""
    t, q = _check(times, positions)
    q = _controller(q, convention)
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(_header(q.shape[1], convention is not None))
    for ti, qi, di in zip(t, q, np.degrees(q), strict=True):
        w.writerow([repr(float(ti)), *(repr(float(x)) for x in qi), *(f"{x:.6f}" for x in di)])
    return buf.getvalue()


def save_csv(path: str | Path, times: ArrayLike, positions: ArrayLike) -> None:
    """Write `csv_text` of the samples to `path` atomically."""
    atomic_write_text(path, csv_text(times, positions))


def load_csv(path: str | Path) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Return (times [s] (n,), positions [rad] (n, dof)) from a CSV written by `save_csv`."""
    with open(path, newline="") as fh:
        rows = list(csv.reader(fh))
    if not rows or not rows[0] or rows[0][0] != "t [s]":
        raise InputError(f"{path}: first row must be the header starting with 't [s]'")
    head = rows[0]
    rad = [k for k, h in enumerate(head) if h.endswith("[rad]")]
    try:
        data = np.array([[float(r[0])] + [float(r[k]) for k in rad] for r in rows[1:]], float)
    except (ValueError, IndexError) as exc:
        raise InputError(f"{path}: every row needs numbers under {head}") from exc
    return data[:, 0].copy(), data[:, 1:].reshape(len(rows) - 1, len(rad))


def json_text(
    times: ArrayLike, positions: ArrayLike, *, convention: JointConvention | None = None
) -> str:
    """Return samples as JSON text with keys t_s, q_rad and q_deg (lists of rows); with
    `convention` the joints are the controller's (`"joints": "controller"`)."""
    t, q = _check(times, positions)
    q = _controller(q, convention)
    doc = {
        "format": FORMAT,
        "version": 1,
        "joints": "controller" if convention is not None else "as given",
        "units": {"t_s": "s", "q_rad": "rad", "q_deg": "deg"},
        "t_s": t.tolist(),
        "q_rad": q.tolist(),
        "q_deg": np.round(np.degrees(q), 6).tolist(),
    }
    return json.dumps(doc)


def save_json(path: str | Path, times: ArrayLike, positions: ArrayLike) -> None:
    """Write `json_text` of the samples to `path` atomically."""
    atomic_write_text(path, json_text(times, positions))


def load_json(path: str | Path) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Return (times [s] (n,), positions [rad] (n, dof)) from a JSON written by `save_json`."""
    try:
        doc = json.loads(Path(path).read_text())
    except json.JSONDecodeError as exc:
        raise InputError(f"{path}: not valid JSON ({exc})") from exc
    if not isinstance(doc, dict) or doc.get("format") != FORMAT:
        raise InputError(f"{path}: 'format' must be {FORMAT!r}")
    t, q = np.asarray(doc["t_s"], float), np.asarray(doc["q_rad"], float)
    return _check(t, q.reshape(t.shape[0], -1))
