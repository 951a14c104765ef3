"""simulate: the CLI's summary.json to the last bit, histories equal to histories.csv, option
errors as InputError, Ctrl-C."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import ornithopter
from conftest import RFW, cli, read_csv_columns, read_summary, without_timings


def test_tethered_equals_cli(tmp_path):
    out = tmp_path / "cli"
    assert cli("simulate", RFW, "--cycles", 3, "--theta", 20, "-o", out) == 0
    expected = read_summary(out)
    got = ornithopter.simulate(ornithopter.load_vehicle(RFW), cycles=3, theta=20)
    histories = got.pop("histories")
    assert without_timings(got) == without_timings(expected)
    assert got["status"] == "ok" and got["cycles"] == 3
    columns = read_csv_columns(out / "histories.csv")
    assert list(columns) == [k for k in histories if k != "units"]
    for name, values in columns.items():
        assert np.array_equal(histories[name], np.array(values)), name
    assert histories["units"]["FV"] == "N"
    # One array behind the columns: views, no copy per column or sample.
    assert histories["FV"].base is not None
    assert histories["FV"].base is histories["FH"].base


def test_histories_off_and_history_every():
    v = ornithopter.load_vehicle(RFW)
    a = ornithopter.simulate(v, cycles=2, histories=False)
    assert "histories" not in a
    b = ornithopter.simulate(v, cycles=2, history_every=5)
    full = ornithopter.simulate(v, cycles=2)
    assert np.array_equal(b["histories"]["t"], full["histories"]["t"][::5])
    # Unsampled, the integrator takes its own steps: the means agree within its tolerance.
    for k in ("FH_N", "power_W", "hinge_power_W"):
        assert abs(a["mean"][k] - full["mean"][k]) <= 1e-3 * abs(full["mean"][k]), k
    assert abs(a["mean"]["FV_N"] - full["mean"]["FV_N"]) <= 1e-3 * abs(full["mean"]["FH_N"])
    assert "last_cycle" in full and "last_cycle" not in a


def test_bad_option_raises_input_error():
    v = ornithopter.load_vehicle(RFW)
    with pytest.raises(ornithopter.InputError) as e:
        ornithopter.simulate(v, cycles=0)
    assert e.value.key == "simulate.cycles"
    assert e.value.expected
    with pytest.raises(ornithopter.InputError) as e:
        ornithopter.simulate(v, speed=-3.0)
    assert e.value.key == "simulate.speed_mps"
    with pytest.raises(ornithopter.InputError) as e:
        ornithopter.simulate(v, no_such_option=1)
    assert "no_such_option" in e.value.key


def test_set_field_changes_the_run():
    v = ornithopter.load_vehicle(RFW)
    a = ornithopter.simulate(v, cycles=2, histories=False)
    v["wing.strips"] = 20
    b = ornithopter.simulate(v, cycles=2, histories=False)
    assert b["strips"] == 20 and a["strips"] != 20
    assert a["mean"]["FV_N"] != b["mean"]["FV_N"]


def test_ctrl_c_stops_a_long_run():
    v = ornithopter.load_vehicle(RFW)
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    t0 = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        ornithopter.simulate(v, cycles=100000, histories=False)  # ~15 s uninterrupted
    assert time.monotonic() - t0 < 3.0
    timer.join()


def test_free_flight_equals_cli(tmp_path):
    from conftest import EFW
    out = tmp_path / "cli"
    assert cli("simulate", EFW, "--mode", "free", "--cycles", 4, "-o", out) == 0
    got = ornithopter.simulate(ornithopter.load_vehicle(EFW), mode="free", cycles=4)
    histories = got.pop("histories")
    assert without_timings(got) == without_timings(read_summary(out))
    columns = read_csv_columns(out / "histories.csv")
    for name, values in columns.items():
        assert np.array_equal(histories[name], np.array(values)), name
