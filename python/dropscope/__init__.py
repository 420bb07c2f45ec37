"""dropscope: light through droplets, from Python (docs/python.md).

Scenes, first-hit queries, Monte Carlo traces with their detectors, Lorenz-Mie theory and headless snapshots,
with numpy arrays in and out. Every function runs the code of the command-line program: the same inputs give
the same numbers, bit for bit, and the same messages for bad input.

    import dropscope
    scene = dropscope.load_scene("assets/scenes/default.json")
    result = dropscope.trace(scene, 1e5, seed=7)
    result.angular["fraction"]        # one value per angular bin, as angular.csv
    result.save("out")                # the files of `dropscope trace --out out`
"""

import functools
import json
import math
import numbers
import os
import warnings

from ._build import PYTHON as _BUILT_FOR
from ._build import PYTHON_VERSION as _BUILT_FOR_VERSION

try:
    import numpy as np
    from . import _dropscope as _core
except ImportError as _error:
    import sys as _sys

    raise ImportError(
        f"dropscope: {_error}. The module was built for {_BUILT_FOR} (Python {_BUILT_FOR_VERSION}) and needs numpy; "
        f"this is {_sys.executable} (Python {_sys.version.split()[0]}). Run it with {_BUILT_FOR}, or build for this "
        "interpreter with -DPython3_EXECUTABLE (docs/python.md)") from None

from ._dropscope import SceneError  # noqa: E402

__all__ = [
    "Scene",
    "SceneError",
    "TraceResult",
    "LostPhotonsWarning",
    "MieResult",
    "load_scene",
    "scene_from_dict",
    "query",
    "trace",
    "mie",
    "snapshot",
    "limits",
    "__version__",
]

__version__ = _core.__version__
# The bounds of the options, as the command-line program's (dict: name -> bound).
limits = dict(_core.limits)
_UINT64_MAX = 2**64 - 1  # photons, seeds and ids: the CLI's whole numbers are unsigned 64-bit

# GNU OpenMP cannot start threads in a process forked after it ran some (multiprocessing's default on Linux):
# such a child computes on one thread instead of hanging (docs/python.md, "Processes and threads").
os.register_at_fork(after_in_child=_core._after_fork_in_child)


def _whole(name, value, lowest, highest=None):
    """`value` as an int from lowest to highest (whole floats such as 1e6 accepted), else ValueError naming it."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name}: expected a whole number, got {type(value).__name__}")
    if isinstance(value, numbers.Integral):
        number = int(value)
    else:
        if not math.isfinite(value) or value != math.floor(value):
            raise ValueError(f"{name}: expected a whole number, got {value!r}")
        number = int(value)
    if number < lowest or (highest is not None and number > highest):
        bound = f"from {lowest} to {highest}" if highest is not None else f">= {lowest}"
        raise ValueError(f"{name}: must be a whole number {bound}, not {value!r}")
    return number


def _choice(name, value, choices):
    if value not in choices:
        raise ValueError(f"{name}: must be one of {', '.join(repr(c) for c in choices)}, not {value!r}")
    return value


def _number(name, value):
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name}: expected a number, got {type(value).__name__}")
    return float(value)


class Scene:
    """A scene (docs/scene-format.md), as `load_scene` or `scene_from_dict` made it.

    Edits (`add_shape`, `remove_shape`) load the edited scene again, so the loader's rules hold after every
    edit, overlaps included; a refused edit raises SceneError and changes nothing. Shape ids are those of the
    scene file: the explicit shapes of "shapes" first, then the droplets of "generators".
    """

    def __init__(self, core):
        self._core = core

    @property
    def origin(self):
        """The file the scene was read from, or "<dict>": how messages and summary.json name it."""
        return self._core.origin

    @property
    def shape_count(self):
        return self._core.shape_count

    def __len__(self):
        return self._core.shape_count

    def __repr__(self):
        return f"<dropscope.Scene {self.origin!r}: {self.shape_count} shapes>"

    def inspect(self):
        """The dict `dropscope inspect --json` prints: shapes by type, totals, bounds, media, octree."""
        return json.loads(self._core.inspect_json())

    def to_dict(self):
        """The scene as a dict of the scene format: the file as written (generators kept), with the edits made."""
        text = self._core.text
        return json.loads(text[1:] if text.startswith("\ufeff") else text)  # a byte-order mark, as the loader

    def add_shape(self, shape):
        """Adds a shape (a dict as in the scene file's "shapes") after the explicit shapes; returns its id.

        The droplets of generators, which come after the explicit shapes, move up by one id.
        """
        if not isinstance(shape, dict):
            raise TypeError(f"add_shape: expected a dict, got {type(shape).__name__}")
        document = self.to_dict()
        document.setdefault("shapes", []).append(shape)
        new_id = self._core.explicit_shape_count
        self._core.replace(_dumps(document, self.origin))
        return new_id

    def remove_shape(self, shape):
        """Removes the shape with this id (int) or name (str); the shapes after it move down by one id.

        Removing a generated droplet writes the scene out with every droplet explicit (as the app saves it):
        to_dict() then has no generators.
        """
        if isinstance(shape, str):
            names = self._core.shape_names
            if not shape or shape not in names:  # unnamed shapes have the name ""
                raise KeyError(f"remove_shape: no shape named {shape!r}")
            index = names.index(shape)
        else:
            index = _whole("remove_shape: id", shape, 0)
            if index >= self._core.shape_count:
                raise IndexError(
                    f"remove_shape: no shape {index} (the scene has {self._core.shape_count}, ids from 0)")
        if index < self._core.explicit_shape_count:
            document = self.to_dict()
        else:
            document = json.loads(self._core.explicit_json())
        del document["shapes"][index]
        self._core.replace(_dumps(document, self.origin))


def _json_value(value):
    """numpy numbers and arrays in a scene dict, as the numbers and lists they hold."""
    if isinstance(value, (np.generic, np.ndarray)):
        return value.tolist()
    raise TypeError(f"Object of type {type(value).__name__} is not JSON serializable")


def _dumps(document, origin):
    try:
        return json.dumps(document, allow_nan=False, default=_json_value)
    except (TypeError, ValueError) as error:
        raise SceneError(f"{origin}: not expressible as JSON: {error}") from None


def _path(name, path):
    text = os.fspath(path)
    if not isinstance(text, str):
        text = os.fsdecode(text)
    if "\0" in text:
        raise ValueError(f"{name}: a path with a NUL character: {text!r}")
    return text


def load_scene(path):
    """Reads a scene file. Raises SceneError ("FILE: JSON.PATH: message") for a bad one."""
    return Scene(_core.SceneCore.read(_path("load_scene", path)))


def scene_from_dict(document, origin="<dict>"):
    """A scene from a dict of the scene format; `origin` names it in messages and results."""
    if not isinstance(document, dict):
        raise TypeError(f"scene_from_dict: expected a dict, got {type(document).__name__}")
    if not isinstance(origin, str) or not origin:
        raise ValueError("scene_from_dict: origin must be a non-empty name")
    return Scene(_core.SceneCore(_dumps(document, origin), origin))


def _scene_core(scene):
    if not isinstance(scene, Scene):
        raise TypeError(f"expected a dropscope.Scene, got {type(scene).__name__}")
    return scene._core


def query(scene, origins, directions, brute=False):
    """The first shape each ray meets and the distance to it, as `dropscope query`.

    origins, directions: (N, 3) arrays (directions need not be unit length). Returns (ids, distances), int64
    and float64 arrays of N: -1 and NaN where a ray meets nothing. brute=True tests every shape.
    """
    return _core.query(_scene_core(scene), np.asarray(origins, dtype=np.float64),
                       np.asarray(directions, dtype=np.float64), bool(brute))


class _RunResult:
    """A finished run of the engine (its core object) with its summary and its files."""

    def __init__(self, core):
        self._core = core

    @functools.cached_property
    def summary(self):
        """The dict of the run's summary.json."""
        return json.loads(self._core.summary_json())

    def save(self, directory):
        """Writes the command's files into the folder (created), all of them or none."""
        self._core.save(_path("save", directory))


class TraceResult(_RunResult):
    """What `trace` returns: the files of `dropscope trace` as Python objects (docs/python.md); save(dir) writes
    them as the CLI does."""

    @functools.cached_property
    def tables(self):
        """Every table of the run by name (angular, angular_spectral, ...): dicts of numpy arrays by column."""
        return {name: {column: np.asarray(values) for column, values in table.items()}
                for name, table in self._core.tables().items()}

    @functools.cached_property
    def images(self):
        """The far-field detectors' pictures by file name: (H, W, 3) uint8 arrays, top row first."""
        return dict(self._core.images())

    @property
    def angular(self):
        """angular.csv: numpy arrays by column name."""
        return self.tables["angular"]

    @property
    def angular_spectral(self):
        """angular_spectral.csv: numpy arrays by column name."""
        return self.tables.get("angular_spectral")

    @property
    def orders(self):
        """angular_orders.csv (trace with orders=True), else None."""
        return self.tables.get("angular_orders")

    @functools.cached_property
    def detectors(self):
        """Each detector by name: its table's columns shaped (ny, nx) like its pixels, plus "records" (a dict
        of arrays, when it records hits) and "image" (a far-field detector's picture)."""
        detectors = {}
        for name in self.summary.get("detectors", {}):
            table = f"detector-{name}"
            detector = dict(self.tables.get(table, {}))
            if f"{table}-records" in self.tables:
                detector["records"] = self.tables[f"{table}-records"]
            if table in self.images:
                detector["image"] = self.images[table]
            detectors[name] = detector
        return detectors

    @functools.cached_property
    def paths(self):
        """The recorded photons (trace with paths=K) as the dicts of paths.jsonl."""
        return [json.loads(line) for line in self._core.paths_jsonl().splitlines()]

    def __repr__(self):
        summary = self.summary
        return f"<dropscope.TraceResult: {summary['photons']} photons of {summary['scene']!r}>"


class LostPhotonsWarning(RuntimeWarning):
    """Issued by trace() when photons were lost; its text is summary.json's "lost_warning"."""


def trace(scene, photons, seed=1, threads=0, bins=180, polarisation=None, diffraction="none",
          wavelength_bins=1, orders=False, paths=0, progress=None, fresnel="exact", max_events=10000):
    """Traces photons through the scene, as `dropscope trace` with the same options; returns a TraceResult.

    polarisation: "stokes" or "none"; None (the default) is the CLI's default, "stokes", or "none" with
    fresnel="schlick". The same seed gives the same numbers as the command-line program, bit for bit, for any
    thread count.
    progress, when given, is called as progress(done, total) about four times a second and once at the end.
    Ctrl-C stops the run cleanly and raises KeyboardInterrupt. The GIL is released while tracing.
    """
    core = _scene_core(scene)
    photons = _whole("photons", photons, 1, _UINT64_MAX)
    seed = _whole("seed", seed, 0, _UINT64_MAX)
    threads = _whole("threads", threads, 0, limits["trace_threads"])
    bins = _whole("bins", bins, 1, limits["trace_bins"])
    polarisation = "" if polarisation is None else _choice("polarisation", polarisation, ("stokes", "none"))
    diffraction = _choice("diffraction", diffraction, ("none", "fraunhofer"))
    wavelength_bins = _whole("wavelength_bins", wavelength_bins, 1, limits["wavelength_bins"])
    paths = _whole("paths", paths, 0, limits["trace_paths"])
    fresnel = _choice("fresnel", fresnel, ("exact", "schlick"))
    max_events = _whole("max_events", max_events, 1, 2**32 - 1)
    if progress is not None and not callable(progress):
        raise TypeError("progress: expected a callable progress(done, total)")
    result = TraceResult(_core.trace(core, photons, seed, threads, bins, polarisation, diffraction, wavelength_bins,
                                     bool(orders), paths, progress, fresnel, max_events))
    lost = result.summary.get("lost_warning")
    if lost:
        # The CLI's stderr line (docs/limits.md, "No silent loss"); the numbers are in summary["first_lost"].
        warnings.warn(lost, LostPhotonsWarning, stacklevel=2)
    return result


class MieResult(_RunResult):
    """What `mie` returns: mie.csv's columns (.angular) and summary.json's dict (.summary: qext, qsca, qabs,
    qback, g, x, index, kappa, ...); save(dir) writes both files as `dropscope mie` does."""

    @functools.cached_property
    def angular(self):
        """mie.csv: theta_lo_deg, theta_hi_deg, fraction, fraction_per_sr, p12_over_p11, p33_over_p11,
        p34_over_p11 as numpy arrays."""
        return dict(self._core.columns())

    def __repr__(self):
        s = self.summary
        return f"<dropscope.MieResult: x {s['x']:.6g}, Q_ext {s['qext']:.6g}, g {s['g']:.6g}>"


def mie(index=None, kappa=None, x=None, x_range=None, x_count=None, scene=None, shape=None, generator=None,
        bins=180):
    """Lorenz-Mie theory, as `dropscope mie` with the same options; returns a MieResult.

    One sphere (index, kappa, x), a uniform range of size parameters (x_range=(lo, hi), x_count), or a scene's
    sphere or droplet cloud (scene, shape=ID or generator=I), in `bins` angular bins.
    """
    x_range_values = []
    if x_range is not None:
        x_range_values = [_number("x_range", value) for value in x_range]
        if len(x_range_values) != 2:
            raise ValueError("x_range: expected two numbers (lo, hi)")
    return MieResult(_core.mie(
        _number("index", index), _number("kappa", kappa), _number("x", x), x_range_values,
        None if x_count is None else _whole("x_count", x_count, 1, limits["mie_sizes"]),
        None if scene is None else _scene_core(scene),
        None if shape is None else _whole("shape", shape, 0, _UINT64_MAX),
        None if generator is None else _whole("generator", generator, 0, _UINT64_MAX),
        _whole("bins", bins, 1, limits["trace_bins"])))


_SNAPSHOT_CHOICES = {
    "octree_filter": ("level", "upto", "leaves"),
    "octree_colour": ("level", "occupancy"),
    "colour_by": ("weight", "event", "dolp", "wavelength"),
    "polarisation": ("stokes", "none"),
}
_SNAPSHOT_SWITCHES = ("markers", "ray_tree", "traversal", "sources", "detectors", "axes", "grid", "no_shapes",
                      "translucent")


def _point_text(name, value):
    values = [_number(name, v) for v in value]
    if len(values) != 3 or not all(math.isfinite(v) for v in values):
        raise ValueError(f"{name}: expected three finite numbers (x, y, z), got {value!r}")
    return ",".join(repr(v) for v in values)


def snapshot(scene, width=800, height=600, **options):
    """The picture `dropscope snapshot` renders (OSMesa, no display): an (height, width, 4) uint8 RGBA array.

    Options are the CLI's, with underscores: eye=(x, y, z), target=(x, y, z), fov_deg, octree_level,
    octree_filter, octree_colour, colour_by, polarisation, paths, photons, seed, select, and the switches
    markers, ray_tree, traversal, sources, detectors, axes, grid, no_shapes, translucent (True/False).
    """
    core = _scene_core(scene)
    lo, hi = limits["snapshot_pixels_min"], limits["snapshot_pixels_max"]
    width = _whole("width", width, lo, hi)
    height = _whole("height", height, lo, hi)
    given = {}
    for name, value in options.items():
        if name in ("eye", "target"):
            given[name] = _point_text(name, value)
        elif name == "fov_deg":
            fov = _number(name, value)
            if not 1.0 <= fov <= 179.0:
                raise ValueError(f"fov_deg: must be from 1 to 179, not {value!r}")
            given[name] = fov
        elif name == "octree_level":
            given[name] = _whole(name, value, 0, 30)
        elif name in _SNAPSHOT_CHOICES:
            given[name] = _choice(name, value, _SNAPSHOT_CHOICES[name])
        elif name == "paths":
            given[name] = _whole(name, value, 0, limits["snapshot_paths"])
        elif name == "photons":
            given[name] = _whole(name, value, 0, limits["snapshot_photons"])
        elif name == "seed":
            given[name] = _whole(name, value, 0, _UINT64_MAX)
        elif name == "select":
            given[name] = _whole(name, value, 0, limits["snapshot_select"])
        elif name in _SNAPSHOT_SWITCHES:
            given[name] = bool(value)
        else:
            raise TypeError(f"snapshot() got an unexpected keyword argument {name!r}")
    return _core.snapshot(core, width, height, given)
