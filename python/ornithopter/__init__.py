"""ornithopter: flexible flapping-wing flight simulation, aero maps, trim and design from Python.

The same readers, checks, runs and summaries as the command line ``ornithopter``: every function
returns what the CLI writes into ``summary.json`` (as a dict; ``wall_time_s`` aside, to the last
bit) and raises :class:`InputError` where the CLI exits with status 2. Units are in the key
suffixes, as in the files (``speed_mps``, ``theta_deg``, ``arm_m``). Every computation releases the
GIL, and Ctrl-C stops it within one short unit of work (a flapping cycle, an aero-map or sweep
point, a design evaluation, a continuation point) with ``KeyboardInterrupt``; a run with ``out``
keeps its journal, so the same call again resumes it.

Library calls are silent: nothing is printed on stdout or stderr (the returned summary holds the
run's message), and no figure is drawn unless ``figures=True`` (gnuplot; the figure scripts are
written into ``out`` either way, and ``ornithopter plot DIR`` draws them later). What the command
line would print goes to the logger ``logging.getLogger("ornithopter")``: result lines and notes
at INFO, progress at DEBUG (``logging.basicConfig(level=logging.INFO)`` shows them).

Functions: :func:`load_vehicle`, :func:`load_study`, :func:`simulate`, :func:`modes`,
:func:`aeromap`, :func:`trim`, :func:`stability`, :func:`continuation`, :func:`sweep`,
:func:`sensitivity`, :func:`optimize`, :func:`run`.
"""

import csv as _csv
import json as _json
import os as _os
import tempfile as _tempfile

import numpy as _np

from . import _ornithopter as _core

__version__ = _core.__version__
__all__ = ["InputError", "Vehicle", "Study", "load_vehicle", "load_study", "simulate", "modes",
           "aeromap", "trim", "stability", "continuation", "sweep", "sensitivity", "optimize",
           "run", "__version__"]

InputError = _core.InputError
Vehicle = _core.Vehicle
Study = _core.Study

Vehicle.__doc__ = """A vehicle as read from its file (:func:`load_vehicle`).

``v["tail.arm_m"]`` reads a field by its file key (file units), ``v["tail.arm_m"] = 0.14`` sets it:
the whole vehicle is then re-read by the file reader, so the value is checked exactly as in a file
(type, range from the field table, cross-checks); a rejected value raises :class:`InputError`
(``.file == "<python>"``, ``.key``, ``.expected``) and leaves the vehicle unchanged. ``v.keys()``
lists every key, ``v.to_toml()`` gives the complete vehicle file (every default filled in; the
``.line`` of an error about a key you did not set refers to this text).

``len(v)`` is the number of keys, ``v.items()`` the (key, value) pairs; ``v.to_dict()`` the
whole vehicle as nested dicts (file key names and units) and ``Vehicle.from_dict(d)`` reads such
a dict back with the file reader (``Vehicle.from_dict(v.to_dict()) == v``). Vehicles compare
equal when their complete files are equal; ``copy.copy``/``copy.deepcopy`` give an independent
vehicle, and vehicles pickle (their complete file), so they travel to ``multiprocessing``
workers."""


def _existing_file(path):
    """The path as a string; FileNotFoundError (not InputError) when no file is there, as open()."""
    p = _os.fspath(path)
    if not _os.path.isfile(p):
        import errno
        raise FileNotFoundError(errno.ENOENT, _os.strerror(errno.ENOENT), p)
    return p


def load_vehicle(path):
    """Read a vehicle file (TOML) with the CLI's reader and checks.

    Returns a :class:`Vehicle`. Raises FileNotFoundError when there is no such file and
    :class:`InputError` (``.file``, ``.line``, ``.key``, ``.expected``) for a bad file."""
    return _core.Vehicle.load(_existing_file(path))


def load_study(path):
    """Read a study file (TOML, any kind) with the CLI's reader and checks.

    Returns a :class:`Study` (``.kind``, ``.name``, ``.path``) for :func:`optimize` or :func:`run`.
    Raises FileNotFoundError when there is no such file and :class:`InputError` for a bad file
    (a vehicle file it names that does not exist included: that is an error in the study)."""
    return _core.load_study(_existing_file(path))


def _read_summary(out_dir):
    with open(_os.path.join(out_dir, "summary.json"), encoding="utf-8") as f:
        return _json.load(f)


def _read_csv(path):
    """A CSV of a run (names row, units row, data) as {name: NumPy array}: float64 for numeric
    columns (the CLI writes the shortest text that reads back exactly), str for word columns
    (status); "units": {name: unit}."""
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(_csv.reader(f))
    names, units, data = rows[0], rows[1], rows[2:]
    out = {}
    for j, name in enumerate(names):
        cells = [r[j] for r in data]
        try:
            out[name] = _np.array([float(x) if x != "" else _np.nan for x in cells], dtype=float)
        except ValueError:
            out[name] = _np.array(cells, dtype=str)
    out["units"] = dict(zip(names, units))
    return out


def _run_in(study, out, threads, figures=False, runner=None):
    """Runs `study` into `out` (kept) or a temporary folder (removed by _cleanup). Returns (rc,
    summary, folder). `runner(folder)` replaces the study run (stability)."""
    def go(folder):
        if runner is not None:
            return runner(folder)
        return _core.run_study(study, folder, int(threads), bool(figures))
    if out is not None:
        _os.makedirs(out, exist_ok=True)
        rc = go(_os.fspath(out))
        return rc, _read_summary(out), _os.fspath(out)
    tmp = _tempfile.mkdtemp(prefix="ornithopter-")
    try:
        rc = go(tmp)
    except BaseException:  # an input error, Ctrl-C: nothing of the temporary folder is kept
        _cleanup(tmp, None)
        raise
    return rc, _read_summary(tmp), tmp


def _cleanup(folder, out):
    if out is None:
        import shutil
        shutil.rmtree(folder, ignore_errors=True)


def _section(**given):
    return {k: v for k, v in given.items() if v is not None}


def simulate(vehicle, mode="tethered", speed=None, freq=None, theta=None, tail=None, cycles=None,
             histories=True, out=None, figures=False, **options):
    """Simulate the vehicle: ``ornithopter simulate`` (a study of kind "simulate").

    Arguments (None = the vehicle's operating point / the CLI's default):
      mode    "tethered" (wind tunnel: body held at speed and theta) or "free" (default tethered)
      speed   U, m/s (key simulate.speed_mps)
      freq    flapping frequency, Hz (simulate.freq_hz)
      theta   body pitch attitude, deg (simulate.theta_deg)
      tail    tail angle, deg (simulate.tail_angle_deg)
      cycles  flapping cycles, default 10 (simulate.cycles)
      histories  sample the run and return the histories (default True). False samples
              nothing (the C++ benchmark's work): the integrator then takes its own steps
              without stopping at the samples, so the means differ from the CLI's (which always
              samples) within the integrator's tolerance (rel_tol), and the summary has no
              "last_cycle" nor "constrained_flight_test" (they need the samples). Only the
              default (True) equals the CLI's summary.json to the last bit.
      out     also keep the CLI's files in this folder (runs the CLI's command; default None)
      figures draw the figures into ``out`` (gnuplot; default False: their scripts only)
      **options  any other [simulate] key in file units: rel_tol (default 1e-6), abs_tol,
              samples_per_cycle (default 100), steady_tol, history_every (default 1),
              sampled_loads ("interpolated", the default: the flexible wing's history loads
              from the integrator's dense output, about 4x cheaper than "evaluated" at the
              sampled state; docs/theory.md 9.4),
              wing_only (default False), at_trim (default False), free={...} ([simulate.free]).

    Returns the summary.json dict (``status``, ``mean`` {FV_N, FH_N, M_Nm, power_W, ...}, ...)
    with, when ``histories``, ``"histories"``: {column: NumPy array} in histories.csv's columns and
    units (``"units"``: {column: unit}). Tethered runs fill one array in place (columns are views,
    no copy per sample); free flight and at_trim runs go through the CLI's files.
    A run that fails or does not converge is a status, not an exception; bad input raises
    :class:`InputError`. The GIL is released; Ctrl-C stops a tethered run at the end of a cycle.
    """
    section = _section(mode=mode, speed_mps=speed, freq_hz=freq, theta_deg=theta,
                       tail_angle_deg=tail, cycles=cycles, **options)
    study = _core.make_study(vehicle, "simulate", _run_name(vehicle), section)
    settings = _core.study_settings(study)
    if out is None and settings["mode"] == "tethered" and not settings["at_trim"]:
        text, rows = _core.simulate_tethered(vehicle, study, bool(histories))
        summary = _json.loads(text)
        if histories:
            every = settings["history_every"]
            names = [n for n, _ in _core.history_columns()]
            kept = rows[::every] if every > 1 else rows
            h = {n: kept[:, j] for j, n in enumerate(names)}
            h["units"] = dict(_core.history_columns())
            summary["histories"] = h
        return summary
    rc, summary, folder = _run_in(study, out, 1, figures)
    try:
        path = _os.path.join(folder, "histories.csv")
        if histories and _os.path.exists(path):
            summary["histories"] = _read_csv(path)
    finally:
        _cleanup(folder, out)
    return summary


def _run_name(vehicle):
    stem = _os.path.splitext(_os.path.basename(vehicle.source or "vehicle"))[0]
    return stem or "vehicle"


def modes(vehicle, out=None, figures=False):
    """Structural modes of the flexible wing: ``ornithopter modes``.

    Returns the summary.json dict (``frequencies_hz`` ascending, ``wing_mass_kg``, ``elements``,
    ...) with ``"table"``: modes.csv as {column: NumPy array}. ``out``: keep the CLI's files there.
    """
    study = _core.make_study(vehicle, "modes", _run_name(vehicle), {})
    rc, summary, folder = _run_in(study, out, 1, figures)
    try:
        path = _os.path.join(folder, "modes.csv")
        if _os.path.exists(path):
            summary["table"] = _read_csv(path)
    finally:
        _cleanup(folder, out)
    return summary


def aeromap(vehicle, speeds, freqs, thetas, tails=None, threads=1, out=None, figures=False,
            **options):
    """Aero map over a grid: ``ornithopter aeromap`` (paper Fig. 5).

    speeds  U values, m/s (array-like; key aeromap.speed_mps)
    freqs   flapping frequencies, Hz (aeromap.freq_hz)
    thetas  pitch attitudes, deg (aeromap.theta_deg)
    tails   tail angles, deg (default: the vehicle's operating-point tail angle)
    threads worker threads (default 1; any number gives the same arrays)
    **options  other [aeromap] keys: cycles (maximum per point, default 40), steady_tol, rel_tol,
            abs_tol, wing_only (default False: the whole vehicle).

    Returns {column of aeromap.csv: NumPy array} (``speed_mps``, ``freq_hz``, ``theta_deg``,
    ``FV_mean_N``, ``FH_mean_N``, ``M_mean_Nm``, ``power_W``, ...; ``"units"``) with
    ``"summary"``: the summary.json dict, and ``"grid"``: every numeric column as an array of
    shape (speeds, freqs, thetas, tails) in the order given, with ``"axes"`` {speed_mps,
    freq_hz, theta_deg, tail_angle_deg} (NaN where a point has no value; ``"status"`` a str
    array). With xarray installed, ``"dataset"`` is the same grid as an ``xarray.Dataset``.
    The GIL is released during the run.
    """
    def values(x):
        return [float(v) for v in _np.atleast_1d(_np.asarray(x, dtype=float))]
    section = _section(speed_mps=values(speeds), freq_hz=values(freqs), theta_deg=values(thetas),
                       tail_angle_deg=None if tails is None else values(tails), **options)
    study = _core.make_study(vehicle, "aeromap", _run_name(vehicle) + "_aeromap", section)
    rc, summary, folder = _run_in(study, out, threads, figures)
    try:
        result = _read_csv(_os.path.join(folder, "aeromap.csv"))
    finally:
        _cleanup(folder, out)
    result["summary"] = summary
    result["grid"] = _aeromap_grid(result)
    dataset = _as_dataset(result["grid"])
    if dataset is not None:
        result["dataset"] = dataset
    return result


_GRID_AXES = ("speed_mps", "freq_hz", "theta_deg", "tail_angle_deg")


def _axis_values(column):
    """The distinct values of a column in order of first appearance (the map's axis order)."""
    seen = {}
    for x in column:
        seen.setdefault(float(x), len(seen))
    return _np.array(list(seen), dtype=float), seen


def _aeromap_grid(table):
    axes, index = {}, []
    for name in _GRID_AXES:
        values, where = _axis_values(table[name])
        axes[name] = values
        index.append(_np.array([where[float(x)] for x in table[name]], dtype=int))
    shape = tuple(len(axes[n]) for n in _GRID_AXES)
    grid = {"axes": axes, "dims": _GRID_AXES}
    for name, column in table.items():
        if name in _GRID_AXES or name == "units" or not isinstance(column, _np.ndarray):
            continue
        if column.dtype.kind == "f":
            g = _np.full(shape, _np.nan)
        else:
            g = _np.full(shape, "", dtype=column.dtype)
        g[tuple(index)] = column
        grid[name] = g
    return grid


def _as_dataset(grid):
    """The grid as an xarray.Dataset when xarray is installed, else None."""
    try:
        import xarray
    except ImportError:
        return None
    data = {n: (grid["dims"], v) for n, v in grid.items() if n not in ("axes", "dims")}
    return xarray.Dataset(data, coords=dict(grid["axes"]))


def trim(vehicle, freq=None, out=None, figures=False, **options):
    """Trim the vehicle in level flight: ``ornithopter trim`` (paper Eq. 4, then free flight).

    freq    flapping frequency, Hz (key trim.freq_hz; default the vehicle's operating point)
    out     keep the CLI's files in this folder (default: none kept)
    **options  any [trim] key in file units, checked like the file: unknowns (default
            ["theta_mean_deg", "speed_mps", "tail_angle_deg"]), initial={theta_mean_deg,
            speed_mps, tail_angle_deg} (default: the operating point), bounds={...},
            max_iterations, residual_tol, function_tol, rel_tol, steady_tol, max_cycles,
            derivative_cycles, refine_in_free_flight, refine_cycles, method ("two_stage" default,
            or "periodic") and periodic={...}. See ``ornithopter keys trim`` for ranges/defaults.

    Returns the summary.json dict: ``converged``, ``freq_hz``, ``theta_mean_deg``, ``speed_mps``,
    ``tail_angle_deg``, ``residual`` {FV_N, FH_N, M_Nm}, ``free_flight`` {...}, ... A trim that
    does not converge is ``status`` "not_converged", not an exception.
    """
    section = _section(freq_hz=freq, **options)
    study = _core.make_study(vehicle, "trim", _run_name(vehicle), section)
    rc, summary, folder = _run_in(study, out, 1, figures)
    _cleanup(folder, out)
    return summary


def stability(vehicle, freq=None, out=None, figures=False, **options):
    """Floquet stability of trimmed flight: ``ornithopter stability`` (the periodic-orbit trim,
    the monodromy matrix of the orbit and all its multipliers).

    freq    flapping frequency, Hz (default: the vehicle's operating point)
    **options  other [trim] keys (initial={...}, bounds={...}, periodic={...}, ...)

    Returns the summary.json dict (``stable``, ``multipliers``, the trim point, ...) with
    ``"floquet"``: floquet.csv as {column: NumPy array} (every multiplier, sorted and labelled).
    """
    section = _section(freq_hz=freq, **options)
    name = _run_name(vehicle)
    rc, summary, folder = _run_in(
        None, out, 1, figures,
        runner=lambda f: _core.run_stability(vehicle, name, section, f, bool(figures)))
    try:
        path = _os.path.join(folder, "floquet.csv")
        if _os.path.exists(path):
            summary["floquet"] = _read_csv(path)
    finally:
        _cleanup(folder, out)
    return summary


def _as_study(study, kind):
    """A Study of `kind` from a Study or a study file's path; ValueError for another kind."""
    if not isinstance(study, _core.Study):
        study = load_study(study)
    if study.kind != kind:
        raise ValueError("%s: kind '%s' is not a %s study" % (study.path, study.kind, kind))
    return study


def _run_study_tables(study, kind, tables, threads, out, figures):
    study = _as_study(study, kind)
    rc, summary, folder = _run_in(study, out, threads, figures)
    try:
        for key, name in tables.items():
            path = _os.path.join(folder, name)
            if _os.path.exists(path):
                summary[key] = _read_csv(path)
    finally:
        _cleanup(folder, out)
    return summary


def continuation(study, threads=1, out=None, figures=False):
    """Continuation of trimmed flight along a parameter (a study of kind "continuation" or its
    path): ``ornithopter run STUDY``. Returns the summary.json dict with ``"table"``:
    continuation.csv as {column: NumPy array} (one row per branch point: the trim, its
    multipliers and stability, the events located on the way)."""
    return _run_study_tables(study, "continuation", {"table": "continuation.csv"}, threads, out,
                             figures)


def sweep(study, threads=1, out=None, figures=False):
    """A parameter sweep (a study of kind "sweep" or its path): ``ornithopter run STUDY -j
    threads``. Returns the summary.json dict with ``"table"``: sweep.csv as {column: NumPy
    array} (one row per point: the swept values and each point's trim or simulation)."""
    return _run_study_tables(study, "sweep", {"table": "sweep.csv"}, threads, out, figures)


def sensitivity(study, threads=1, out=None, figures=False):
    """A sensitivity study (kind "sensitivity" or its path): the trim and free flight of the base
    vehicle and of each parameter at the ends of its plausible range. Returns the summary.json
    dict with ``"table"``: sensitivity.csv and ``"tornado"``: tornado.csv, as {column: NumPy
    array}."""
    return _run_study_tables(study, "sensitivity",
                             {"table": "sensitivity.csv", "tornado": "tornado.csv"}, threads, out,
                             figures)


def optimize(study, threads=1, out=None, figures=False):
    """Run an optimize study (a :class:`Study` of kind "optimize" or its path): ``ornithopter
    optimize STUDY -j threads``. Returns the summary.json dict (``converged``, ``objective``,
    ``baseline_objective``, ``evaluations``, ``design`` {name: value},
    ``constraints_satisfied``, ...). ``out``: keep the CLI's files (and its resumable journal)."""
    study = _as_study(study, "optimize")
    rc, summary, folder = _run_in(study, out, threads, figures)
    _cleanup(folder, out)
    return summary


def run(study_path, out=None, threads=1, figures=False):
    """``ornithopter run STUDY -o out -j threads``: any study, the CLI's files in ``out``
    (default results/<study name>, as the CLI) with its report ``index.html``; figures only with
    ``figures=True``. Returns the summary.json dict."""
    study = load_study(study_path)
    if out is None:
        out = _os.path.join("results", study.name)
    rc, summary, folder = _run_in(study, out, threads, figures)
    return summary
