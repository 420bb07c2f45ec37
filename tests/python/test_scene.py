"""Scenes: load_scene, scene_from_dict, inspect, to_dict and the edits, against `dropscope inspect`."""

import json

import pytest

import dropscope
from conftest import SOURCE_DIR, run_cli

DEFAULT = SOURCE_DIR / "assets/scenes/default.json"


def test_inspect_is_the_cli_inspect_json():
    scene = dropscope.load_scene(str(DEFAULT))
    assert scene.inspect() == json.loads(run_cli("inspect", DEFAULT, "--json").stdout)
    assert scene.origin == str(DEFAULT)
    assert len(scene) == scene.inspect()["totals"]["shapes"] > 0


def test_a_dict_round_trips_to_the_same_scene(tmp_path):
    scene = dropscope.load_scene(DEFAULT)  # a path-like is accepted too
    document = scene.to_dict()
    assert document == json.loads(DEFAULT.read_text())
    again = dropscope.scene_from_dict(document)
    assert again.origin == "<dict>"
    assert again.inspect()["shapes"] == scene.inspect()["shapes"]


def test_a_bad_file_raises_scene_error_with_the_cli_text(tmp_path):
    bad = tmp_path / "bad.json"
    document = json.loads((SOURCE_DIR / "tests/data/scenes/one_sphere.json").read_text())
    document["shapes"][0]["radius"] = -1
    bad.write_text(json.dumps(document))
    cli = run_cli("inspect", bad, expect=2).stderr.strip()
    with pytest.raises(dropscope.SceneError) as raised:
        dropscope.load_scene(bad)
    assert str(raised.value) == cli
    assert cli.startswith(f"{bad}: shapes[0].radius: ")
    assert isinstance(raised.value, ValueError)


def test_a_missing_file_and_malformed_json_name_the_file(tmp_path):
    with pytest.raises(dropscope.SceneError, match=r"nowhere\.json: no such file"):
        dropscope.load_scene(tmp_path / "nowhere.json")
    malformed = SOURCE_DIR / "tests/data/scenes/malformed.json"
    with pytest.raises(dropscope.SceneError) as raised:
        dropscope.load_scene(malformed)
    assert str(raised.value) == run_cli("inspect", malformed, expect=2).stderr.strip()


def test_a_bad_dict_names_the_json_path():
    document = json.loads((SOURCE_DIR / "tests/data/scenes/one_sphere.json").read_text())
    document["media"]["water"]["n"] = "thick"
    with pytest.raises(dropscope.SceneError, match=r"^<dict>: media\.water\.n: "):
        dropscope.scene_from_dict(document)
    with pytest.raises(dropscope.SceneError, match=r"^mine: "):
        dropscope.scene_from_dict({"dropscope": 1, "shapes": [{"type": "sphere", "radius": float("nan")}]},
                                  origin="mine")
    with pytest.raises(TypeError):
        dropscope.scene_from_dict("not a dict")


def test_overlapping_shapes_are_refused_as_the_loader_refuses_them():
    overlapping = SOURCE_DIR / "tests/data/scenes/overlapping.json"
    with pytest.raises(dropscope.SceneError) as raised:
        dropscope.load_scene(overlapping)
    assert str(raised.value) == run_cli("inspect", overlapping, expect=2).stderr.strip()


def test_add_shape_follows_the_overlap_rule_and_a_refusal_changes_nothing():
    scene = dropscope.scene_from_dict(json.loads((SOURCE_DIR / "tests/data/scenes/overlapping.json").read_text())
                                      | {"shapes": [{"type": "sphere", "name": "d1", "center": [0, 0, 0],
                                                     "radius": 1, "medium": "water"}]})
    before = scene.to_dict()
    with pytest.raises(dropscope.SceneError, match=r"shapes\[1\].*overlap"):
        scene.add_shape({"type": "sphere", "name": "d2", "center": [1.5, 0, 0], "radius": 1, "medium": "water"})
    assert scene.to_dict() == before and len(scene) == 1
    assert scene.add_shape({"type": "sphere", "name": "d2", "center": [3, 0, 0], "radius": 1,
                            "medium": "water"}) == 1
    assert scene.add_shape({"type": "sphere", "center": [0, 0, 0], "radius": 0.5, "medium": "water"}) == 2
    assert len(scene) == 3 and scene.inspect()["shapes"][1]["name"] == "d2"
    scene.remove_shape("d2")
    assert [shape.get("name") for shape in scene.to_dict()["shapes"]] == ["d1", None]
    scene.remove_shape(0)
    assert len(scene) == 1
    with pytest.raises(IndexError):
        scene.remove_shape(5)
    with pytest.raises(KeyError):
        scene.remove_shape("nobody")


def test_removing_a_generated_droplet_makes_every_droplet_explicit():
    document = json.loads((SOURCE_DIR / "assets/scenes/cloud.json").read_text())
    document["generators"][0]["count"] = 50
    scene = dropscope.scene_from_dict(document)
    shapes = scene.inspect()["shapes"]
    scene.remove_shape(10)
    after = scene.to_dict()
    assert "generators" not in after and len(after["shapes"]) == 49
    assert scene.inspect()["shapes"][10]["bounds"] == shapes[11]["bounds"]


def test_an_interpreter_without_numpy_is_told_which_one_the_module_is_for():
    import subprocess
    import sys

    # numpy hidden (None in sys.modules makes its import fail), as on an interpreter that lacks it.
    done = subprocess.run([sys.executable, "-c", "import sys; sys.modules['numpy'] = None; import dropscope"],
                          capture_output=True, text=True)
    assert done.returncode == 1
    last = done.stderr.strip().splitlines()[-1]
    assert last.startswith("ImportError: dropscope: ") and "The module was built for " in last
    assert "needs numpy" in last and "docs/python.md" in last



def test_awkward_names_paths_and_values(tmp_path, monkeypatch):
    document = json.loads((SOURCE_DIR / "assets/scenes/cloud.json").read_text())
    document["generators"][0]["count"] = 5
    scene = dropscope.scene_from_dict(document)
    with pytest.raises(KeyError):
        scene.remove_shape("")  # unnamed shapes have no name to be removed by
    assert len(scene) == 5
    with pytest.raises(ValueError, match="origin must be a non-empty name"):
        dropscope.scene_from_dict(document, origin="")
    with pytest.raises(ValueError, match="NUL"):
        dropscope.load_scene(str(DEFAULT) + "\0zzz")
    import numpy as np

    document["generators"][0]["count"] = np.int64(7)  # numpy numbers are numbers
    document["sources"][0]["origin"] = np.array([0.0, 0.0, -20.0])
    assert len(dropscope.scene_from_dict(document)) == 7
    bom = tmp_path / "bom.json"
    bom.write_bytes(b"\xef\xbb\xbf" + DEFAULT.read_bytes())
    assert dropscope.load_scene(bom).to_dict() == json.loads(DEFAULT.read_text())


def test_a_scene_read_by_a_relative_path_can_be_edited_after_a_chdir(monkeypatch):
    monkeypatch.chdir(SOURCE_DIR / "assets/scenes")
    scene = dropscope.load_scene("shapes_gallery.json")  # its Bezier patches are in a file beside it
    monkeypatch.chdir("/")
    scene.remove_shape(len(scene) - 1)
    assert scene.origin == "shapes_gallery.json"
