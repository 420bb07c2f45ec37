"""A plane detector's image with a colour bar: the rainbow ring a sunlit drop throws back onto a screen.

    PYTHONPATH=build/python /usr/bin/python3 examples/detector_image.py [OUTPUT_DIR]

writes detector_image.png: the "screen" of assets/scenes/rainbow-sky.json, 2.5 mm in front of a 1 mm drop, facing
it. The screen counts light that reaches its front, the side facing the drop: the incoming beam crosses it from
behind uncounted. Each pixel is the detector's "irradiance", the power it receives per mm² as a share of the
emitted power.
"""

import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # files, no window
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import dropscope  # noqa: E402

SCENES = pathlib.Path(__file__).resolve().parents[1] / "assets" / "scenes"
out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
out.mkdir(parents=True, exist_ok=True)

scene = dropscope.load_scene(SCENES / "rainbow-sky.json")
screen_spec = next(d for d in scene.to_dict()["detectors"] if d["name"] == "screen")
result = dropscope.trace(scene, 1_000_000, seed=2)
screen = result.detectors["screen"]
width, height = screen_spec["size"]
irradiance = screen["irradiance"]  # rows are iy (up), columns ix

fig, ax = plt.subplots(figsize=(7, 6))
image = ax.imshow(irradiance, origin="lower", cmap="inferno", extent=(-width / 2, width / 2, -height / 2, height / 2),
                  vmax=np.percentile(irradiance, 99.5))
fig.colorbar(image, ax=ax, label="power per mm² (share of the emitted power)")
ax.set_xlabel("screen x (mm)")
ax.set_ylabel("screen y (mm)")
ax.set_title(f"A screen 2.5 mm before a sunlit 1 mm drop ({result.summary['photons']:.0e} photons)")
fig.tight_layout()
fig.savefig(out / "detector_image.png", dpi=110)
share = result.summary["detectors"]["screen"]["fraction"]
print(f"detector_image: {share:.4f} of the power on the screen; wrote {out / 'detector_image.png'}")
