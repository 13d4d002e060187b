"""TODO"""

from workbench.geometry.distance import capsule_rectangle_distance, segment_segment_distance  # noqa: F401
from workbench.geometry.lbvh import LBVH  # noqa: F401
from workbench.geometry.obb import OBB, obb_overlap  # noqa: F401
from workbench.geometry.sdf import SparseSDF  # noqa: F401
from workbench.geometry.spheres import SphereSet, fit_spheres  # noqa: F401
