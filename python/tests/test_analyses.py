"""modes, aeromap (threads, GIL) and trim against the CLI's summary.json."""
import threading
import time

import numpy as np

import ornithopter
from conftest import EFW, RFW, cli, read_csv_columns, read_summary, without_timings


def test_modes_equals_cli(tmp_path):
    out = tmp_path / "cli"
    assert cli("modes", EFW, "-o", out) == 0
    got = ornithopter.modes(ornithopter.load_vehicle(EFW))
    table = got.pop("table")
    assert without_timings(got) == without_timings(read_summary(out))
    assert np.array_equal(table["frequency"], np.array(got["frequencies_hz"]))


def test_aeromap_equals_cli_and_threads(tmp_path):
    out = tmp_path / "cli"
    assert cli("aeromap", RFW, "--speed", "4:8:2", "--freq", "4:4:1", "--theta", "0:20:2",
               "-o", out) == 0
    v = ornithopter.load_vehicle(RFW)
    one = ornithopter.aeromap(v, [4, 8], [4], np.array([0.0, 20.0]), threads=1)
    two = ornithopter.aeromap(v, [4, 8], [4], [0, 20], threads=2)
    expected = read_csv_columns(out / "aeromap.csv")
    for name, values in expected.items():
        assert np.array_equal(one[name], np.array(values)), name
        assert np.array_equal(two[name], one[name]), name
    assert one["summary"]["points"] == 4
    assert without_timings(one["summary"]) == without_timings(read_summary(out))


def test_gil_released_during_aeromap():
    v = ornithopter.load_vehicle(EFW)  # flexible wing: 20 points take a while
    count = [0]
    stop = threading.Event()

    def spin():
        while not stop.is_set():
            count[0] += 1

    t = threading.Thread(target=spin)
    t.start()
    time.sleep(0.05)
    before = count[0]
    t0 = time.monotonic()
    ornithopter.aeromap(v, [12, 14, 16, 18], [12], [0, 5, 10, 15, 20], threads=1)
    elapsed = time.monotonic() - t0
    during = count[0] - before
    stop.set()
    t.join()
    # A held GIL would leave the spinning thread at most a few switch intervals (5 ms each).
    assert elapsed > 0.05
    assert during > 10000, (during, elapsed)


def test_trim_equals_cli(tmp_path):
    out = tmp_path / "cli"
    assert cli("trim", EFW, "--freq", 12, "-o", out) == 0
    got = ornithopter.trim(ornithopter.load_vehicle(EFW), freq=12)
    assert without_timings(got) == without_timings(read_summary(out))
    assert isinstance(got["converged"], bool)
    assert set(got["residual"]) == {"FV_N", "FH_N", "M_Nm"}


def test_trim_option_error_names_the_key():
    v = ornithopter.load_vehicle(EFW)
    try:
        ornithopter.trim(v, freq=12, max_iterations=-1)
    except ornithopter.InputError as e:
        assert e.key == "trim.max_iterations"
        assert e.expected
    else:
        raise AssertionError("no InputError")
