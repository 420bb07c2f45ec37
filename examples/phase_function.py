"""The phase function of a water droplet traced with diffraction, and its -P12/P11, against Lorenz-Mie theory.

    PYTHONPATH=build/python /usr/bin/python3 examples/phase_function.py [OUTPUT_DIR]

writes phase_function.png. The droplet is assets/scenes/mie-droplet.json (x = 1200); Mie theory is averaged over
x within 5 % to smooth its ripples, which a ray tracer does not have (docs/validation.md).
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

scene = dropscope.load_scene(SCENES / "mie-droplet.json")
result = dropscope.trace(scene, 300_000, seed=1, bins=180, diffraction="fraunhofer")
traced = result.angular
one_size = dropscope.mie(scene=scene, bins=180).summary
x = one_size["x"]
theory = dropscope.mie(index=one_size["index"], kappa=one_size["kappa"], x_range=(0.95 * x, 1.05 * x), x_count=40,
                       bins=180).angular

# The phase function of the scattered light: the photons that missed the droplet and its diffraction ring
# escape at exactly 0 degrees (summary "unscattered") and are taken out of the first bin; both are normalised
# to 1 over the sphere.
lo, hi = np.radians(traced["theta_lo_deg"]), np.radians(traced["theta_hi_deg"])
solid_angle = 2 * np.pi * (np.cos(lo) - np.cos(hi))
scattered = traced["fraction"].copy()
scattered[0] -= result.summary["fractions"]["unscattered"]
traced_phase = scattered / scattered.sum() / solid_angle
theory_phase = theory["fraction"] / theory["fraction"].sum() / solid_angle
with np.errstate(invalid="ignore", divide="ignore"):
    traced_ratio = -traced["stokes_q"] / traced["fraction"]
angle = np.degrees(0.5 * (lo + hi))

fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7), sharex=True, height_ratios=[3, 2])
top.semilogy(angle, theory_phase, color="black", lw=1, label="Lorenz-Mie theory (x within 5 %)")
top.semilogy(angle, traced_phase, ".", ms=3, color="tab:blue", label="traced: ray optics + Fraunhofer diffraction")
top.set_ylabel("phase function (1/sr)")
top.set_title(f"Water droplet, x = {x:.0f}, m = {one_size['index']:.4f}, 3e5 photons")
top.legend()
bottom.plot(angle, -theory["p12_over_p11"], color="black", lw=1, label="Lorenz-Mie theory")
bottom.plot(angle, traced_ratio, ".", ms=3, color="tab:red", label="traced")
bottom.set_ylim(-1.05, 1.05)
bottom.set_xlim(0, 180)
bottom.set_xlabel("scattering angle (degrees)")
bottom.set_ylabel("-P12 / P11")
bottom.legend(loc="lower left")
fig.tight_layout()
fig.savefig(out / "phase_function.png", dpi=110)
print(f"phase_function: x = {x:.1f}, g Mie {one_size['g']:.4f}; wrote {out / 'phase_function.png'}")
