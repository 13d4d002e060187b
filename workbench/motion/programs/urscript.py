"""Universal Robots URScript post-processor: movej / movel with blend radius r."""

from __future__ import annotations

from workbench.motion.program import JOINT, Program
from workbench.motion.programs.angles import rotation_vector


def _f(x: float, nd: int = 6) -> str:
    s = f"{x:.{nd}f}"
    return "0." + "0" * nd if s == "-0." + "0" * nd else s


def to_urscript(
    program: Program, *, joint_speed: float = 3.14, joint_accel: float = 1.4, tcp_accel: float = 1.2
) -> str:
    """Return a URScript program: joints in rad, poses p[x, y, z, rx, ry, rz] in m and rad.

    A joint move's speed fraction scales `joint_speed` [rad/s]; linear speeds are [m/s];
    accelerations `joint_accel` [rad/s^2], `tcp_accel` [m/s^2]; zones become r [m].
    """
    out = [f"def {program.name}():"]
    for mv in program.moves:
        if mv.name:
            out.append(f"  # {mv.name}")
        r = _f(mv.zone, 4)
        if mv.kind == JOINT:
            q = ", ".join(_f(x) for x in mv.q)
            v = _f(mv.speed * joint_speed, 4)
            out.append(f"  movej([{q}], a={_f(joint_accel, 4)}, v={v}, r={r})")
        else:
            T = mv.T
            p = ", ".join(_f(x) for x in [*T[:3, 3], *rotation_vector(T[:3, :3])])
            out.append(f"  movel(p[{p}], a={_f(tcp_accel, 4)}, v={_f(mv.speed, 4)}, r={r})")
    out += ["end", f"{program.name}()", ""]
    return "\n".join(out)
