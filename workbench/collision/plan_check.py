"""The plan collision policy and the checks every plan runs with it (SI units).

A plan (a robot program, a bending sequence, an assembly timeline, a polishing path) checks
its motion with `check_trajectory` or `check_motion` under a `CollisionPolicy`, which the
project file's `collision` section sets (`Workbench.collision_policy`):

- ``"spheres"`` (default): the spheres engine (PSO spheres against the cell's sparse SDF,
  sphere pairs for self-collision) over all samples at once; what it flags is confirmed
  with python-fcl, and the motion between samples is certified (bisection on the real
  motion). Where it cannot apply (an obstacle mesh that is not watertight, an engine that
  cannot be built) every sample is checked exactly and the report says why (`fallback`).
- ``"exact"``: every sample checked densely with python-fcl (meshes plus containment);
  nothing certified between samples (`fallback` says the policy asked for it).
- ``"capsules"``: the capsules engine (each body a capsule holding its vertices, obstacles
  as their oriented boxes), confirmed and certified as the spheres mode. It serves any
  cell (an oriented box holds any mesh, watertight or not); where its engine cannot be
  built it falls back to the dense exact check with the reason, like the spheres mode.

Engines are built once per checker and policy (`shared_engine`) and kept with the checker
(`RobotCollisionChecker.engines`): the plans and the GUI's collision panel share them.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, Literal, get_args

import numpy as np
from numpy.typing import NDArray

from workbench.collision.clearance import check_margin, exempt_pairs, plan_clearance
from workbench.collision.engine import CollisionEngine, EnginePathReport
from workbench.collision.path_check import AccelerationBound
from workbench.collision.robot_checker import RobotCollisionChecker
from workbench.errors import InputError, PlanLimitError, WorkbenchError

if TYPE_CHECKING:
    from workbench.motion import Trajectory

FloatArray = NDArray[np.float64]
Progress = Callable[[float, str], None]
PolicyMode = Literal["spheres", "exact", "capsules"]
POLICY_MODES: tuple[str, ...] = get_args(PolicyMode)
# Engine parameters the plans and the GUI share (fits, fields and tables are cached on disk).
SPHERES_PER_LINK = 6
RESOLUTION = 32


def default_cache_dir() -> Path:
    """Return where fits, fields and pair tables are cached (~/.cache/workbench/sdf, or $WORKBENCH_CACHE/sdf)."""
    root = os.environ.get("WORKBENCH_CACHE")
    return (Path(root) if root else Path.home() / ".cache" / "workbench") / "sdf"


@dataclass(frozen=True)
class CollisionPolicy:
    """How a plan checks its motion for collisions (see the module docstring).

    mode: ``"spheres"``, ``"exact"`` or ``"capsules"``. spheres_per_link, resolution (coarse
    SDF cells along the cell's largest extent): the spheres engine's parameters. cache_dir:
    where engines cache fits, fields and pair tables; None: `default_cache_dir()` when the
    engine is built. margin [m]: the clearance a plan must keep (`clearance.plan_clearance`:
    closer is a problem naming the pair; 0 here, the project's default is set in
    `project/collision.py`); exempt: body-name pairs the margin does not apply to (the
    contacts a process needs). Neither changes the engine (`key`).
    """

    mode: PolicyMode = "spheres"
    spheres_per_link: int = SPHERES_PER_LINK
    resolution: int = RESOLUTION
    cache_dir: Path | None = None
    margin: float = 0.0
    exempt: tuple[tuple[str, str], ...] = ()

    def __post_init__(self) -> None:
        if self.mode not in POLICY_MODES:
            raise InputError(f"mode: {self.mode!r} is not one of {', '.join(POLICY_MODES)}")
        if int(self.spheres_per_link) < 1:
            raise InputError(
                f"spheres_per_link: {self.spheres_per_link} must be a positive integer"
            )
        if int(self.resolution) < 2:
            raise InputError(f"resolution: {self.resolution} must be >= 2 coarse cells")
        object.__setattr__(self, "margin", check_margin(self.margin))
        object.__setattr__(self, "exempt", exempt_pairs(self.exempt))

    def exempting(self, pairs: Iterable[Iterable[str]]) -> CollisionPolicy:
        """Return this policy with `pairs` (body names) exempt from the margin as well."""
        return replace(self, exempt=exempt_pairs((*self.exempt, *pairs)))

    def cache(self) -> Path:
        """Return the cache folder in use (`cache_dir`, else the default now)."""
        return Path(self.cache_dir) if self.cache_dir is not None else default_cache_dir()

    def key(self) -> tuple[str, int, int, str]:
        """Return what an engine built under this policy depends on (the engine cache's key)."""
        if self.mode == "spheres":
            return (self.mode, int(self.spheres_per_link), int(self.resolution), str(self.cache()))
        return (self.mode, 0, 0, str(self.cache()))


def engine(
    checker: RobotCollisionChecker, policy: CollisionPolicy, *, progress: Progress | None = None
) -> CollisionEngine:
    """Return the engine of `policy.mode` on `checker`, built on first use and kept.

    A build that failed raises the same `WorkbenchError` again (it is not retried).
    """
    key = policy.key()
    found = checker.engines.get(key)
    if found is None:
        try:
            found = CollisionEngine(
                checker,
                policy.mode,
                spheres_per_link=int(policy.spheres_per_link),
                resolution=int(policy.resolution),
                cache_dir=key[3],
                progress=progress,
            )
        except PlanLimitError:
            raise  # a plan's time limit or cancel, not a failed build: not kept
        except WorkbenchError as exc:
            found = exc
        checker.engines[key] = found
    elif progress is not None:
        progress(1.0, "collision engine ready")
    if isinstance(found, WorkbenchError):
        raise found
    assert isinstance(found, CollisionEngine)
    return found


def shared_engine(
    checker: RobotCollisionChecker, policy: CollisionPolicy, *, progress: Progress | None = None
) -> tuple[CollisionEngine | None, str | None]:
    """Return (the fast engine a plan uses under `policy`, None), or (None, why there is none).

    None for the exact mode (the policy asks for the dense check), for an engine that cannot
    be built (e.g. a joint that is not revolute), and in the spheres mode for a cell mesh that
    is not watertight (its field is unsigned: a link wholly inside an obstacle would not be
    seen; no engine is built for it, and one the collision panel built is not used).
    """
    if policy.mode == "exact":
        return None, "the project's collision mode is exact"
    if policy.mode == "spheres":
        open_meshes = [
            n for n, e in checker.scene.static.items() if e.solid.kind == "mesh" and not e.closed
        ]
        if open_meshes:  # whether or not an engine was built (the GUI's panel builds one)
            return None, (
                f"obstacle {open_meshes[0]!r} is not watertight, so the cell's distance field"
                " would have no inside"
            )
    try:
        eng = engine(checker, policy, progress=progress)
    except PlanLimitError:
        raise
    except WorkbenchError as exc:
        return None, f"the {policy.mode} engine could not be built ({exc})"
    if eng.sdf is not None and not eng.sdf.signed:
        return None, "the cell's merged mesh is not watertight, so its distance field has no inside"
    return eng, None


def check_trajectory(
    trajectory: Trajectory,
    times: FloatArray,
    q: FloatArray,
    checker: RobotCollisionChecker,
    policy: CollisionPolicy,
    *,
    progress: Progress | None = None,
) -> EnginePathReport:
    """Return the collision report of a trajectory sampled at `times` [s] as q (N, dof) [rad].

    Fast modes bisect between samples on the real motion (`trajectory.at`) with the exact
    acceleration bound of each interval (`interval_acceleration_bound`).
    """
    from workbench.motion.validation import interval_acceleration_bound

    return check_motion(
        times,
        q,
        checker,
        policy,
        sampler=lambda t: trajectory.at(t)[0],
        acceleration=interval_acceleration_bound(trajectory),
        progress=progress,
    )


def check_motion(
    times: FloatArray,
    q: FloatArray,
    checker: RobotCollisionChecker,
    policy: CollisionPolicy,
    *,
    sampler: Callable[[FloatArray], FloatArray],
    acceleration: FloatArray | AccelerationBound,
    progress: Progress | None = None,
    clearance: bool = True,
) -> EnginePathReport:
    """Return the collision report of a motion sampled at `times` [s] as q (N, dof) [rad].

    sampler(times (M,) [s]) -> (M, dof) [rad] gives the real motion between samples;
    acceleration (dof,) [rad/s^2] bounds |q''| over it, or bound(t0, t1) -> (M, dof) bounds it
    over each interval (the motion must be C1: the chord deviation bound
    ``acceleration * h**2 / 8`` needs a continuous velocity). Without a fast engine (exact
    mode or a fallback) every sample is checked exactly and `fallback` says why. A motion free
    of contact is then measured against `policy.margin` (`EnginePathReport.nearest`: the least
    fcl distance over the samples and its pair, `clearance.plan_clearance`); with
    `clearance` False it is not (`nearest` None: the caller asks `clearance.margin_kept`).
    """
    report = progress or (lambda f, m: None)
    eng, why = shared_engine(checker, policy, progress=lambda f, m: report(0.2 * f, m))
    if eng is not None:
        rep = eng.check_path(
            q,
            times,
            sampler=sampler,
            acceleration=acceleration,
            progress=lambda f, m: report(0.2 + 0.7 * f, m),
        )
    else:
        assert why is not None
        rep = dense_report(times, q, checker, why, progress=lambda f, m: report(0.2 + 0.7 * f, m))
    if not rep.collision_free or not clearance:
        return rep
    report(0.9, "clearance against the margin")
    near = plan_clearance(checker, times, q, margin=policy.margin, exempt=policy.exempt, engine=eng)
    return replace(rep, nearest=near)


def dense_report(
    times: FloatArray,
    q: FloatArray,
    checker: RobotCollisionChecker,
    why: str,
    *,
    progress: Progress | None = None,
) -> EnginePathReport:
    """Return the exact check of every sample as an `EnginePathReport` (mode exact, `fallback` why)."""
    dense = checker.check_path(q, progress=progress)
    hits = dense.colliding_indices
    extra: dict[str, object] = {}
    if hits:
        rep = dense.first_report
        a, b = rep.colliding[0] if rep is not None else (None, None)
        extra = {
            "first_time": float(times[hits[0]]),
            "first_q": q[hits[0]],
            "link": a,
            "obstacle": b,
        }
    return EnginePathReport(
        collision_free=dense.collision_free,
        first_index=dense.first_index,
        first_report=dense.first_report,
        min_distance=dense.min_distance,
        samples=dense.samples,
        colliding_indices=hits,
        mode="exact",
        evaluated=len(q),
        certified=False,
        fallback=why,
        **extra,  # type: ignore[arg-type]
    )
