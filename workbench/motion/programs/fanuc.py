"""FANUC LS post-processor: J and L lines with FINE or CNT, positions in /POS."""

from __future__ import annotations

import numpy as np

from workbench.motion.program import JOINT, Program
from workbench.motion.programs.angles import wpr_deg


def cnt_value(zone_m: float) -> str:
    """Return FANUC termination for a blend radius [m]: FINE, or CNT = radius in mm (1..100)."""
    mm = zone_m * 1000.0
    return "FINE" if mm <= 0 else f"CNT{max(1, min(100, round(mm)))}"


def _f(x: float) -> str:
    s = f"{x:9.3f}"
    return s.replace("-0.000", " 0.000")


def to_ls(program: Program, *, date: str = "26-01-01") -> str:
    """Return a FANUC .LS program: /PROG, /ATTR, /MN with J/L lines, /POS, /END.

    Joint positions are J1..J6 [deg]; Cartesian positions X, Y, Z [mm], W, P, R [deg]
    (fixed-axis x, y, z). J speeds are % of maximum; L speeds mm/sec.
    """
    mn, pos = [], []
    for i, mv in enumerate(program.moves, start=1):
        term = cnt_value(mv.zone)
        note = f" ;  ! {mv.name}" if mv.name else " ;"
        if mv.kind == JOINT:
            pct = max(1, min(100, round(mv.speed * 100)))
            mn.append(f"{i:4d}:J P[{i}] {pct}% {term}{note}")
            j = np.degrees(mv.q)
            body = [
                f"\tJ1={_f(j[0])} deg,\tJ2={_f(j[1])} deg,\tJ3={_f(j[2])} deg,",
                f"\tJ4={_f(j[3])} deg,\tJ5={_f(j[4])} deg,\tJ6={_f(j[5])} deg",
            ]
            cfg = ""
        else:
            mn.append(f"{i:4d}:L P[{i}] {round(mv.speed * 1000.0)}mm/sec {term}{note}")
            T = mv.T
            x, y, z = T[:3, 3] * 1000.0
            w, p, r = wpr_deg(T[:3, :3])
            body = [
                f"\tX ={_f(x)}  mm,\tY ={_f(y)}  mm,\tZ ={_f(z)}  mm,",
                f"\tW ={_f(w)} deg,\tP ={_f(p)} deg,\tR ={_f(r)} deg",
            ]
            cfg = "\t\tCONFIG : 'N U T, 0, 0, 0',"
        comment = f' : "{mv.name[:16]}"' if mv.name else ""
        pos += [f"P[{i}{comment}]{{", "   GP1:", f"\tUF : 0, UT : 1,{cfg}", *body, "};"]
    attr = [
        "/ATTR",
        "OWNER\t\t= MNEDITOR;",
        'COMMENT\t\t= "workbench";',
        "PROG_SIZE\t= 0;",
        f"CREATE\t\t= DATE {date}  TIME 00:00:00;",
        f"MODIFIED\t= DATE {date}  TIME 00:00:00;",
        "FILE_NAME\t= ;",
        "VERSION\t\t= 0;",
        f"LINE_COUNT\t= {len(mn)};",
        "MEMORY_SIZE\t= 0;",
        "PROTECT\t\t= READ_WRITE;",
        "TCD:  STACK_SIZE\t= 0,",
        "      TASK_PRIORITY\t= 50,",
        "      TIME_SLICE\t= 0,",
        "      BUSY_LAMP_OFF\t= 0,",
        "      ABORT_REQUEST\t= 0,",
        "      PAUSE_REQUEST\t= 0;",
        "DEFAULT_GROUP\t= 1,*,*,*,*;",
        "CONTROL_CODE\t= 00000000 00000000;",
    ]
    lines = [f"/PROG  {program.name.upper()}", *attr, "/MN", *mn, "/POS", *pos, "/END", ""]
    return "\n".join(lines)
