"""A measurement file from Python (``fit_file``) and the ``pendulum``
command the package installs: both the very program the binary is, so
their answers equal the binary's, key for key, and their refusals its
sentences."""

import json
import os
import pathlib
import shutil
import subprocess
import sys

import pytest

import pendulum_theory as pt
from test_simulate import ROOT, binary

REAL = ROOT / "crates" / "pendulum-cli" / "tests" / "data" / "real"

#: (fit, file relative to the repository, keywords, the same as flags)
CASES = [
    ("decay", "examples/rundown.csv", {"length": 0.994}, ["--length", "0.994m"]),
    ("decay", "examples/rundown-semicolon.csv", {"length": 0.994, "mass": 1.2},
     ["--length", "0.994m", "--mass", "1.2kg"]),
    ("trajectory", "crates/pendulum-cli/tests/data/real/pendulum_length2.trk",
     {"pivot": "fit", "length": 0.9906, "length_uncertainty": 0.002},
     ["--pivot", "fit", "--length", "0.9906m", "--length-uncertainty", "0.002m"]),
    ("trajectory", "crates/pendulum-cli/tests/data/real/pendulum_fullPeriod.trk",
     {"pivot": "fit", "start": 1.0, "stop": 20.0}, ["--pivot", "fit", "--from", "1s", "--to", "20s"]),
    ("trajectory", "examples/tracker.txt", {}, []),
    ("period", "crates/pendulum-cli/tests/data/period/amedeker2022.csv", {}, []),
    ("period", "crates/pendulum-cli/tests/data/period/nelson_olsson1986.csv", {}, []),
]


def binary_json(args):
    out = subprocess.run([str(binary()), *args, "--json"], capture_output=True, text=True,
                         cwd=ROOT)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout)


@pytest.mark.parametrize("fit,path,kw,flags", CASES, ids=[f"{c[0]}:{pathlib.Path(c[1]).name}"
                                                         for c in CASES])
def test_fit_file_is_the_binarys_fit(fit, path, kw, flags, monkeypatch):
    monkeypatch.chdir(ROOT)
    mine = pt.fit_file(path, fit, **kw)
    theirs = binary_json(["fit", fit, path, *flags])
    assert isinstance(mine.pop("figure")["panels"], list)
    assert isinstance(mine.pop("notes"), list)
    assert mine == theirs


@pytest.mark.parametrize("kw,flags", [
    ({"length": -1.0}, ["--length", "-1m"]),
    ({"length_uncertainty": 0.001}, ["--length-uncertainty", "0.001m"]),
    ({"frame_rate": 0.0}, ["--frame-rate", "0"]),
    ({"pivot": "1,inf"}, ["--pivot", "1,inf"]),
    ({"run": 0}, ["--run", "0"]),
])
def test_fit_file_refuses_as_the_binary(kw, flags, monkeypatch):
    monkeypatch.chdir(ROOT)
    with pytest.raises(ValueError) as caught:
        pt.fit_file("examples/rundown.csv", "decay", **kw)
    out = subprocess.run([str(binary()), "fit", "decay", "examples/rundown.csv", *flags],
                         capture_output=True, text=True, cwd=ROOT)
    assert out.returncode == 2 and out.stdout == ""
    assert out.stderr.strip() == f"error: {caught.value}"


def test_a_length_uncertainty_without_its_length_is_refused(monkeypatch):
    # A table against lengths has no one length: its uncertainty would be
    # taken for nothing (the command line's --length-uncertainty needs
    # --length); from a file and from arrays alike.
    monkeypatch.chdir(ROOT)
    table = "examples/notebooks/lengths.csv"
    with pytest.raises(ValueError, match="^--length-uncertainty: is the uncertainty of the "
                                         "pendulum's one length"):
        pt.fit_file(table, "period", length_uncertainty=0.002)
    with pytest.raises(ValueError, match="^pendulum_length_standard_error: is the uncertainty"):
        pt.fit_period([1.0, 1.5, 2.0], length=[0.25, 0.56, 0.99], length_uncertainty=0.002)


@pytest.mark.parametrize("value,words", [(float("nan"), "a value that is not a number"),
                                         (float("inf"), "an infinite value")])
def test_a_number_that_is_not_finite_is_refused_as_the_arrays_fits_refuse_it(value, words,
                                                                            monkeypatch):
    monkeypatch.chdir(ROOT)
    with pytest.raises(ValueError, match=f"^length: must be a finite number, got {words}$"):
        pt.fit_file("examples/rundown.csv", "decay", length=value)
    with pytest.raises(ValueError, match=f"^length: must be a finite number, got {words}$"):
        pt.fit_decay([0, 1, 2, 3, 4, 5], [0.1, 0.09, 0.08, 0.07, 0.06, 0.05], length=value)


def test_a_missing_file_is_a_value_error():
    with pytest.raises(ValueError, match="no-such-file.csv: cannot read it"):
        pt.fit_file("no-such-file.csv", "decay")


def command():
    """The ``pendulum`` console script installed beside this interpreter."""
    here = pathlib.Path(sys.executable).parent / "pendulum"
    return str(here) if here.exists() else shutil.which("pendulum")


@pytest.mark.parametrize("args", [
    ["period", "--length", "0.99362m", "--amplitude", "2deg", "--json"],
    ["fit", "decay", "examples/rundown.csv", "--length", "0.994m"],
    ["regulate", "--rate", "+12s/day", "--length", "0.994m"],
    ["period", "--length", "-1m", "--amplitude", "2deg"],
    ["period", "--help"],
    ["--version"],
    ["no-such-command"],
])
def test_the_console_script_is_the_binary(args):
    script = command()
    assert script is not None, "the package installs a `pendulum` command"
    ours = subprocess.run([script, *args], capture_output=True, cwd=ROOT)
    theirs = subprocess.run([str(binary()), *args], capture_output=True, cwd=ROOT)
    assert (ours.returncode, ours.stdout, ours.stderr) == \
        (theirs.returncode, theirs.stdout, theirs.stderr)
