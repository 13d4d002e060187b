"""The robot library: one current arm of each vendor the program posts serve, as data.

Each `LibraryRobot` holds the published kinematics (as standard DH rows), the controller's
joint convention, joint limits and speeds from the vendor's data, the vendor and its native
program format. `library_robot(name)` returns one; `preset_robot(name)` builds its model.
Every robot is data: no code tests a robot's name (tests/kinematics/test_robot_data.py).

The OPW arms (ABB, KUKA, FANUC) are given by the seven OPW parameters of ROS-Industrial's
support packages (a1, a2, b, c1, c2, c3, c4, joint offsets and sign corrections, the form of
ros-industrial/opw_kinematics) and turned into DH rows by `opw_dh`: the model's joint values
are the ROS joint values times the sign corrections (the offsets are folded into the DH theta
column), so the convention is q_ctrl = sign * q_model, plus FANUC's J2/J3 coupling. ROS-
Industrial's joint values are the controllers' for ABB and KUKA (their drivers pass them
through in radians) and for FANUC except J3: the FANUC controller shows J3 as the forearm's
angle to the horizontal, ROS the angle between forearm and upper arm, ros_j3 = ctrl_j3 +
ctrl_j2 (the fanuc driver's J23 correction).

Sources (lengths in mm, angles in deg, speeds in deg/s). Each robot's kinematic chain is
checked against the description named first, stored as a plain URDF under
tests/data/robot_descriptions/ (repository, path and commit in its header), by
tests/kinematics/test_robot_descriptions.py: flange pose equal within 0.1 mm and 0.01 deg at
50 random joints within limits, in the controller's base frame.

- ABB IRB 1200-7/0.7: a1 0, a2 -42, b 0, c1 399.1, c2 350, c3 351, c4 82; offsets (0, 0,
  -90, 0, 0, 0); signs all +1: ros-industrial/abb, abb_irb1200_support/urdf/
  irb1200_7_70_macro.xacro (commit 30e6c442cd14), joint_1..joint_6 origins (0.3991 / 0 /
  0.350 / 0.042 / 0.351 / 0.082 m) and the link_6-tool0 joint (tool0 = ABB tool0).
  Limits: axis 1 +-170, 2 -100..+135, 3 -200..+70, 4 +-270, 5 +-130 deg: the same xacro's
  <limit> (2.967, -1.745..2.356, -3.491..1.222, 4.712, 2.269 rad); axis 6 +-400 deg: ABB
  product specification IRB 1200 (3HAC046982-001), "Robot motion" (the xacro stops at
  +-360). Speeds 288, 240, 297, 400, 405, 600 deg/s: the same product specification,
  "Robot motion", IRB 1200-7/0.7 (the xacro's velocity limits 5.027, 4.189, 5.236, 6.981,
  7.069, 10.472 rad/s are 288, 240, 300, 400, 405, 600: axis 3 rounded up). Payload 7 kg,
  reach 703 mm: the model name (IRB 1200-7/0.7) and the same specification.
- KUKA KR 6 R900-2 (KR AGILUS): a1 25, a2 -25, b 0, c1 400, c2 455, c3 420, c4 90; offsets
  (0, -90, 0, 0, 0, 0); signs (-1, 1, 1, -1, 1, -1): ros-industrial/kuka_experimental,
  kuka_kr6_support/config/opw_parameters_kr6r900_2.yaml and urdf/kr6r900_2_macro.xacro
  (commit b4b53f4fb7f4), joint_a1..joint_a6 origins and flange-tool0 (tool0 = $FLANGE).
  Limits A1 +-170, A2 -190..+45, A3 -120..+156, A4 +-185, A5 +-120, A6 +-350 deg and speeds
  360, 300, 360, 450, 450, 540 deg/s: the same xacro's <limit> lower/upper/velocity
  (radians(...) of those degrees), and KUKA's own ROS 2 description, kroshu/
  kuka_robot_descriptions, kuka_agilus_support/config/kr6_r900_2_joint_limits.yaml (commit
  0b788db8df49): max_velocity 6.2832, 5.236, 6.2832, 7.854, 7.854, 9.4248 rad/s. (Until
  issue 28 the library had A4-A6 381, 388, 615 deg/s: the older KR 6 R900 sixx's, the same
  repository's kr6_r900_sixx_joint_limits.yaml.) KUKA's specification "Spez KR AGILUS-2"
  itself could not be read here (only its title page is reachable), so its page is not
  cited. Payload 6 kg, reach 901 mm: KUKA's data sheet of the KR 6 R900-2.
- FANUC M-10iA: a1 150, a2 -200, b 0, c1 450, c2 600, c3 640, c4 100; offsets (0, 0, -90,
  0, 0, 180); signs (1, 1, -1, -1, -1, -1): ros-industrial/fanuc, fanuc_m10ia_support/
  config/opw_parameters_m10ia.yaml and urdf/m10ia_macro.xacro (commit e9bafced8e1f):
  joint_1..joint_6 origins, base_link-base (FANUC world frame 450 mm up) and link_6-tool0.
  Limits J1 +-180, J2 -90..+160, J3 -180..+264, J4 +-190, J5 +-190, J6 +-360 deg and speeds
  210, 190, 210, 400, 400, 600 deg/s: the same xacro's <limit> (3.14, -1.57..2.79,
  -3.14..4.61, 3.31, 3.31, 6.28 rad; 3.67, 3.32, 3.67, 6.98, 6.98, 10.47 rad/s), J3 taken
  as the controller's (coupled) value; payload 10 kg, reach 1420 mm: FANUC's M-10iA data
  sheet. CHECK J3's range against the robot's manual: the xacro gives the range, not which
  zero it counts from.
- Universal Robots UR5e: d1 162.5, a2 -425, a3 -392.2, d4 133.3, d5 99.7, d6 99.6, alpha
  (90, 0, 0, 90, -90, 0): UniversalRobots/Universal_Robots_ROS2_Description,
  config/ur5e/default_kinematics.yaml (commit 2221ec0f720f), and UR's "DH parameters for
  calculations of kinematics and dynamics" (universal-robots.com). Controller joints are the
  DH angles (no offsets, no sign changes). Limits +-360 deg and speeds 180 deg/s every joint:
  the same repository's config/ur5e/joint_limits.yaml (its sources: UR5e User Manual,
  version 5.8; it cuts the elbow to +-180 for planning only); payload 5 kg, reach 850 mm:
  UR5e technical specifications.
- NACHI MZ07: `presets.py` (a real MZ07F's teach-pendant data and the chain fitted to it,
  with each number's source there).

The model's base is the robot's foot (ROS-Industrial's base_link); programs state work
objects in the controller's base frame, `LibraryRobot.T_base_controller`: the same frame for
ABB (base frame), KUKA ($ROBROOT), UR (base) and NACHI, but FANUC's world frame lies on the J1
axis at the height of J2 (the URDF's base_link-base joint, 450 mm on the M-10iA); the service
moves work objects into it before a post writes them (`motion.programs.controller_base`).
The model's flange frame is each controller's own: ABB tool0, KUKA $FLANGE (the URDF's tool0
"corresponds to the $FLANGE coordinate system"), FANUC's faceplate (tool0, "all-zeros tool
frame"), UR's tool flange, so tool data are the controller's.

FANUC's coupled J3 (`JointConvention.coupling`): the controller's limits form a slanted
region of model values. The model's box (`DHRobot.limits`) is the smallest box holding it,
cut to +-180 deg on J3 (the forearm cannot fold through the upper arm), and the robot keeps
the controller's limits (`DHRobot.controller_limits`): its IK returns only solutions inside
them (`DHRobot.within_limits`). A joint-space move between two such solutions is checked
against the box only.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from workbench.errors import InputError
from workbench.kinematics import presets
from workbench.kinematics.dh_robot import DHRobot
from workbench.kinematics.joint_convention import JointConvention

FloatArray = NDArray[np.float64]
_DEG = math.pi / 180.0

#: Each vendor's native robot-program format (the name of its post).
VENDOR_FORMATS = {
    "abb": "rapid",
    "kuka": "krl",
    "fanuc": "ls",
    "ur": "urscript",
    "nachi": "nachi",
}


@dataclass(frozen=True, eq=False)
class LibraryRobot:
    """One robot of the library: kinematics, convention, limits and speeds, vendor data."""

    name: str  # the preset name of the project file, e.g. "irb1200_7_70"
    title: str  # the vendor's name of the robot, e.g. "ABB IRB 1200-7/0.7"
    vendor: str  # a key of VENDOR_FORMATS
    dh: FloatArray  # (6, 4) [rad, m, m, rad]
    controller_limits_deg: FloatArray  # (6, 2) [deg], the controller's values
    max_velocity_deg_s: FloatArray  # (6,) [deg/s]
    convention: JointConvention
    payload_kg: float
    reach_mm: float  # the data sheet's reach (to the wrist centre for OPW arms)
    home_deg: FloatArray  # (6,) the controller's home or zero posture [deg]
    source: str
    controller_base_m: tuple[float, float, float] = (0.0, 0.0, 0.0)
    # the controller's base (world) frame's origin in the model's base [m]; axes parallel
    model_limits_deg: FloatArray | None = None
    # (6, 2) the model's joint limits [deg] where the data state them (the MZ07's, mapped
    # from the controller's in whole degrees); None: derived from the controller's limits

    @property
    def T_base_controller(self) -> FloatArray:
        """Return the controller's base frame in the model's base (4, 4) [m] (FANUC: Tz(c1))."""
        T = np.eye(4)
        T[:3, 3] = self.controller_base_m
        return T

    @property
    def program_format(self) -> str:
        """Return the vendor's native robot-program format ("rapid", "krl", "ls", ...)."""
        return VENDOR_FORMATS[self.vendor]

    @property
    def model_limits(self) -> FloatArray:
        """Return the model's joint limits (6, 2) [rad] (see the module docstring for FANUC)."""
        if self.model_limits_deg is not None:
            return self.model_limits_deg * _DEG
        lim = self.convention.limits_to_model(self.controller_limits_deg * _DEG)
        if self.convention.coupling is not None:
            coupled = np.any(self.convention.coupling != 0.0, axis=1)
            lim[coupled] = np.clip(lim[coupled], -math.pi, math.pi)
        return lim

    def dh_robot(self) -> DHRobot:
        """Return the `DHRobot` of this robot (flange without tool)."""
        coupled = self.convention.coupling is not None
        return DHRobot(
            self.dh,
            self.model_limits,
            name=self.title,
            max_velocity=self.max_velocity_deg_s * _DEG,
            convention=self.convention,
            controller_limits=self.controller_limits_deg * _DEG if coupled else None,
        )


def opw_dh(
    a1: float,
    a2: float,
    b: float,
    c1: float,
    c2: float,
    c3: float,
    c4: float,
    offsets: tuple[float, ...] = (0.0,) * 6,
) -> FloatArray:
    """Return standard DH rows (6, 4) [rad, m, m, rad] of OPW parameters [m] and offsets [rad].

    The rows' joint values are the OPW joint values plus `offsets` (opw_kinematics:
    q_opw = sign * q_ros - offset, so the rows take sign * q_ros). At q_opw = 0 the arm
    stands straight up: upper arm c2 and forearm c3 vertical, wrist c4 above, elbow offset
    a2 along +x, flange frame = base frame orientation; joints 2, 3 and 5 turn about +y.
    """
    phi = (0.0, -math.pi / 2, math.pi / 2, 0.0, 0.0, 0.0)
    rows = [
        [c1, a1, -math.pi / 2],
        [b, c2, 0.0],
        [0.0, a2, math.pi / 2],
        [c3, 0.0, -math.pi / 2],
        [0.0, 0.0, math.pi / 2],
        [c4, 0.0, 0.0],
    ]
    return np.array([[phi[i] - offsets[i], *rows[i]] for i in range(6)])


def _convention(
    sign: tuple[float, ...], coupling: FloatArray | None = None, flip_sign: float = -1.0
) -> JointConvention:
    return JointConvention(
        offset=np.zeros(6), sign=np.array(sign, float), coupling=coupling, flip_sign=flip_sign
    )


_FANUC_COUPLING = np.zeros((6, 6))
_FANUC_COUPLING[2, 1] = -1.0  # ctrl J3 = ros J3 - ros J2 = s3 q3 - s2 q2, s2 = +1

_UR5E_DH = np.array(  # config/ur5e/default_kinematics.yaml (module docstring)
    [
        [0.0, 0.1625, 0.0, math.pi / 2],
        [0.0, 0.0, -0.425, 0.0],
        [0.0, 0.0, -0.3922, 0.0],
        [0.0, 0.1333, 0.0, math.pi / 2],
        [0.0, 0.0997, 0.0, -math.pi / 2],
        [0.0, 0.0996, 0.0, 0.0],
    ]
)

_ROBOTS = (
    LibraryRobot(
        name="irb1200_7_70",
        title="ABB IRB 1200-7/0.7",
        vendor="abb",
        # irb1200_7_70_macro.xacro joint origins (module docstring)
        dh=opw_dh(0.0, -0.042, 0.0, 0.3991, 0.350, 0.351, 0.082, (0, 0, -math.pi / 2, 0, 0, 0)),
        # xacro <limit>, axis 6 and the speeds: ABB product specification IRB 1200
        controller_limits_deg=np.array(
            [[-170, 170], [-100, 135], [-200, 70], [-270, 270], [-130, 130], [-400, 400]], float
        ),
        max_velocity_deg_s=np.array([288, 240, 297, 400, 405, 600], float),
        convention=_convention((1, 1, 1, 1, 1, 1)),
        payload_kg=7.0,
        reach_mm=703.0,
        home_deg=np.zeros(6),
        source="ros-industrial/abb abb_irb1200_support irb1200_7_70_macro.xacro;"
        " ABB product specification IRB 1200 (3HAC046982-001)",
    ),
    LibraryRobot(
        name="kr6_r900_2",
        title="KUKA KR 6 R900-2",
        vendor="kuka",
        # opw_parameters_kr6r900_2.yaml = kr6r900_2_macro.xacro joint origins
        dh=opw_dh(0.025, -0.025, 0.0, 0.400, 0.455, 0.420, 0.090, (0, -math.pi / 2, 0, 0, 0, 0)),
        # kr6r900_2_macro.xacro <limit lower upper>
        controller_limits_deg=np.array(
            [[-170, 170], [-190, 45], [-120, 156], [-185, 185], [-120, 120], [-350, 350]], float
        ),
        # xacro <limit velocity> and kroshu kr6_r900_2_joint_limits.yaml (module docstring)
        max_velocity_deg_s=np.array([360, 300, 360, 450, 450, 540], float),
        convention=_convention((-1, 1, 1, -1, 1, -1)),
        payload_kg=6.0,
        reach_mm=901.0,
        home_deg=np.array([0.0, -90.0, 90.0, 0.0, 0.0, 0.0]),
        source="ros-industrial/kuka_experimental kuka_kr6_support kr6r900_2_macro.xacro;"
        " kroshu/kuka_robot_descriptions kr6_r900_2_joint_limits.yaml",
    ),
    LibraryRobot(
        name="m10ia",
        title="FANUC M-10iA",
        vendor="fanuc",
        # opw_parameters_m10ia.yaml = m10ia_macro.xacro joint origins
        dh=opw_dh(
            0.150, -0.200, 0.0, 0.450, 0.600, 0.640, 0.100, (0, 0, -math.pi / 2, 0, 0, math.pi)
        ),
        # m10ia_macro.xacro <limit lower upper> and <limit velocity> (module docstring)
        controller_limits_deg=np.array(
            [[-180, 180], [-90, 160], [-180, 264], [-190, 190], [-190, 190], [-360, 360]], float
        ),
        max_velocity_deg_s=np.array([210, 190, 210, 400, 400, 600], float),
        convention=_convention((1, 1, -1, -1, -1, -1), _FANUC_COUPLING, flip_sign=1.0),
        payload_kg=10.0,
        reach_mm=1420.0,
        home_deg=np.zeros(6),
        source="ros-industrial/fanuc fanuc_m10ia_support m10ia_macro.xacro",
        controller_base_m=(0.0, 0.0, 0.450),  # URDF base_link-base: FANUC world coordinates
    ),
    LibraryRobot(
        name="ur5e",
        title="Universal Robots UR5e",
        vendor="ur",
        dh=_UR5E_DH,
        controller_limits_deg=np.tile([-360.0, 360.0], (6, 1)),
        max_velocity_deg_s=np.full(6, 180.0),
        convention=_convention((1, 1, 1, 1, 1, 1)),
        payload_kg=5.0,
        reach_mm=850.0,
        home_deg=np.zeros(6),
        source="Universal_Robots_ROS2_Description config/ur5e (default_kinematics.yaml,"
        " joint_limits.yaml); Universal Robots DH parameters",
    ),
    LibraryRobot(
        name="mz07",
        title="NACHI MZ07",
        vendor="nachi",
        dh=presets.MZ07_DH,
        controller_limits_deg=presets.MZ07_CONTROLLER_LIMITS_DEG,
        max_velocity_deg_s=presets.MZ07_MAX_VELOCITY_DEG_S,
        convention=presets.MZ07_CONVENTION,
        payload_kg=7.0,
        reach_mm=723.0,  # to the wrist centre: 50 + 330 + hypot(340, 45) of the table
        home_deg=presets.MZ07_CONTROLLER_UPRIGHT_DEG,
        source="a real MZ07F's teach-pendant data, gstorm-b/RobotKinematics nachi-mz07f.md;"
        " see presets.py",
        model_limits_deg=presets.MZ07_LIMITS_DEG,
    ),
)

#: The library's robots by preset name.
LIBRARY: dict[str, LibraryRobot] = {r.name: r for r in _ROBOTS}
#: The preset names, in the library's order (ABB, KUKA, FANUC, UR, NACHI).
ROBOT_NAMES: tuple[str, ...] = tuple(LIBRARY)


def library_robot(name: str) -> LibraryRobot:
    """Return the library robot called `name`; InputError listing the names when there is none."""
    if name not in LIBRARY:
        raise InputError(
            f"robot preset {name!r} is not in the robot library; presets: {', '.join(ROBOT_NAMES)}"
        )
    return LIBRARY[name]


def preset_robot(name: str) -> DHRobot:
    """Return the `DHRobot` of the library robot called `name` (flange without tool).

    Raises InputError listing the library's names when there is none of that name.
    """
    return library_robot(name).dh_robot()
