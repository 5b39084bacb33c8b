# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""floodplane.distributed.segment_files on a LocalCluster of two worker processes: the
workers write what segment_file (and so pcd_segment) writes, the summaries come back in
input order, and a file that fails is reported while the others go on."""

import os

import numpy as np
import pytest

distributed = pytest.importorskip("distributed")

import floodplane  # noqa: E402
import floodplane.distributed  # noqa: E402
from conftest import two_plane_scene  # noqa: E402


@pytest.fixture(scope="module")
def client():
    # Two processes of one thread each, on the loopback interface; the dashboard on any free port.
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                       dashboard_address=":0", silence_logs=40)
    with distributed.Client(cluster) as client:
        yield client
    cluster.close()


def _frames(folder, count):
    """`count` PCD files of the two-plane scene, each shifted so their labels files differ."""
    paths = []
    for i in range(count):
        points = two_plane_scene(160, 120)
        points[..., 2] += 0.05 * i
        path = folder / f"frame_{i:02d}.pcd"
        floodplane.write_labels_pcd(str(path), points, np.zeros((120, 160), np.uint32))
        paths.append(path)
    return paths


def test_workers_write_what_segment_file_writes_in_input_order(tmp_path, client):
    inputs = _frames(tmp_path, 6)
    out = tmp_path / "out"
    results = floodplane.distributed.segment_files(client, [str(p) for p in reversed(inputs)], out, batch_size=1)
    assert [r["input"] for r in results] == [str(p) for p in reversed(inputs)]
    local = floodplane.Segmenter()
    for result in results:
        assert "error" not in result, result
        assert set(result) == {"input", "output", "planes", "ms"}
        assert result["planes"] == 2 and result["ms"] > 0
        output = os.path.join(str(out), os.path.basename(result["input"])[:-4] + ".labels.pcd")
        assert result["output"] == output
        reference = tmp_path / "reference.pcd"
        local.segment_file(result["input"], str(reference))
        with open(output, "rb") as written:
            assert written.read() == reference.read_bytes(), result["input"]
    # Both workers took part.
    assert len(client.scheduler_info()["workers"]) == 2


def test_a_failed_file_is_reported_and_the_others_go_on(tmp_path, client):
    good = _frames(tmp_path, 3)
    broken = tmp_path / "broken.pcd"
    broken.write_bytes(b"VERSION 0.7\nFIELDS x y z\nDATA binary\n\x00\x01")
    missing = tmp_path / "missing.pcd"
    twin_folder = tmp_path / "twin"
    twin_folder.mkdir()
    twin = _frames(twin_folder, 1)[0]  # frame_00.pcd again: the same output name
    paths = [good[0], broken, good[1], missing, good[2], twin]
    results = floodplane.distributed.segment_files(client, paths, tmp_path / "out")
    assert [r["input"] for r in results] == [str(p) for p in paths]
    assert [("error" in r) for r in results] == [False, True, False, True, False, True]
    assert "OSError" in results[1]["error"] and "broken.pcd" in results[1]["error"]
    assert "FileNotFoundError" in results[3]["error"]
    assert "same name" in results[5]["error"]
    for result in results:
        if "error" not in result:
            assert os.path.exists(result["output"]) and result["planes"] == 2
    assert sorted(os.listdir(tmp_path / "out")) == ["frame_00.labels.pcd", "frame_01.labels.pcd",
                                                    "frame_02.labels.pcd"]


def test_depth_pngs_with_intrinsics_and_parameters(tmp_path, client):
    depth = np.round(two_plane_scene()[..., 2] * 1000)
    depth[np.isnan(depth)] = 0
    paths = []
    for i in range(3):
        path = tmp_path / f"depth_{i}.png"
        floodplane.write_depth_png(str(path), depth.astype(np.uint16) + 10 * i)
        paths.append(path)
    intrinsics = (131.25, 131.25, 79.5, 59.5)
    results = floodplane.distributed.segment_files(client, paths, tmp_path / "out", intrinsics=intrinsics,
                                                   subsampling=2)
    for path, result in zip(paths, results):
        assert "error" not in result, result
        assert result["output"].endswith(path.stem + ".labels.pcd")
        expected = floodplane.segment_depth(floodplane.read_depth_png(str(path)), *intrinsics, subsampling=2)
        np.testing.assert_array_equal(floodplane.read_labels_pcd(result["output"]), expected.labels)
    # Without intrinsics a depth image is an error of its own.
    unsent = floodplane.distributed.segment_files(client, paths[:1], tmp_path / "out2")
    assert "intrinsics" in unsent[0]["error"]


def test_bad_parameters_are_refused_before_any_work(tmp_path, client):
    paths = _frames(tmp_path, 1)
    with pytest.raises(ValueError, match="subsampling"):
        floodplane.distributed.segment_files(client, paths, tmp_path / "out", subsampling=3)
    with pytest.raises(TypeError, match="unexpected keyword argument 'treshold'"):
        floodplane.distributed.segment_files(client, paths, tmp_path / "out", treshold=0.01)
    with pytest.raises(ValueError, match="intrinsics"):
        floodplane.distributed.segment_files(client, paths, tmp_path / "out", intrinsics=(1.0, 2.0))
    for batch_size in (0, -1, 2.5, True, "4"):
        with pytest.raises(ValueError, match="batch_size must be an integer >= 1"):
            floodplane.distributed.segment_files(client, paths, tmp_path / "out", batch_size=batch_size)
    assert not (tmp_path / "out").exists()


def test_batches_of_any_size_give_the_same_outputs(tmp_path, client):
    inputs = _frames(tmp_path, 5)
    outputs = {}
    for batch_size in (1, 2, 5, 100):
        results = floodplane.distributed.segment_files(client, inputs, tmp_path / f"out_{batch_size}",
                                                       batch_size=batch_size)
        assert [r["input"] for r in results] == [str(p) for p in inputs]
        outputs[batch_size] = [open(r["output"], "rb").read() for r in results]
    assert outputs[1] == outputs[2] == outputs[5] == outputs[100]


def _divide_by_zero():
    return 1 / 0


def test_a_batch_lost_as_a_whole_gives_each_of_its_files_the_error(client):
    good = client.submit(lambda: [{"planes": 1}], pure=False)
    lost = client.submit(_divide_by_zero, pure=False)
    gathered = floodplane.distributed._gather(client, [good, lost], [["a"], ["b", "c"]])
    assert gathered[0] == [{"planes": 1}]
    assert len(gathered[1]) == 2
    assert all(summary["error"].startswith("ZeroDivisionError") for summary in gathered[1])


def test_an_empty_list_gives_an_empty_list(tmp_path, client):
    assert floodplane.distributed.segment_files(client, [], tmp_path / "out") == []


def test_output_path_is_pcd_segments_name():
    assert floodplane.distributed.output_path("/a/b/scan.pcd", "/o") == "/o/scan.labels.pcd"
    assert floodplane.distributed.output_path("1305031102.160407.png", "o") == "o/1305031102.160407.labels.pcd"
    assert floodplane.distributed.output_path("notes.txt", "o") == "o/notes.txt.labels.pcd"


def _plane_count_and_labels_sum(segmenter, result):
    return len(segmenter.segment(two_plane_scene()).planes), int(result.labels.sum())


def test_results_and_segmenters_travel_between_client_and_workers(client):
    points = two_plane_scene()
    local = floodplane.segment(points)
    # A result made on a worker comes back whole (pickled by the worker, unpickled here).
    remote = client.submit(floodplane.segment, points, pure=False).result()
    assert type(remote) is floodplane.Segmentation
    np.testing.assert_array_equal(remote.labels, local.labels)
    assert [(p.label, p.inliers, p.d) for p in remote.planes] == [(p.label, p.inliers, p.d) for p in local.planes]
    for a, b in zip(remote.planes, local.planes):
        np.testing.assert_array_equal(a.normal, b.normal)
    assert remote.noise.patches == local.noise.patches
    # A Segmenter and a result sent to a worker arrive intact.
    planes, labels_sum = client.submit(_plane_count_and_labels_sum, floodplane.Segmenter(min_inliers=10**6), local,
                                       pure=False).result()
    assert planes == 0 and labels_sum == int(local.labels.sum())
    # Many frames at once, as users map over their own arrays.
    frames = [two_plane_scene() + np.float32(0.01 * i) for i in range(4)]
    results = client.gather(client.map(floodplane.segment, frames, pure=False))
    assert [len(r.planes) for r in results] == [2, 2, 2, 2]


def test_depth_pngs_with_a_camera_matrix(tmp_path, client):
    depth = np.nan_to_num(np.round(two_plane_scene()[..., 2] * 1000)).astype(np.uint16)
    path = tmp_path / "depth.png"
    floodplane.write_depth_png(str(path), depth)
    K = [[131.25, 0, 79.5], [0, 131.25, 59.5], [0, 0, 1]]
    result, = floodplane.distributed.segment_files(client, [path], tmp_path / "out", intrinsics=np.array(K))
    assert "error" not in result, result
    np.testing.assert_array_equal(floodplane.read_labels_pcd(result["output"]),
                                  floodplane.segment_depth(depth, K).labels)
    skewed = [[1, 1, 0], [0, 1, 0], [0, 0, 1]]
    with pytest.raises(ValueError, match="segment_files: intrinsics must be a pinhole camera matrix"):
        floodplane.distributed.segment_files(client, [path], tmp_path / "out", intrinsics=skewed)
