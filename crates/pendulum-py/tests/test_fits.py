"""The fits from Python: the same figures as the binary's JSON on the same
data (the same library), and bad input as ValueError."""

import json
import math
import subprocess

import numpy as np
import pytest

import pendulum_theory as pt
from test_simulate import binary


def test_fit_decay_as_the_binary(tmp_path):
    rng = np.random.default_rng(7)
    t = np.linspace(0, 3000, 120)
    a = 0.05 * np.exp(-2e-4 * t) / (1 + 0.002 * t) + rng.normal(0, 2e-5, t.size)
    path = tmp_path / "decay.csv"
    np.savetxt(path, np.column_stack([t, a]), delimiter=",", header="time_s,amplitude_rad", comments="")
    out = subprocess.run(
        [str(binary()), "fit", "decay", str(path), "--length", "0.99362m", "--json"],
        capture_output=True, text=True, check=True,
    )
    cli = json.loads(out.stdout)
    ours = pt.fit_decay(t, a, length=0.99362)
    assert ours.preferred == cli["preferred"]
    assert ours["omega_rad_s"] == pytest.approx(cli["omega_rad_s"], rel=1e-15)
    assert ours["preferred"] == cli["preferred"]
    for mine, theirs in zip(ours["models"], cli["models"]):
        assert mine["model"] == theirs["model"]
        for name, value in theirs["parameters"].items():
            assert mine["parameters"][name] == pytest.approx(value, rel=1e-12, abs=1e-300), name
            assert mine["standard_errors"][name] == pytest.approx(theirs["standard_errors"][name], rel=1e-12)
        assert mine["akaike_weight"] == pytest.approx(theirs["akaike_weight"], rel=1e-9, abs=1e-300)
    best = next(m for m in cli["models"] if m["model"] == cli["preferred"])
    assert ours.parameters == pytest.approx(best["parameters"], rel=1e-12)
    assert ours.standard_errors.keys() == best["standard_errors"].keys()


def test_fit_beats_as_the_binary(tmp_path):
    rng = np.random.default_rng(3)
    n = 600
    beat = 0.5 * (1 - 12 / 86400)  # a 7,200 bph clock gaining 12 s/day
    t = np.arange(n) * beat + np.where(np.arange(n) % 2 == 0, 0.0, 1.5e-3) + rng.normal(0, 1e-4, n)
    path = tmp_path / "beats.csv"
    np.savetxt(path, t, header="time_s", comments="")
    cli = json.loads(subprocess.run(
        [str(binary()), "fit", "beats", str(path), "--json"],
        capture_output=True, text=True, check=True,
    ).stdout)
    ours = pt.fit_beats(t)
    for key in ["beats", "mean_beat_s", "beats_per_hour", "nominal_beat_s", "rate_s_per_day", "beat_error_ms", "jitter_ms"]:
        assert ours[key] == pytest.approx(cli[key], rel=1e-12), key
    assert abs(ours["rate_s_per_day"] - 12) < 0.5
    assert ours["allan_deviation"] == cli["allan_deviation"]
    assert pt.fit_beats(t, bph=7200)["rate_s_per_day"] == pytest.approx(ours["rate_s_per_day"], rel=1e-12)


def test_fits_refuse_bad_input():
    with pytest.raises(ValueError, match="points"):
        pt.fit_decay([0.0, 1.0], [0.1, 0.09])
    with pytest.raises(ValueError, match="model"):
        pt.fit_decay(np.arange(10.0), np.exp(-np.arange(10.0)), model="cubic")
    with pytest.raises(ValueError, match="one-dimensional"):
        pt.fit_decay(np.zeros((3, 3)), np.zeros((3, 3)))
    with pytest.raises(ValueError, match="too few"):
        pt.fit_beats([0.0, 0.5, 1.0])


def test_fit_trajectory_as_the_binary(tmp_path):
    rng = np.random.default_rng(11)
    t = np.arange(0, 12, 0.01)
    theta = pt.damped_angle(t, 0.5, math.radians(8), 0.004) + rng.normal(0, 2e-4, t.size)
    path = tmp_path / "video.csv"
    np.savetxt(path, np.column_stack([t, np.degrees(theta)]), delimiter=",", header="time_s,angle_deg", comments="")
    cli = json.loads(subprocess.run(
        [str(binary()), "fit", "trajectory", str(path), "--length", "0.5m", "--json"],
        capture_output=True, text=True, check=True,
    ).stdout)
    ours = pt.fit_trajectory(t, theta, length=0.5)
    assert ours["model"] == cli["model"] == ours.preferred == "nonlinear"
    # The CSV holds degrees: the data differ in the last bit, the phase (near 0) by 1e-11 rad.
    assert ours.parameters == pytest.approx(cli["parameters"], rel=1e-9, abs=1e-9)
    assert ours.standard_errors == pytest.approx(cli["standard_errors"], rel=1e-6)
    assert ours["residual_rms_rad"] == pytest.approx(cli["residual_rms_rad"], rel=1e-9)
    # The linear model at 8° gives no g, and says why.
    linear = pt.fit_trajectory(t, theta, "linear", length=0.5)
    assert "g_m_s2" not in linear.parameters and linear["warnings"]


def test_fit_trajectory_of_a_gyroscope_as_the_binary():
    """A phyphox gyroscope record (tests/data/gyroscope, made by SciPy):
    the three axes as an (n, 3) array give the binary's figures whole."""
    from pathlib import Path
    path = Path(__file__).parents[2] / "pendulum-cli" / "tests" / "data" / "gyroscope" / "gyroscope-comma.csv"
    cli = json.loads(subprocess.run(
        [str(binary()), "fit", "trajectory", str(path), "--length", "0.45m", "--json"],
        capture_output=True, text=True, check=True,
    ).stdout)
    d = np.genfromtxt(path, delimiter=",", skip_header=1)
    t = d[:, 0] - d[0, 0]  # the reader measures times from the first row
    ours = pt.fit_trajectory(t, angular_velocity=d[:, 1:4], length=0.45)
    assert ours["observed"] == cli["observed"] == "angular_velocity"
    assert ours.parameters == pytest.approx(cli["parameters"], rel=1e-9, abs=1e-12)
    assert ours.standard_errors == pytest.approx(cli["standard_errors"], rel=1e-6)
    assert ours["gyroscope_axis"] == pytest.approx(cli["gyroscope_axis"], rel=1e-12)
    assert ours["residual_rms_rad_s"] == pytest.approx(cli["residual_rms_rad_s"], rel=1e-9)
    assert "residual_rms_rad" not in ours
    # One axis alone is that axis.
    one = pt.fit_trajectory(t, angular_velocity=d[:, 2])
    assert one["gyroscope_axis"] == [1.0]
    with pytest.raises(ValueError, match="not both"):
        pt.fit_trajectory(t, np.zeros_like(t), angular_velocity=d[:, 2])
    with pytest.raises(ValueError, match="angle"):
        pt.fit_trajectory(t)


def test_the_length_uncertainty_is_in_g():
    """Issue 44, item 2, from Python: a 0.8 m pendulum measured to 2 mm
    has g's standard error at least 9.81 × 2/800 = 0.0245 m/s², its parts
    listed, in every fit that gives g; the same figures as the binary's
    --length-uncertainty."""
    from pathlib import Path
    path = Path(__file__).parents[2] / "pendulum-cli" / "tests" / "data" / "record_q" / "drag.csv"
    d = np.genfromtxt(path, delimiter=",", skip_header=3)
    t, theta = d[:, 0], d[:, 1]
    ours = pt.fit_trajectory(t, theta, length=0.8, length_uncertainty=0.002)
    assert ours.standard_errors["g_m_s2"] >= 0.024
    parts = ours["standard_error_parts"]["g_m_s2"]
    assert math.hypot(parts["fit"], parts["length"]) == pytest.approx(
        ours.standard_errors["g_m_s2"], rel=1e-12)
    cli = json.loads(subprocess.run(
        [str(binary()), "fit", "trajectory", str(path), "--length", "0.8m",
         "--length-uncertainty", "2mm", "--json"],
        capture_output=True, text=True, check=True,
    ).stdout)
    assert ours.standard_errors["g_m_s2"] == pytest.approx(cli["standard_errors"]["g_m_s2"], rel=1e-6)
    # Without it, the length's part is absent (None) and g's ± is the fit's.
    bare = pt.fit_trajectory(t, theta, length=0.8)
    assert bare["standard_error_parts"]["g_m_s2"]["length"] is None
    assert bare.standard_errors["g_m_s2"] < 1e-3
    # A period table of the pendulum: the same length's part.
    a = np.radians([5.0, 10.0, 15.0, 20.0])
    periods = np.array([pt.period(0.8, x) for x in a])
    table = pt.fit_period(periods, amplitude=a, pendulum_length=0.8, length_uncertainty=0.002)
    assert table.standard_errors["g_m_s2"] >= 0.024
    with pytest.raises(ValueError, match="^length_uncertainty: is the length"):
        pt.fit_trajectory(t, theta, length_uncertainty=0.002)
    with pytest.raises(ValueError, match="^length_uncertainty: must be positive"):
        pt.fit_trajectory(t, theta, length=0.8, length_uncertainty=-1.0)
