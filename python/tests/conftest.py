"""Shared helpers of the Python suite: the CLI (ORNI_BINARY) and summary comparison."""
import csv
import json
import os
import subprocess

import pytest

SOURCE_DIR = os.environ.get("ORNI_SOURCE_DIR",
                            os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))
BINARY = os.environ.get("ORNI_BINARY", "")
RFW = os.path.join(SOURCE_DIR, "studies", "vehicles", "rfw_tunnel.toml")
EFW = os.path.join(SOURCE_DIR, "studies", "vehicles", "efw_magpie.toml")


def cli(*args):
    """Runs the CLI; returns its exit status."""
    if not BINARY:
        pytest.skip("ORNI_BINARY (the ornithopter executable) is not set")
    return subprocess.run([BINARY, *map(str, args)], stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, check=False).returncode


def read_summary(folder):
    with open(os.path.join(folder, "summary.json"), encoding="utf-8") as f:
        return json.load(f)


def read_csv_columns(path):
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    out = {}
    for j, name in enumerate(rows[0]):
        cells = [r[j] for r in rows[2:]]
        try:
            out[name] = [float(x) for x in cells]
        except ValueError:
            out[name] = cells
    return out


def without_timings(d):
    """The summary without its wall-clock entries (the only keys that differ between runs)."""
    if isinstance(d, dict):
        return {k: without_timings(v) for k, v in d.items()
                if not (k.endswith("time_s") or k == "timing_s")}
    if isinstance(d, list):
        return [without_timings(v) for v in d]
    return d
