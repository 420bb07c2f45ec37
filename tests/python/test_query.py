"""dropscope.query against `dropscope query` on the same rays: the same ids and distances, bit for bit."""

import csv
import json

import numpy as np
import pytest

import dropscope
from conftest import SOURCE_DIR, run_cli


def cloud_document(count=3000):
    document = json.loads((SOURCE_DIR / "assets/scenes/cloud.json").read_text())
    document["generators"][0]["count"] = count
    return document


@pytest.fixture(params=["cloud", "gallery"])
def scene_file(request, tmp_path):
    if request.param == "gallery":
        return SOURCE_DIR / "assets/scenes/shapes_gallery.json"
    path = tmp_path / "cloud.json"
    path.write_text(json.dumps(cloud_document()))
    return path


def rays(count, scene, seed=3):
    """Rays from around the scene towards random points of its bounds (every fifth in a random direction)."""
    bounds = scene.inspect()["totals"]["bounds"]
    lo, hi = np.array(bounds["min"]), np.array(bounds["max"])
    rng = np.random.default_rng(seed)
    origins = rng.uniform(lo - 0.5 * (hi - lo), hi + 0.5 * (hi - lo), size=(count, 3))
    directions = rng.uniform(lo, hi, size=(count, 3)) - origins  # not unit length: the CLI accepts that too
    directions[::5] = rng.normal(size=(len(directions[::5]), 3))
    return origins, directions


def cli_query(tmp_path, scene_file, origins, directions, *extra):
    rays_file = tmp_path / "rays.csv"
    with rays_file.open("w") as out:
        out.write("ox,oy,oz,dx,dy,dz\n")
        for o, d in zip(origins, directions):
            out.write(",".join(repr(float(v)) for v in (*o, *d)) + "\n")
    hits_file = tmp_path / "hits.csv"
    run_cli("query", scene_file, "--rays", rays_file, "--out", hits_file, *extra)
    with hits_file.open() as hits:
        rows = list(csv.DictReader(hits))
    return np.array([int(r["shape"]) for r in rows]), np.array([float(r["distance"]) for r in rows])


@pytest.mark.parametrize("brute", [False, True])
def test_the_same_hits_as_the_cli(tmp_path, scene_file, brute):
    scene = dropscope.load_scene(scene_file)
    origins, directions = rays(3000, scene)
    ids, distances = dropscope.query(scene, origins, directions, brute=brute)
    expected_ids, expected_distances = cli_query(tmp_path, scene_file, origins, directions,
                                                 *(["--brute"] if brute else []))
    assert ids.dtype == np.int64 and distances.dtype == np.float64
    np.testing.assert_array_equal(ids, expected_ids)
    np.testing.assert_array_equal(distances, expected_distances)  # NaN where both miss
    assert (ids >= 0).sum() > 100 and (ids == -1).sum() > 100  # hits and misses both compared
    assert np.isnan(distances[ids == -1]).all()


def test_octree_and_brute_force_agree_after_an_edit():
    scene = dropscope.scene_from_dict(cloud_document())
    origins, directions = rays(2000, scene, seed=5)
    before, _ = dropscope.query(scene, origins, directions)
    scene.add_shape({"type": "sphere", "center": [0, 0, 12], "radius": 1.5, "medium": "water"})
    octree = dropscope.query(scene, origins, directions)
    brute = dropscope.query(scene, origins, directions, brute=True)
    np.testing.assert_array_equal(octree[0], brute[0])
    np.testing.assert_array_equal(octree[1], brute[1])
    assert (octree[0] == 0).sum() > 0  # the new sphere (the one explicit shape, id 0) is found: the octree was rebuilt
    assert (octree[0][before >= 0] == before[before >= 0] + 1).mean() > 0.9  # the droplets moved up one id


def test_bad_arrays_raise_value_error_naming_them():
    scene = dropscope.scene_from_dict(cloud_document(10))
    with pytest.raises(ValueError, match=r"origins: expected an \(N, 3\) array, got shape \(4, 2\)"):
        dropscope.query(scene, np.zeros((4, 2)), np.ones((4, 3)))
    with pytest.raises(ValueError, match="4 and 5 rays"):
        dropscope.query(scene, np.zeros((4, 3)), np.ones((5, 3)))
    with pytest.raises(ValueError, match=r"directions\[1\]: is zero"):
        dropscope.query(scene, np.zeros((2, 3)), [[1, 0, 0], [0, 0, 0]])
    with pytest.raises(ValueError, match=r"origins\[0\]: not finite"):
        dropscope.query(scene, [[np.nan, 0, 0]], [[1, 0, 0]])
    ids, distances = dropscope.query(scene, np.zeros((0, 3)), np.zeros((0, 3)))
    assert ids.shape == (0,) and distances.shape == (0,)
