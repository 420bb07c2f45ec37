"""dropscope.mie against `dropscope mie`: the same table and summary, bit for bit; errors with the CLI's text."""

import csv
import json

import numpy as np
import pytest

import dropscope
from conftest import SOURCE_DIR, run_cli


def cli_mie(tmp_path, *args):
    out = tmp_path / "cli"
    run_cli("mie", *args, "--out", out)
    with (out / "mie.csv").open() as file:
        rows = list(csv.reader(file))
    columns = {name: np.array([float(row[i]) for row in rows[1:]]) for i, name in enumerate(rows[0])}
    return columns, json.loads((out / "summary.json").read_text())


def same(result, columns, summary):
    assert list(result.angular) == list(columns)
    for name, values in columns.items():
        np.testing.assert_array_equal(result.angular[name], values, err_msg=name)
    drop = lambda s: {k: v for k, v in s.items() if k != "seconds"}  # noqa: E731
    assert drop(result.summary) == drop(summary)


def test_one_sphere(tmp_path):
    result = dropscope.mie(index=1.33, kappa=1e-3, x=150, bins=90)
    same(result, *cli_mie(tmp_path, "--index", 1.33, "--kappa", 1e-3, "--x", 150, "--bins", 90))
    assert result.angular["fraction"].shape == (90,)
    assert result.summary["qext"] == pytest.approx(result.summary["qsca"] + result.summary["qabs"], rel=1e-12)


def test_a_range_of_sizes(tmp_path):
    result = dropscope.mie(index=1.5, x_range=(10, 20), x_count=12)
    same(result, *cli_mie(tmp_path, "--index", 1.5, "--x-range", 10, 20, "--x-count", 12))
    assert result.summary["sizes"] == 12


def test_a_scene_sphere_and_a_scene_cloud(tmp_path):
    droplet = SOURCE_DIR / "assets/scenes/mie-droplet.json"
    same(dropscope.mie(scene=dropscope.load_scene(droplet), bins=60), *cli_mie(tmp_path, "--scene", droplet,
                                                                               "--bins", 60))
    cloud = tmp_path / "cloud.json"
    document = json.loads((SOURCE_DIR / "assets/scenes/cloud.json").read_text())
    document["generators"][0]["radius"] = {"distribution": "uniform", "min": 0.0001, "max": 0.0002}
    document["generators"][0]["count"] = 10
    cloud.write_text(json.dumps(document))
    (tmp_path / "second").mkdir()
    same(dropscope.mie(scene=dropscope.load_scene(cloud), generator=0, bins=30),
         *cli_mie(tmp_path / "second", "--scene", cloud, "--generator", 0, "--bins", 30))


def test_save_writes_the_cli_files(tmp_path):
    result = dropscope.mie(index=1.33, x=40)
    result.save(tmp_path / "python")
    cli_mie(tmp_path, "--index", 1.33, "--x", 40)
    assert (tmp_path / "python/mie.csv").read_bytes() == (tmp_path / "cli/mie.csv").read_bytes()


@pytest.mark.parametrize("kwargs, cli_args", [
    (dict(index=1.33, x=0.0), ["--index", 1.33, "--x", 0]),
    (dict(index=-1, x=10), ["--index", -1, "--x", 10]),
    (dict(index=1.33, x=3e4), ["--index", 1.33, "--x", 3e4]),
    (dict(x=10), ["--x", 10]),
    (dict(index=1.33, x=10, x_range=(1, 2)), ["--index", 1.33, "--x", 10, "--x-range", 1, 2]),
    (dict(index=1.33, x_range=(5, 2)), ["--index", 1.33, "--x-range", 5, 2]),
])
def test_bad_input_raises_value_error_with_the_cli_text(tmp_path, kwargs, cli_args):
    with pytest.raises(ValueError) as raised:
        dropscope.mie(**kwargs)
    assert str(raised.value) == run_cli("mie", *cli_args, "--out", tmp_path / "never", expect=2).stderr.strip()
    assert not (tmp_path / "never").exists()


def test_a_scene_without_a_sphere_names_it():
    scene = dropscope.load_scene(SOURCE_DIR / "assets/scenes/shapes_gallery.json")
    with pytest.raises(ValueError, match=r"shapes_gallery\.json: .*--shape ID or --generator I"):
        dropscope.mie(scene=scene)


def test_a_scene_is_a_scene_whatever_its_name():
    scene = dropscope.load_scene(SOURCE_DIR / "assets/scenes/mie-droplet.json")
    with pytest.raises(ValueError, match="give exactly one of --x, --x-range and --scene"):
        dropscope.mie(scene=scene, x=5, index=1.33)
    with pytest.raises(ValueError, match="--shape: only with --scene"):
        dropscope.mie(index=1.33, x=5, shape=0)
    with pytest.raises(ValueError, match=r"shape: must be a whole number from 0 to 18446744073709551615"):
        dropscope.mie(scene=scene, shape=2**64)
