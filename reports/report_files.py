"""Reading and writing of the sweep reports' files, shared by
make_component_sweep_report.py and make_system_sweep_report.py: a missing
or malformed input ends the script with `NAME: error: ...` on stderr and
exit status 1; every output is written whole (a temporary file, then a
rename)."""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def die(name, message):
    sys.stderr.write(f"{name}: error: {message}\n")
    sys.exit(1)


def number(text):
    return float(text) if text != "" else math.nan


def read_csv(name, path, columns, optional=()):
    """The rows of `path`, whose columns must be `columns` (then `optional`, if any)."""
    if not os.path.isfile(path):
        die(name, f"{path}: missing")
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        if reader.fieldnames not in (columns, columns + list(optional)):
            die(name, f"{path}: columns {reader.fieldnames}, expected {columns}")
        return list(reader)


def write_whole(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def save_figure(fig, path):
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=130, bbox_inches="tight")
    plt.close(fig)
    os.replace(tmp, path)
