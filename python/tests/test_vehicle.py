"""load_vehicle, load_study and a vehicle's fields by file key, checked like the file reader."""
import os
import subprocess

import pytest

import ornithopter
from conftest import BINARY, EFW, RFW, SOURCE_DIR


def test_version_is_the_cli_version():
    if not BINARY:
        pytest.skip("ORNI_BINARY is not set")
    out = subprocess.run([BINARY, "--version"], capture_output=True, text=True, check=True).stdout
    assert out.split()[1] == ornithopter.__version__
    assert ornithopter.__version__.count(".") == 2


def test_get_and_set_by_file_key():
    v = ornithopter.load_vehicle(EFW)
    assert isinstance(v["tail.arm_m"], float)
    assert "tail.arm_m" in v.keys()
    v["tail.arm_m"] = 0.14
    assert v["tail.arm_m"] == 0.14
    v["wing.strips"] = 20
    assert v["wing.strips"] == 20
    with pytest.raises(KeyError):
        v["tail.no_such_key"]


def test_bad_value_raises_input_error_naming_the_key():
    v = ornithopter.load_vehicle(EFW)
    before = v["tail.arm_m"]
    with pytest.raises(ornithopter.InputError) as e:
        v["tail.arm_m"] = -0.1
    assert e.value.key == "tail.arm_m"
    assert e.value.file == "<python>"
    assert e.value.expected != ""
    assert "tail.arm_m" in str(e.value)
    assert v["tail.arm_m"] == before  # unchanged
    with pytest.raises(ornithopter.InputError) as e:
        v["wing.strips"] = 2.5  # an integer key
    assert e.value.key == "wing.strips"
    with pytest.raises(ornithopter.InputError) as e:
        v["tail.arm_mm"] = 0.1  # unknown key, as in a file
    assert "tail.arm_mm" in e.value.key
    assert isinstance(e.value, ValueError)


def test_bad_file_names_file_line_key(tmp_path):
    bad = tmp_path / "bad.toml"
    text = open(RFW, encoding="utf-8").read().replace("semispan_m = ", "semispan_m = -", 1)
    assert text != open(RFW, encoding="utf-8").read()
    bad.write_text(text)
    with pytest.raises(ornithopter.InputError) as e:
        ornithopter.load_vehicle(bad)
    assert e.value.file.endswith("bad.toml")
    assert e.value.line > 0
    assert e.value.key == "wing.semispan_m"
    assert e.value.expected


def test_load_study():
    s = ornithopter.load_study(os.path.join(SOURCE_DIR, "studies", "examples", "rfw_theta20.toml"))
    assert s.kind == "simulate"
    assert s.name
    with pytest.raises(FileNotFoundError):  # as open() would: not an InputError
        ornithopter.load_study(os.path.join(SOURCE_DIR, "no_such_study.toml"))


def test_docstrings_say_units_and_defaults():
    for f in (ornithopter.simulate, ornithopter.trim, ornithopter.aeromap, ornithopter.modes,
              ornithopter.optimize, ornithopter.run, ornithopter.load_vehicle,
              ornithopter.load_study):
        assert f.__doc__ and len(f.__doc__) > 80
    assert "Hz" in ornithopter.trim.__doc__ and "default" in ornithopter.trim.__doc__
    assert "m/s" in ornithopter.simulate.__doc__ and "deg" in ornithopter.simulate.__doc__


def test_missing_file_raises_file_not_found(tmp_path):
    missing = tmp_path / "no_such_vehicle.toml"
    for load in (ornithopter.load_vehicle, ornithopter.load_study, ornithopter.run):
        with pytest.raises(FileNotFoundError) as e:
            load(missing)
        assert e.value.filename == str(missing)
    # A directory is not a file either.
    with pytest.raises(FileNotFoundError):
        ornithopter.load_vehicle(tmp_path)
