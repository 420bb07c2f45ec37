"""read_results_h5.py WRITER WORKDIR: results.h5 as h5py and pandas users read it (docs/results-format.md).

Runs WRITER (write_sample_results_h5) to write the sample report's results.h5, then reads it the way the
document says, and checks what it reads. Also checks that two processes write the same bytes, one of them
with glibc filling all its fresh and freed memory (MALLOC_PERTURB_), so that no byte of the file comes from
memory HDF5 did not write. Run by Debian's /usr/bin/python3 (python3-h5py); exit 77 (skipped) without h5py.
"""
import json
import math
import os
import subprocess
import sys

try:
    import h5py
    import numpy as np
except ImportError as error:
    print(f"SKIP: {error} (scripts/install-deps.sh installs python3-h5py for /usr/bin/python3)")
    sys.exit(77)
try:
    import pandas as pd
except ImportError:
    pd = None  # python3-pandas is optional: the same checks through numpy


def check(condition, message):
    if not condition:
        print(f"FAIL: {message}", file=sys.stderr)
        sys.exit(1)


def write(writer, path, environment=None):
    subprocess.run([writer, path], check=True, env={**os.environ, **(environment or {})})
    with open(path, "rb") as file:
        return file.read()


def table(group):
    """A table as its CSV has it, as docs/results-format.md reads it (a dict of columns without pandas)."""
    def column(dataset):
        values = dataset.asstr()[:] if h5py.check_string_dtype(dataset.dtype) else dataset[:]
        return values.reshape(-1)
    columns = {name: column(group[name]) for name in group.attrs["columns"]}
    return pd.DataFrame(columns) if pd else columns


def summary_of(group):
    """/summary as the nested dict of summary.json, as docs/results-format.md reads it."""
    values = {k: None if isinstance(v, h5py.Empty) else v for k, v in group.attrs.items()}
    values.update({k: summary_of(g) for k, g in group.items()})
    return values


def main(writer, workdir):
    os.makedirs(workdir, exist_ok=True)
    path = os.path.join(workdir, "results.h5")
    plain = write(writer, path)
    perturbed = write(writer, os.path.join(workdir, "perturbed.h5"), {"MALLOC_PERTURB_": "165"})
    check(plain == perturbed, "two processes wrote different bytes for the same report")

    with h5py.File(path, "r") as f:
        check(f.attrs["format"] == "dropscope results", f"format {f.attrs['format']!r}")
        check(f.attrs["format_version"] == 1, "format_version")
        check(isinstance(f.attrs["dropscope_version"], str), "dropscope_version is not a str")
        check(f.attrs["seed"] == 7 and f.attrs["photons"] == 1000, "seed and photons")
        # h5py lists a File (not its groups) by name; f["/"] lists the root in creation order.
        check(list(f["/"]) == ["scene_json", "summary", "tables", "images"], f"root members {list(f)}")
        scene = json.loads(f["scene_json"].asstr()[()])
        check(scene == {"format": 1, "shapes": []}, f"scene_json {scene}")

        summary = f["summary"]
        check(list(summary.attrs) == ["photons", "seed", "partial", "scene", "polarised", "wavelength_nm", "bins",
                                      "max_events", "paths", "sources"],
              f"summary attributes {list(summary.attrs)}")
        check(summary.attrs["photons"] == 1000 and summary.attrs["photons"].dtype == np.uint64, "photons")
        check(summary.attrs["partial"].dtype == np.bool_ and not summary.attrs["partial"], "partial")
        check(summary.attrs["polarised"].dtype == np.bool_ and summary.attrs["polarised"], "polarised")
        check(summary.attrs["scene"] == "scenes/caf\u00e9.json", f"scene {summary.attrs['scene']!r}")
        check(isinstance(summary.attrs["wavelength_nm"], h5py.Empty), "null is not h5py.Empty")
        check("seconds" not in summary.attrs and "threads" not in summary.attrs, "run-dependent keys")
        check(summary["fractions"].attrs["escaped"] == 0.75, "fractions/escaped")
        check(math.isnan(summary["fractions"].attrs["absorbed"]), "fractions/absorbed is not NaN")
        check(summary["spectra/0"].attrs["spectrum"] == "sun", "spectra/0/spectrum")
        as_json = summary_of(summary)
        check(as_json["wavelength_nm"] is None and as_json["spectra"]["0"]["lo_nm"] == 380.0, f"summary {as_json}")

        tables = f["tables"]
        check(list(tables) == ["angular", "detector-sky", "detector-sky-records", "empty"], f"tables {list(tables)}")
        angular = tables["angular"]
        check(list(angular) == list(angular.attrs["columns"]), "column order")
        check(angular["theta_lo_deg"].attrs["unit"] == "deg", "unit")
        check(angular["count"].dtype == np.uint64 and angular["fraction"].dtype == np.float64, "dtypes")
        rows = table(angular)
        check(list(rows["fraction"]) == [0.25, 0.75] and list(rows["count"]) == [1, 3], "angular values")

        sky = tables["detector-sky"]
        check(tuple(sky.attrs["grid"]) == (2, 3), f"grid {sky.attrs['grid']}")
        check(sky["fraction"].shape == (2, 3), f"fraction shape {sky['fraction'].shape}")
        check(sky["fraction"][1, 2] == 0.5, "fraction[iy=1, ix=2]")
        check(list(sky) == ["ix", "iy", "fraction", "radiance", "label", "stokes_q", "stokes_u", "stokes_v", "cie_x",
                            "cie_y", "cie_z"], f"detector columns {list(sky)}")
        check(sky["radiance"].attrs["unit"] == "1/sr", "radiance unit")
        check(list(sky["label"].asstr()[0]) == ["a", "b", "c"], "text column")
        pixels = table(sky)
        check(list(pixels["ix"]) == [0, 1, 2, 0, 1, 2] and list(pixels["iy"]) == [0, 0, 0, 1, 1, 1], "pixel order")
        check(list(pixels["label"]) == ["a", "b", "c", "d", "e", "f"], "text column rows")
        records = table(tables["detector-sky-records"])
        check(list(records["shape"]) == ["sphere 0", "box, 1"] and list(records["x"]) == [-0.5, 2.0], "records")
        check(tables["empty"]["value"].shape == (0,), "empty table")

        image = f["images/detector-sky"]
        check(image.shape == (2, 3, 3) and image.dtype == np.uint8, f"image {image.shape} {image.dtype}")
        check(image[0, 1].tolist() == [3, 4, 5], "image pixel (row 0, column 1)")
        check(image.attrs["CLASS"] == b"IMAGE", f"image CLASS {image.attrs['CLASS']!r}")
    print(f"results.h5 reads as documented (h5py {h5py.__version__}, {'pandas' if pd else 'numpy only'})")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: read_results_h5.py WRITER WORKDIR")
    main(sys.argv[1], sys.argv[2])
