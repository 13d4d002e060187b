"""Force/position hybrid control of a polishing tool along a path, simulated (seed 004, eqs. 5-7).

At a fixed control rate the controller sends a Cartesian twist (as a `speedl`-style
interface takes it: a TCP velocity and an angular velocity), built from three loops. The
velocity is split along the tool's actual z axis z (unit, into the surface):

    tangent plane (position, PD):  v_p = P_t (dX_d + k_pp e + k_pd de/dt),   e = X_d - X,
    tool z (force, PI):            v_f = k_fp e_F + k_fi ∫ e_F dt,          e_F = F_d - F_meas,
    command:                       v = v_p + (v_f + dX_d.z) z,

with P_t = I - z zᵀ and dX_d the reference velocity (feed along the path); dX_d.z feeds the
path's own motion along the tool axis forward (v_f > 0 pushes into the surface).

Orientation (eq. 7, derived again): the tool z should lie along -n_s, n_s the normal of the
actual surface at the contact. The rotation taking the current axis z to the target z_d is
about the unit axis (z × z_d)/|z × z_d| by the angle θ = atan2(|z × z_d|, z·z_d); its
rotation vector e_R = θ (z × z_d)/|z × z_d| is the orientation error. (The seed's
f_01 = ||n_0 × n_1||₂ ω_01 multiplies a scalar norm by a rate; an axis needs the *unit*
cross product, and the error to drive to zero is the angle, not sin θ = |z × z_d|.) The
angular velocity command is eq. 5's position law carried over to rotations (the seed's
PID on the rotation error):

    ω = ω_d + k_op e_R + k_od de_R/dt + k_oi ∫ e_R dt,

ω_d the rotation rate of the planned normal along the path (fed forward). For a tilt about
a fixed axis with no latency or limits the angle obeys, per cycle Δt,
θ_{k+1} = θ_k - Δt (k_op θ_k + k_od (θ_k - θ_{k-1})/Δt + k_oi Δt Σ θ_j): with k_oi = 0 a
constant tilt decays as exp(-t/τ), τ = (1 + k_od)/k_op in continuous time. The target
normal comes from the contact (the force/torque sensor, friction compensated): the actual
normal through the sensor's first-order low-pass. The command is applied after the
latency, its magnitude limited to `max_angular_speed`; the tool rotates about the TCP.

The robot executes the commands after a latency, within speed and acceleration limits.
The contact is a spring-damper of stiffness k and damping c along the actual normal n_s
against the actual surface (the nominal path plus a sinusoidal form error h(s) along the
normal, which tilts the normal by -h'(s) along the path's tangent); friction mu F deflects
the tool tip against the feed through a lateral compliance; the force sensor adds Gaussian
noise and is low-pass filtered (first order). With `orientation_loop` off the tool axis is
held along the planned normal (the form error's tilt is then all orientation error).

Along z the loop is linear: with no noise, latency, filter, damping or limits, F/F_d =
k (k_fp s + k_fi) / (s² + k k_fp s + k k_fi) in continuous time. The defaults (k = 5000 N/m,
k_fp = 0.006 (m/s)/N, k_fi = 0.05 (m/s)/(N s)) give s² + 30 s + 250: poles -15 ± 5i rad/s,
damping ratio 0.95, with margin for the 8 ms latency, the 40 Hz filter and the 4 m/s² limit.
The orientation defaults (k_op = 40 /s, k_od = 0.05, k_oi = 0) give τ = 26 ms; with the
2-cycle latency at 250 Hz the largest discrete pole is |z| = 0.74 (`orientation_loop_radius`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from workbench.errors import InputError
from workbench.polishing.orientation import (
    instability_message,
    rotate3,
    rotation_vector3,
    rotation_vectors,
)

F64 = NDArray[np.float64]
MAX_STEPS = 500_000
"""Most control steps of one simulation ((dwell + path length / feed) x control rate),
refused before it starts, with the estimate."""


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
    orientation_loop: bool = True  # close eq. 7's loop; off: tool z held along the planned normal
    kop: float = 40.0  # [1/s] orientation loop P gain
    kod: float = 0.05  # [-] orientation loop D gain (on the error rate)
    koi: float = 0.0  # [1/s²] orientation loop I gain
    max_angular_speed: float = math.pi / 2  # [rad/s] limit on the commanded angular velocity


@dataclass(frozen=True)
class ForceControlResult:
    """Simulation record, one row per control cycle. t (K,) [s]; force (K,) true contact force
    [N]; force_measured (K,) filtered sensor force [N]; tracking_error (K,) tangential
    distance of the tool tip from the reference [m]; orientation_error (K,) angle between the
    tool z and the actual surface normal (into the surface) [rad]; position (K, 3) tool tip
    [m]; tool_z (K, 3) unit tool axis; commanded_velocity (K, 3) [m/s]; commanded_rate
    (K, 3) angular velocity command [rad/s]; reference (K, 3) reference point on the path
    [m]; surface (K, 3) the point of the actual surface (form error included) under the
    reference, the contact's spring anchor [m]; surface_normal (K, 3) unit normal of the actual
    surface there."""

    t: F64
    force: F64
    force_measured: F64
    tracking_error: F64
    orientation_error: F64
    position: F64
    tool_z: F64
    commanded_velocity: F64
    commanded_rate: F64
    reference: F64
    surface: F64
    surface_normal: F64
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
    if params.orientation_loop:
        _check_orientation_gains(params)
    return p, n / nn[:, None]


def _check_orientation_gains(prm: HybridForceParams) -> None:
    for name, val in (("kop", prm.kop), ("kod", prm.kod), ("koi", prm.koi)):
        if not math.isfinite(val) or val < 0:
            raise InputError(f"params.{name} must be finite and >= 0, got {val!r}")
    if prm.kop == 0 and prm.koi == 0:
        raise InputError(
            "params.kop and params.koi are both 0: the orientation loop would not correct a "
            "tilt; give kop > 0 or koi > 0, or set orientation_loop=False"
        )
    if not prm.max_angular_speed > 0:  # inf: no limit
        raise InputError(
            f"params.max_angular_speed must be > 0 rad/s, got {prm.max_angular_speed!r}"
        )
    msg = instability_message(
        prm.kop,
        prm.kod,
        prm.koi,
        prm.control_rate,
        prm.latency,
        names=("params.kop", "params.kod", "params.koi"),
    )
    if msg is not None:
        raise InputError(msg)


def _actual_normals(p: F64, s_path: F64, s_ref: F64, nrm: F64, slope: F64) -> F64:
    """Return the unit normals (K, 3) of the actual surface, the nominal one plus a form error
    h(s) along the normal: tilted by -h'(s) along the path's unit tangent."""
    d = np.diff(p, axis=0)
    dl = np.linalg.norm(d, axis=1, keepdims=True)
    d = d / np.where(dl > 0, dl, 1.0)
    tang = np.vstack([d[:1], d[:-1] + d[1:], d[-1:]])  # mean direction of the adjacent segments
    tan_k = np.stack([np.interp(s_ref, s_path, tang[:, i]) for i in range(3)], axis=1)
    tan_k -= np.sum(tan_k * nrm, axis=1, keepdims=True) * nrm
    tl = np.linalg.norm(tan_k, axis=1, keepdims=True)
    tan_k /= np.where(tl > 0, tl, 1.0)
    out = nrm - slope[:, None] * tan_k
    return out / np.linalg.norm(out, axis=1, keepdims=True)


def simulate_hybrid_force_control(
    points: ArrayLike,
    normals: ArrayLike,
    target_force: float,
    feed_speed: float,
    *,
    params: HybridForceParams | None = None,
    dwell: float = 0.0,
    tool_z0: ArrayLike | None = None,
) -> ForceControlResult:
    """Return the `ForceControlResult` of running the path under hybrid force/position control.

    points (N, 3) [m] on the nominal surface, normals (N, 3) pointing to the tool side;
    target_force [N] (> 0, <= params.max_force); feed_speed [m/s] along the path; dwell [s]
    at the first point before the feed starts; tool_z0 (3,) the tool axis at the start
    (unit after normalising; default -normals[0], along the planned normal). The tool starts
    touching the surface (zero force) at points[0]. Raises `InputError` for bad shapes or
    values, and for orientation gains that make the loop unstable at the rate and latency.
    """
    prm = params or HybridForceParams()
    p, n = _check(points, normals, target_force, feed_speed, prm)
    z_start = -n[0] if tool_z0 is None else _start_axis(tool_z0)
    dt = 1.0 / prm.control_rate
    s_path, t = _time_grid(p, feed_speed, dwell, dt, prm)
    sig = _path_signals(p, n, s_path, t, feed_speed, dwell, float(target_force), prm)
    run = _ControlLoop(prm, dt, float(target_force), len(t))
    run.simulate(sig, p[0].tolist(), z_start.tolist())
    return ForceControlResult(
        t=t,
        force=np.asarray(run.force),
        force_measured=np.asarray(run.fmeas),
        tracking_error=np.asarray(run.err),
        orientation_error=np.asarray(run.oerr),
        position=np.asarray(run.pos),
        tool_z=np.asarray(run.zs),
        commanded_velocity=np.asarray(run.vcmd),
        commanded_rate=np.asarray(run.wcmd),
        reference=sig.ref,
        surface=sig.surf,
        surface_normal=sig.n_act,
        target_force=float(target_force),
        params=prm,
    )


def _start_axis(tool_z0: ArrayLike) -> F64:
    """Return the unit tool axis (3,) at the start; InputError unless a finite non-zero 3-vector."""
    z_start = np.asarray(tool_z0, dtype=float).reshape(-1)
    zn = float(np.linalg.norm(z_start)) if z_start.shape == (3,) else 0.0
    if not (math.isfinite(zn) and zn > 1e-9):
        raise InputError(f"tool_z0 must be a finite non-zero 3-vector, got {tool_z0!r}")
    return z_start / zn


def _time_grid(
    p: F64, feed_speed: float, dwell: float, dt: float, prm: HybridForceParams
) -> tuple[F64, F64]:
    """Return the arc length at each point (N,) [m] and the control cycles' times (K,) [s];
    InputError when the cycles would be more than MAX_STEPS."""
    seg = np.linalg.norm(np.diff(p, axis=0), axis=1)
    s_path = np.concatenate([[0.0], np.cumsum(seg)])
    total = dwell + s_path[-1] / feed_speed
    k_steps = int(math.ceil(total / dt)) + 1
    if k_steps > MAX_STEPS:
        raise InputError(
            f"the simulation would take {k_steps:,} control steps ({total:.4g} s of dwell and "
            f"feed at {prm.control_rate:g} Hz), above the budget of {MAX_STEPS:,} "
            "(workbench.polishing.force_control.MAX_STEPS); raise the feed, shorten the dwell "
            "or lower the control rate"
        )
    t: F64 = np.arange(k_steps, dtype=np.float64) * dt
    return s_path, t


@dataclass(frozen=True)
class _PathSignals:
    """What the path gives each control cycle (K rows): the reference point, planned normal
    and velocity, the normal's rotation rate, the actual surface and its normal, the pressed
    reference the position loop tracks, the sensor noise and the feed direction."""

    ref: F64
    nrm: F64
    vel_ref: F64
    w_ref: F64
    surf: F64
    n_act: F64
    ref_cmd: F64
    noise: F64
    feed_dir: F64


def _path_signals(
    p: F64,
    n: F64,
    s_path: F64,
    t: F64,
    feed_speed: float,
    dwell: float,
    fdes: float,
    prm: HybridForceParams,
) -> _PathSignals:
    """Return the `_PathSignals` of the reference moving along the path at `feed_speed`."""
    dt = 1.0 / prm.control_rate
    s_ref = np.clip(feed_speed * (t - dwell), 0.0, s_path[-1])
    ref = np.stack([np.interp(s_ref, s_path, p[:, i]) for i in range(3)], axis=1)
    nrm = np.stack([np.interp(s_ref, s_path, n[:, i]) for i in range(3)], axis=1)
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True)
    vel_ref = np.diff(ref, axis=0, append=ref[-1:]) / dt
    # Feed-forward rotation rate of the planned normal (eq. 7's omega_01 along the path).
    w_ref = rotation_vectors(nrm, np.vstack([nrm[1:], nrm[-1:]])) / dt
    form, slope = _form_error(s_ref, prm)
    noise = (
        np.random.default_rng(prm.seed + 1).normal(0.0, prm.noise_std, len(t))
        if prm.noise_std
        else 0 * t
    )
    feed_dir = np.where(np.linalg.norm(vel_ref, axis=1, keepdims=True) > 0, vel_ref, 0.0)
    fd_norm = np.linalg.norm(feed_dir, axis=1, keepdims=True)
    return _PathSignals(
        ref=ref,
        nrm=nrm,
        vel_ref=vel_ref,
        w_ref=w_ref,
        surf=ref + form[:, None] * nrm,
        n_act=_actual_normals(p, s_path, s_ref, nrm, slope) if prm.form_error else nrm,
        # The position loop's reference is the path pressed D = F_d/k into the surface (the
        # seed's offset trajectory): the tool's depth is then no position error seen through
        # a tilt.
        ref_cmd=ref - (fdes / prm.stiffness) * nrm,
        noise=noise,
        feed_dir=feed_dir / np.where(fd_norm > 0, fd_norm, 1.0),
    )


def _form_error(s_ref: F64, prm: HybridForceParams) -> tuple[F64, F64]:
    """Return the actual surface's form error h(s) (K,) [m] along the normal and its slope h'(s)
    (K,): a sine of random phase (the seed's generator), zero when params.form_error is 0."""
    phase = np.random.default_rng(prm.seed).uniform(0.0, 2 * np.pi)
    if not prm.form_error:
        zero = 0 * s_ref
        return zero, zero
    arg = 2 * np.pi * s_ref / prm.form_wavelength + phase
    form = prm.form_error * np.sin(arg)
    slope = prm.form_error * 2 * np.pi / prm.form_wavelength * np.cos(arg)
    return form, slope


Vec3 = tuple[float, float, float]


def _limited(c: Vec3, c_prev: Vec3, max_speed: float, a_max: float) -> Vec3:
    """Return the velocity command c [m/s] cut to `max_speed` and then to a change of at most
    `a_max` [m/s] from the previous command."""
    cx, cy, cz = c
    sp = math.sqrt(cx * cx + cy * cy + cz * cz)
    if sp > max_speed:
        cx, cy, cz = cx * max_speed / sp, cy * max_speed / sp, cz * max_speed / sp
    dx, dy, dz = cx - c_prev[0], cy - c_prev[1], cz - c_prev[2]
    dn = math.sqrt(dx * dx + dy * dy + dz * dz)
    if dn > a_max:
        cx, cy, cz = (
            c_prev[0] + dx * a_max / dn,
            c_prev[1] + dy * a_max / dn,
            c_prev[2] + dz * a_max / dn,
        )
    return (cx, cy, cz)


class _ControlLoop:
    """The control cycles in scalar math: contact, sensor, the position/force loops (eq. 5) and
    the orientation loop (eq. 7), with the commands delayed by the latency; one record per
    cycle in the lists `force`, `fmeas`, `err`, `oerr`, `pos`, `zs`, `vcmd`, `wcmd`."""

    def __init__(self, prm: HybridForceParams, dt: float, fdes: float, k_steps: int) -> None:
        self.prm, self.dt, self.fdes = prm, dt, fdes
        self.alpha = (
            1.0
            if not math.isfinite(prm.filter_cutoff)
            else 1.0 - math.exp(-2 * math.pi * prm.filter_cutoff * dt)
        )
        self.lag = int(round(prm.latency / dt))
        self.force = [0.0] * k_steps
        self.fmeas = [0.0] * k_steps
        self.err = [0.0] * k_steps
        self.oerr = [0.0] * k_steps
        zero = (0.0, 0.0, 0.0)
        self.pos = [zero] * k_steps
        self.zs = [zero] * k_steps
        self.vcmd = [zero] * k_steps
        self.wcmd = [zero] * k_steps
        # position and force loops' state
        self.integ = 0.0
        self.ep = zero
        self.c_prev = zero
        # orientation loop's state: the filtered normal (set by `simulate`), the last error
        # (None: no derivative kick on the first cycle) and its integral
        self.m = zero
        self.er_prev: Vec3 | None = None
        self.ri = zero
        # the path's signals as lists of rows (set by `simulate`)
        self.N: list[list[float]] = []
        self.NA: list[list[float]] = []
        self.R: list[list[float]] = []
        self.V: list[list[float]] = []
        self.WR: list[list[float]] = []

    def simulate(self, sig: _PathSignals, x_start: list[float], z_start: list[float]) -> None:
        """Run every cycle from the tool tip's base point `x_start` and axis `z_start`."""
        prm, dt, alpha = self.prm, self.dt, self.alpha
        k, c = prm.stiffness, prm.damping
        loop = prm.orientation_loop
        S, NZ, FD = (a.tolist() for a in (sig.surf, sig.noise, sig.feed_dir))
        self.N, self.NA = N, NA = sig.nrm.tolist(), sig.n_act.tolist()
        self.R, self.V, self.WR = (a.tolist() for a in (sig.ref_cmd, sig.vel_ref, sig.w_ref))
        x0, x1, x2 = x_start
        z0, z1, z2 = z_start  # tool axis, into the surface
        m0, m1, m2 = NA[0]
        self.m = (m0, m1, m2)  # the controller's (filtered) estimate of the surface normal
        queue = [(0.0, 0.0, 0.0)] * self.lag  # commands wait `lag` cycles before they move
        wqueue = [(0.0, 0.0, 0.0)] * self.lag
        ff = 0.0
        d_prev = 0.0
        for i in range(len(N)):
            nx, ny, nz = N[i]
            ax_, ay_, az_ = NA[i]
            sx, sy, sz = S[i]
            if not loop:
                z0, z1, z2 = -nx, -ny, -nz  # the tool axis held along the planned normal
            self.zs[i] = (z0, z1, z2)
            # Contact along the actual normal: penetration of the tool below the actual surface.
            d = ax_ * (sx - x0) + ay_ * (sy - x1) + az_ * (sz - x2)
            ddot = (d - d_prev) / dt if i else 0.0
            d_prev = d
            f = max(k * d + c * ddot, 0.0) if d > 0 else 0.0
            self.force[i] = f
            ff += alpha * (f + NZ[i] - ff)
            self.fmeas[i] = ff
            # Tool tip: deflected against the feed by friction through the lateral compliance.
            defl = prm.friction * f / prm.lateral_stiffness
            fx, fy, fz = FD[i]
            tip = (x0 - defl * fx, x1 - defl * fy, x2 - defl * fz)
            self.pos[i] = tip
            self.oerr[i] = math.atan2(
                math.sqrt(
                    (z1 * az_ - z2 * ay_) ** 2
                    + (z2 * ax_ - z0 * az_) ** 2
                    + (z0 * ay_ - z1 * ax_) ** 2
                ),
                -(z0 * ax_ + z1 * ay_ + z2 * az_),
            )
            cx, cy, cz = self._velocity(i, tip, (z0, z1, z2), ff)
            queue.append((cx, cy, cz))
            qx, qy, qz = queue.pop(0)
            x0, x1, x2 = x0 + qx * dt, x1 + qy * dt, x2 + qz * dt
            if loop:
                wqueue.append(self._rate(i, (z0, z1, z2)))
                a0, a1, a2 = wqueue.pop(0)
                z0, z1, z2 = rotate3(z0, z1, z2, a0 * dt, a1 * dt, a2 * dt)

    def _velocity(self, i: int, tip: Vec3, z: Vec3, ff: float) -> Vec3:
        """Return cycle i's velocity command [m/s]: the position PD in the tool's xy plane and
        the force PI along the tool z (eq. 5), limited; records the tracking error."""
        prm, dt = self.prm, self.dt
        z0, z1, z2 = z
        nx, ny, nz = self.N[i]
        rx, ry, rz = self.R[i]
        tx, ty, tz = tip
        ex, ey, ez = rx - tx, ry - ty, rz - tz
        en = ex * nx + ey * ny + ez * nz
        gx, gy, gz = ex - en * nx, ey - en * ny, ez - en * nz  # tangential to the path
        self.err[i] = math.sqrt(gx * gx + gy * gy + gz * gz)
        # Position PD in the tool's xy plane (eq. 5, first row), with the tool z = (z0, z1, z2).
        ez_ = ex * z0 + ey * z1 + ez * z2
        ex, ey, ez = ex - ez_ * z0, ey - ez_ * z1, ez - ez_ * z2
        vx, vy, vz = self.V[i]
        ep = self.ep
        px = vx + prm.kpp * ex + prm.kpd * (ex - ep[0]) / dt
        py = vy + prm.kpp * ey + prm.kpd * (ey - ep[1]) / dt
        pz = vz + prm.kpp * ez + prm.kpd * (ez - ep[2]) / dt
        self.ep = (ex, ey, ez)
        pn = px * z0 + py * z1 + pz * z2
        px, py, pz = px - pn * z0, py - pn * z1, pz - pn * z2
        # Force PI along the tool z (eq. 5, second row).
        ef = self.fdes - ff
        self.integ += ef * dt
        vf = prm.kfp * ef + prm.kfi * self.integ
        if prm.normal_feedforward:
            vf += vx * z0 + vy * z1 + vz * z2
        c = (px + vf * z0, py + vf * z1, pz + vf * z2)
        self.c_prev = self.vcmd[i] = _limited(c, self.c_prev, prm.max_speed, prm.max_accel * dt)
        return self.c_prev

    def _rate(self, i: int, z: Vec3) -> Vec3:
        """Return cycle i's angular velocity command [rad/s]: the PID on the rotation vector
        from the tool z to the filtered measured normal (eq. 7), limited; records it."""
        prm, dt, alpha = self.prm, self.dt, self.alpha
        ax_, ay_, az_ = self.NA[i]
        m0, m1, m2 = self.m
        m0 += alpha * (ax_ - m0)
        m1 += alpha * (ay_ - m1)
        m2 += alpha * (az_ - m2)
        self.m = (m0, m1, m2)
        mn = math.sqrt(m0 * m0 + m1 * m1 + m2 * m2)
        r0, r1, r2, _ = rotation_vector3(*z, -m0 / mn, -m1 / mn, -m2 / mn)
        er_prev = (r0, r1, r2) if self.er_prev is None else self.er_prev
        ri0, ri1, ri2 = self.ri
        ri0, ri1, ri2 = ri0 + r0 * dt, ri1 + r1 * dt, ri2 + r2 * dt
        self.ri = (ri0, ri1, ri2)
        wx0, wy0, wz0 = self.WR[i]
        kop, kod, koi, w_max = prm.kop, prm.kod, prm.koi, prm.max_angular_speed
        w0 = wx0 + kop * r0 + kod * (r0 - er_prev[0]) / dt + koi * ri0
        w1 = wy0 + kop * r1 + kod * (r1 - er_prev[1]) / dt + koi * ri1
        w2 = wz0 + kop * r2 + kod * (r2 - er_prev[2]) / dt + koi * ri2
        self.er_prev = (r0, r1, r2)
        wn = math.sqrt(w0 * w0 + w1 * w1 + w2 * w2)
        if wn > w_max:
            w0, w1, w2 = w0 * w_max / wn, w1 * w_max / wn, w2 * w_max / wn
        self.wcmd[i] = (w0, w1, w2)
        return self.wcmd[i]
