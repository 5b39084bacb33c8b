# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Segmenting many files on a dask.distributed cluster.

    from dask.distributed import Client
    import floodplane.distributed

    client = Client("tcp://scheduler:8786")      # or Client(LocalCluster(...))
    results = floodplane.distributed.segment_files(client, paths, "out/")

Each worker reads its files, segments them and writes <name>.labels.pcd itself (the same
bytes as pcd_segment), so only a small summary per file travels back. The workers must see
the input and output paths (a shared file system) and have floodplane installed. Each worker
thread keeps one Segmenter per parameter set, so its buffers are reused from file to file.
"""

import os
import threading

from . import Segmenter
from ._floodplane import _pinhole

__all__ = ["output_path", "segment_files"]


def _gather(client, futures, batches):
    """The summaries of every batch: all in one transfer, or batch by batch when some failed
    as a whole (a worker lost, a task cancelled), each of its files then with the error."""
    try:
        return client.gather(futures)
    except Exception:  # which batches failed is found out one by one
        pass
    gathered = []
    for future, batch in zip(futures, batches):
        try:
            gathered.append(future.result())
        except Exception as error:  # this batch's files failed
            gathered.append([{"error": f"{type(error).__name__}: {error}"} for _ in batch])
    return gathered

_thread_state = threading.local()


def output_path(input, out_dir):
    """Where segment_files writes the labels of `input`: out_dir/<name>.labels.pcd, <name>
    being the file name without its .pcd or .png extension (as pcd_segment names it)."""
    name = os.path.basename(input)
    stem, extension = os.path.splitext(name)
    if extension in (".pcd", ".png"):
        name = stem
    return os.path.join(out_dir, name + ".labels.pcd")


def _segmenter(params):
    """This thread's Segmenter for `params`, made on first use."""
    segmenters = getattr(_thread_state, "segmenters", None)
    if segmenters is None:
        segmenters = _thread_state.segmenters = {}
    key = tuple(sorted(params.items()))
    if key not in segmenters:
        segmenters[key] = Segmenter(**params)
    return segmenters[key]


def _segment_one(input, output, params, intrinsics, depth_scale):
    """Runs on a worker: one file in, one label file out, a summary back. A failure is
    reported in the summary, so one bad file does not stop the others."""
    try:
        os.makedirs(os.path.dirname(output) or ".", exist_ok=True)
        summary = _segmenter(params).segment_file(input, output, intrinsics=intrinsics, depth_scale=depth_scale)
    except Exception as error:  # every failure becomes the file's summary
        return {"input": input, "error": f"{type(error).__name__}: {error}"}
    return {"input": input, "output": output, "planes": summary["planes"], "ms": summary["ms"]}


def _segment_batch(inputs, outputs, params, intrinsics, depth_scale):
    """Runs on a worker: a few files, one summary each."""
    return [_segment_one(input, output, params, intrinsics, depth_scale) for input, output in zip(inputs, outputs)]


def segment_files(client, paths, out_dir, *, intrinsics=None, depth_scale=1000.0, batch_size=4, **params):
    """Segments every file of `paths` (PCD files, or 16-bit depth PNGs with intrinsics:
    (fx, fy, cx, cy), a 3 x 3 K or an Open3D PinholeCameraIntrinsic, whose image size is not
    checked here, and depth_scale units per metre) on the workers of `client`,
    a dask.distributed.Client, writing out_dir/<name>.labels.pcd for each. Each task takes
    `batch_size` files, which keeps the scheduler's share of the work small.

    Returns one dict per input, in the order of `paths`: {'input', 'output', 'planes', 'ms'}
    ('ms': the segmentation call on the worker), or {'input', 'error'} for a file that failed
    (missing, broken, an output that cannot be written, two inputs of one name, an output that
    is another input, a worker lost); the other files go on. Bad parameters raise TypeError or ValueError here, before
    any work is sent.
    """
    Segmenter(**params)  # checks the parameters in the caller's process
    if isinstance(batch_size, bool) or not isinstance(batch_size, int) or batch_size < 1:
        raise ValueError(f"segment_files: batch_size must be an integer >= 1, got {batch_size!r}")
    if intrinsics is not None:
        # Plain numbers travel to the workers (Open3D's intrinsics do not pickle).
        intrinsics = _pinhole(intrinsics, "segment_files")
    given = [os.fspath(path) for path in paths]
    # Absolute paths: the workers' working directory need not be the caller's.
    inputs = [os.path.abspath(path) for path in given]
    out_dir = os.path.abspath(os.fspath(out_dir))
    os.makedirs(out_dir, exist_ok=True)

    results = [None] * len(inputs)
    # The inputs by device and inode: an output that is one of them (a.labels.pcd given as an
    # input beside a.pcd) would destroy it, so that input is refused, as pcd_segment refuses.
    input_of_file = {}
    for position, input in enumerate(inputs):
        try:
            status = os.stat(input)
        except OSError:
            continue
        input_of_file.setdefault((status.st_dev, status.st_ino), given[position])
    first_of_output = {}
    tasks = []  # (position, absolute input, output)
    for position, input in enumerate(inputs):
        output = output_path(input, out_dir)
        if output in first_of_output:
            results[position] = {
                "input": given[position],
                "error": f"has the same name as {first_of_output[output]}, whose output it would overwrite",
            }
            continue
        first_of_output[output] = given[position]
        try:
            status = os.stat(output)
            overwritten = input_of_file.get((status.st_dev, status.st_ino))
        except OSError:
            overwritten = None
        if overwritten is not None:
            results[position] = {"input": given[position],
                                 "error": f"its output {output} would overwrite the input {overwritten}"}
            continue
        tasks.append((position, input, output))

    batches = [tasks[start:start + batch_size] for start in range(0, len(tasks), batch_size)]
    futures = client.map(
        _segment_batch,
        [[input for _, input, _ in batch] for batch in batches],
        [[output for _, _, output in batch] for batch in batches],
        params=params,
        intrinsics=intrinsics,
        depth_scale=float(depth_scale),
        pure=False,
    )
    for batch, summaries in zip(batches, _gather(client, futures, batches)):
        for (position, _, _), summary in zip(batch, summaries):
            summary["input"] = given[position]  # as the caller named it
            results[position] = summary
    return results
