# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""floodplane.describe_planes: what each plane of a segmentation is (floor, wall, table top),
by the up direction; from a Segmentation or a list of its planes, with options as keywords,
and a clear exception for every bad argument."""

import math
import pickle

import numpy as np
import pytest

import floodplane

CAMERA_HEIGHT = 1.2  # m above the floor, looking level (y down)
TABLE_HEIGHT = 0.7
UP = (0.0, -1.0, 0.0)


def room(width=320, height=240):
    """A level pinhole view (f = 525 scaled to the width) of a floor, a wall 4 m ahead and a
    0.8 x 0.8 m table top 0.7 m above the floor, 1.6-2.4 m ahead."""
    focal = 525.0 * width / 640.0
    v, u = np.mgrid[0:height, 0:width].astype(np.float64)
    rx = (u - (width - 1) / 2.0) / focal
    ry = (v - (height - 1) / 2.0) / focal
    t = np.full((height, width), 4.0)  # the wall
    with np.errstate(divide="ignore"):
        floor = np.where(ry > 0, CAMERA_HEIGHT / ry, np.inf)
        table = np.where(ry > 0, (CAMERA_HEIGHT - TABLE_HEIGHT) / ry, np.inf)
    on_table = (table >= 1.6) & (table <= 2.4) & (np.abs(rx * table) <= 0.4)
    t = np.minimum(t, floor)
    t = np.where(on_table, np.minimum(t, table), t)
    return np.stack([t * rx, t * ry, t], axis=-1).astype(np.float32)


@pytest.fixture(scope="module")
def segmented():
    return floodplane.segment(room())


def by_class(result, descriptions):
    """{class: [(plane, description)]}."""
    out = {}
    for plane, description in zip(result.planes, descriptions):
        out.setdefault(description.plane_class, []).append((plane, description))
    return out


def test_tells_the_floor_the_wall_and_the_table(segmented):
    descriptions = floodplane.describe_planes(segmented, UP)
    assert len(descriptions) == len(segmented.planes) == 3
    classes = by_class(segmented, descriptions)
    assert sorted(classes) == ["floor", "horizontal_surface", "wall"]
    (floor, floor_description), = classes["floor"]
    (table, table_description), = classes["horizontal_surface"]
    (wall, wall_description), = classes["wall"]
    assert abs(floor.normal[1] + 1) < 1e-3 and abs(wall.normal[2] + 1) < 1e-3
    assert floor_description.height_above_floor == pytest.approx(0.0, abs=1e-3)
    assert table_description.height_above_floor == pytest.approx(TABLE_HEIGHT, abs=1e-3)
    # The wall's centroid: where its pixels are, above the floor, as the camera sees it.
    assert wall_description.height_above_floor == pytest.approx(CAMERA_HEIGHT - wall.centroid[1], abs=1e-3)


def test_takes_a_list_of_planes_any_up_length_and_array_likes(segmented):
    reference = floodplane.describe_planes(segmented, UP)
    assert floodplane.describe_planes(segmented.planes, UP) == reference
    assert floodplane.describe_planes(list(reversed(segmented.planes)), UP) == list(reversed(reference))
    assert floodplane.describe_planes(segmented, np.array([0, -9.81, 0], dtype=np.float32)) == reference
    assert floodplane.describe_planes(segmented, [0, -1, 0]) == reference
    assert floodplane.describe_planes([], UP) == []


def test_gravity_the_wrong_way_finds_no_floor(segmented):
    # Upside down, the floor and the table face down: no floor, heights are nan.
    descriptions = floodplane.describe_planes(segmented, (0.0, 1.0, 0.0))
    assert all(math.isnan(d.height_above_floor) for d in descriptions)
    assert "floor" not in {d.plane_class for d in descriptions}
    assert "wall" in {d.plane_class for d in descriptions}


def test_options_are_keywords(segmented):
    # A floor larger than any plane here: none is the floor.
    descriptions = floodplane.describe_planes(segmented, UP, min_floor_area_m2=1000.0)
    assert sorted(d.plane_class for d in descriptions) == ["horizontal_surface", "horizontal_surface", "wall"]
    assert all(math.isnan(d.height_above_floor) for d in descriptions)
    # Every keyword is taken.
    floodplane.describe_planes(segmented, UP, horizontal_tolerance_rad=0.2, vertical_tolerance_rad=0.2,
                               min_floor_area_m2=1, floor_height_tolerance_m=0.1, min_ceiling_area_m2=2,
                               min_ceiling_height_m=2)


def test_descriptions_print_and_pickle(segmented):
    descriptions = floodplane.describe_planes(segmented, UP)
    assert pickle.loads(pickle.dumps(descriptions)) == descriptions
    assert "plane_class='floor'" in " ".join(repr(d) for d in descriptions)
    no_floor = floodplane.describe_planes(segmented, (0, 1, 0))
    assert pickle.loads(pickle.dumps(no_floor)) == no_floor  # nan equals nan here
    assert "height_above_floor=nan" in repr(no_floor[0])


@pytest.mark.parametrize("up, error, words", [
    ((0, 0, 0), ValueError, "up direction"),
    ((0, math.nan, 1), ValueError, "up direction"),
    ((0, math.inf, 1), ValueError, "up direction"),
    ((0, 1), ValueError, "shape (3,)"),
    ([[0, 1, 0]], ValueError, "shape (3,)"),
    ("0,1,0", TypeError, "up must be"),
    (None, TypeError, "up must be"),
    ((True, False, False), TypeError, "dtype bool"),
])
def test_refuses_a_bad_up(segmented, up, error, words):
    with pytest.raises(error, match="describe_planes") as raised:
        floodplane.describe_planes(segmented, up)
    assert words in str(raised.value)


def test_refuses_bad_planes_and_options(segmented):
    with pytest.raises(TypeError, match="planes must be a floodplane.Segmentation"):
        floodplane.describe_planes(room(), UP)
    with pytest.raises(TypeError, match="planes must be"):
        floodplane.describe_planes("planes", UP)
    with pytest.raises(TypeError, match=r"planes\[1\] must be a floodplane.Plane"):
        floodplane.describe_planes([segmented.planes[0], 3], UP)
    with pytest.raises(ValueError, match="vertical_tolerance_rad"):
        floodplane.describe_planes(segmented, UP, vertical_tolerance_rad=1.0)
    with pytest.raises(ValueError, match="min_floor_area_m2"):
        floodplane.describe_planes(segmented, UP, min_floor_area_m2=-1.0)
    with pytest.raises(TypeError, match="floor_height_tolerance_m"):
        floodplane.describe_planes(segmented, UP, floor_height_tolerance_m="5 cm")
    with pytest.raises(TypeError, match="min_ceiling_height_m"):
        floodplane.describe_planes(segmented, UP, min_ceiling_height_m=True)
    with pytest.raises(TypeError):
        floodplane.describe_planes(segmented, UP, min_floor_area=1.0)
    with pytest.raises(TypeError):
        floodplane.describe_planes(segmented, UP, 0.1)  # the options are keywords only
