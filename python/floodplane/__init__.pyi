# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# Type stubs of the floodplane package (the compiled _floodplane and __init__.py), so that
# editors complete the API and type checkers check calls. test/python/test_stubs.py keeps
# them in step with the module: every public name, member and argument name.

import os
from typing import Any, Dict, List, Literal, Optional, Protocol, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str
PARAMETER_NAMES: Tuple[str, ...]

_Path = Union[str, os.PathLike]
# Anything numpy.asarray makes an array of numbers of: arrays of any float or integer dtype,
# nested lists or tuples (float32 points are read in place, the rest converted).
_Points = npt.ArrayLike  # (H, W, 3) x y z in metres, NaN (and (0, 0, 0)) no return
_Depth = npt.ArrayLike  # (H, W) or (H, W, 1), integer units or float metres

class _PinholeIntrinsic(Protocol):
    """Open3D's PinholeCameraIntrinsic, or anything with its intrinsic_matrix."""

    @property
    def intrinsic_matrix(self) -> npt.ArrayLike: ...

# fx, fy, cx, cy as one sequence, a 3 x 3 K, or an Open3D PinholeCameraIntrinsic.
_Intrinsics = Union[Sequence[float], Sequence[Sequence[float]], npt.ArrayLike, _PinholeIntrinsic]

class NoiseModel:
    """The depth noise a segmentation assumed: sigma(r) = sigma_constant + sigma_quadratic r^2."""

    @property
    def sigma_constant(self) -> float: ...
    @property
    def sigma_quadratic(self) -> float: ...
    @property
    def step_constant(self) -> float: ...
    @property
    def step_quadratic(self) -> float: ...
    @property
    def patches(self) -> int: ...
    @property
    def estimated(self) -> bool: ...
    def sigma(self, range: float) -> float: ...
    def step(self, range: float) -> float: ...

class PhaseTimes:
    """Milliseconds per phase of one segmentation (with measure_phases=True)."""

    @property
    def preparation(self) -> float: ...
    @property
    def seed_selection(self) -> float: ...
    @property
    def flood_fill(self) -> float: ...
    @property
    def relabelling(self) -> float: ...
    @property
    def merging(self) -> float: ...
    @property
    def region_output(self) -> float: ...
    @property
    def pcl_conversion(self) -> float: ...
    @property
    def total(self) -> float: ...

class SegmentationStats:
    """What happened inside one segmentation."""

    @property
    def seed_candidates(self) -> int: ...
    @property
    def seeds(self) -> int: ...
    @property
    def pixels_taken_over(self) -> int: ...
    @property
    def segments(self) -> int: ...
    @property
    def merges(self) -> int: ...
    @property
    def head_start(self) -> bool: ...

class Plane:
    """One plane n . p + d = 0 in the camera frame (n unit, towards the camera)."""

    @property
    def label(self) -> int: ...
    @property
    def normal(self) -> npt.NDArray[np.float64]: ...
    @property
    def d(self) -> float: ...
    @property
    def centroid(self) -> npt.NDArray[np.float64]: ...
    @property
    def inliers(self) -> int: ...
    @property
    def covariance(self) -> npt.NDArray[np.float64]: ...
    @property
    def eigenvalues(self) -> npt.NDArray[np.float64]: ...
    @property
    def mean_squared_error(self) -> float: ...
    @property
    def curvature(self) -> float: ...
    @property
    def first_pixel(self) -> int: ...

class PlaneDescription:
    """What describe_planes says of one plane; pickles."""

    @property
    def plane_class(self) -> Literal["floor", "ceiling", "wall", "horizontal_surface", "other"]: ...
    @property
    def height_above_floor(self) -> float: ...

class Segmentation:
    """The planes found in one frame; pickles. A frame with no finite point (all NaN; all
    (0, 0, 0) with zero_is_hole; a depth image of zeros) or fewer than three has planes == []
    and labels all 0: a valid, empty result, never an error."""

    @property
    def labels(self) -> npt.NDArray[np.uint32]: ...
    @property
    def planes(self) -> List[Plane]: ...
    @property
    def width(self) -> int: ...
    @property
    def height(self) -> int: ...
    @property
    def noise(self) -> NoiseModel: ...
    @property
    def phases(self) -> PhaseTimes: ...
    @property
    def stats(self) -> SegmentationStats: ...
    @property
    def ms(self) -> float: ...
    def boundary(self, plane: int) -> npt.NDArray[np.int32]: ...

class Segmenter:
    """Plane segmentation by seeded flood fill; keep one for a sequence of frames."""

    def __init__(
        self,
        *,
        distance_threshold: Optional[float] = ...,
        seed_size: Optional[float] = ...,
        angular_threshold: float = ...,
        merge_distance: Optional[float] = ...,
        min_inliers: Optional[int] = ...,
        maximum_curvature: float = ...,
        subsampling: int = ...,
        depth_noise_coefficient: Optional[float] = ...,
        depth_noise_constant: Optional[float] = ...,
    ) -> None: ...
    @property
    def params(self) -> Dict[str, Any]: ...
    def segment(
        self,
        points: _Points,
        *,
        refine: bool = True,
        measure_phases: bool = False,
        head_start: bool = False,
        zero_is_hole: bool = True,
    ) -> Segmentation: ...
    def segment_file(
        self,
        input: _Path,
        output: _Path,
        *,
        intrinsics: Optional[_Intrinsics] = None,
        depth_scale: float = 1000.0,
    ) -> Dict[str, Any]: ...

class Track:
    """One surface followed over frames."""

    @property
    def id(self) -> int: ...
    @property
    def first_frame(self) -> int: ...
    @property
    def last_frame(self) -> int: ...
    @property
    def frames_seen(self) -> int: ...
    @property
    def plane(self) -> int: ...
    @property
    def inliers(self) -> int: ...
    @property
    def normal(self) -> npt.NDArray[np.float64]: ...
    @property
    def offset(self) -> float: ...
    @property
    def centroid(self) -> npt.NDArray[np.float64]: ...
    @property
    def smoothed_normal(self) -> npt.NDArray[np.float64]: ...
    @property
    def smoothed_offset(self) -> float: ...
    @property
    def best_inliers(self) -> int: ...
    @property
    def best_normal(self) -> npt.NDArray[np.float64]: ...
    @property
    def best_offset(self) -> float: ...
    @property
    def best_centroid(self) -> npt.NDArray[np.float64]: ...

class Tracker:
    """Ids for the planes of a stream of segmentations that persist over frames."""

    def __init__(
        self,
        *,
        max_normal_angle: float = ...,
        max_offset_difference: float = ...,
        max_lost_frames: int = ...,
        smoothing: float = ...,
        overlap_max_rotation: float = ...,
        overlap_max_translation: float = ...,
    ) -> None: ...
    @property
    def options(self) -> Dict[str, Any]: ...
    def update(self, result: Segmentation, motion: Optional[npt.ArrayLike] = None) -> List[int]: ...
    def relabel(self, labels: npt.ArrayLike) -> npt.NDArray[np.uint32]: ...
    @property
    def tracks(self) -> List[Track]: ...
    @property
    def track_ids(self) -> List[int]: ...
    def track(self, id: int) -> Optional[Track]: ...
    @property
    def frame_count(self) -> int: ...
    def reset(self) -> None: ...

def describe_planes(
    planes: Union[Segmentation, Sequence[Plane]],
    up: npt.ArrayLike,
    *,
    horizontal_tolerance_rad: float = ...,
    vertical_tolerance_rad: float = ...,
    min_floor_area_m2: float = ...,
    floor_height_tolerance_m: float = ...,
    min_ceiling_area_m2: float = ...,
    min_ceiling_height_m: float = ...,
) -> List[PlaneDescription]: ...
def segment(
    points: _Points,
    *,
    zero_is_hole: bool = True,
    distance_threshold: Optional[float] = ...,
    seed_size: Optional[float] = ...,
    angular_threshold: float = ...,
    merge_distance: Optional[float] = ...,
    min_inliers: Optional[int] = ...,
    maximum_curvature: float = ...,
    subsampling: int = ...,
    depth_noise_coefficient: Optional[float] = ...,
    depth_noise_constant: Optional[float] = ...,
) -> Segmentation: ...
@overload
def depth_to_points(
    depth: _Depth, intrinsics: float, fy: float, cx: float, cy: float, depth_scale: Optional[float] = None
) -> npt.NDArray[np.float32]: ...
@overload
def depth_to_points(
    depth: _Depth, intrinsics: _Intrinsics, *, depth_scale: Optional[float] = None
) -> npt.NDArray[np.float32]: ...
@overload
def segment_depth(
    depth: _Depth,
    intrinsics: float,
    fy: float,
    cx: float,
    cy: float,
    depth_scale: Optional[float] = None,
    *,
    distance_threshold: Optional[float] = ...,
    seed_size: Optional[float] = ...,
    angular_threshold: float = ...,
    merge_distance: Optional[float] = ...,
    min_inliers: Optional[int] = ...,
    maximum_curvature: float = ...,
    subsampling: int = ...,
    depth_noise_coefficient: Optional[float] = ...,
    depth_noise_constant: Optional[float] = ...,
) -> Segmentation: ...
@overload
def segment_depth(
    depth: _Depth,
    intrinsics: _Intrinsics,
    *,
    depth_scale: Optional[float] = None,
    distance_threshold: Optional[float] = ...,
    seed_size: Optional[float] = ...,
    angular_threshold: float = ...,
    merge_distance: Optional[float] = ...,
    min_inliers: Optional[int] = ...,
    maximum_curvature: float = ...,
    subsampling: int = ...,
    depth_noise_coefficient: Optional[float] = ...,
    depth_noise_constant: Optional[float] = ...,
) -> Segmentation: ...
def segment_file(
    input: _Path,
    output: _Path,
    *,
    intrinsics: Optional[_Intrinsics] = None,
    depth_scale: float = 1000.0,
    distance_threshold: Optional[float] = ...,
    seed_size: Optional[float] = ...,
    angular_threshold: float = ...,
    merge_distance: Optional[float] = ...,
    min_inliers: Optional[int] = ...,
    maximum_curvature: float = ...,
    subsampling: int = ...,
    depth_noise_coefficient: Optional[float] = ...,
    depth_noise_constant: Optional[float] = ...,
) -> Dict[str, Any]: ...
def label_colors(labels: npt.ArrayLike) -> npt.NDArray[np.uint8]: ...
@overload
def read_pcd(path: _Path, *, colors: Literal[False] = False) -> npt.NDArray[np.float32]: ...
@overload
def read_pcd(
    path: _Path, *, colors: Literal[True]
) -> Tuple[npt.NDArray[np.float32], Optional[npt.NDArray[np.uint8]]]: ...
def read_labels_pcd(path: _Path) -> npt.NDArray[np.uint32]: ...
def write_labels_pcd(path: _Path, points: _Points, labels: npt.ArrayLike, *, ascii: bool = False) -> None: ...
def read_depth_png(path: _Path) -> npt.NDArray[np.uint16]: ...
def write_depth_png(path: _Path, depth: npt.ArrayLike) -> None: ...
