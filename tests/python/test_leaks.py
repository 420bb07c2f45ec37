"""A thousand calls of every function leave the process's memory where it was."""

import gc
import json

import numpy as np

import dropscope
from conftest import DETECTOR_SCENE


def resident_bytes():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * 4096


def calls(scene, origins, directions):
    dropscope.scene_from_dict(DETECTOR_SCENE).inspect()
    dropscope.query(scene, origins, directions)
    result = dropscope.trace(scene, 20, threads=1, paths=2, orders=True)
    result.summary, result.angular, result.detectors, result.paths
    dropscope.mie(index=1.33, x=5, bins=18).angular
    try:
        dropscope.scene_from_dict(json.loads('{"dropscope": 1, "shapes": [{"type": "cube"}]}'))
    except dropscope.SceneError:
        pass


def test_a_thousand_calls_do_not_leak():
    scene = dropscope.scene_from_dict(DETECTOR_SCENE)
    rng = np.random.default_rng(1)
    origins, directions = rng.normal(size=(100, 3)), rng.normal(size=(100, 3))
    for _ in range(200):  # allocators and caches settle
        calls(scene, origins, directions)
    gc.collect()
    before = resident_bytes()
    for _ in range(1000):
        calls(scene, origins, directions)
    gc.collect()
    grown = resident_bytes() - before
    # One call allocates about 2 MB (a trace's tallies, the detector images) and frees it; a leak of even 2 KB
    # a call would add 2 MB.
    assert grown < 2_000_000, f"resident memory grew by {grown} bytes over 1000 calls"


def test_a_thousand_snapshots_do_not_leak():
    # Each builds and frees an OSMesa context and its buffers (about 25 ms at 16 x 16).
    scene = dropscope.scene_from_dict(DETECTOR_SCENE)
    for _ in range(50):
        dropscope.snapshot(scene, 16, 16)
    gc.collect()
    before = resident_bytes()
    for _ in range(1000):
        dropscope.snapshot(scene, 16, 16)
    gc.collect()
    grown = resident_bytes() - before
    assert grown < 2_000_000, f"resident memory grew by {grown} bytes over 1000 snapshots"
