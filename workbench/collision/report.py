"""What a collision check reports: one configuration (`ConfigCheck`) and a path (`EnginePathReport`).

Both modes' reports carry the exact verdict (python-fcl) of what the fast items flagged, the
certified clearance lower bound [m] and, for a collision, the pair, the time and a lower
bound of the penetration. `path_report` turns the certifier's outcome into the report.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from workbench.collision.fcl_checker import ContactReport
from workbench.collision.path_oracle import PathOutcome
from workbench.collision.robot_checker import PathReport

if TYPE_CHECKING:
    from workbench.collision.clearance import Clearance

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class ConfigCheck:
    """One configuration: verdict, clearance lower bound [m] and, when colliding, what touches.

    For the fast modes `colliding` is the exact (fcl) verdict on what the mode flagged;
    `flagged` says the fast test could not rule a contact out.
    """

    colliding: bool
    flagged: bool
    clearance: float
    link: str | None = None
    obstacle: str | None = None
    penetration: float = 0.0
    exact: ContactReport | None = None


@dataclass(frozen=True)
class EnginePathReport(PathReport):
    """A joint path's report: `PathReport` fields plus the guarantee between samples.

    `colliding_indices`: samples in collision (the exact verdict of each sample);
    `between_indices`: samples i whose interval to i+1 collides (or could not be certified)
    between them; `uncertified_indices`: those of them not certified at the finest
    subdivision (`path_check.MAX_DEPTH` halvings) without a colliding configuration found.
    clearance [m]: lower bound over the whole path (samples and between) when
    collision-free. first_time [s] / first_q [rad]: where the first collision is (a sample
    or, `between`, between two); link/obstacle: the colliding pair's names; penetration [m]:
    deepest vertex of either body inside the other. `evaluated`: configurations checked,
    subdivisions included; `flagged_samples`: samples the fast mode sent to the exact check;
    `exact_pairs`: exact pair tests (collide or distance) run. `fallback`: why the fast mode
    was not used (the samples were then checked densely and exactly, not between them).
    `nearest`: a free motion's least fcl distance over the samples, its pair and the margin
    asked (`plan_check.check_motion`; None where not measured, e.g. a collision).
    """

    mode: str = "spheres"
    clearance: float = float("nan")
    first_time: float | None = None
    first_q: FloatArray | None = field(default=None, repr=False)
    link: str | None = None
    obstacle: str | None = None
    penetration: float = 0.0
    evaluated: int = 0
    certified: bool = True
    between: bool = False
    between_indices: tuple[int, ...] = ()
    uncertified_indices: tuple[int, ...] = ()
    flagged_samples: int = 0
    exact_pairs: int = 0
    fallback: str | None = None
    nearest: Clearance | None = field(default=None, repr=False)

    @property
    def keeps_margin(self) -> bool:
        """Return False when a free motion comes closer than the margin (`margin_problem`)."""
        return self.nearest is None or self.nearest.keeps_margin

    @property
    def margin_problem(self) -> str | None:
        """Return the margin problem naming the pair and distance (mm), or None."""
        return None if self.nearest is None else self.nearest.problem

    @property
    def message(self) -> str:
        """Return the report as one sentence for a user (mm), the margin's verdict after it."""
        text = self._contact_message()
        if self.nearest is None:
            return text
        return f"{text}; {self.margin_problem or self.nearest.describe()}"

    def _contact_message(self) -> str:
        if self.fallback is not None:
            if self.collision_free:
                return (
                    f"collision-free at every sample ({self.samples} samples, exact check;"
                    f" not certified between samples: {self.fallback})"
                )
            return (
                f"collision at t = {self.first_time:.3f} s (sample {self.first_index}):"
                f" {self.link} hits {self.obstacle} (exact check of every sample;"
                f" {self.fallback})"
            )
        if self.collision_free:
            bound = (  # the one clearance figure is `nearest`'s where it was measured
                f", with clearance of at least {self.clearance * 1e3:.1f} mm"
                if self.nearest is None
                else ""
            )
            return (
                f"collision-free, including between samples{bound} ({self.samples} samples,"
                f" {self.evaluated} configurations checked, {self.mode})"
            )
        if not self.certified and self.link is None:
            i = self.first_index if self.first_index is not None else -1
            return (
                f"not certified between samples {i} and {i + 1} near t = {self.first_time:.3f} s"
                f" (no colliding configuration found; {len(self.uncertified_indices)}"
                " interval(s) whose clearance is below what the finest subdivision resolves):"
                " treat it as touching"
            )
        where = f"t = {self.first_time:.3f} s" if self.first_time is not None else "?"
        at = (
            f" (between samples {self.first_index} and {self.first_index + 1})"
            if self.between and self.first_index is not None
            else f" (sample {self.first_index})"
        )
        return (
            f"collision at {where}{at}: {self.link} hits {self.obstacle},"
            f" penetration {self.penetration * 1e3:.1f} mm"
        )


def path_report(
    out: PathOutcome,
    q: FloatArray,
    t: FloatArray,
    *,
    mode: str,
    pairs_checked: int,
    penetration: Callable[[FloatArray, str, str], float],
) -> EnginePathReport:
    """Return the report of samples q (N, dof) [rad] at times t (N,) [s] from the certifier's outcome.

    penetration(q, a, b) -> depth [m] of the first colliding pair at its configuration.
    """
    n = len(q)
    hits = sorted(out.sample_hits)
    between = sorted({e[1] for e in out.events})
    uncertified = sorted({e[1] for e in out.events if not e[3]})
    base: dict[str, Any] = {
        "collision_free": not hits and not out.events,
        "first_index": None,
        "first_report": None,
        "min_distance": 0.0,
        "samples": n,
        "colliding_indices": tuple(hits),
        "mode": mode,
        "clearance": 0.0,
        "evaluated": out.evaluated,
        "between_indices": tuple(between),
        "uncertified_indices": tuple(uncertified),
        "flagged_samples": out.flagged,
        "exact_pairs": out.exact_pairs,
    }
    if base["collision_free"]:
        clr = max(out.clearance, 0.0) if np.isfinite(out.clearance) else float("inf")
        base.update(min_distance=clr, clearance=clr)
        return EnginePathReport(**base)
    # The first event: a colliding sample or an interval (collision or not certified).
    cands: list[tuple[float, int | None, FloatArray, tuple[tuple[str, str], ...]]]
    cands = [(float(t[i]), i, q[i], out.sample_hits[i]) for i in hits[:1]]
    cands += [(e[0], None, e[2], e[3]) for e in out.events[:1]]
    tm, i0, qm, pairs = min(cands, key=lambda c: c[0])
    extra: dict[str, object] = {
        "first_index": i0 if i0 is not None else int(np.searchsorted(t, tm) - 1),
        "first_time": tm,
        "first_q": qm,
        "between": i0 is None,
    }
    if pairs:
        a, b = pairs[0]
        extra.update(
            first_report=ContactReport(pairs, 0.0, pairs[0], pairs_checked),
            link=a,
            obstacle=b,
            penetration=penetration(qm, a, b),
        )
    else:
        extra["certified"] = False
    base.update(extra)
    return EnginePathReport(**base)
