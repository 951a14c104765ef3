"""Ctrl-C (SIGINT) stops every kind of run within one short unit of work, raises
KeyboardInterrupt, leaves a resumable journal, and the next call runs normally."""
import glob
import json
import os
import signal
import tempfile
import threading
import time

import pytest

import ornithopter
from conftest import EFW, SOURCE_DIR

# The bound on the time from the signal to the exception: one unit of work (an aero-map point of
# the flexible wing ~0.1 s, a flapping cycle, a continuation point ~0.3 s) with a wide margin for
# a loaded machine.
STOP_WITHIN_S = 3.0


def interrupted(call, after_s=0.5):
    """Runs call() with SIGINT sent after `after_s`; returns the seconds from signal to raise."""
    timer = threading.Timer(after_s, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    t0 = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        call()
    timer.join()
    late = time.monotonic() - t0 - after_s
    print("stopped %.3f s after the signal" % late)
    return late


def temp_folders():
    return set(glob.glob(os.path.join(tempfile.gettempdir(), "ornithopter-*")))


def test_ctrl_c_stops_an_aeromap_and_the_next_call_runs(tmp_path, monkeypatch):
    # A temporary folder of its own: other tests running at the same time (ctest -j) create and
    # remove ornithopter-* folders in the shared one.
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    v = ornithopter.load_vehicle(EFW)
    before = temp_folders()
    assert before == set()
    # 20 x 10 x 21 points on two threads: ~10 s uninterrupted.
    late = interrupted(lambda: ornithopter.aeromap(v, range(6, 26), range(8, 18), range(0, 21),
                                                   threads=2))
    assert late < STOP_WITHIN_S
    assert temp_folders() == before  # the temporary output folder is removed
    small = ornithopter.aeromap(v, [12], [12], [0], threads=1)  # the request was withdrawn
    assert small["summary"]["points"] == 1


def test_ctrl_c_stops_a_trim():
    v = ornithopter.load_vehicle(EFW)
    # The two-stage trim: Ceres on tethered runs, then free flight; the cost function reports a
    # cancelled run as failed and the solver's caller raises.
    assert interrupted(lambda: ornithopter.trim(v, freq=12), after_s=0.2) < STOP_WITHIN_S


def test_ctrl_c_stops_an_optimisation_and_keeps_its_journal(tmp_path):
    study = os.path.join(SOURCE_DIR, "studies", "paper", "optimize_magpie.toml")
    out = tmp_path / "opt"  # ~9 min uninterrupted
    assert interrupted(lambda: ornithopter.optimize(study, out=str(out)), after_s=2.0) < \
        STOP_WITHIN_S
    assert (out / "optimize.journal").exists()
    # The folder says so (docs/design.md 4.4): summary.json "interrupted", never "ok".
    assert json.loads((out / "summary.json").read_text())["status"] == "interrupted"


def test_interrupted_continuation_resumes_to_the_same_bytes(tmp_path):
    # 12 -> 16 Hz takes about 4 s (2.3 s to 14 Hz since the leading-multiplier route: a branch
    # that short could finish before the signal at 1.5 s).
    toml = tmp_path / "branch.toml"
    toml.write_text('kind = "continuation"\nname = "branch"\nvehicle = "%s"\n[trim]\n'
                    'freq_hz = 12.0\n[continuation]\nparameter = "freq_hz"\nto = 16.0\n'
                    'step = 0.1\nmax_points = 40\n' % EFW)
    whole, cut = tmp_path / "whole", tmp_path / "cut"
    ornithopter.run(str(toml), out=str(whole))
    interrupted(lambda: ornithopter.run(str(toml), out=str(cut)), after_s=1.5)
    assert not (cut / "continuation.csv").exists()
    ornithopter.run(str(toml), out=str(cut))  # resumes from the journal
    assert (cut / "continuation.csv").read_bytes() == (whole / "continuation.csv").read_bytes()


class SlowHandler:
    """A logging handler that takes 0.1 s a record: the main thread spends most of a run inside
    Python code, where the interpreter runs the SIGINT handler."""

    def __init__(self):
        import logging
        self.handler = logging.Handler(level=logging.DEBUG)
        self.handler.emit = lambda record: time.sleep(0.1)
        self.records = 0

    def __enter__(self):
        import logging
        logger = logging.getLogger("ornithopter")
        self.level = logger.level
        logger.setLevel(logging.DEBUG)
        logger.addHandler(self.handler)
        return self

    def __exit__(self, *exc):
        import logging
        logger = logging.getLogger("ornithopter")
        logger.removeHandler(self.handler)
        logger.setLevel(self.level)


def test_ctrl_c_inside_a_logging_handler_still_interrupts(tmp_path):
    # A KeyboardInterrupt raised inside logging (the run's progress lines going to a handler) is
    # the caller's Ctrl-C: it was once discarded as "unraisable" and the run went on to its end.
    toml = tmp_path / "branch.toml"
    toml.write_text('kind = "continuation"\nname = "branch"\nvehicle = "%s"\n[trim]\n'
                    'freq_hz = 12.0\n[continuation]\nparameter = "freq_hz"\nto = 16.0\n'
                    'step = 0.1\nmax_points = 40\n' % EFW)
    with SlowHandler():
        late = interrupted(lambda: ornithopter.run(str(toml), out=str(tmp_path / "cut")),
                           after_s=1.0)
    assert late < STOP_WITHIN_S
    assert not (tmp_path / "cut" / "continuation.csv").exists()
