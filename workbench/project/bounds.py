"""The physical range of every number in a project file, and the work budgets of the plans.

One module, so the ranges are named once and listed in docs/security.md ("Input bounds");
`tests/test_bounds.py` checks that the docs name every constant here and that the example
projects lie inside them. Units are the project file's (mm, deg, s, N, Hz) unless a name
says otherwise. A range is ``(lo, hi)``, both ends allowed unless the name ends in ``_OPEN``
(lower end excluded: the value must be > lo).

`Range` is the pydantic annotation that checks one of them at load, so a value outside
names its field path (``polishing.controller.latency: 1e+09 ms is out of range ...``) and
the JSON schema publishes the range (``minimum``/``maximum``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from pydantic import GetCoreSchemaHandler, GetJsonSchemaHandler
from pydantic.json_schema import JsonSchemaValue
from pydantic_core import CoreSchema, core_schema

from workbench.cad.isolation import SETTINGS as CAD_READER_BOUNDS

# -- the cell -------------------------------------------------------------------------------------
CELL_HALF_EXTENT_MM = 100_000.0
"""Largest absolute x, y or z of any position, in the world or a local frame [mm] (a 200 m cube)."""
SIZE_MM = (0.1, 200_000.0)
"""Edge lengths, radii and heights of cell objects, tools and parts [mm]: > 0.1 mm, at most the cell."""
TOOL_SIZE_MM = (0.1, 5_000.0)
"""Edge lengths of a tool's box [mm] (the robot's and the assembly arms' tools)."""
ANGLE_DEG = 3600.0
"""Largest absolute angle of an orientation (rpy), a DH offset or twist, a grasp yaw [deg] (ten turns)."""
JOINT_DEG = 720.0
"""Largest absolute joint value or joint limit [deg] (two turns each way: at most 5 turns per joint)."""
MESH_SCALE = (1e-6, 10.0)
"""Mesh file units to metres (0.001 for mm, 1 for m)."""
MAX_DOF = 16
"""Most joints (DH rows, per-joint lists) a robot may have."""
MAX_ITEMS = 10_000
"""Most entries of a list in a project (cell objects, moves, parts, polygon points, via poses)."""
MAX_INDEX = 10_000
"""Largest integer index (a bend's flange edge)."""
MAX_SEED = 2**32 - 1
"""Largest random seed."""
JSON_MAX_DEPTH = 64
"""Deepest nesting of objects and lists in a project or part file."""

# -- robot rates (per joint) ------------------------------------------------------------------------
JOINT_SPEED_DEG_S = (0.1, 100_000.0)
"""A joint's speed limit [deg/s]."""
JOINT_ACCEL_DEG_S2 = (1.0, 1e7)
"""A joint's acceleration limit [deg/s²]."""
JOINT_JERK_DEG_S3 = (10.0, 1e9)
"""A joint's jerk limit [deg/s³]."""

# -- program moves ----------------------------------------------------------------------------------
JOINT_MOVE_PERCENT_OPEN = (0.0, 100.0)
"""A joint move's speed [% of the joint speed limits]: > 0, at most 100."""
LINEAR_SPEED_MM_S = (0.1, 10_000.0)
"""A linear move's TCP speed [mm/s]."""
ZONE_MM = (0.0, 1_000.0)
"""A move's blend radius [mm] (0: exact stop)."""

# -- bending ------------------------------------------------------------------------------------------
THICKNESS_MM = (0.1, 100.0)
"""Sheet thickness [mm]."""
INNER_RADIUS_MM = (0.05, 10_000.0)
"""A bend's inner radius [mm] (also at least 0.5 x thickness, Table 1)."""
DIE_LENGTH_MM = (1.0, 200_000.0)
"""The die's longest bend line [mm]."""
LIFT_MM_OPEN = (0.0, 10_000.0)
"""Bending: vertical approach and retreat at the blank stack, the regrip station and the pallet [mm]: > 0."""
GRASP_SPACING_MM_OPEN = (0.0, 1_000.0)
"""Bending: the sequence search's grid of candidate grasps on each flange [mm]: > 0."""
GRASP_INSET_MM = (0.0, 500.0)
"""Bending: how far inside a flange's edge a candidate grasp lies at least [mm]."""
GRASP_YAWS_MAX = 36
"""Bending: the most gripper yaws a candidate grasp point is tried with."""

# -- the press brake (bending.press) -------------------------------------------------------------------
PRESS_TOOL_MM = (0.1, 2_000.0)
"""Press brake: the punch's width and height, the die's V-opening, width and height, a back-gauge
finger's depth, width and height [mm]."""
PRESS_RADIUS_MM = (0.0, 100.0)
"""Press brake: the punch's tip radius and the die's shoulder radius [mm] (0: sharp)."""
PRESS_ANGLE_DEG_OPEN = (0.0, 180.0)
"""Press brake: the punch's tip angle and the die's V angle [deg]: > 0, and below 180 (flat, also refused)."""
BACKGAUGE_FINGERS = (1, 4)
"""Press brake: the number of back-gauge fingers."""
RAM_OPEN_MM_OPEN = (0.0, 2_000.0)
"""Press brake: the gap between the punch tip and the sheet when the ram is open [mm]: > 0."""
RAM_SPEED_MM_S_OPEN = (0.0, 1_000.0)
"""Press brake: the ram's approach, bending and return speeds [mm/s]: > 0."""
AIR_RADIUS_RATIO_OPEN = (0.0, 0.5)
"""Press brake: inner radius / V-opening in air bending [-] (0.16 for mild steel); above 0.5 the
radius would be wider than the V, which holds the part on its shoulders."""
CONTACT_TOLERANCE_MM_OPEN = (0.0, 5.0)
"""Press brake: the contact tolerance between the part and the tools [mm]: > 0."""
PRESS_FRAME_MM = (1.0, 10_000.0)
"""Press brake: the gap from the longest tool to a side housing, the housings' depth and width,
the upper beam's height over the punch [mm]."""

# -- assembly -----------------------------------------------------------------------------------------
PLANNER_CELL_MM = (0.1, 200_000.0)
"""Assembly planner: the part subdivision cell, the ant's grid spacing `dis` and the
carrying robot's resolution [mm] (see also assembly.cells.MAX_CELLS)."""
PLANNER_STEPS = (1, 1_000)
"""Assembly planner: the ant's segments along the dominant axis."""
PLANNER_TIME_S_OPEN = (0.0, 3_600.0)
"""Assembly planner: the RRT planners' time limit [s]."""
APPROACH_MM = (0.0, 10_000.0)
"""Assembly task: approach and retreat distances along the TCP z [mm]."""
SPEED_PERCENT_OPEN = (0.0, 100.0)
"""Assembly: the robots' speed [% of their joint limits]."""

# -- polishing -----------------------------------------------------------------------------------------
PATH_STEP_MM = (0.1, 1_000.0)
"""Polishing: chord between consecutive path points [mm]."""
PASS_SPACING_MM = (0.5, 10_000.0)
"""Polishing: distance between neighbouring passes [mm] (see also polishing.process_path.MAX_PASSES)."""
TOOL_RADIUS_MM = (0.5, 1_000.0)
"""Polishing: the pad's radius [mm]."""
LEAD_HEIGHT_MM = (0.1, 1_000.0)
"""Polishing: height of the first lead-in and last lead-out point [mm]."""
FEED_MM_S = (0.1, 10_000.0)
"""Polishing: feed, the controller's speed limit [mm/s]."""
TCP_ACCEL_MM_S2 = (1.0, 1e7)
"""Polishing: the controller's limit on the change of the command [mm/s²]."""
DWELL_S = (0.0, 60.0)
"""Polishing: dwell at the first point [s]."""
FORCE_N = (0.001, 100_000.0)
"""Polishing: target force and the tool's force limit [N] (force must be > 0.001 N)."""
CONTROL_RATE_HZ = (1.0, 10_000.0)
"""Polishing: the controller's rate [Hz]."""
LATENCY_MS = (0.0, 1_000.0)
"""Polishing: command-to-motion latency [ms] (see also LATENCY_MAX_CYCLES)."""
GAIN = (0.0, 1e6)
"""Polishing: every controller gain (position, force and orientation loops), in its own unit."""
ANGULAR_SPEED_DEG_S = (0.1, 100_000.0)
"""Polishing: the orientation loop's angular speed limit [deg/s]."""
STIFFNESS_N_M = (1.0, 1e10)
"""Polishing contact: normal and lateral stiffness [N/m]."""
DAMPING_N_S_M = (0.0, 1e8)
"""Polishing contact: damping [N s/m]."""
FRICTION = (0.0, 10.0)
"""Polishing contact: Coulomb friction coefficient [-]."""
FORM_ERROR_MM = (0.0, 100.0)
"""Polishing contact: amplitude of the surface form error [mm]."""
WAVELENGTH_MM = (1.0, 200_000.0)
"""Polishing contact: wavelength of the form error [mm]."""
NOISE_N = (0.0, 10_000.0)
"""Polishing contact: force sensor noise, standard deviation [N]."""
CUTOFF_HZ = (0.1, 100_000.0)
"""Polishing contact: the force sensor's low-pass cutoff [Hz]."""

# -- CAD import ---------------------------------------------------------------------------------------
LINEAR_TOLERANCE_MM = (0.001, 10.0)
"""STEP tessellation: the chordal deviation, the largest distance from a triangle to the exact surface [mm]."""
ANGULAR_TOLERANCE_DEG = (0.5, 60.0)
"""STEP tessellation: the largest angle between the normals of neighbouring triangles on one face [deg]."""

# -- planning ------------------------------------------------------------------------------------------
PLAN_TIME_S_OPEN = (0.0, 86_400.0)
"""planning.time_limit: how long one workflow's planning may run [s]: > 0, at most a day."""

# -- work budgets (refused before the work starts, with the estimate) ---------------------------------
LATENCY_MAX_CYCLES = 100
"""Polishing: latency x control rate, in whole control cycles (the orientation loop's
stability check solves for poles of a matrix that grows with it; 200 cycles take ~25 s)."""

BUDGETS = (
    "workbench.project.bounds.LATENCY_MAX_CYCLES",
    "workbench.motion.trajectory.MAX_SAMPLES",
    "workbench.assembly.cells.MAX_CELLS",
    "workbench.assembly.planners.ant.MAX_PLANE_POINTS",
    "workbench.assembly.planners.ant.MAX_LINE_SAMPLES",
    "workbench.polishing.process_path.MAX_PASSES",
    "workbench.polishing.process_path.MAX_PATH_POINTS",
    "workbench.polishing.force_control.MAX_STEPS",
    "workbench.collision.shapes.SOLID_SIZE",
    *CAD_READER_BOUNDS,  # the CAD readers' bounds, sent to their worker with every read
    "workbench.pressbrake.grasp_grid.MAX_GRID_POINTS",
)
"""The work budgets, each a named setting next to the work it bounds (the domain packages
cannot import the project's modules): work whose estimate exceeds one is refused before it
starts, naming the setting and the estimate."""


@dataclass(frozen=True)
class Range:
    """A pydantic annotation: the number lies in [lo, hi] (or (lo, hi] with `lo_open`).

    The message names the value, the range and its unit; pydantic prefixes the field path."""

    lo: float
    hi: float
    unit: str = ""
    lo_open: bool = False

    def check(self, v: Any) -> Any:
        ok = (v > self.lo if self.lo_open else v >= self.lo) and v <= self.hi
        if not ok:
            u = f" {self.unit}" if self.unit else ""
            left = "(" if self.lo_open else "["
            raise ValueError(
                f"{v:g}{u} is out of range; allowed {left}{self.lo:g}, {self.hi:g}]{u}"
            )
        return v

    def __get_pydantic_core_schema__(
        self, source: Any, handler: GetCoreSchemaHandler
    ) -> CoreSchema:
        return core_schema.no_info_after_validator_function(self.check, handler(source))

    def __get_pydantic_json_schema__(
        self, schema: CoreSchema, handler: GetJsonSchemaHandler
    ) -> JsonSchemaValue:
        out = handler(schema)
        out["exclusiveMinimum" if self.lo_open else "minimum"] = self.lo
        out["maximum"] = self.hi
        return out


def span(bounds: tuple[float, float], unit: str = "", *, lo_open: bool = False) -> Range:
    """Return the `Range` of a ``(lo, hi)`` constant (lo excluded with `lo_open`)."""
    return Range(bounds[0], bounds[1], unit, lo_open)


def symmetric(limit: float, unit: str = "") -> Range:
    """Return the `Range` [-limit, limit]."""
    return Range(-limit, limit, unit)
