"""Sheet-metal part: planar flanges joined by bends, a bend sequence, the flat blank.

Plain spec accepted by `SheetMetalPart.from_spec` (SI units; the project layer converts
mm/deg)::

    {
      "thickness": 0.002,                 # [m], > 0
      "k_factor": None,                   # optional K override for every bend, else Table 1
      "flanges": [                        # flanges[0] is the base: its frame is the part frame
        {"name": "1", "polygon": [[x, y], ...],    # [m], counter-clockwise, simple
         "holes": [[[x, y], ...], ...]},          # optional inner loops [m] (sheetmetal.holes)
        ...
      ],
      "bends": [
        {"name": "b1", "parent": "1", "parent_edge": 0,   # edge i joins vertex i and i+1
         "child": "2", "child_edge": 2,                   # same length as the parent edge
         "included_angle": 1.5708,                         # [rad] in (0, pi); or "bend_angle"
         "inner_radius": 0.002, "direction": "up"},       # up = towards the parent's +z
        ...
      ],
      "sequence": ["b3", "b1", ...],      # optional; default: the order of "bends";
                                          # every bend exactly once (sheetmetal.sequence)
    }

Each flange's frame has its polygon in the x-y plane and z = 0 on the sheet's mid-surface
(the neutral surface of a flat sheet); the sheet spans z in [-t/2, t/2]. In the flat blank a
child flange lies a bend allowance beyond its parent's edge.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
import shapely
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.geometry.polygon import signed_area
from workbench.sheetmetal.holes import ccw, check_holes
from workbench.sheetmetal.kfactor import MIN_R_OVER_T, bend_allowance, k_factor
from workbench.sheetmetal.sequence import check_sequence

if TYPE_CHECKING:
    from workbench.sheetmetal.folding import FoldedState


@dataclass(frozen=True, eq=False)
class Flange:
    """A planar flange: `polygon` (n, 2) [m] counter-clockwise in the flange's own frame.

    `holes` are its inner loops (k, 2) [m], counter-clockwise, in the same frame; they go
    through the sheet (checked by `sheetmetal.holes.check_holes`).
    """

    name: str
    polygon: NDArray[np.float64]
    holes: tuple[NDArray[np.float64], ...] = ()


@dataclass(frozen=True)
class Bend:
    """A bend joining `parent` edge `parent_edge` to `child` edge `child_edge` (flange indices).

    `angle` is the bend (deflection) angle [rad], `inner_radius` [m], `direction` +1 (up,
    towards the parent's +z) or -1 (down), `k` the neutral-layer factor used.
    """

    name: str
    parent: int
    parent_edge: int
    child: int
    child_edge: int
    angle: float
    inner_radius: float
    direction: int
    k: float

    @property
    def included_angle(self) -> float:
        """Return the included angle [rad] between the two flanges (π = flat)."""
        return float(np.pi - self.angle)


def _edge(poly: NDArray[np.float64], i: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    return poly[i], poly[(i + 1) % len(poly)]


def _ring(value: Any, where: str) -> NDArray[np.float64]:
    """Return `value` as (n, 2) floats; InputError naming `where` unless >= 3 finite points."""
    ring = np.asarray(value, dtype=float)
    if ring.ndim != 2 or ring.shape[1] != 2 or len(ring) < 3 or not np.all(np.isfinite(ring)):
        raise InputError(
            f"expected >= 3 finite [x, y] points [m], got shape {ring.shape}", field=where
        )
    return ring


class SheetMetalPart:
    """A sheet-metal part: `thickness` [m], `flanges`, `bends` in sequence order."""

    def __init__(
        self,
        thickness: float,
        flanges: list[Flange],
        bends: list[Bend],
        *,
        check: bool = True,
    ) -> None:
        t = float(thickness)
        if not np.isfinite(t) or t <= 0:
            raise InputError(f"thickness: must be > 0 m, got {thickness!r}")
        self.thickness = t
        self.flanges: tuple[Flange, ...] = tuple(flanges)
        self.bends: tuple[Bend, ...] = tuple(bends)
        self._validate()
        self.bend_allowances = np.array(
            [float(bend_allowance(b.inner_radius, t, b.angle, b.k)) for b in self.bends]
        )
        self.bend_lengths = np.array(
            [
                float(
                    np.linalg.norm(
                        np.subtract(*_edge(self.flanges[b.parent].polygon, b.parent_edge))
                    )
                )
                for b in self.bends
            ]
        )
        # Parent bend of every flange, and flanges in root-first order for forward kinematics.
        self.parent_bend = np.full(len(self.flanges), -1)
        for i, b in enumerate(self.bends):
            self.parent_bend[b.child] = i
        order, frontier = [0], [0]
        while frontier:
            f = frontier.pop()
            for b in self.bends:
                if b.parent == f:
                    order.append(b.child)
                    frontier.append(b.child)
        self.order = np.array(order)
        if check:
            self.check_sequence()

    # ------------------------------------------------------------------ construction
    @classmethod
    def from_spec(cls, spec: Any, *, check: bool = True) -> SheetMetalPart:
        """Return a part built from the plain spec of the module docstring (SI units).

        `spec` is a dict, or a dataclass with those fields (e.g. the project's `PartSI`).
        """
        if dataclasses.is_dataclass(spec) and not isinstance(spec, type):
            spec = dataclasses.asdict(spec)
        if not isinstance(spec, dict):
            raise InputError(f"part spec: expected a dict, got {type(spec).__name__}")
        for key in ("thickness", "flanges", "bends"):
            if key not in spec:
                raise InputError(f"part spec: missing '{key}'")
        t = float(spec["thickness"])
        if not np.isfinite(t) or t <= 0:
            raise InputError(f"thickness: must be > 0 m, got {spec['thickness']!r}")
        flanges = []
        for i, f in enumerate(spec["flanges"]):
            poly = _ring(f.get("polygon"), f"flanges[{i}].polygon")
            holes = [
                ccw(_ring(h, f"flanges[{i}].holes[{j}]"))
                for j, h in enumerate(f.get("holes") or ())
            ]
            flanges.append(Flange(str(f.get("name", i)), poly, tuple(holes)))
        names = [f.name for f in flanges]
        if len(set(names)) != len(names):
            raise InputError(f"flanges: names must be unique, got {names}")

        def flange_index(ref: Any, where: str) -> int:
            if isinstance(ref, int | np.integer) and 0 <= int(ref) < len(flanges):
                return int(ref)
            if str(ref) in names:
                return names.index(str(ref))
            raise InputError(f"{where}: no flange {ref!r}; flanges are {names}")

        k_override = spec.get("k_factor")
        bends = []
        for i, b in enumerate(spec["bends"]):
            where = f"bends[{i}]"
            if "bend_angle" in b:
                angle = float(b["bend_angle"])
            elif "included_angle" in b:
                inc = float(b["included_angle"])
                if not (0.0 < inc < np.pi):
                    raise InputError(
                        f"{where}.included_angle: must be in (0, 180) deg, got {np.degrees(inc):.6g} deg"
                    )
                angle = np.pi - inc
            else:
                raise InputError(f"{where}: give 'included_angle' or 'bend_angle' [rad]")
            if not (0.0 < angle < np.pi):
                raise InputError(
                    f"{where}.bend_angle: must be in (0, 180) deg, got {np.degrees(angle):.6g} deg"
                )
            direction = b.get("direction", "up")
            if direction not in ("up", "down", 1, -1):
                raise InputError(f"{where}.direction: must be 'up' or 'down', got {direction!r}")
            r = float(b.get("inner_radius", np.nan))
            if not np.isfinite(r) or r < MIN_R_OVER_T * t - 1e-12:
                raise InputError(
                    f"{where}.inner_radius: {r * 1e3:.4g} mm is below Table 1's range; "
                    f"minimum {MIN_R_OVER_T} x thickness = {MIN_R_OVER_T * t * 1e3:.4g} mm"
                )
            k = (
                float(b["k_factor"])
                if b.get("k_factor") is not None
                else (float(k_override) if k_override is not None else float(k_factor(r / t)))
            )
            if not 0.0 <= k <= 1.0:
                raise InputError(f"{where}.k_factor: must be in [0, 1], got {k}")
            bends.append(
                Bend(
                    str(b.get("name", f"b{i + 1}")),
                    flange_index(b.get("parent"), f"{where}.parent"),
                    int(b.get("parent_edge", -1)),
                    flange_index(b.get("child"), f"{where}.child"),
                    int(b.get("child_edge", -1)),
                    float(angle),
                    r,
                    1 if direction in ("up", 1) else -1,
                    k,
                )
            )
        bnames = [b.name for b in bends]
        if len(set(bnames)) != len(bnames):
            raise InputError(f"bends: names must be unique, got {bnames}")
        seq = spec.get("sequence")
        if seq is not None:
            seq = check_sequence(seq, bnames)
            bends = [bends[bnames.index(s)] for s in seq]
        return cls(t, flanges, bends, check=check)

    def _validate(self) -> None:
        nf = len(self.flanges)
        if nf == 0:
            raise InputError("flanges: a part needs at least one flange")
        for i, f in enumerate(self.flanges):
            if signed_area(f.polygon) <= 0:
                raise InputError(
                    f"flanges[{i}] ('{f.name}').polygon: must be counter-clockwise with area > 0"
                )
            if not shapely.Polygon(f.polygon).is_valid:
                raise InputError(
                    f"flanges[{i}] ('{f.name}').polygon: must be simple (no self-crossing)"
                )
        seen_child: set[int] = set()
        used_edges: set[tuple[int, int]] = set()
        for b in self.bends:
            where = f"bend '{b.name}'"
            for fl, e, role in (
                (b.parent, b.parent_edge, "parent"),
                (b.child, b.child_edge, "child"),
            ):
                n = len(self.flanges[fl].polygon)
                if not 0 <= e < n:
                    raise InputError(
                        f"{where}.{role}_edge: {e} is not an edge of flange '{self.flanges[fl].name}' (0..{n - 1})"
                    )
                if (fl, e) in used_edges:
                    raise InputError(
                        f"{where}: edge {e} of flange '{self.flanges[fl].name}' already carries a bend"
                    )
                used_edges.add((fl, e))
            if b.child == 0 or b.child in seen_child or b.child == b.parent:
                raise InputError(
                    f"{where}.child: flange '{self.flanges[b.child].name}' already has a parent or is the base; "
                    "bends must form a tree rooted at flanges[0]"
                )
            seen_child.add(b.child)
            lp = np.linalg.norm(np.subtract(*_edge(self.flanges[b.parent].polygon, b.parent_edge)))
            lc = np.linalg.norm(np.subtract(*_edge(self.flanges[b.child].polygon, b.child_edge)))
            if abs(lp - lc) > 1e-6:
                raise InputError(
                    f"{where}: parent edge is {lp * 1e3:.4g} mm long, child edge {lc * 1e3:.4g} mm; they must match"
                )
            if not (0 < b.angle < np.pi):
                raise InputError(f"{where}: included angle must be in (0, 180) deg")
            if b.inner_radius < MIN_R_OVER_T * self.thickness - 1e-12:
                raise InputError(
                    f"{where}.inner_radius: below Table 1's minimum {MIN_R_OVER_T} x thickness"
                )
        if len(seen_child) != nf - 1:
            loose = [f.name for i, f in enumerate(self.flanges) if i and i not in seen_child]
            raise InputError(f"bends: flanges {loose} are not connected to the base flange")
        check_holes(self)

    # ------------------------------------------------------------------ queries
    def flange_index(self, flange: int | str) -> int:
        """Return the index of a flange given by index or name; InputError lists the valid ones."""
        names = [f.name for f in self.flanges]
        if isinstance(flange, int | np.integer) and 0 <= int(flange) < len(names):
            return int(flange)
        if isinstance(flange, str) and flange in names:
            return names.index(flange)
        raise InputError(f"flange: no flange {flange!r}; valid are {names} or 0..{len(names) - 1}")

    def blank_area(self) -> float:
        """Return the area [m²] of the flat blank: flange polygons less holes, plus bend strips."""
        flanges = sum(
            signed_area(f.polygon) - sum(signed_area(h) for h in f.holes) for f in self.flanges
        )
        return float(flanges + np.sum(self.bend_allowances * self.bend_lengths))

    def fold(self, step: float, fraction: float = 0.0) -> FoldedState:
        """Return the `FoldedState` after `step` bends of the sequence (0 = flat blank).

        A float step or `fraction` in [0, 1] folds bend number floor(step) partway (animation).
        Raises InputError when flanges of that state intersect each other.
        """
        from workbench.sheetmetal.folding import fold_state

        return fold_state(self, step, fraction)

    def check_sequence(self) -> None:
        """Raise InputError naming the bend and flanges if any step of the sequence self-intersects."""
        for step in range(len(self.bends) + 1):
            self.fold(step)
