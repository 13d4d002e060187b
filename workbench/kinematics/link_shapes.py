"""Robot link geometry generated from DH lengths: convex, watertight shapes like an industrial arm.

Link i (the body moved by joint i) is the convex hull of
- cylinders along its DH polyline: from the joint-i axis along z_(i-1) by d_i, then along x_i
  by a_i; the first piece starts where the previous link's housing ends (minus 10 % so that
  adjacent links overlap), so a short offset does not reach back into link i-2;
- a cylindrical housing around the joint-(i+1) axis at frame i's origin.
Link 0 is the base: a cylinder around the joint-1 axis. The last link ends in the flange
plate. Radii scale with the arm's length so a small arm gets thin links. Every mesh is
expressed in its DH frame i (``robot.link_transforms(q)[..., i, :, :]`` places it).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
import trimesh
from numpy.typing import NDArray

from workbench.geometry.transforms import invert_transform
from workbench.kinematics.dh_chain import dh_fixed_part

if TYPE_CHECKING:
    from workbench.kinematics.dh_robot import DHRobot
    from workbench.kinematics.model import RobotModel

FloatArray = NDArray[np.float64]
SECTIONS = 24
# Segment radius of links 1..6 as a fraction of the arm's length (later links get the last).
RADIUS_FRACTIONS = (0.075, 0.065, 0.055, 0.040, 0.035, 0.022)
HOUSING_RADIUS = 1.1  # housing radius / segment radius
HOUSING_HALF_LENGTH = 1.4  # housing half-length / housing radius
OVERLAP = 0.9  # a link starts at 90 % of the distance to leave the previous housing
FLANGE_THICKNESS = 0.01  # m, scaled with the arm


def arm_scale(dh: FloatArray) -> float:
    """Return the arm's length [m]: sum of hypot(a, d) over the rows, at least 0.2 m."""
    return max(float(np.hypot(dh[:, 1], dh[:, 2]).sum()), 0.2)


def link_radii(dh: FloatArray) -> FloatArray:
    """Return the segment radius [m] of links 1..n (n,)."""
    n = dh.shape[0]
    frac = [RADIUS_FRACTIONS[min(i, len(RADIUS_FRACTIONS) - 1)] for i in range(n)]
    return arm_scale(dh) * np.asarray(frac)


def _cylinder_points(p0: FloatArray, p1: FloatArray, radius: float) -> FloatArray:
    axis = p1 - p0
    length = float(np.linalg.norm(axis))
    u = axis / length
    helper = np.array([1.0, 0.0, 0.0]) if abs(u[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    e1 = np.cross(u, helper)
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(u, e1)
    ang = np.linspace(0.0, 2.0 * math.pi, SECTIONS, endpoint=False)
    ring = radius * (np.cos(ang)[:, None] * e1 + np.sin(ang)[:, None] * e2)
    return np.vstack([p0 + ring, p1 + ring])


def _exit_distance(u: FloatArray, radius: float, half_length: float) -> float:
    """Return the distance along unit u from a housing's centre to its surface (axis = z)."""
    axial, radial = abs(u[2]), math.hypot(u[0], u[1])
    t_ax = half_length / axial if axial > 1e-12 else math.inf
    t_rad = radius / radial if radial > 1e-12 else math.inf
    return min(t_ax, t_rad)


def _hull(points: FloatArray) -> trimesh.Trimesh:
    hull = trimesh.convex.convex_hull(points)
    hull.fix_normals()
    return hull


def _spherical_wrist(dh: FloatArray) -> bool:
    n = dh.shape[0]
    return n >= 6 and bool(np.all(np.abs([dh[n - 3, 2], dh[n - 2, 1], dh[n - 2, 2]]) < 1e-9))


def _wrist_fold_angle(dh: FloatArray, limits: FloatArray | None) -> float:
    """Return the smallest angle [rad] between the flange direction and the way back along the
    forearm, over the range of the second-to-last joint (the others at 0)."""
    n = dh.shape[0]
    lo, hi = (
        (-math.pi, math.pi)
        if limits is None
        else (float(limits[n - 2, 0]), float(limits[n - 2, 1]))
    )
    q = np.zeros((181, n))
    q[:, n - 2] = np.linspace(lo, hi, 181)
    B = dh_fixed_part(dh)
    angles = []
    for row in q:
        T = np.eye(4)
        origins = [T[:3, 3].copy()]
        for i in range(n):
            T = T @ _rz(row[i]) @ B[i]
            origins.append(T[:3, 3].copy())
        wrist, flange, back = origins[n - 1], origins[n], origins[n - 3]
        u, v = flange - wrist, back - wrist
        c = float(u @ v / (np.linalg.norm(u) * np.linalg.norm(v)))
        angles.append(math.acos(max(-1.0, min(1.0, c))))
    return min(angles)


def _rz(q: float) -> FloatArray:
    c, s_ = math.cos(q), math.sin(q)
    return np.array([[c, -s_, 0, 0], [s_, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1.0]])


def dh_link_meshes(dh: FloatArray, limits: FloatArray | None = None) -> list[trimesh.Trimesh]:
    """Return n+1 watertight meshes [m]: base in the base frame, link i in DH frame i.

    With a spherical wrist, the forearm's wrist housing is no wider than the forearm (a wider
    one would bulge the convex hull toward the flange), and the flange link starts far enough
    from the wrist centre to clear the forearm over the whole range of the wrist-bend joint
    (`limits`), as a real wrist does; it is at least a thin plate.
    """
    n = dh.shape[0]
    B = dh_fixed_part(dh)
    r = link_radii(dh)
    h = HOUSING_RADIUS * r
    scale = arm_scale(dh)
    wrist = _spherical_wrist(dh)
    if wrist:
        h[n - 3] = r[n - 3]
    ell = HOUSING_HALF_LENGTH * h
    flange_start = 0.0
    if wrist:
        theta = _wrist_fold_angle(dh, limits)
        r_fore, r_fl = float(r[n - 3]), float(r[n - 1])
        if theta < math.pi / 2 - 1e-9:
            need = (1.1 * r_fore + r_fl * math.cos(theta)) / max(math.sin(theta), 1e-6)
        else:
            need = 1.05 * r_fore
        flange_start = min(need, abs(dh[n - 1, 1]) - FLANGE_THICKNESS * scale)
    # The forearm (link n-2) starts outside the upper arm's elbow housing, as a real forearm
    # sits beside it: otherwise folding the elbow a little makes the two meet.
    fore_start = 0.0
    if wrist:
        e = n - 5  # the upper arm, which carries the elbow housing
        fore_start = math.sqrt(max((h[e] + r[n - 3]) ** 2 - dh[n - 4, 2] ** 2, 0.0))
    # Base: a cylinder up the joint-1 axis, half as tall as the shoulder height.
    base_h = max(0.5 * abs(dh[0, 1]), 0.1 * scale)
    base_sign = 1.0 if dh[0, 1] >= 0 else -1.0
    base_r = 1.3 * r[0]
    meshes = [_hull(_cylinder_points(np.zeros(3), np.array([0, 0, base_sign * base_h]), base_r))]
    prev_radius, prev_half = base_r, base_h  # the base reaches base_h up the joint-1 axis
    for i in range(n):
        off, d, a = dh[i, 0], dh[i, 1], dh[i, 2]
        # DH polyline in the joint-rotated frame (i-1)': P0 on the joint-i axis, P1, P2 = o_i.
        P0 = np.zeros(3)
        P1 = np.array([0.0, 0.0, d])
        P2 = P1 + a * np.array([math.cos(off), math.sin(off), 0.0])
        pts: list[FloatArray] = []
        pieces = [(P0, P1), (P1, P2)]
        first = True
        for p, q in pieces:
            length = float(np.linalg.norm(q - p))
            if length < 1e-9:
                continue
            if first:
                first = False
                u = (q - p) / length
                start = OVERLAP * _exit_distance(u, prev_radius, prev_half)
                if i == n - 1:
                    start = max(start, flange_start)
                if wrist and i == n - 3:
                    start = max(start, fore_start)
                if start >= length:
                    continue
                p = p + start * u
            pts.append(_cylinder_points(p, q, r[i]))
        # Housing of joint i+1 (or the flange plate on the last link), in frame i.
        if i < n - 1:
            lo_z, hi_z = -ell[i], ell[i]
            # Reach out along the next joint's axis to where the next link starts.
            reach = 0.0
            if wrist and i == n - 2:
                reach, d_next = 1.02 * flange_start, dh[n - 1, 1]
            elif wrist and i == n - 4:
                reach, d_next = 1.02 * fore_start, dh[n - 3, 1]
            if reach > 0.0:
                lo_z, hi_z = (min(lo_z, -reach), hi_z) if d_next < 0 else (lo_z, max(hi_z, reach))
            housing = _cylinder_points(np.array([0.0, 0.0, lo_z]), np.array([0.0, 0.0, hi_z]), h[i])
        else:
            t = FLANGE_THICKNESS * scale
            housing = _cylinder_points(np.array([0.0, 0.0, -t]), np.zeros(3), r[i])
        inv_B = invert_transform(B[i])
        local = [p @ inv_B[:3, :3].T + inv_B[:3, 3] for p in pts] + [housing]
        meshes.append(_hull(np.vstack(local)))
        prev_radius, prev_half = h[i], ell[i]
    return meshes


def link_meshes(robot: RobotModel) -> list[trimesh.Trimesh]:
    """Return the n+1 link meshes of a robot [m], each in the frame of ``link_transforms``.

    DH robots get generated shapes (`dh_link_meshes`); URDF robots their own geometry.
    """
    return robot.link_meshes()


def flange_mesh(robot: DHRobot, thickness: float | None = None) -> trimesh.Trimesh:
    """Return the flange plate [m] in the flange frame: a disk from z = -thickness to 0."""
    dh = robot.dh
    t = FLANGE_THICKNESS * arm_scale(dh) if thickness is None else float(thickness)
    radius = float(link_radii(dh)[-1])
    return _hull(_cylinder_points(np.array([0.0, 0.0, -t]), np.zeros(3), radius))
