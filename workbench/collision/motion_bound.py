"""How far a point fixed on a robot link can move for a given joint step (seed 001, step 5).

Joint j turns frame j (and everything after it) about a line that is fixed both in frame
j-1 and in frame j. Take a point p_j on that line. A point x on the body of frame k (k >= j)
moves, when only joint j turns by dq, along an arc of radius dist(x, axis_j) <= |x - p_j|,
and |x - p_j| <= |x - p_k| + sum_{i=j}^{k-1} |p_{i+1} - p_i|, where every term is constant:
p_{i+1} and p_i are both fixed in frame i. So along any joint path the point travels at
most ``sum_j |dq_j| * lever[j]`` with ``lever[j]`` that configuration-independent bound.
Revolute joints only (a prismatic joint is refused).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.geometry.transforms import invert_transform
from workbench.kinematics.model import RobotModel

FloatArray = NDArray[np.float64]


class JointLevers:
    """Axis points of a serial robot's joints and the lever bounds they give."""

    def __init__(self, robot: RobotModel) -> None:
        n = robot.dof
        lim = np.asarray(robot.limits, float)
        q0 = np.clip(np.zeros(n), lim[:, 0], lim[:, 1])
        T0 = robot.link_transforms(q0)
        # Axis point of joint j (1..n) in frame j-1 and in frame j coordinates.
        self.in_prev = np.zeros((n + 1, 3))
        self.in_own = np.zeros((n + 1, 3))
        for j in range(1, n + 1):
            step = 0.5 if q0[j - 1] + 0.5 <= lim[j - 1, 1] else -0.5
            q1 = q0.copy()
            q1[j - 1] += step
            T1 = robot.link_transforms(q1)
            A0 = invert_transform(T0[j - 1]) @ T0[j]
            A1 = invert_transform(T1[j - 1]) @ T1[j]
            G = A1 @ invert_transform(A0)  # the joint's motion, in frame j-1
            R, t = G[:3, :3], G[:3, 3]
            angle = np.arccos(np.clip((np.trace(R) - 1.0) / 2.0, -1.0, 1.0))
            if abs(angle - abs(step)) > 1e-6:
                raise InputError(
                    f"joint {j}: not a revolute joint (turned {angle:.6f} rad for a step of"
                    f" {abs(step)} rad); the motion bound needs revolute joints"
                )
            axis = np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
            axis /= np.linalg.norm(axis)
            p, *_ = np.linalg.lstsq(np.eye(3) - R, t, rcond=None)
            o = A0[:3, 3]  # frame j's origin: take the axis point nearest to it
            p = p + axis * float(np.dot(o - p, axis))
            self.in_prev[j] = p
            self.in_own[j] = (invert_transform(A0) @ np.append(p, 1.0))[:3]
        self.dof = n
        # hop[i] = |p_{i+1} - p_i| (both in frame i), i = 1..n-1.
        self.hop = np.zeros(n + 1)
        for i in range(1, n):
            self.hop[i] = float(np.linalg.norm(self.in_prev[i + 1] - self.in_own[i]))

    def levers(self, frame: int, points: FloatArray) -> FloatArray:
        """Return levers (dof,) [m/rad] bounding the motion of `points` (P,3) fixed in `frame`.

        Entry j bounds the distance of every point from joint j+1's axis over all
        configurations; 0 for joints after `frame` (they do not move it).
        """
        out = np.zeros(self.dof)
        if frame == 0 or len(points) == 0:
            return out
        reach = float(np.linalg.norm(np.asarray(points, float) - self.in_own[frame], axis=1).max())
        for j in range(frame, 0, -1):
            out[j - 1] = reach
            if j > 1:
                reach += self.hop[j - 1]
        return out
