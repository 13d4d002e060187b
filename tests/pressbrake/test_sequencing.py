"""The bend-sequence and grasp search against a brute-force twin of its ranking.

The twin enumerates every bend order and every assignment of a grasp to each bend, and
prices each with an explicit loop over the search's cost model (`sequencing`): a regrip
costs REGRIP + the regrip time and needs both grasps reachable on the regrip station; a flip
(top up changes between bends) FLIP; the time is the moves at the joints' top speed (home
to the blank, blank to the first bend, bend to bend while the grasp stays, the last bend to
the pallet), each bend's ram time and the handling estimate. It reads the same `evaluate`
verdicts the search does, so what is compared is the search (dynamic programme over grasps,
best-first over orders, heuristic, batching), not the cheap checks.

Contexts: the U-channel cell of `projects/u_channel_cell.json`, with its candidate grasps
cut to a seeded dozen (brute force over 2 orders x 12^2 assignments); a seeded screen of a
larger sample keeps a few grasps that make each bend, whatever the cell's tuning. Each runs
as the project has it (stack, pallet and regrip station checked) and "open" (none of the
three: every grasp starts and ends anywhere and regrips everywhere), and the same for the
U-channel with a short flange A (both orders feasible, so the ranking orders two sequences).
Those depend on the cell's tuning (which grasps the robot reaches); the crafted tests do
not: seeded verdicts stand in for `evaluate` on a three-bend U-channel (6 orders x 5^3
assignments), with regrip stations, flips and moves in play.
"""

from __future__ import annotations

import dataclasses
import itertools
import sys
import uuid
from collections.abc import Callable, Iterator
from pathlib import Path

import numpy as np
import pytest

from workbench import Workbench
from workbench.batch import engine_session
from workbench.errors import InputError
from workbench.pressbrake import sequencing
from workbench.pressbrake.bend_eval import (
    BendEval,
    SideEval,
    SweepContext,
    evaluate,
    grasp_label,
    reach_where_part_rests,
)
from workbench.pressbrake.grasp_grid import GridSettings, grasp_grid
from workbench.pressbrake.press import ram_time
from workbench.pressbrake.sequencing import (
    FLIP,
    REGRIP,
    SearchSettings,
    SequencePlan,
    find_sequences,
)
from workbench.service.bending_process import sweep_context
from workbench.sheetmetal import SheetMetalPart

ROOT = Path(__file__).resolve().parents[2]
SCREEN = 96  # grasps sampled for the screen
KEEP = 12  # grasps of a context
PER_KEY = 3  # grasps kept that make each (bends done, next bend)

Key = tuple[tuple[int, ...], int]  # (bends done, next bend)
Evals = dict[Key, BendEval]


# --- contexts ---------------------------------------------------------------------------


def _keys(nb: int) -> list[Key]:
    """Return every (bends done, next bend) of a part with nb bends."""
    out = []
    for n in range(nb):
        for done in itertools.combinations(range(nb), n):
            out += [(done, b) for b in range(nb) if b not in done]
    return out


def _screened(ctx: SweepContext, seed: int) -> SweepContext:
    """Return `ctx` with a seeded dozen of its grasps: up to PER_KEY that make each bend
    candidate (screened on a seeded sample of SCREEN), the rest drawn from the sample."""
    rng = np.random.default_rng(seed)
    G = len(ctx.grasps)
    sample = np.sort(rng.choice(G, min(SCREEN, G), replace=False))
    probe = dataclasses.replace(ctx, grasps=tuple(ctx.grasps[i] for i in sample))
    chosen: list[int] = []
    for done, b in _keys(len(ctx.part().bends)):
        ok = np.flatnonzero(evaluate(probe, done, b).grasp_ok)
        ok = [int(i) for i in ok if int(sample[i]) not in chosen]
        for i in rng.permutation(ok)[:PER_KEY]:
            chosen.append(int(sample[i]))
    rest = [int(i) for i in sample if int(i) not in chosen]
    chosen += [int(i) for i in rng.permutation(rest)[: max(0, KEEP - len(chosen))]]
    chosen = sorted(chosen[:KEEP])
    return dataclasses.replace(ctx, grasps=tuple(ctx.grasps[i] for i in chosen))


def _open(ctx: SweepContext) -> SweepContext:
    """Return `ctx` without the stack, the pallet and the regrip station."""
    return dataclasses.replace(ctx, T_world_blank=None, T_world_pallet=None, T_world_regrip=None)


@pytest.fixture(scope="module")
def base_ctx() -> SweepContext:
    """Return the U-channel cell's full search context (every candidate grasp)."""
    return sweep_context(Workbench.open(ROOT / "projects" / "u_channel_cell.json").bending)


@pytest.fixture(scope="module")
def u_ctx(base_ctx: SweepContext) -> SweepContext:
    """Return the U-channel cell's context with a screened dozen of its grasps."""
    return _screened(base_ctx, seed=40)


@pytest.fixture(scope="module")
def short_ctx(base_ctx: SweepContext) -> SweepContext:
    """Return the U-channel with flange A at most 40 mm tall (both orders feasible), its own
    grasps."""
    spec = dataclasses.asdict(base_ctx.part_spec)
    for f in spec["flanges"]:
        if f["name"] == "A":  # a rectangle on its bend edge (y = 0): cut it at 40 mm
            poly = np.array(f["polygon"], float)
            poly[:, 1] = np.minimum(poly[:, 1], 0.04)
            f["polygon"] = poly
    part = SheetMetalPart.from_spec(spec)
    g = GridSettings()  # the project's default grid
    grasps = grasp_grid(part, spacing=g.spacing, inset=g.inset, yaws=g.yaws, faces=g.faces)
    ctx = dataclasses.replace(base_ctx, part_spec=spec, grasps=tuple(grasps), key=uuid.uuid4().hex)
    return _screened(ctx, seed=41)


# --- the twin -----------------------------------------------------------------------------


def transit(q_from: np.ndarray, q_to: np.ndarray, vmax: np.ndarray) -> float:
    """Return the slowest joint's time [s] at top speed (0 when either pose is unknown)."""
    if not (np.all(np.isfinite(q_from)) and np.all(np.isfinite(q_to))):
        return 0.0
    return max(
        abs(float(b) - float(a)) / float(v) for a, b, v in zip(q_from, q_to, vmax, strict=True)
    )


@dataclasses.dataclass
class Twin:
    """The brute force's view of one context: evaluations, rest masks and joints."""

    ctx: SweepContext
    evals: Evals
    at_blank: np.ndarray
    q_blank: np.ndarray
    at_pallet: np.ndarray
    q_pallet: np.ndarray

    @classmethod
    def of(cls, ctx: SweepContext, evals: Evals | None = None) -> Twin:
        nb, G, dof = len(ctx.part().bends), len(ctx.grasps), ctx.reach.model.dof
        if evals is None:
            evals = {k: evaluate(ctx, *k) for k in _keys(nb)}
        at_blank, q_blank = np.ones(G, bool), np.full((G, dof), np.nan)
        if ctx.T_world_blank is not None:
            at_blank, q_blank = reach_where_part_rests(ctx, ctx.T_world_blank, 0)
        at_pallet, q_pallet = np.ones(G, bool), np.full((G, dof), np.nan)
        if ctx.T_world_pallet is not None:
            at_pallet, q_pallet = reach_where_part_rests(ctx, ctx.T_world_pallet, nb)
        return cls(ctx, evals, at_blank, q_blank, at_pallet, q_pallet)

    def cost(
        self, order: tuple[int, ...], grasps: tuple[int, ...], s: SearchSettings
    ) -> tuple[float, int, int]:
        """Return (cost, regrips, flips) of making the bends in `order` with `grasps`."""
        vmax = self.ctx.reach.model.max_velocity
        es = [self.evals[(tuple(sorted(order[:j])), order[j])] for j in range(len(order))]
        g = grasps[0]
        if not self.at_blank[g]:
            return np.inf, 0, 0
        total = transit(self.ctx.reach.q, self.q_blank[g], vmax)
        q_prev = self.q_blank[g]
        regrips = flips = 0
        up_prev = None
        for j, (e, g) in enumerate(zip(es, grasps, strict=True)):
            if not e.grasp_ok[g]:
                return np.inf, 0, 0
            side = e.sides[int(e.grasp_side[g])]
            if j > 0:
                gp = grasps[j - 1]
                if g == gp:
                    total += transit(q_prev, e.q0[g], vmax)
                else:
                    station = (
                        np.ones(len(self.ctx.grasps), bool)
                        if e.at_station is None
                        else e.at_station
                    )
                    if not (station[gp] and station[g]):
                        return np.inf, 0, 0
                    total += REGRIP + s.regrip_time
                    regrips += 1
                if side.top_up != up_prev:
                    total += FLIP
                    flips += 1
            else:
                total += transit(q_prev, e.q0[g], vmax)
            total += side.ram_time + s.handling_time
            q_prev, up_prev = e.q1[g], side.top_up
        g = grasps[-1]
        if not self.at_pallet[g]:
            return np.inf, 0, 0
        total += transit(q_prev, self.q_pallet[g], vmax)
        return total, regrips, flips

    def ranking(self, s: SearchSettings) -> list[tuple[float, tuple[int, ...]]]:
        """Return (least cost, order) of every feasible order, cheapest first."""
        nb, G = len(self.ctx.part().bends), len(self.ctx.grasps)
        out = []
        for order in itertools.permutations(range(nb)):
            assignments = itertools.product(range(G), repeat=nb)
            best = min(self.cost(order, a, s)[0] for a in assignments)
            if np.isfinite(best):
                out.append((best, order))
        return sorted(out)


def check_against_twin(twin: Twin, settings: SearchSettings) -> list[SequencePlan]:
    """Run the search on the twin's context and compare; return the plans."""
    ctx = twin.ctx
    names = [b.name for b in ctx.part().bends]
    if not twin.at_blank.any():
        with pytest.raises(InputError, match="bending.blank"):
            find_sequences(ctx, verify=None, settings=settings)
        return []
    if not twin.at_pallet.any():
        with pytest.raises(InputError, match="bending.pallet"):
            find_sequences(ctx, verify=None, settings=settings)
        return []
    seen: list[float] = []
    result = find_sequences(
        ctx, verify=None, settings=settings, progress=lambda f, m: seen.append(f)
    )
    assert seen and seen[-1] == 1.0
    ranking = twin.ranking(settings)
    expected = ranking[: settings.max_plans]
    got = [(p.cost, tuple(names.index(b) for b in p.sequence)) for p in result.plans]
    where = (
        f"twin {[(c, [names[i] for i in o]) for c, o in ranking]}, "
        f"search {[(c, [names[i] for i in o]) for c, o in got]}"
    )
    assert len(got) == len(expected), where
    assert len({o for _, o in got}) == len(got), "each order once"
    for (c_got, o_got), (c_exp, o_exp) in zip(got, expected, strict=True):
        assert c_got == pytest.approx(c_exp, abs=1e-9), where
        # equal costs may come in either order
        assert o_got == o_exp or any(o == o_got and abs(c - c_exp) <= 1e-9 for c, o in ranking), (
            where
        )
    for plan in result.plans:
        order = tuple(names.index(b) for b in plan.sequence)
        c, regrips, flips = twin.cost(order, plan.grasp_ids, settings)
        assert c == pytest.approx(plan.cost, abs=1e-9), (plan.sequence, plan.grasp_ids)
        assert (plan.regrips, plan.flips) == (regrips, flips)
        assert plan.cycle_time == pytest.approx(c - REGRIP * regrips - FLIP * flips, abs=1e-9)
        assert plan.grasps == tuple(ctx.grasps[g] for g in plan.grasp_ids)
        assert plan.estimated and not plan.verified
        for j, g in enumerate(plan.grasp_ids):
            e = twin.evals[(tuple(sorted(order[:j])), order[j])]
            assert plan.stations[j] == e.sides[int(e.grasp_side[g])].station
    if not result.plans:
        assert "no feasible sequence" in result.note
    return result.plans


# --- the search against the twin ---------------------------------------------------------


SETTINGS = SearchSettings()


@pytest.fixture(scope="module")
def twins(request: pytest.FixtureRequest) -> Callable[[str], Twin]:
    """Return the twin of a context by name, built on first use: the U-channel ("u") and
    the short one ("short"), as the project has them or "open"."""
    made: dict[str, Twin] = {}

    def get(which: str) -> Twin:
        if which not in made:
            ctx = request.getfixturevalue("u_ctx" if which.startswith("u") else "short_ctx")
            made[which] = Twin.of(_open(ctx) if which.endswith("open") else ctx)
        return made[which]

    return get


@pytest.mark.parametrize(
    "which",
    [
        pytest.param("u", marks=pytest.mark.slow),
        pytest.param("u open", marks=pytest.mark.slow),
        pytest.param("short", marks=pytest.mark.slow),
        "short open",
    ],
)
def test_plans_equal_the_brute_force_ranking(twins: Callable[[str], Twin], which: str) -> None:
    plans = check_against_twin(twins(which), SETTINGS)
    if which == "short open":
        assert len(plans) == 2, "both orders of the short U-channel are feasible"


def test_one_plan_asked_is_the_cheapest(twins: Callable[[str], Twin]) -> None:
    settings = dataclasses.replace(SETTINGS, max_plans=1)
    assert len(check_against_twin(twins("short open"), settings)) == 1


@pytest.mark.slow
def test_other_estimates_keep_the_ranking(twins: Callable[[str], Twin]) -> None:
    # slower regrips, free handling, one candidate per batch: the same twin prices them
    settings = SearchSettings(regrip_time=60.0, handling_time=0.0, batch_size=1)
    for which in ("u open", "short open"):
        check_against_twin(twins(which), settings)


def test_bending_a_first_is_rejected_for_the_punch(base_ctx: SweepContext) -> None:
    ctx = _open(base_ctx)  # nothing but the bends to stop the branch
    names = [b.name for b in ctx.part().bends]  # the project's order (it may set one)
    a, b = names.index("bA"), names.index("bB")
    # the part against the press does not depend on the grasp: after bA, bB fails on
    # either side of the die
    e = evaluate(dataclasses.replace(ctx, grasps=ctx.grasps[:1]), (a,), b)
    assert not e.feasible
    for side in e.sides:
        assert not side.ok and side.reason is not None and "punch" in side.reason, side.reason
    # in the search: the grasps that make bA first take the branch to bB, which is rejected
    probe = dataclasses.replace(ctx, grasps=ctx.grasps[::3])
    makes_a = [probe.grasps[i] for i in np.flatnonzero(evaluate(probe, (), a).grasp_ok)]
    assert makes_a, "no candidate grasp makes bA first (the cell's tuning?)"
    result = find_sequences(dataclasses.replace(ctx, grasps=tuple(makes_a[:4])), verify=None)
    assert all(p.sequence != ("bA", "bB") for p in result.plans)
    reasons = [why for branch, why in result.rejected if branch == ("bA", "bB")]
    assert reasons, result.rejected
    assert any("punch" in why for why in reasons), reasons


# --- the search on crafted verdicts -----------------------------------------------------
# The cheap checks replaced by seeded verdicts (the search's batch function patched): three
# bends, every order feasible or not by chance, regrip stations, flips and moves all in
# play, whatever the cell's tuning. The ram times are real ones (`press.ram_time` of a
# depth), so the search's heuristic (the ram's least time per bend) stays admissible.


def _three_bends(ctx: SweepContext) -> SweepContext:
    """Return `ctx` (open) with a third flange C on the base's edge 1, its own grasps."""
    spec = dataclasses.asdict(ctx.part_spec)
    spec["flanges"] = list(spec["flanges"])
    spec["bends"] = [dict(b) for b in spec["bends"]]
    base = np.asarray(spec["flanges"][0]["polygon"], float)
    width = float(np.linalg.norm(base[2] - base[1]))
    c = [[0.0, 0.0], [width, 0.0], [width, 0.03], [0.0, 0.03]]
    spec["flanges"].append({"name": "C", "polygon": c})
    spec["bends"].append(dict(spec["bends"][0], name="bC", parent_edge=1, child="C", child_edge=0))
    spec["sequence"] = None
    ctx = dataclasses.replace(_open(ctx), part_spec=spec, key=uuid.uuid4().hex)
    assert [b.name for b in ctx.part().bends] == ["bA", "bB", "bC"]
    return ctx


def crafted(ctx: SweepContext, rng: np.random.Generator, G: int) -> Evals:
    """Return seeded verdicts of every (bends done, next bend) of `ctx`'s part."""
    dof = ctx.reach.model.dof
    out: Evals = {}
    for done, b in _keys(len(ctx.part().bends)):
        ok = rng.random(G) < (0.0 if rng.random() < 0.1 else 0.6)
        sides = tuple(
            SideEval(
                True,
                None,
                "S1",
                0.1,
                depth,
                ram_time(ctx.press, depth),
                bool(rng.random() < 0.5),
            )
            for depth in rng.uniform(0.002, 0.005, 2)
        )
        q0 = np.where(ok[:, None], rng.uniform(-2, 2, (G, dof)), np.nan)
        q1 = np.where(ok[:, None], rng.uniform(-2, 2, (G, dof)), np.nan)
        reasons = tuple(None if k else f"crafted: grasp {i} cannot" for i, k in enumerate(ok))
        out[(done, b)] = BendEval(
            done,
            b,
            None,
            sides,  # type: ignore[arg-type]
            rng.integers(0, 2, G),
            ok,
            reasons,
            q0,
            q1,
            rng.random(G) < 0.7,
        )
    return out


@pytest.fixture(scope="module")
def three_ctx(base_ctx: SweepContext) -> SweepContext:
    """Return the three-bend U-channel (open) with five grasps."""
    ctx = _three_bends(base_ctx)
    return dataclasses.replace(
        ctx, grasps=tuple(grasp_grid(ctx.part(), spacing=0.05, inset=0.008)[:5])
    )


def _search_crafted(
    ctx: SweepContext, evals: Evals, monkeypatch: pytest.MonkeyPatch, settings: SearchSettings
) -> list[SequencePlan]:
    asked: list[Key] = []

    def fake(context: SweepContext, keys: list[Key]) -> list[BendEval]:
        asked.extend(keys)
        return [evals[k] for k in keys]

    monkeypatch.setattr(sequencing, "evaluate_batch", fake)
    plans = check_against_twin(Twin.of(ctx, evals), settings)
    assert len(asked) == len(set(asked)), "each (bends done, next bend) evaluated once"
    return plans


@pytest.mark.parametrize("width", [1, 8])
@pytest.mark.parametrize("seed", range(6))
def test_crafted_verdicts_rank_as_the_brute_force(
    three_ctx: SweepContext, monkeypatch: pytest.MonkeyPatch, seed: int, width: int
) -> None:
    rng = np.random.default_rng([50, seed])
    evals = crafted(three_ctx, rng, len(three_ctx.grasps))
    settings = SearchSettings(max_plans=6, width=width, batch_size=int(rng.integers(1, 6)))
    _search_crafted(three_ctx, evals, monkeypatch, settings)


def test_crafted_one_plan_asked_is_the_cheapest(
    three_ctx: SweepContext, monkeypatch: pytest.MonkeyPatch
) -> None:
    wrong = []
    for seed in range(8):
        evals = crafted(three_ctx, np.random.default_rng([50, seed]), len(three_ctx.grasps))
        twin = Twin.of(three_ctx, evals)
        settings = SearchSettings(max_plans=1)
        ranking = twin.ranking(settings)
        monkeypatch.setattr(
            sequencing, "evaluate_batch", lambda c, keys, e=evals: [e[k] for k in keys]
        )
        plans = find_sequences(three_ctx, verify=None, settings=settings).plans
        if ranking and (len(plans) != 1 or plans[0].cost > ranking[0][0] + 1e-9):
            wrong.append(
                (seed, [p.sequence for p in plans], plans[0].cost if plans else None, ranking[0])
            )
    assert not wrong, f"(seed, plan, its cost, the cheapest (cost, order)): {wrong}"


# --- limits -------------------------------------------------------------------------------


def _few(ctx: SweepContext) -> SweepContext:
    """Return `ctx` open, with its first dozen grasps (the limits need no feasible one)."""
    return dataclasses.replace(_open(ctx), grasps=ctx.grasps[:KEEP])


def test_a_tiny_time_limit_stops_early_with_a_note(base_ctx: SweepContext) -> None:
    result = find_sequences(_few(base_ctx), verify=None, time_limit=1e-9)
    assert result.note.startswith("stopped at the time limit of 1e-09 s")
    assert result.plans == [] and result.stats.candidates == 0


@pytest.mark.parametrize("limit", [0.0, -1.0, np.nan, np.inf])
def test_a_bad_time_limit_is_an_input_error(base_ctx: SweepContext, limit: float) -> None:
    with pytest.raises(InputError, match="time_limit: must be > 0 s or None"):
        find_sequences(_few(base_ctx), verify=None, time_limit=limit)


def test_cancel_returns_with_the_note(base_ctx: SweepContext) -> None:
    result = find_sequences(_few(base_ctx), verify=None, cancel=lambda: True)
    assert result.note.startswith("cancelled: the plans found so far are returned")
    assert result.plans == [] and result.stats.candidates == 0


# --- serial and Ray -----------------------------------------------------------------------


@pytest.fixture(scope="module")
def local_ray() -> Iterator[None]:
    """Start one local Ray for this module's Ray tests, as a search does; shut it down after."""
    ray = pytest.importorskip("ray")
    ray.cloudpickle.register_pickle_by_value(sys.modules[__name__])
    with engine_session("ray"):  # as a search starts it: local, on all cores, a token
        yield


def _summary(plans: list[SequencePlan]) -> list[tuple[object, ...]]:
    return [
        (p.sequence, p.grasp_ids, p.stations, p.orientations, p.regrips, p.flips, round(p.cost, 9))
        for p in plans
    ]


@pytest.mark.slow
def test_ray_gives_the_serial_plans(
    local_ray: None, u_ctx: SweepContext, short_ctx: SweepContext
) -> None:
    import ray

    for ctx in (u_ctx, _open(u_ctx), _open(short_ctx)):
        serial = find_sequences(ctx, verify=None)
        on_ray = find_sequences(ctx, verify=None, engine="ray")
        assert ray.is_initialized(), "the search reuses the running Ray and leaves it up"
        assert _summary(on_ray.plans) == _summary(serial.plans)
        assert on_ray.rejected == serial.rejected
        assert on_ray.stats.engine == "ray" and on_ray.stats.candidates == serial.stats.candidates


def test_the_cheap_stage_checks_the_cycles_straight_moves_pose_for_pose() -> None:
    """The search's IK waypoints near the die are the cycle's (`cycle_path._line`): the same
    poses, so a grasp the search keeps does not fail the full cycle on the way in or out."""
    from workbench.geometry.transforms import xyz_rpy_to_transform
    from workbench.pressbrake.bend_eval import _line_poses
    from workbench.pressbrake.cycle_path import LINE_STEP, _line

    rng = np.random.default_rng(5)
    for _ in range(20):
        T = xyz_rpy_to_transform(rng.uniform(-1, 1, 3), rng.uniform(-np.pi, np.pi, 3))
        offset = rng.uniform(-0.3, 0.3, 3) * rng.choice([0.0, 1.0], 3)
        got = _line_poses(T[None], offset)[:, 0]
        end = T.copy()
        end[:3, 3] += offset
        want = np.array(_line(T, end, LINE_STEP))
        np.testing.assert_allclose(got, want, atol=1e-12)


def test_via_home_the_wrist_goes_halfway_and_the_arm_home() -> None:
    from workbench.pressbrake.cycle import ARM_JOINTS, _carry_the_wrist

    home = np.zeros(6)
    q = np.tile(home, (5, 1))
    q[0] = [0.1, 0.2, 0.3, 1.0, -0.5, 2.0]
    q[2] = [0.4, 0.5, 0.6, -1.0, 0.5, -2.5]
    q[4] = [0.7, 0.8, 0.9, 3.0, 0.1, 0.0]
    _carry_the_wrist(q, [0, 2, 4])
    np.testing.assert_array_equal(q[1, :ARM_JOINTS], home[:ARM_JOINTS])
    np.testing.assert_allclose(q[1, ARM_JOINTS:], [0.0, 0.0, -0.25])
    np.testing.assert_allclose(q[3, ARM_JOINTS:], [1.0, 0.3, -1.25])
    lone = np.tile(home, (2, 1))  # a via with nothing after it keeps home
    lone[0] = [0.1, 0.2, 0.3, 1.0, -0.5, 2.0]
    _carry_the_wrist(lone, [0])
    np.testing.assert_array_equal(lone[1], home)


def test_grasps_set_apart_by_their_footprint_head_the_rejected_table(
    base_ctx: SweepContext,
) -> None:
    ctx = _few(base_ctx)
    g = ctx.grasps[0]
    refused = ((g, "covers hole H1 of flange F2"),)
    result = find_sequences(dataclasses.replace(ctx, refused=refused), verify=None, time_limit=1e-9)
    assert result.rejected[0] == ((), f"grasp {grasp_label(g)}: covers hole H1 of flange F2")
    plain = find_sequences(ctx, verify=None, time_limit=1e-9)
    assert all(why != result.rejected[0][1] for _, why in plain.rejected)
