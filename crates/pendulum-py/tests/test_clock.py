"""The clock from Python: the binary's figures on the same clock (the same
library), the isochronism curve, a long run, bad input."""

import json
import math
import subprocess

import numpy as np
import pytest

import pendulum_theory as pt
from test_simulate import binary


def test_the_steady_state_as_the_binary():
    cli = json.loads(subprocess.run(
        [str(binary()), "clock", "--length", "0.99362m", "--escapement", "recoil", "--drive", "2e-05J", "--json"],
        capture_output=True, text=True, check=True,
    ).stdout)["steady"]
    ours = pt.clock(0.99362, escapement="recoil", drive_energy=20e-6)["steady"]
    assert ours == cli


def test_isochronism_and_a_long_run():
    f = np.array([0.05, 0.5, 1.0, 2.0])
    curve = pt.clock(0.99362, drive_energy=20e-6, drive_factor=f)["isochronism"]
    assert [p["stops"] for p in curve] == [True, False, False, False]
    assert "amplitude_rad" not in curve[0]
    rates = np.array([p["rate_s_per_day"] for p in curve[1:]])
    assert np.all(np.diff(rates) < 0)  # the deadbeat loses as the drive grows
    rows, summary = pt.clock_run(0.99362, 8 * 86400, every=3600, drive_energy=20e-6,
                                 drive_schedule=([0, 8 * 86400], [1.0, 0.7]))
    assert rows["time_s"].shape == (8 * 24 + 1,)
    assert rows["amplitude_rad"][-1] < rows["amplitude_rad"][0]
    assert rows["time_error_s"][-1] > 0  # a smaller arc: less circular error, the clock gains
    assert summary["long_run"]["beats"] == rows["beats"][-1]


def test_a_rate_change_from_outside():
    # A clock that gains 2 s/day from the start gains 2 s a day to 1e-6 s
    # (the period shortens by 1/(1 + 2/86400)); a warm spell from day 1 at
    # -0.5 s/day per °C and 10 °C costs 5 s a day from then on.
    base = dict(drive_energy=20e-6, every=3600)
    _, plain = pt.clock_run(0.99362, 8 * 86400, **base)
    _, gaining = pt.clock_run(0.99362, 8 * 86400, rate_schedule=([0], [2.0]), **base)
    # The last row falls on the first turning point past the 8 days.
    plain, gaining = plain["long_run"], gaining["long_run"]
    expected = 2.0 * gaining["duration_s"] / 86400
    assert abs(gaining["time_error_s"] - plain["time_error_s"] - expected) < 1e-6
    _, warm = pt.clock_run(0.99362, 3 * 86400, rate_schedule=([0, 86400, 86401], [0, 0, -5.0]),
                           **base)
    _, cool = pt.clock_run(0.99362, 3 * 86400, **base)
    warm, cool = warm["long_run"], cool["long_run"]
    assert abs(warm["time_error_s"] - cool["time_error_s"] + 10.0) < 1e-3
    with pytest.raises(ValueError, match="rate_schedule"):
        pt.clock_run(0.99362, 86400, rate_schedule=([0, 0], [1.0, 2.0]), **base)
    with pytest.raises(ValueError, match="rate_schedule"):
        pt.clock_run(0.99362, 86400, rate_schedule=([0], [float("nan")]), **base)


def test_bad_clocks():
    with pytest.raises(ValueError, match="the pendulum stops"):
        pt.clock(0.99362, drive_energy=1e-6)
    with pytest.raises(ValueError, match="torque"):
        pt.clock(0.99362)
    with pytest.raises(ValueError, match="escapement"):
        pt.clock(0.99362, drive_energy=2e-5, escapement="verge")
    with pytest.raises(ValueError, match="lift_angle"):
        pt.clock(0.99362, drive_energy=2e-5, lift_angle=math.radians(400))
    with pytest.raises(ValueError, match="energy per beat"):
        pt.clock(0.99362, drive_torque=2e-4, escapement="impulse")
