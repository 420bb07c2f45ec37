"""What the Python module costs over the command-line program: the same work timed both ways in one run.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_bench.py [build/app/dropscope]

Trace: dropscope.trace's wall time (building the scene's octrees included) against the run's own "seconds"
(runTrace alone, as summary.json records it), and the CLI's whole process (reading the scene, writing the
files) against the same, for a droplet and a cloud. Query: rays per second through
dropscope.query (numpy in and out) against the CLI's "query ... rays/s" on the same rays (the octree's work
alone) and the CLI's whole process (reading and writing CSV). One thread throughout. docs/performance.md,
"Python".
"""

import json
import pathlib
import re
import subprocess
import sys
import tempfile
import time

import numpy as np

import dropscope

ROOT = pathlib.Path(__file__).resolve().parents[1]
CLI = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "build/app/dropscope")


def best_of(count, work):
    times = []
    for _ in range(count):
        start = time.perf_counter()
        value = work()
        times.append(time.perf_counter() - start)
    return min(times), value


def cloud_file(folder, count):
    document = json.loads((ROOT / "assets/scenes/cloud.json").read_text())
    document["generators"][0]["count"] = count
    path = pathlib.Path(folder) / f"cloud-{count}.json"
    path.write_text(json.dumps(document))
    return path


with tempfile.TemporaryDirectory() as folder:
    print("trace, 1 thread: seconds (best of 3)")
    print(f"{'scene':<14}{'photons':>9}{'runTrace':>10}{'Python':>9}{'CLI':>9}{'Python/runTrace':>17}{'CLI/runTrace':>14}")
    for name, path, photons in [("droplet", ROOT / "assets/scenes/default.json", 200_000),
                                ("cloud 20000", cloud_file(folder, 20000), 20_000)]:
        scene = dropscope.load_scene(path)
        inners = []
        python, _ = best_of(3, lambda: inners.append(dropscope.trace(scene, photons, threads=1).summary["seconds"]))
        inner = min(inners)
        out = pathlib.Path(folder) / "out"
        cli, _ = best_of(3, lambda: subprocess.run([CLI, "trace", str(path), "--photons", str(photons),
                                                    "--threads", "1", "--out", str(out / str(time.time()))],
                                                   check=True, capture_output=True))
        print(f"{name:<14}{photons:>9}{inner:>10.3f}{python:>9.3f}{cli:>9.3f}{python / inner:>17.3f}{cli / inner:>14.3f}")

    print("\nquery, 1e6 random rays into a cloud of 20000 droplets: rays per second (best of 3)")
    path = cloud_file(folder, 20000)
    scene = dropscope.load_scene(path)
    rng = np.random.default_rng(1)
    origins = rng.uniform(-12, 12, size=(1_000_000, 3))
    directions = rng.normal(size=(1_000_000, 3))
    dropscope.query(scene, origins[:10], directions[:10])  # builds the octree, as the CLI's build step
    python, _ = best_of(3, lambda: dropscope.query(scene, origins, directions))
    rays = pathlib.Path(folder) / "rays.csv"
    np.savetxt(rays, np.hstack([origins, directions]), delimiter=",", header="ox,oy,oz,dx,dy,dz", comments="",
               fmt="%.17g")
    best_inner, best_cli = float("inf"), float("inf")
    for _ in range(3):
        start = time.perf_counter()
        done = subprocess.run([CLI, "query", str(path), "--rays", str(rays), "--out", str(pathlib.Path(folder) / "h.csv")],
                              check=True, capture_output=True, text=True)
        best_cli = min(best_cli, time.perf_counter() - start)
        best_inner = min(best_inner, float(re.search(r"query ([0-9.]+) s", done.stderr).group(1)))
    n = len(origins)
    print(f"  octree alone (CLI's query time)  {n / best_inner:>12.0f}")
    print(f"  dropscope.query                  {n / python:>12.0f}   ({best_inner / python:.3f} of the octree's rate)")
    print(f"  dropscope query, whole process   {n / best_cli:>12.0f}   ({best_inner / best_cli:.3f})")
