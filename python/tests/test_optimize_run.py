"""optimize and run: the CLI's summary.json and files."""
import os

import ornithopter
from conftest import SOURCE_DIR, cli, read_summary, without_timings

HERE = os.path.dirname(os.path.abspath(__file__))
TINY = os.path.join(HERE, "data", "tiny_optimize.toml")


def test_optimize_equals_cli(tmp_path):
    out = tmp_path / "cli"
    assert cli("optimize", TINY, "-o", out) == 0
    got = ornithopter.optimize(ornithopter.load_study(TINY))
    assert without_timings(got) == without_timings(read_summary(out))
    assert got["kind"] == "optimize" and got["evaluations"] >= 1


def test_run_writes_the_cli_files(tmp_path):
    study = os.path.join(SOURCE_DIR, "studies", "examples", "rfw_theta20.toml")
    a, b = tmp_path / "cli", tmp_path / "py"
    assert cli("run", study, "-o", a) == 0
    got = ornithopter.run(study, out=str(b), figures=True)
    assert without_timings(got) == without_timings(read_summary(a))
    for name in sorted(os.listdir(a)):
        if name.endswith(".csv") or name.endswith(".gp"):
            assert (a / name).read_bytes() == (b / name).read_bytes(), name
    assert sorted(os.listdir(a)) == sorted(os.listdir(b))
    # Without figures (the default): the same files but the drawn figures.
    c = tmp_path / "py_quiet"
    ornithopter.run(study, out=str(c))
    drawn = {n for n in os.listdir(a) if n.endswith(".png") or n.endswith(".svg")}
    assert drawn and sorted(set(os.listdir(a)) - drawn) == sorted(os.listdir(c))
