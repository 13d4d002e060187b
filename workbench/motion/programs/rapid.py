"""ABB RAPID post-processor: MoveAbsJ for joint moves, MoveL for linear moves."""

from __future__ import annotations

import numpy as np

from workbench.motion.program import JOINT, Program
from workbench.motion.programs.angles import quaternion_wxyz

# ABB's predefined zones (TCP path radius in mm); other radii become zonedata literals.
_ZONES = (0, 1, 5, 10, 15, 20, 30, 40, 50, 60, 80, 100, 150, 200)
_VMAX_TCP = 7000.0  # ABB's vmax speeddata [mm/s], the reference for joint-move fractions


def _f(x: float, nd: int = 3) -> str:
    s = f"{x:.{nd}f}"
    return "0." + "0" * nd if s == "-0." + "0" * nd else s


def zone_name(zone_m: float) -> str:
    """Return the RAPID zonedata for a blend radius [m]: fine, z10, ... or a literal."""
    mm = zone_m * 1000.0
    if mm <= 0.0:
        return "fine"
    for z in _ZONES:
        if abs(mm - z) < 1e-6:
            return f"z{z}"
    return f"[FALSE,{_f(mm, 1)},{_f(1.5 * mm, 1)},{_f(1.5 * mm, 1)},{_f(0.15 * mm, 2)},{_f(1.5 * mm, 1)},{_f(0.15 * mm, 2)}]"


def to_rapid(program: Program, *, tool: str = "tool0") -> str:
    """Return a RAPID module (text): jointtargets in degrees, robtargets in mm and quaternions.

    Speeds are speeddata literals [v_tcp mm/s, v_ori deg/s, v_leax, v_reax]; a joint move's
    fraction scales ABB's vmax (7000 mm/s). Robot configuration data is [0,0,0,0].
    """
    decl, body = [], []
    for i, mv in enumerate(program.moves, start=1):
        label = mv.name if mv.name.isidentifier() else f"p{i}"
        zone = zone_name(mv.zone)
        if mv.kind == JOINT:
            deg = ", ".join(_f(x, 4) for x in np.degrees(mv.q))
            decl.append(f"    CONST jointtarget {label}:=[[{deg}],[9E9,9E9,9E9,9E9,9E9,9E9]];")
            speed = f"[{_f(mv.speed * _VMAX_TCP, 1)},500,5000,1000]"
            body.append(f"        MoveAbsJ {label}, {speed}, {zone}, {tool};")
        else:
            T = mv.T
            xyz = ",".join(_f(x) for x in T[:3, 3] * 1000.0)
            quat = ",".join(_f(x, 6) for x in quaternion_wxyz(T[:3, :3]))
            decl.append(
                f"    CONST robtarget {label}:=[[{xyz}],[{quat}],[0,0,0,0],"
                "[9E9,9E9,9E9,9E9,9E9,9E9]];"
            )
            speed = f"[{_f(mv.speed * 1000.0, 1)},500,5000,1000]"
            body.append(f"        MoveL {label}, {speed}, {zone}, {tool};")
    lines = [
        f"MODULE {program.name}",
        *decl,
        "",
        "    PROC main()",
        *body,
        "    ENDPROC",
        "ENDMODULE",
        "",
    ]
    return "\n".join(lines)
