"""THE TOUCH-UP ROUND TRIP: a program edited on the controller (targets re-taught on the pendant)
compared with the program it was exported from, move by move, and one rigid correction of each
work object fitted to the changes where they agree.

The shop floor touches up a target by jogging the robot to where the part really is and
recording it again; the work object on the controller stays as it was. When a fixture was
placed 3 mm off, every target on it moves by the same rigid transform: that transform belongs
in the work object (then the project's targets, unchanged in the work object, land where the
pendant put them). A target moved alone (a re-taught grip point) does not share it: it is named
and kept as taught.

- `planned` targets: the project's moves (`PlannedTarget`: TCP pose in the world, the work
  object the program states it in, joints for joint targets); `taught` targets: the program
  read back (`taught_targets`: every target as the controller reaches it, joint targets
  through FK and the tool).
- `match_moves` pairs them by name where the format keeps names (most read names are the
  project's), else by order; both by one alignment (Needleman-Wunsch) whose gaps are the moves
  added or deleted on the pendant, so a deleted move never shifts the pairs after it.
- `compare` gives each pair's change as the pendant programmer reads it (dx, dy, dz in the
  work object, rotation angle) and per work object the fit (`geometry.rigid_fit.fit_rigid_robust`
  on the positions, then the orientations checked against the fitted rotation), naming the
  targets that do not agree within `TouchupSettings`.

SI inside (m, rad); `TouchupRow.delta_mm`, `angle_deg` and `summary()` are for display.
"""

from __future__ import annotations

import dataclasses
import itertools
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.geometry.rigid_fit import RigidFit, check_spread, fit_rigid, fit_rigid_robust
from workbench.kinematics.model import RobotModel
from workbench.motion.programs.controller_program import ReadProgram
from workbench.motion.programs.readback import solve_moves

FloatArray = NDArray[np.float64]

MOVED_DISTANCE = 0.05e-3
"""A target moved when its position changed by more than this [m]: well above what the
workbench's own posts print (RAPID: 8 significant digits of mm, quaternions to 1e-9; KRL and
LS: 1e-6 mm and deg; URScript joints 1e-9 rad; NACHI joints 1e-6 deg)."""
MOVED_ANGLE = np.radians(0.05)
"""... or its orientation by more than this [rad]."""
FIT_DISTANCE = 0.5e-3
"""A target agrees with its work object's fitted correction within this [m] (the tolerance of
`fit_rigid_robust`); beyond it the target is named as moved alone."""
FIT_ANGLE = np.radians(0.5)
"""... and its orientation within this [rad] of the fitted rotation."""
GAP_COST = 1.0
"""The alignment's cost of a move added or deleted on the pendant."""
REPLACED_DISTANCE = 0.1
"""Matched by order (a format without names), a read target farther than this [m] from the
project's is another move (one deleted, one added on the pendant), not a touch-up: a pair
costs its distance / REPLACED_DISTANCE * 2 gaps, so it is preferred to two gaps below it."""

Status = Literal["same", "moved", "deleted", "added"]


@dataclass(frozen=True)
class TouchupSettings:
    """The tolerances of a touch-up comparison [m, rad] (defaults: the module's constants)."""

    moved_distance: float = MOVED_DISTANCE
    moved_angle: float = float(MOVED_ANGLE)
    fit_distance: float = FIT_DISTANCE
    fit_angle: float = float(FIT_ANGLE)

    def __post_init__(self) -> None:
        for name in ("moved_distance", "moved_angle", "fit_distance", "fit_angle"):
            value = getattr(self, name)
            if not (np.isfinite(value) and value > 0.0):
                raise InputError(f"{name} must be a positive number, got {value}", field=name)


@dataclass(frozen=True, eq=False)
class PlannedTarget:
    """A move of the project's program: `index` in the program's items, its `name`, `kind`
    (joint, linear), the work object `wobj` its program states it in, the TCP pose
    `T_world_tcp` (4, 4) [m] and, for a joint-valued target, its `joints` (dof,) [rad, model]."""

    index: int
    name: str
    kind: str
    wobj: str
    T_world_tcp: FloatArray
    joints: FloatArray | None = None


@dataclass(frozen=True, eq=False)
class TaughtTarget:
    """A move as the controller runs it (read back): `name`, `kind`, work object name, source
    `line`, the TCP pose `T_world_tcp` (4, 4) [m] and the joints `q` (dof,) [rad, model] the
    controller reaches it with; `pose_stated`: the program states a pose (not joints)."""

    name: str
    kind: str
    wobj: str
    line: int
    T_world_tcp: FloatArray
    q: FloatArray
    pose_stated: bool


@dataclass(frozen=True, eq=False)
class TouchupRow:
    """One move compared: `status` same, moved, deleted (on the pendant: in the project only)
    or added (in the read program only); `delta` (3,) [m] the position change in the work
    object's axes and `angle` [rad] the orientation change (None for added and deleted moves);
    `agrees`: within the tolerance of its work object's fitted correction (None: no fit)."""

    name: str
    status: Status
    wobj: str
    planned: PlannedTarget | None
    taught: TaughtTarget | None
    delta: FloatArray | None = None
    angle: float | None = None
    agrees: bool | None = None

    @property
    def moved(self) -> bool:
        """Return True when the target changed beyond the moved thresholds."""
        return self.status == "moved"

    @property
    def delta_mm(self) -> tuple[float, float, float] | None:
        """Return (dx, dy, dz) [mm] in the work object's axes (for display)."""
        return None if self.delta is None else tuple(float(v) * 1000.0 for v in self.delta)  # type: ignore[return-value]

    @property
    def angle_deg(self) -> float | None:
        """Return the rotation angle [deg] (for display)."""
        return None if self.angle is None else float(np.degrees(self.angle))


@dataclass(frozen=True, eq=False)
class WobjCorrection:
    """The rigid correction of one work object: `T_correction` (4, 4) [m] maps the project's
    targets onto the taught ones in the work object's frame (taught = C @ planned), so the work
    object must become `T_world_wobj @ C` (`T_world_wobj_new`). `fit` is None when the targets
    cannot determine one (`reason` says why); `outliers` names the targets it does not fit,
    `rms` and `max` [m] are over the targets it does."""

    wobj: str
    T_world_wobj: FloatArray
    T_correction: FloatArray
    fit: RigidFit | None
    names: tuple[str, ...]
    outliers: tuple[str, ...] = ()
    reason: str = ""
    moved: int = 0  # how many of its targets moved

    @property
    def fitted(self) -> bool:
        """Return True when a correction was fitted."""
        return self.fit is not None

    @property
    def T_world_wobj_new(self) -> FloatArray:
        """Return the corrected work object (4, 4) [m] in the world."""
        return np.asarray(self.T_world_wobj @ self.T_correction)

    @property
    def rms(self) -> float:
        """Return the RMS residual [m] of the targets the fit kept (0 without a fit)."""
        return 0.0 if self.fit is None else self.fit.rms

    @property
    def max(self) -> float:
        """Return the largest residual [m] of the targets the fit kept (0 without a fit)."""
        return 0.0 if self.fit is None else self.fit.max

    def significant(self, settings: TouchupSettings) -> bool:
        """Return True when the correction moves the work object beyond the moved thresholds."""
        return self.fitted and _changed(np.eye(4), self.T_correction, settings)


@dataclass(frozen=True, eq=False)
class TouchupReport:
    """A program read back compared with the project's: a row per move (in the read program's
    order, deleted moves where they were), a correction per work object with moves, the notes."""

    source: str
    fmt: str
    rows: tuple[TouchupRow, ...]
    corrections: tuple[WobjCorrection, ...]
    settings: TouchupSettings = field(default_factory=TouchupSettings)
    notes: tuple[str, ...] = ()

    @property
    def correction(self) -> WobjCorrection | None:
        """Return the correction of the work object with the most moves, fitted ones first."""
        ranked = sorted(self.corrections, key=lambda c: (not c.fitted, -len(c.names)))
        return ranked[0] if ranked else None

    @property
    def outliers(self) -> tuple[str, ...]:
        """Return the names of every target no correction fits."""
        return tuple(n for c in self.corrections for n in c.outliers)

    def row(self, name: str) -> TouchupRow:
        """Return the row of the move named `name`."""
        for r in self.rows:
            if r.name == name:
                return r
        raise InputError(
            f"no move {name!r} in the comparison; moves: {[r.name for r in self.rows]}"
        )

    def summary(self) -> str:
        """Return the table and the fits as text lines (mm, deg), for the CLI and the GUI."""
        return "\n".join(summary_lines(self))


# -- the taught targets ------------------------------------------------------------------------


def taught_targets(
    read: ReadProgram, model: RobotModel, T_world_base: FloatArray, T_flange_tcp: FloatArray
) -> list[TaughtTarget]:
    """Return every read move's target as the controller reaches it: a stated pose through its
    work object (as stated), a joint target through FK and the tool `T_flange_tcp`; the
    joints of each by the controller's own selection (`readback.solve_moves`)."""
    joints = solve_moves(read, model)
    wobjs = {w.name: w.T_base_wobj for w in read.work_objects}
    out = []
    for mv, q in zip(read.moves, joints, strict=True):
        tgt = mv.target
        if tgt.T_wobj_tcp is not None and tgt.joints is None:
            T = T_world_base @ wobjs[mv.wobj] @ tgt.T_wobj_tcp
        else:
            T = T_world_base @ model.fk(q) @ T_flange_tcp
        out.append(
            TaughtTarget(mv.name, mv.kind, mv.wobj, mv.line, T, np.asarray(q), tgt.joints is None)
        )
    return out


def read_notes(
    read: ReadProgram,
    frames: Mapping[str, FloatArray],
    T_world_base: FloatArray,
    T_flange_tcp: FloatArray,
    settings: TouchupSettings | None = None,
) -> list[str]:
    """Return what the comparison of `read` must say besides its rows: the lines the reader
    did not understand, circular moves (their end compared, not their via), a work object or
    tool of the program that differs from the project's (`frames`: the project's work objects
    in the world; the targets are compared in the world all the same)."""
    s = settings or TouchupSettings()
    notes = [f"line {n}: {t!r} is not understood; left out" for n, t in read.unknown]
    notes += [
        f"line {m.line} ({m.name}): a circular move; its end point is compared, its via point not"
        for m in read.moves
        if m.via is not None
    ]
    for w in read.work_objects:
        if w.name in frames and _changed(frames[w.name], T_world_base @ w.T_base_wobj, s):
            notes.append(
                f"work object {w.name}: the program's differs from the project's (changed on"
                " the controller?); its targets are compared where the program puts them"
            )
    for tool in {m.tool for m in read.moves}:
        data = next((t for t in read.tools if t.name == tool), None)
        if data is not None and _changed(T_flange_tcp, data.T_flange_tcp, s):
            notes.append(
                f"tool {tool}: the program's TCP differs from the project's; its pose targets are"
                " that tool's, its joint targets are compared through the project's tool"
            )
    return notes


# -- matching ----------------------------------------------------------------------------------

_NOT_IDENT = re.compile(r"[^a-z0-9_]")


def _ident(name: str) -> str:
    """Return a name as a post writes it: lower case (FANUC, NACHI: upper), illegal
    characters as _."""
    return _NOT_IDENT.sub("_", name.lower())


def _key(name: str) -> str:
    """Return a name as the posts may have renamed it: `_ident`, a numbering suffix ("_1",
    "_2": reserved or repeated names) dropped."""
    return re.sub(r"_\d+$", "", _ident(name))


def same_name(planned: str, taught: str) -> bool:
    """Return True when `taught` is `planned` as a post writes it (renamed, truncated)."""
    a, b = _key(planned), _key(taught)
    if not a or not b:
        return False
    return a == b or (len(b) >= 8 and a.startswith(b))


RENAMED_COST = 0.5 * GAP_COST
"""The alignment's cost of a pair whose names are the same only as renamed (`same_name`):
exactly equal names pair first ("pt_2" with "pt_2", not with "pt_3")."""


def pair_costs(
    planned: Sequence[PlannedTarget], taught: Sequence[TaughtTarget], by_name: bool
) -> FloatArray:
    """Return the alignment's cost (n, m) of pairing each planned with each taught move: by
    name, 0 (equal), `RENAMED_COST` (`same_name`) or 3 gaps (another move); by order, the
    distance in units of `REPLACED_DISTANCE` (two gaps), a quarter gap more for another kind."""
    if by_name:
        out = np.full((len(planned), len(taught)), 3.0 * GAP_COST)
        for i, p in enumerate(planned):
            for j, t in enumerate(taught):
                if _ident(p.name) == _ident(t.name):
                    out[i, j] = 0.0
                elif same_name(p.name, t.name):
                    out[i, j] = RENAMED_COST
        return out
    P = np.array([p.T_world_tcp[:3, 3] for p in planned]).reshape(-1, 3)
    T = np.array([t.T_world_tcp[:3, 3] for t in taught]).reshape(-1, 3)
    d = np.linalg.norm(P[:, None, :] - T[None, :, :], axis=2)
    joint_p = np.array([p.kind == "joint" for p in planned], bool)
    joint_t = np.array([t.kind == "joint" for t in taught], bool)
    kind = 0.25 * GAP_COST * (joint_p[:, None] != joint_t[None, :])
    return np.asarray(2.0 * GAP_COST * d / REPLACED_DISTANCE + kind)


def names_kept(planned: Sequence[PlannedTarget], taught: Sequence[TaughtTarget]) -> bool:
    """Return True when at least half the read moves carry a name of the project's moves."""
    if not taught:
        return False
    hits = sum(any(same_name(p.name, t.name) for p in planned) for t in taught)
    return hits * 2 >= len(taught)


def match_moves(
    planned: Sequence[PlannedTarget], taught: Sequence[TaughtTarget]
) -> list[tuple[int | None, int | None]]:
    """Return the alignment of the two move lists as (planned index, taught index) pairs in
    order; None on one side: a move deleted (taught None) or added (planned None) on the
    pendant. By name where the format keeps names (`names_kept`), else by order and distance:
    the least total cost (`pair_costs`, `GAP_COST` a gap; Needleman-Wunsch)."""
    pairs = pair_costs(planned, taught, names_kept(planned, taught))
    n, m = pairs.shape
    cost = np.zeros((n + 1, m + 1))
    cost[:, 0] = np.arange(n + 1) * GAP_COST
    cost[0, :] = np.arange(m + 1) * GAP_COST
    for i in range(1, n + 1):
        for j in range(1, m + 1):
            cost[i, j] = min(
                cost[i - 1, j - 1] + pairs[i - 1, j - 1],
                cost[i - 1, j] + GAP_COST,
                cost[i, j - 1] + GAP_COST,
            )
    out: list[tuple[int | None, int | None]] = []
    i, j = n, m
    while i > 0 or j > 0:
        if i > 0 and j > 0 and np.isclose(cost[i, j], cost[i - 1, j - 1] + pairs[i - 1, j - 1]):
            out.append((i - 1, j - 1))
            i, j = i - 1, j - 1
        elif i > 0 and np.isclose(cost[i, j], cost[i - 1, j] + GAP_COST):
            out.append((i - 1, None))
            i -= 1
        else:
            out.append((None, j - 1))
            j -= 1
    return out[::-1]


# -- the comparison ----------------------------------------------------------------------------


def rotation_angle(R_a: FloatArray, R_b: FloatArray) -> float:
    """Return the angle [rad] of the rotation between two rotation matrices."""
    c = (np.trace(R_a.T @ R_b) - 1.0) / 2.0
    return float(np.arccos(np.clip(c, -1.0, 1.0)))


def _changed(T_a: FloatArray, T_b: FloatArray, settings: TouchupSettings) -> bool:
    d = float(np.linalg.norm(T_b[:3, 3] - T_a[:3, 3]))
    return d > settings.moved_distance or rotation_angle(T_a[:3, :3], T_b[:3, :3]) > (
        settings.moved_angle
    )


def _row(
    p: PlannedTarget | None,
    t: TaughtTarget | None,
    frames: Mapping[str, FloatArray],
    settings: TouchupSettings,
) -> TouchupRow:
    if p is None:
        assert t is not None
        return TouchupRow(t.name, "added", t.wobj if t.wobj in frames else "base", None, t)
    if t is None:
        return TouchupRow(p.name, "deleted", p.wobj, p, None)
    R_wobj = frames[p.wobj][:3, :3]
    delta = R_wobj.T @ (t.T_world_tcp[:3, 3] - p.T_world_tcp[:3, 3])
    angle = rotation_angle(p.T_world_tcp[:3, :3], t.T_world_tcp[:3, :3])
    status: Status = "moved" if _changed(p.T_world_tcp, t.T_world_tcp, settings) else "same"
    return TouchupRow(p.name, status, p.wobj, p, t, delta, angle)


def _in_wobj(T_world_wobj: FloatArray, T_world: FloatArray) -> FloatArray:
    R, o = T_world_wobj[:3, :3], T_world_wobj[:3, 3]
    out = np.eye(4)
    out[:3, :3] = R.T @ T_world[:3, :3]
    out[:3, 3] = R.T @ (T_world[:3, 3] - o)
    return out


def _agreement(
    C: FloatArray, planned: Sequence[FloatArray], taught: Sequence[FloatArray], s: TouchupSettings
) -> tuple[list[int], float]:
    """Return the indices of the targets that `C` maps onto their taught pose within the fit
    tolerances (position and orientation), and the sum of their distances [m]."""
    P, Q = np.asarray(planned), np.asarray(taught)  # (n, 4, 4)
    moved = P[:, :3, 3] @ C[:3, :3].T + C[:3, 3]
    dist = np.linalg.norm(moved - Q[:, :3, 3], axis=1)
    # angle of (C_R P_R)^T Q_R: trace = sum of the elementwise product of C_R P_R and Q_R
    cos = (np.einsum("ij,njk,nik->n", C[:3, :3], P[:, :3, :3], Q[:, :3, :3]) - 1.0) / 2.0
    ok = (dist <= s.fit_distance) & (np.arccos(np.clip(cos, -1.0, 1.0)) <= s.fit_angle)
    return [int(k) for k in np.flatnonzero(ok)], float(dist[ok].sum())


MAX_TRIPLES = 220
"""The consensus tries every triple of targets up to 12 targets (220 triples), beyond that
this many, drawn with a fixed seed (the same report for the same programs)."""


def _candidates(planned: Sequence[FloatArray], taught: Sequence[FloatArray]) -> list[FloatArray]:
    """Return the rigid changes the consensus tries: each target's own (taught @ inv(planned):
    a pose fixes one) and the least-squares change of the positions of each triple of targets
    (the pendant may re-teach positions and leave a tool's orientation as it was)."""
    out = [Q @ np.linalg.inv(P) for P, Q in zip(planned, taught, strict=True)]
    n = len(planned)
    triples = list(itertools.combinations(range(n), 3))
    if len(triples) > MAX_TRIPLES:
        rng = np.random.default_rng(0)
        triples = [triples[k] for k in rng.choice(len(triples), MAX_TRIPLES, replace=False)]
    src = np.array([P[:3, 3] for P in planned])
    tgt = np.array([Q[:3, 3] for Q in taught])
    for tri in triples:
        try:
            out.append(fit_rigid(src[list(tri)], tgt[list(tri)]).T)
        except InputError:  # on one line: no change determined
            continue
    return out


def consensus(
    planned: Sequence[FloatArray], taught: Sequence[FloatArray], settings: TouchupSettings
) -> list[int]:
    """Return the largest set of targets that share one rigid change: every candidate change
    (`_candidates`) tried on all targets, the one most agree with kept, within the fit
    tolerances in position and orientation (ties: the smaller summed distance). A
    least-squares fit of all targets can mask a target moved alone by spreading its error over
    a few coplanar others; a change fixed by a few targets cannot (RANSAC's idea, exhaustive
    where the targets are few)."""
    best: list[int] = []
    best_cost = np.inf
    for C in _candidates(planned, taught):
        agree, cost = _agreement(C, planned, taught, settings)
        if len(agree) > len(best) or (len(agree) == len(best) and cost < best_cost - 1e-12):
            best, best_cost = agree, cost
    return best


def fit_work_object(
    wobj: str,
    T_world_wobj: FloatArray,
    rows: Sequence[TouchupRow],
    settings: TouchupSettings,
) -> WobjCorrection:
    """Return the rigid correction of work object `wobj` fitted to its compared `rows`: the
    targets that share one change (`consensus`), their positions fitted by `fit_rigid_robust`
    (tolerance `fit_distance`), then every target within the tolerances of that fit (position
    and orientation, `fit_angle`) fitted again; the others are named as outliers."""
    names = tuple(r.name for r in rows)
    planned = [_in_wobj(T_world_wobj, r.planned.T_world_tcp) for r in rows]  # type: ignore[union-attr]
    taught = [_in_wobj(T_world_wobj, r.taught.T_world_tcp) for r in rows]  # type: ignore[union-attr]
    src = np.array([T[:3, 3] for T in planned]).reshape(-1, 3)
    tgt = np.array([T[:3, 3] for T in taught]).reshape(-1, 3)

    def refused(reason: str) -> WobjCorrection:
        return WobjCorrection(wobj, T_world_wobj, np.eye(4), None, names, reason=reason)

    try:
        check_spread(src, f"the {len(src)} target(s) of work object {wobj!r}")
        shared = consensus(planned, taught, settings)
        check_spread(src[shared], f"the {len(shared)} target(s) that share one change")
    except InputError as exc:
        return refused(str(exc))
    first = fit_rigid_robust(src[shared], tgt[shared], settings.fit_distance)
    kept, _ = _agreement(first.T, planned, taught, settings)
    try:
        fit = fit_rigid(src[kept], tgt[kept])
    except InputError as exc:
        return refused(f"the targets that agree: {exc}")
    residuals = np.linalg.norm(src @ fit.T[:3, :3].T + fit.T[:3, 3] - tgt, axis=1)
    dropped = tuple(sorted(set(range(len(rows))) - set(kept), key=lambda k: -float(residuals[k])))
    final = RigidFit(fit.T, residuals, tuple(kept), dropped)
    return WobjCorrection(
        wobj, T_world_wobj, final.T, final, names, tuple(names[k] for k in dropped)
    )


def compare(
    planned: Sequence[PlannedTarget],
    taught: Sequence[TaughtTarget],
    frames: Mapping[str, FloatArray],
    *,
    source: str = "program",
    fmt: str = "",
    settings: TouchupSettings | None = None,
    notes: Sequence[str] = (),
) -> TouchupReport:
    """Return the comparison of the project's moves (`planned`) with the read-back ones
    (`taught`): rows in order, a correction per work object with at least one pair.
    `frames`: the project's work objects in the world (4, 4) [m] by name, "base" included."""
    settings = settings or TouchupSettings()
    for p in planned:
        if p.wobj not in frames:
            raise InputError(f"move {p.name!r}: no work object {p.wobj!r}; have {list(frames)}")
    rows = [
        _row(None if i is None else planned[i], None if j is None else taught[j], frames, settings)
        for i, j in match_moves(planned, taught)
    ]
    corrections = []
    for wobj in dict.fromkeys(r.wobj for r in rows if r.planned and r.taught):
        group = [r for r in rows if r.wobj == wobj and r.planned and r.taught]
        fitted = fit_work_object(wobj, frames[wobj], group, settings)
        corrections.append(dataclasses.replace(fitted, moved=sum(r.moved for r in group)))
    by_wobj = {c.wobj: c for c in corrections}
    final = []
    for r in rows:
        c = by_wobj.get(r.wobj)
        if c is not None and c.fitted and r.planned and r.taught:
            r = dataclasses.replace(r, agrees=r.name not in c.outliers)
        final.append(r)
    return TouchupReport(source, fmt, tuple(final), tuple(corrections), settings, tuple(notes))


# -- display -----------------------------------------------------------------------------------


def _mm(v: float) -> str:
    return f"{round(v * 1000.0, 2) + 0.0:8.2f}"  # + 0.0: no "-0.00"


def summary_lines(report: TouchupReport) -> list[str]:
    """Return the report as text: a row per move (dx dy dz mm in its work object, angle deg,
    status, agrees with the fit), then each work object's correction and residuals."""
    out = [
        f"{report.source}: {len(report.rows)} moves compared"
        + (f" ({report.fmt})" if report.fmt else ""),
        f"{'move':<24} {'wobj':<12} {'dx':>8} {'dy':>8} {'dz':>8} {'angle':>7}  status",
    ]
    still = {c.wobj for c in report.corrections if not c.moved}  # nothing to fit there
    for r in report.rows:
        if r.delta is None or r.angle is None:
            out.append(f"{r.name:<24} {r.wobj:<12} {'':>8} {'':>8} {'':>8} {'':>7}  {r.status}"
                       + (" on the pendant" if r.status in ("added", "deleted") else ""))  # fmt: skip
            continue
        fit = (
            ""
            if r.agrees is None or r.wobj in still
            else ("  fits" if r.agrees else "  does not fit")
        )
        dx, dy, dz = (_mm(v) for v in r.delta)
        out.append(
            f"{r.name:<24} {r.wobj:<12} {dx} {dy} {dz} {np.degrees(r.angle) + 0.0:7.3f}"
            f"  {r.status}{fit}"
        )
    for c in report.corrections:
        out += correction_lines(c, report.settings)
    out += [f"note: {n}" for n in report.notes]
    return out


def correction_lines(c: WobjCorrection, settings: TouchupSettings) -> list[str]:
    """Return a work object's correction as text (mm, deg)."""
    if not c.moved:
        return [f"work object {c.wobj}: {len(c.names)} target(s), none moved"]
    if not c.fitted:
        return [f"work object {c.wobj}: no correction fitted: {c.reason}"]
    T = c.T_correction
    angle = np.degrees(rotation_angle(np.eye(3), T[:3, :3]))
    xyz = ", ".join(f"{v * 1000.0:.3f}" for v in T[:3, 3])
    head = f"work object {c.wobj}: correction [{xyz}] mm, {angle:.4f} deg in its frame"
    if not c.significant(settings):
        head = f"work object {c.wobj}: no common change (every agreeing target within tolerance)"
    lines = [
        head + f"; residual rms {c.rms * 1000.0:.3f} mm, max {c.max * 1000.0:.3f} mm over"
        f" {len(c.names) - len(c.outliers)} targets"
    ]
    if c.outliers:
        lines.append(f"  moved alone (not folded into {c.wobj}): {', '.join(c.outliers)}")
    return lines
