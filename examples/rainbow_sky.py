"""The rainbow of a sunlit water drop as a far-field camera sees it, in true colour.

    PYTHONPATH=build/python /usr/bin/python3 examples/rainbow_sky.py [OUTPUT_DIR]

writes rainbow_sky.png: the "sky" detector of assets/scenes/rainbow-sky.json (sunlight, the sun's 0.53 degree
disk, water's dispersion), with circles at the primary and secondary bows' angles from the antisolar point, and
beside it the radiance against that angle.
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
result = dropscope.trace(scene, 3_000_000, seed=1)
sky = result.detectors["sky"]
camera = next(d for d in scene.to_dict()["detectors"] if d["name"] == "sky")
half_fov = camera["fov_deg"] / 2
bows = [(180 - 137.9, "primary"), (180 - 129.4, "secondary")]  # Descartes' minimum deviations for n = 1.333

fig, (left, right) = plt.subplots(1, 2, figsize=(13, 6), width_ratios=[1, 1.1])
# The camera looks the way the sunlight travels (+z): its centre is the antisolar point.
left.imshow(sky["image"], extent=(-half_fov, half_fov, -half_fov, half_fov))
circle = np.linspace(0, 2 * np.pi, 400)
for angle, name in bows:
    left.plot(angle * np.cos(circle), angle * np.sin(circle), "--", lw=0.8, color="white", alpha=0.8)
    left.annotate(f"{name} bow, {angle:.1f}°", (0, angle + 1), color="white", ha="center", va="bottom", fontsize=8)
left.set_xlabel("degrees from the antisolar point (equidistant projection)")
left.set_title(f"The sky camera's picture ({result.summary['photons']:.0e} photons)")

# The radiance against the angle from the antisolar point: the pixels' radiance averaged in rings of 1 degree.
theta = sky["theta_deg"].ravel()
radiance = sky["radiance"].ravel()
edges = np.arange(0, half_fov + 1, 1.0)
ring = np.digitize(theta, edges) - 1
inside = (ring >= 0) & (ring < len(edges) - 1)
mean = np.bincount(ring[inside], weights=radiance[inside], minlength=len(edges) - 1)
mean /= np.maximum(np.bincount(ring[inside], minlength=len(edges) - 1), 1)
right.semilogy(0.5 * (edges[1:] + edges[:-1]), mean, drawstyle="steps-mid", color="black")
for angle, name in bows:
    right.axvline(angle, ls="--", color="tab:red", lw=0.8)
    right.annotate(f"{name}\n{angle:.1f}°", (angle - 0.6, mean.max()), color="tab:red", ha="right", va="top", fontsize=9)
right.set_xlabel("angle from the antisolar point (degrees)")
right.set_ylabel("mean radiance of the ring (share of the emitted power per sr)")
right.set_title("Averaged over azimuth: two bows, Alexander's dark band")
fig.tight_layout()
fig.savefig(out / "rainbow_sky.png", dpi=100)
print(f"rainbow_sky: {result.summary['detectors']['sky']['hits']} photons on the sky; wrote {out / 'rainbow_sky.png'}")
