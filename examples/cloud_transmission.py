"""A cloud's direct transmission against Beer-Lambert's law, with and without diffraction.

    PYTHONPATH=build/python /usr/bin/python3 examples/cloud_transmission.py [OUTPUT_DIR]

writes cloud_transmission.png. N droplets of radius a are scattered through a slab whose droplet centres cover an
area A; a beam crosses it. On average over clouds, the share of photons that come out unscattered is
exp(-N pi a^2 / A) with ray optics (extinction by the geometric cross-section) and exp(-2 N pi a^2 / A) with
diffraction, whose extinction is twice it (the extinction paradox, docs/transport.md "Diffraction"). Each point
averages three clouds (seeds): one cloud differs from the average by a few per cent, since the beam meets a few
hundred droplets.
"""

import math
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # files, no window
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import dropscope  # noqa: E402

out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
out.mkdir(parents=True, exist_ok=True)

RADIUS = 0.1  # mm: x = 2 pi a / lambda = 1181 at 532 nm
HALF_WIDTH = 5.0  # the slab is 10 x 10 mm across and 10 mm thick
PHOTONS = 20_000
SEEDS = (3, 4, 5)


def cloud(count, seed):
    return {
        "dropscope": 1, "unit": "mm", "wavelength_nm": 532, "ambient": "air",
        "media": {"air": {"n": 1.0}, "water": {"n": 1.3337}},
        "generators": [{"type": "droplet_cloud", "count": count, "medium": "water", "seed": seed,
                        "region": {"min": [-HALF_WIDTH, -HALF_WIDTH, 0], "max": [HALF_WIDTH, HALF_WIDTH, 10]},
                        "radius": {"distribution": "fixed", "value": RADIUS}}],
        "sources": [{"type": "beam", "origin": [0, 0, -1], "direction": [0, 0, 1], "radius": 4.5}],
    }


counts = [0, 500, 1000, 2000, 3000, 4000]
centres_area = (2 * (HALF_WIDTH - RADIUS)) ** 2
measured = {"none": [], "fraunhofer": []}
for count in counts:
    scenes = [dropscope.scene_from_dict(cloud(count, seed)) for seed in SEEDS]
    for diffraction in measured:
        shares = [dropscope.trace(scene, PHOTONS, seed=1, diffraction=diffraction).summary["fractions"]["unscattered"]
                  for scene in scenes]
        measured[diffraction].append(sum(shares) / len(shares))

depth = np.linspace(0, max(counts), 200) * math.pi * RADIUS**2 / centres_area
fig, ax = plt.subplots(figsize=(7, 5))
ax.semilogy(depth, np.exp(-depth), color="tab:blue", lw=1, label="Beer-Lambert, extinction $\\pi a^2$")
ax.semilogy(depth, np.exp(-2 * depth), color="tab:red", lw=1, label="Beer-Lambert, extinction $2\\pi a^2$")
x = np.array(counts) * math.pi * RADIUS**2 / centres_area
error = lambda t: np.sqrt(np.array(t) * (1 - np.array(t)) / (PHOTONS * len(SEEDS)))  # noqa: E731
ax.errorbar(x, measured["none"], yerr=error(measured["none"]), fmt="o", color="tab:blue", label="traced, ray optics")
ax.errorbar(x, measured["fraunhofer"], yerr=error(measured["fraunhofer"]), fmt="s", color="tab:red",
            label="traced, with diffraction")
ax.set_xlabel("N $\\pi a^2$ / A (droplets' geometric cross-section per area)")
ax.set_ylabel("unscattered share of the beam")
ax.set_title(f"Direct transmission through droplet slabs (a = {RADIUS} mm, x = 1181)")
ax.legend()
fig.tight_layout()
fig.savefig(out / "cloud_transmission.png", dpi=110)
for count, plain, diffracted in zip(counts, measured["none"], measured["fraunhofer"]):
    tau = count * math.pi * RADIUS**2 / centres_area
    print(f"  N {count:5d}: unscattered {plain:.4f} (Beer-Lambert {math.exp(-tau):.4f}), with diffraction "
          f"{diffracted:.4f} ({math.exp(-2 * tau):.4f})")
print(f"cloud_transmission: wrote {out / 'cloud_transmission.png'}")
