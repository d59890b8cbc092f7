"""simulate from Python: the same turning points as the `pendulum` binary
(the same library: equal to the last bit), the summary's keys as the
CLI's JSON, bad input as ValueError."""

import json
import math
import pathlib
import shutil
import subprocess

import numpy as np
import pytest

import pendulum_theory as pt

ROOT = pathlib.Path(__file__).resolve().parents[3]


def binary():
    path = ROOT / "target" / "release" / "pendulum"
    if not path.exists():
        subprocess.run(["cargo", "build", "--release", "-q", "-p", "pendulum-cli"], cwd=ROOT, check=True)
    return path


def test_the_same_turning_points_as_the_binary(tmp_path):
    swings = tmp_path / "swings.csv"
    out = subprocess.run(
        [str(binary()), "simulate", "--length", "0.99362m", "--amplitude", "10deg", "--q", "300",
         "--duration", "100s", "--swings", str(swings), "--json"],
        capture_output=True, text=True, check=True,
    )
    cli = json.loads(out.stdout)
    rows = np.genfromtxt(swings, delimiter=",", names=True)
    t, angle, rate, summary = pt.simulate(0.99362, math.radians(10), 100.0, q=300)
    assert summary["swings"] == cli["swings"] == len(t) - 1
    assert summary["final_amplitude_rad"] == cli["final_amplitude_rad"]
    for key in ["method", "swings", "final_time_s", "final_angle_rad", "final_amplitude_rad", "steps", "stopped"]:
        assert summary[key] == cli[key], key
    assert np.array_equal(t, rows["time_s"])
    assert np.array_equal(angle, rows["angle_rad"])
    assert np.array_equal(rate[1:], rows["rate_s_per_day"][1:])
    assert np.isnan(rate[0]) and np.all(np.diff(t) > 0)
    # Every turning point alternates sides and decays.
    assert np.all(np.sign(angle[1:]) == -np.sign(angle[:-1]))
    assert np.all(np.abs(angle[1:]) < np.abs(angle[:-1]))


def test_methods_agree_and_bad_input():
    a0 = math.radians(3)
    t1, a1, _, _ = pt.simulate(0.99362, a0, 200.0, q=1e4, method="symplectic", tolerance=1e-12)
    t2, a2, _, _ = pt.simulate(0.99362, a0, 200.0, q=1e4, method="averaged")
    assert len(t1) == len(t2)
    assert np.max(np.abs(t1 - t2)) < 1e-8
    assert np.max(np.abs(np.abs(a1) / np.abs(a2) - 1)) < 1e-9
    with pytest.raises(ValueError, match="length"):
        pt.simulate(-1.0, a0, 10.0)
    with pytest.raises(ValueError, match="method"):
        pt.simulate(1.0, a0, 10.0, method="euler")
    with pytest.raises(ValueError, match="give one of q, zeta"):
        pt.simulate(1.0, a0, 10.0, q=10, zeta=0.1)
    with pytest.raises(ValueError, match="exact method has no damping"):
        pt.simulate(1.0, a0, 10.0, q=10, method="exact")
