"""Force/position hybrid control of a polishing tool along a path, simulated (seed 004, eqs. 5-6).

At a fixed control rate the controller sends a Cartesian velocity (as a `speedl`-style
interface takes it), built from two loops split along the tool z axis z = -n (n the
surface normal at the reference point, pointing to the tool side):

    tangent plane (position, PD):  v_p = P_t (dX_d + k_pp e + k_pd de/dt),   e = X_d - X,
    tool z (force, PI):            v_f = k_fp e_F + k_fi ∫ e_F dt,          e_F = F_d - F_meas,
    command:                       v = v_p + (v_f + dX_d.z) z,

with P_t = I - z zᵀ and dX_d the reference velocity (feed along the path); dX_d.z feeds the
path's own motion along the tool axis forward. The robot executes the command after a
latency, within speed and acceleration limits. The contact is a spring-damper of stiffness
k and damping c along n against the actual surface (the nominal path plus a sinusoidal
form error); friction mu F deflects the tool tip against the feed through a lateral
compliance; the force sensor adds Gaussian noise and is low-pass filtered (first order).
The tool axis is taken to follow the path normal (eq. 7's orientation loop is not simulated).

Along z the loop is linear: with no noise, latency, filter, damping or limits, F/F_d =
k (k_fp s + k_fi) / (s² + k k_fp s + k k_fi) in continuous time. The defaults (k = 5000 N/m,
k_fp = 0.006 (m/s)/N, k_fi = 0.05 (m/s)/(N s)) give s² + 30 s + 250: poles -15 ± 5i rad/s,
damping ratio 0.95, with margin for the 8 ms latency, the 40 Hz filter and the 4 m/s² limit.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class HybridForceParams:
    """Controller gains and contact model. Units in each field's comment; inf/0 turn a part off."""

    control_rate: float = 250.0  # [Hz] controller and speedl command rate
    latency: float = 0.008  # [s] from command to motion (rounded to whole cycles)
    kpp: float = 8.0  # [1/s] position loop P gain
    kpd: float = 0.05  # [-] position loop D gain (on the error rate)
    kfp: float = 0.006  # [(m/s)/N] force loop P gain
    kfi: float = 0.05  # [(m/s)/(N s)] force loop I gain
    stiffness: float = 5000.0  # k [N/m] contact stiffness (tool pad); D = F/k
    damping: float = 10.0  # c [N s/m] contact damping
    friction: float = 0.3  # mu [-] Coulomb friction coefficient
    lateral_stiffness: float = 2.0e5  # [N/m] tool tip compliance against friction
    form_error: float = 3.0e-4  # [m] amplitude of the surface form error along the normal
    form_wavelength: float = 0.06  # [m] wavelength of the form error along the path
    noise_std: float = 0.5  # [N] force sensor noise, standard deviation
    filter_cutoff: float = 40.0  # [Hz] force sensor low-pass (first order); inf = none
    max_speed: float = 0.25  # [m/s] speed limit of the commanded TCP velocity
    max_accel: float = 4.0  # [m/s²] limit on the change of the command per cycle
    max_force: float = 100.0  # [N] the tool's force limit; targets above it are refused
    normal_feedforward: bool = True  # feed the path's own motion along z forward
    seed: int = 0  # noise generator seed


@dataclass(frozen=True)
class ForceControlResult:
    """Simulation record, one row per control cycle. t (K,) [s]; force (K,) true contact force
    [N]; force_measured (K,) filtered sensor force [N]; tracking_error (K,) tangential
    distance of the tool tip from the reference [m]; position (K, 3) tool tip [m];
    commanded_velocity (K, 3) [m/s]; reference (K, 3) reference point on the path [m]."""

    t: F64
    force: F64
    force_measured: F64
    tracking_error: F64
    position: F64
    commanded_velocity: F64
    reference: F64
    target_force: float
    params: HybridForceParams


def _check(
    points: ArrayLike,
    normals: ArrayLike,
    target_force: float,
    feed_speed: float,
    params: HybridForceParams,
) -> tuple[F64, F64]:
    p = np.asarray(points, dtype=float)
    n = np.asarray(normals, dtype=float)
    if p.ndim != 2 or p.shape[1] != 3 or len(p) < 2:
        raise InputError(f"points must have shape (N, 3) with N >= 2, got {p.shape}")
    if n.shape != p.shape:
        raise InputError(f"normals must have the shape of points {p.shape}, got {n.shape}")
    if not (np.isfinite(p).all() and np.isfinite(n).all()):
        raise InputError("points and normals must be finite")
    nn = np.linalg.norm(n, axis=1)
    if (nn < 1e-9).any():
        raise InputError("normals contains zero-length vectors")
    if not math.isfinite(target_force) or target_force <= 0:
        raise InputError(f"target_force must be > 0 N, got {target_force!r}")
    if target_force > params.max_force:
        raise InputError(
            f"target_force = {target_force:g} N is above the tool's limit params.max_force = {params.max_force:g} N"
        )
    if not math.isfinite(feed_speed) or feed_speed <= 0:
        raise InputError(f"feed_speed must be > 0 m/s, got {feed_speed!r}")
    if feed_speed > params.max_speed:
        raise InputError(
            f"feed_speed = {feed_speed:g} m/s is above params.max_speed = {params.max_speed:g} m/s"
        )
    if params.control_rate <= 0 or params.stiffness <= 0:
        raise InputError("params.control_rate and params.stiffness must be > 0")
    return p, n / nn[:, None]


def simulate_hybrid_force_control(
    points: ArrayLike,
    normals: ArrayLike,
    target_force: float,
    feed_speed: float,
    *,
    params: HybridForceParams | None = None,
    dwell: float = 0.0,
) -> ForceControlResult:
    """Return the `ForceControlResult` of running the path under hybrid force/position control.

    points (N, 3) [m] on the nominal surface, normals (N, 3) pointing to the tool side;
    target_force [N] (> 0, <= params.max_force); feed_speed [m/s] along the path; dwell [s]
    at the first point before the feed starts. The tool starts touching the surface
    (zero force) at points[0]. Raises `InputError` for bad shapes or values.
    """
    prm = params or HybridForceParams()
    p, n = _check(points, normals, target_force, feed_speed, prm)
    dt = 1.0 / prm.control_rate
    seg = np.linalg.norm(np.diff(p, axis=0), axis=1)
    s_path = np.concatenate([[0.0], np.cumsum(seg)])
    total = dwell + s_path[-1] / feed_speed
    k_steps = int(math.ceil(total / dt)) + 1
    t: F64 = np.arange(k_steps, dtype=np.float64) * dt
    s_ref = np.clip(feed_speed * (t - dwell), 0.0, s_path[-1])
    ref = np.stack([np.interp(s_ref, s_path, p[:, i]) for i in range(3)], axis=1)
    nrm = np.stack([np.interp(s_ref, s_path, n[:, i]) for i in range(3)], axis=1)
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True)
    vel_ref = np.diff(ref, axis=0, append=ref[-1:]) / dt
    # The actual surface: nominal plus a form error along the normal.
    phase = np.random.default_rng(prm.seed).uniform(0.0, 2 * np.pi)
    form = (
        prm.form_error * np.sin(2 * np.pi * s_ref / prm.form_wavelength + phase)
        if prm.form_error
        else 0 * s_ref
    )
    surf = ref + form[:, None] * nrm
    noise = (
        np.random.default_rng(prm.seed + 1).normal(0.0, prm.noise_std, k_steps)
        if prm.noise_std
        else 0 * t
    )
    feed_dir = np.where(np.linalg.norm(vel_ref, axis=1, keepdims=True) > 0, vel_ref, 0.0)
    fd_norm = np.linalg.norm(feed_dir, axis=1, keepdims=True)
    feed_dir = feed_dir / np.where(fd_norm > 0, fd_norm, 1.0)
    alpha = (
        1.0
        if not math.isfinite(prm.filter_cutoff)
        else 1.0 - math.exp(-2 * math.pi * prm.filter_cutoff * dt)
    )
    lag = int(round(prm.latency / dt))
    k, c, fdes = prm.stiffness, prm.damping, float(target_force)
    a_max = prm.max_accel * dt

    R, N, V, S, FD, NZ = (a.tolist() for a in (ref, nrm, vel_ref, surf, feed_dir, noise))
    force = [0.0] * k_steps
    fmeas = [0.0] * k_steps
    err = [0.0] * k_steps
    pos = [(0.0, 0.0, 0.0)] * k_steps
    vcmd = [(0.0, 0.0, 0.0)] * k_steps
    x0, x1, x2 = p[0].tolist()
    queue = [(0.0, 0.0, 0.0)] * lag  # commands wait `lag` cycles before they move the robot
    integ = 0.0
    ff = 0.0
    d_prev = 0.0
    ep = (0.0, 0.0, 0.0)
    c_prev = (0.0, 0.0, 0.0)
    for i in range(k_steps):
        nx, ny, nz = N[i]
        sx, sy, sz = S[i]
        # Contact along n: penetration of the tool below the actual surface.
        d = nx * (sx - x0) + ny * (sy - x1) + nz * (sz - x2)
        ddot = (d - d_prev) / dt if i else 0.0
        d_prev = d
        f = max(k * d + c * ddot, 0.0) if d > 0 else 0.0
        force[i] = f
        ff += alpha * (f + NZ[i] - ff)
        fmeas[i] = ff
        # Tool tip: deflected against the feed by friction through the lateral compliance.
        defl = prm.friction * f / prm.lateral_stiffness
        fx, fy, fz = FD[i]
        tx, ty, tz = x0 - defl * fx, x1 - defl * fy, x2 - defl * fz
        pos[i] = (tx, ty, tz)
        rx, ry, rz = R[i]
        ex, ey, ez = rx - tx, ry - ty, rz - tz
        en = ex * nx + ey * ny + ez * nz
        ex, ey, ez = ex - en * nx, ey - en * ny, ez - en * nz  # tangential error
        err[i] = math.sqrt(ex * ex + ey * ey + ez * ez)
        # Position PD in the tangent plane (eq. 5, first row).
        vx, vy, vz = V[i]
        px = vx + prm.kpp * ex + prm.kpd * (ex - ep[0]) / dt
        py = vy + prm.kpp * ey + prm.kpd * (ey - ep[1]) / dt
        pz = vz + prm.kpp * ez + prm.kpd * (ez - ep[2]) / dt
        ep = (ex, ey, ez)
        pn = px * nx + py * ny + pz * nz
        px, py, pz = px - pn * nx, py - pn * ny, pz - pn * nz
        # Force PI along the tool z = -n (eq. 5, second row).
        ef = fdes - ff
        integ += ef * dt
        vf = prm.kfp * ef + prm.kfi * integ
        if prm.normal_feedforward:
            vf += -(vx * nx + vy * ny + vz * nz)
        cx, cy, cz = px - vf * nx, py - vf * ny, pz - vf * nz
        sp = math.sqrt(cx * cx + cy * cy + cz * cz)
        if sp > prm.max_speed:
            cx, cy, cz = cx * prm.max_speed / sp, cy * prm.max_speed / sp, cz * prm.max_speed / sp
        dx, dy, dz = cx - c_prev[0], cy - c_prev[1], cz - c_prev[2]
        dn = math.sqrt(dx * dx + dy * dy + dz * dz)
        if dn > a_max:
            cx, cy, cz = (
                c_prev[0] + dx * a_max / dn,
                c_prev[1] + dy * a_max / dn,
                c_prev[2] + dz * a_max / dn,
            )
        c_prev = (cx, cy, cz)
        vcmd[i] = (cx, cy, cz)
        queue.append((cx, cy, cz))
        ax, ay, az = queue.pop(0)
        x0, x1, x2 = x0 + ax * dt, x1 + ay * dt, x2 + az * dt
    return ForceControlResult(
        t=t,
        force=np.asarray(force),
        force_measured=np.asarray(fmeas),
        tracking_error=np.asarray(err),
        position=np.asarray(pos),
        commanded_velocity=np.asarray(vcmd),
        reference=ref,
        target_force=fdes,
        params=prm,
    )
