"""dropscope.trace against `dropscope trace`: the same files, bit for bit; progress, threads, Ctrl-C, errors."""

import csv
import json
import os
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import dropscope
from conftest import CLI, DETECTOR_SCENE, SOURCE_DIR, run_cli

OPTIONS = dict(seed=11, bins=90, wavelength_bins=3, orders=True, paths=4)
CLI_OPTIONS = ["--seed", 11, "--bins", 90, "--wavelength-bins", 3, "--orders", "--paths", 4]
PHOTONS = 20000


def without_timing(summary):
    return {key: value for key, value in summary.items() if key != "seconds"}


def read_csv_columns(path):
    with path.open() as file:
        rows = list(csv.reader(file))
    header, rows = rows[0], rows[1:]
    return {name: [row[i] for row in rows] for i, name in enumerate(header)}


@pytest.fixture(scope="module")
def traced(tmp_path_factory):
    folder = tmp_path_factory.mktemp("trace")
    scene_file = folder / "detectors.json"
    scene_file.write_text(json.dumps(DETECTOR_SCENE, indent=1))
    run_cli("trace", scene_file, "--photons", PHOTONS, *CLI_OPTIONS, "--threads", 2, "--out", folder / "cli")
    calls = []
    result = dropscope.trace(dropscope.load_scene(scene_file), PHOTONS, threads=2,
                             progress=lambda done, total: calls.append((done, total)), **OPTIONS)
    result.save(folder / "python")
    return folder, result, calls


def h5_items(path):
    """Every dataset and attribute of an HDF5 file by path, the run's seconds left out."""
    import h5py

    items = {}
    with h5py.File(path, "r") as file:
        def visit(name, node):
            for key, value in node.attrs.items():
                items[f"{name}@{key}"] = np.asarray(value).tolist()
            if isinstance(node, h5py.Dataset):
                items[name] = np.asarray(node[()]).tolist()
        file.visititems(visit)
        for key, value in file.attrs.items():
            items[f"@{key}"] = np.asarray(value).tolist()
    return {key: value for key, value in items.items() if "seconds" not in key and "summary_json" not in key}


def test_save_writes_the_cli_files_byte_for_byte(traced):
    folder, result, _ = traced
    cli, python = folder / "cli", folder / "python"
    names = sorted(os.listdir(cli))
    assert names == sorted(os.listdir(python))
    assert {"angular.csv", "angular_spectral.csv", "angular_orders.csv", "detector-screen.csv",
            "detector-screen-records.csv", "detector-sky.png", "paths.jsonl", "results.h5"} <= set(names)
    for name in names:
        if name in ("summary.json", "results.h5"):  # both record the run's seconds
            continue
        assert (cli / name).read_bytes() == (python / name).read_bytes(), name
    cli_items, python_items = h5_items(cli / "results.h5"), h5_items(python / "results.h5")
    assert len(cli_items) > 20 and cli_items == python_items  # the scene's JSON text and every table
    cli_summary = json.loads((cli / "summary.json").read_text())
    assert without_timing(cli_summary) == without_timing(json.loads((python / "summary.json").read_text()))
    assert without_timing(result.summary) == without_timing(cli_summary)


def test_arrays_hold_the_numbers_of_the_files(traced):
    folder, result, _ = traced
    for table, name in [(result.angular, "angular.csv"), (result.angular_spectral, "angular_spectral.csv"),
                        (result.orders, "angular_orders.csv")]:
        columns = read_csv_columns(folder / "cli" / name)
        assert list(table) == list(columns)
        for column, texts in columns.items():
            values = table[column]
            assert values.shape == (len(texts),)
            parsed = np.array([int(t) if values.dtype == np.int64 else float(t) for t in texts], dtype=values.dtype)
            np.testing.assert_array_equal(values, parsed, err_msg=f"{name} {column}")
    assert result.angular["theta_lo_deg"].shape == (90,)
    assert result.angular_spectral is not None and result.orders is not None


def test_detectors_are_shaped_like_their_pixels(traced):
    folder, result, _ = traced
    screen = result.detectors["screen"]
    columns = read_csv_columns(folder / "cli" / "detector-screen.csv")
    for column, texts in columns.items():
        assert screen[column].shape == (48, 48), column
        flat = screen[column].reshape(-1)
        np.testing.assert_array_equal(flat, np.array(texts, dtype=float).astype(flat.dtype))
    assert screen["ix"][0, 5] == 5 and screen["iy"][5, 0] == 5  # rows are iy, columns ix
    assert len(screen["records"]["photon"]) == 50
    assert result.detectors["floor"]["ix"].shape == (16, 16)
    assert result.detectors["sky"]["image"].shape == (64, 64, 3)
    assert result.detectors["sky"]["image"].dtype == np.uint8
    assert set(result.detectors) == {"screen", "floor", "sky", "absorbed"}


def test_paths_are_the_lines_of_paths_jsonl(traced):
    folder, result, _ = traced
    lines = (folder / "cli" / "paths.jsonl").read_text().splitlines()
    assert result.paths == [json.loads(line) for line in lines]
    assert len(result.paths) == 4


def test_progress_is_called_and_ends_with_every_photon(traced):
    _, _, calls = traced
    assert calls and calls[-1] == (PHOTONS, PHOTONS)
    assert all(done <= total == PHOTONS for done, total in calls)


def test_the_default_options_are_the_cli_defaults(tmp_path):
    scene_file = SOURCE_DIR / "assets/scenes/default.json"
    run_cli("trace", scene_file, "--photons", 3000, "--out", tmp_path / "cli")
    result = dropscope.trace(dropscope.load_scene(scene_file), 3000)
    result.save(tmp_path / "python")
    assert (tmp_path / "cli/angular.csv").read_bytes() == (tmp_path / "python/angular.csv").read_bytes()
    assert result.summary["polarisation"] == "stokes" and result.summary["diffraction"] == "none"
    assert result.orders is None and result.paths == []


def test_diffraction_and_unpolarised_match_the_cli(tmp_path):
    scene_file = SOURCE_DIR / "assets/scenes/mie-droplet.json"
    run_cli("trace", scene_file, "--photons", 4000, "--diffraction", "fraunhofer", "--polarisation", "none",
            "--out", tmp_path / "cli")
    result = dropscope.trace(dropscope.load_scene(scene_file), 4e3, diffraction="fraunhofer", polarisation="none")
    result.save(tmp_path / "python")
    assert (tmp_path / "cli/angular.csv").read_bytes() == (tmp_path / "python/angular.csv").read_bytes()
    assert result.summary["events"]["diffract"] > 0


def test_the_thread_count_does_not_change_the_numbers():
    scene = dropscope.scene_from_dict(DETECTOR_SCENE)
    one = dropscope.trace(scene, 5000, threads=1, seed=3)
    two = dropscope.trace(scene, 5000, threads=2, seed=3)
    for column in one.angular:
        np.testing.assert_array_equal(one.angular[column], two.angular[column])
    np.testing.assert_array_equal(one.detectors["screen"]["fraction"], two.detectors["screen"]["fraction"])


def test_bad_options_raise_value_error_and_save_refuses_a_file(tmp_path):
    scene = dropscope.scene_from_dict(DETECTOR_SCENE)
    with pytest.raises(ValueError, match=r"photons: must be a whole number from 1 to \d+, not 0"):
        dropscope.trace(scene, 0)
    with pytest.raises(ValueError, match=r"photons: expected a whole number, got 1\.5"):
        dropscope.trace(scene, 1.5)
    with pytest.raises(ValueError, match=r"bins: must be a whole number from 1 to 100000"):
        dropscope.trace(scene, 10, bins=100001)
    with pytest.raises(ValueError, match=r"polarisation: must be one of 'stokes', 'none', not 'circular'"):
        dropscope.trace(scene, 10, polarisation="circular")
    with pytest.raises(ValueError, match=r"--polarisation stokes: needs --fresnel exact"):
        dropscope.trace(scene, 10, fresnel="schlick", polarisation="stokes")
    assert dropscope.trace(scene, 10, fresnel="schlick").summary["polarisation"] == "none"  # as the CLI's default
    with pytest.raises(ValueError, match=r"photons: must be a whole number from 1 to 18446744073709551615"):
        dropscope.trace(scene, 2**64)
    with pytest.raises(ValueError, match=r"seed: must be a whole number from 0 to 18446744073709551615"):
        dropscope.trace(scene, 10, seed=1e20)
    assert dropscope.trace(scene, np.int64(10), seed=2**64 - 1).summary["seed"] == 2**64 - 1
    with pytest.raises(ValueError, match=r"more than 10000000 cells"):
        dropscope.trace(scene, 10, bins=100000, wavelength_bins=1000)
    no_sources = dropscope.load_scene(SOURCE_DIR / "tests/data/scenes/no_sources.json")
    with pytest.raises(dropscope.SceneError, match=r"no_sources\.json: sources: the scene has no light sources"):
        dropscope.trace(no_sources, 10)
    with pytest.raises(TypeError):
        dropscope.trace("scene.json", 10)
    result = dropscope.trace(scene, 10)
    (tmp_path / "file").write_text("x")
    with pytest.raises(ValueError, match="file"):
        result.save(tmp_path / "file")


def test_an_exception_in_progress_stops_the_run_and_is_raised():
    scene = dropscope.scene_from_dict(DETECTOR_SCENE)

    def refuse(done, total):
        raise RuntimeError("enough")

    started = time.monotonic()
    with pytest.raises(RuntimeError, match="enough"):
        dropscope.trace(scene, 1e9, threads=1, progress=refuse)
    assert time.monotonic() - started < 30


def test_the_gil_is_released_while_tracing():
    scene = dropscope.scene_from_dict(DETECTOR_SCENE)
    ticks = []
    running = threading.Event()

    def count():
        running.set()
        while running.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    running.wait()
    started = time.monotonic()
    dropscope.trace(scene, 400000, threads=1)
    ended = time.monotonic()
    running.clear()
    counter.join()
    during = [t for t in ticks if started < t < ended]
    # With the GIL held the other thread would run only when progress takes it, four times a second; free, it
    # ticks about every millisecond (5 % of that is asked).
    assert ended - started > 0.2
    assert len(during) > 0.05 * (ended - started) / 0.001


CTRL_C_SCRIPT = """
import sys, dropscope
scene = dropscope.load_scene(sys.argv[1])
print("tracing", flush=True)
try:
    dropscope.trace(scene, 1e10, threads=1)
except KeyboardInterrupt:
    print("KeyboardInterrupt", flush=True)
    raise SystemExit(7)
"""


def test_ctrl_c_stops_the_run_and_raises_keyboard_interrupt(detector_scene_file):
    process = subprocess.Popen([sys.executable, "-c", CTRL_C_SCRIPT, str(detector_scene_file)],
                               stdout=subprocess.PIPE, text=True)
    assert process.stdout.readline().strip() == "tracing"
    time.sleep(1.0)
    process.send_signal(signal.SIGINT)
    try:
        out, _ = process.communicate(timeout=30)
    except subprocess.TimeoutExpired:
        process.kill()
        raise
    assert process.returncode == 7 and "KeyboardInterrupt" in out


FORK_SCRIPT = """
import multiprocessing, sys, dropscope
scene = dropscope.load_scene(sys.argv[1])
def child(_):
    r = dropscope.trace(scene, 2000, threads=2, seed=4)
    return r.summary["threads"], r.summary["counts"]["escaped"], dropscope.mie(index=1.33, x=30).summary["qext"]
parent = dropscope.trace(scene, 2000, threads=2, seed=4)
with multiprocessing.get_context("fork").Pool(1) as pool:
    threads, escaped, qext = pool.map(child, [0])[0]
assert threads == 1 and escaped == parent.summary["counts"]["escaped"], (threads, escaped)
assert qext == dropscope.mie(index=1.33, x=30).summary["qext"]
print("forked child traced on one thread")
"""


def test_a_forked_child_traces_on_one_thread_instead_of_hanging(detector_scene_file):
    done = subprocess.run([sys.executable, "-c", FORK_SCRIPT, str(detector_scene_file)], capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "forked child traced on one thread" in done.stdout


def test_lost_photons_are_warned_with_the_cli_line(tmp_path):
    # docs/limits.md, "No silent loss": the same line as the CLI's stderr warning and summary.json.
    scene = SOURCE_DIR / "tests" / "data" / "scenes" / "pencil_at_box_edge.json"
    with pytest.warns(dropscope.LostPhotonsWarning) as caught:
        result = dropscope.trace(dropscope.load_scene(scene), 2000, threads=2)
    assert len(caught) == 1
    assert str(caught[0].message) == result.summary["lost_warning"]
    assert result.summary["first_lost"]["photon"] == 0
    cli = run_cli("trace", str(scene), "--photons", "2000", "--out", str(tmp_path / "cli"))
    assert cli.stderr == "dropscope: warning: " + str(caught[0].message) + "\n"


def test_no_warning_without_loss(recwarn):
    dropscope.trace(dropscope.load_scene(SOURCE_DIR / "assets" / "scenes" / "default.json"), 500)
    assert not [w for w in recwarn if issubclass(w.category, dropscope.LostPhotonsWarning)]
