"""dropscope.snapshot against `dropscope snapshot`: the same pixels as the PNG."""

import numpy as np
import pytest
from PIL import Image

import dropscope
from conftest import SOURCE_DIR, run_cli

DETECTORS = SOURCE_DIR / "tests/data/scenes/detectors.json"


@pytest.mark.parametrize("kwargs, cli_args", [
    (dict(), []),
    (dict(paths=6, markers=True, colour_by="event"), ["--paths", 6, "--markers", "--colour-by", "event"]),
    (dict(eye=(8, 4, -6), target=(0, 0, 1), fov_deg=50, detectors=True, photons=2000, octree_level=0),
     ["--eye", "8,4,-6", "--target", "0,0,1", "--fov-deg", 50, "--detectors", "--photons", 2000,
      "--octree-level", 0]),
])
def test_the_pixels_of_the_cli_png(tmp_path, kwargs, cli_args):
    png = tmp_path / "cli.png"
    run_cli("snapshot", DETECTORS, "--width", 160, "--height", 120, *cli_args, "--out", png)
    expected = np.asarray(Image.open(png).convert("RGBA"))
    pixels = dropscope.snapshot(dropscope.load_scene(DETECTORS), 160, 120, **kwargs)
    assert pixels.shape == (120, 160, 4) and pixels.dtype == np.uint8
    np.testing.assert_array_equal(pixels, expected)
    assert len(np.unique(pixels.reshape(-1, 4), axis=0)) > 10  # a picture, not a blank


def test_bad_options_are_refused():
    scene = dropscope.load_scene(DETECTORS)
    with pytest.raises(ValueError, match="width: must be a whole number from 16 to 8192"):
        dropscope.snapshot(scene, 8, 100)
    with pytest.raises(TypeError, match="unexpected keyword argument 'colour'"):
        dropscope.snapshot(scene, 64, 64, colour="red")
    with pytest.raises(ValueError, match="eye: expected three finite numbers"):
        dropscope.snapshot(scene, 64, 64, eye=(1, 2))
    with pytest.raises(ValueError, match="--eye and --target must differ"):
        dropscope.snapshot(scene, 64, 64, eye=(1, 2, 3), target=(1, 2, 3))
    with pytest.raises(dropscope.SceneError, match=r"--select 9: no such shape"):
        dropscope.snapshot(scene, 64, 64, select=9)
