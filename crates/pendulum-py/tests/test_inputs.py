"""Issue 44, the data and inputs from Python: a rate schedule that stops
the clock, the body tide's work estimate, and one unit per quantity (the
keywords named with their units where the module had two), each against
the binary where the binary takes the same question."""

import json
import re
import subprocess

import numpy as np
import pytest

import pendulum_theory as pt
from test_parity import STEEL_CLOCK as PARTS, check, write_csv
from test_simulate import binary

DAY = 86400.0


# --- a rate schedule that stops the clock -----------------------------------

def rate_case(tmp_path, times, rates):
    path = tmp_path / "rate.csv"
    write_csv(path, ["time_s", "rate_change_s_per_day"], [times, rates])
    args = ["clock", "--length", "0.99362m", "--drive", "2e-05J", "--duration", f"{2 * DAY!r}s",
            "--every", "3600.0s", "--drive-file", str(path), "--json"]
    return args, lambda: pt.clock_run(0.99362, 2 * DAY, every=3600.0,
                                      rate_schedule=(times, rates), drive_energy=2e-5)[1]


RATES = {
    # A ramp to -86400 s/day hung (its beats grew without end).
    "ramp_to_a_stop": ([0.0, DAY], [0.0, -86400.0]),
    "a_stop_at_once": ([0.0], [-86400.0]),
    "past_a_stop": ([0.0, DAY], [0.0, -86401.0]),
    "far_past_a_stop": ([0.0, DAY], [0.0, -1e300]),
    "twice_as_fast": ([0.0, DAY], [0.0, 86400.0]),
    "close_to_a_stop": ([0.0, DAY], [0.0, -86399.999999]),
    "a_day_behind_in_a_day_less_a_second": ([0.0], [-86399.0]),
    "ordinary": ([0.0, DAY], [0.0, 2.0]),
}


@pytest.mark.parametrize("name", sorted(RATES))
def test_a_rate_schedule_alike_from_python_and_the_drive_file(name, tmp_path):
    args, call = rate_case(tmp_path, *RATES[name])
    check(args, call)


@pytest.mark.parametrize("rate, says", [
    (-86400.0, "above -86400 s/day: a clock that loses a day a day has stopped; got -86400 s/day"),
    (-86401.0, "has stopped; got -86401 s/day"),
    (86400.0, "below 86400 s/day"),
])
def test_a_rate_schedule_that_stops_the_clock_is_refused_by_its_sample(rate, says):
    with pytest.raises(ValueError, match=r"^rate_schedule\[1\]: must be a rate change within a "
                                         r"day per day, .*" + re.escape(says)):
        pt.clock_run(0.99362, 2 * DAY, every=3600.0, rate_schedule=([0.0, DAY], [0.0, rate]),
                     drive_energy=2e-5)


def test_close_to_a_stop_the_run_ends_and_says_so():
    rows, result = pt.clock_run(0.99362, 2 * DAY, every=3600.0,
                                rate_schedule=([0.0, DAY], [0.0, -86399.999999]),
                                drive_energy=2e-5)
    run = result["long_run"]
    assert np.all(np.isfinite(rows["time_s"])) and run["duration_s"] > 3 * DAY
    assert "(a clock all but stopped)" in run["warnings"][0]["message"]


# --- one unit per quantity: pressures in hPa, named so -----------------------

def weather_run(pressure_hpa):
    return pt.clock_run(None, 2 * DAY, every=3600.0, parts=PARTS, drive_energy=2e-5,
                        weather={"time_s": [0.0, DAY], "pressure_hpa": pressure_hpa})[1]


def test_clock_run_takes_the_drive_files_pressure_in_hpa():
    """The weather's pressures are hPa, as the drive file's column and
    the CLI's --pressure (test_parity's test_clock_weather: the binary's
    run on the same file): hPa given to the old tuple (Pa) made the
    effect 100 times too small, silently. A fall of 30 hPa moves the
    clock's rate by the design's own barometric coefficient (-0.0110
    s/day per hPa: +0.331 s/day) less the circular error of the larger
    arc it swings in thinner air (-86400 s/day × ΔA²/16: -0.029 s/day)."""
    fell = weather_run([1013.25, 983.25])["long_run"]
    steady = weather_run([1013.25, 1013.25])["long_run"]
    per_hpa = pt.design(PARTS)["pressure_coefficient_s_per_day_per_hpa"]
    arc = -DAY * (fell["final_amplitude_rad"] ** 2 - steady["final_amplitude_rad"] ** 2) / 16.0
    expected = -30.0 * per_hpa + arc
    moved = fell["final_rate_s_per_day"] - steady["final_rate_s_per_day"]
    assert moved == pytest.approx(expected, rel=1e-2), (moved, expected)
    assert moved > 0.25


def test_the_old_weather_tuple_and_a_pressure_in_pa_are_refused_by_name():
    with pytest.raises(ValueError, match=r"^weather: give a dict of named columns \(time_s, "
                                         r"temperature_c, pressure_hpa, .*pressures in Pa\)"):
        pt.clock_run(None, DAY, every=3600.0, parts=PARTS,
                     weather=([0.0, DAY], [20.0, 21.0], [101325.0, 101325.0]))
    with pytest.raises(ValueError, match=r"^weather: no column 'pressure_pa' \(pressures go "
                                         r"in hPa as pressure_hpa\)"):
        pt.clock_run(None, DAY, every=3600.0, parts=PARTS,
                     weather={"time_s": [0.0, DAY], "pressure_pa": [101325.0, 101325.0]})
    with pytest.raises(ValueError, match=r"^weather: give its times as time_s"):
        pt.clock_run(None, DAY, every=3600.0, parts=PARTS,
                     weather={"pressure_hpa": [1013.25, 1013.25]})
    with pytest.raises(TypeError, match=r"design\(\) takes no keyword 'pressure'; give "
                                        r"pressure_hpa: a pressure in hPa"):
        pt.design(PARTS, pressure=101325.0)


def test_a_logs_weather_keywords_name_their_units():
    """``clock_log`` took ``pressure`` in hPa and ``amplitude`` in
    degrees where every other amplitude keyword is radians, unnamed: the
    keywords are ``pressure_hpa`` and ``amplitude_deg``, the old names
    refused, and a pressure in hPa gives the coefficient the file does."""
    t = np.arange(3 * 144) * 600.0
    pressure = 1013.0 + 5.0 * np.cos(t / 50000.0)
    rate = 0.5 - 0.01 * (pressure - 1013.0)
    offset = np.concatenate([[0.0], np.cumsum(rate[1:] * 600.0 / 86400.0)])
    offset += 1e-5 * np.sin(np.arange(t.size) * 1.7)
    for old in ["pressure", "amplitude"]:
        with pytest.raises(TypeError, match=rf"clock_log\(\) takes no keyword '{old}'; give "
                                            rf"{old}_(hpa|deg): the log's"):
            pt.clock_log(t, offset, **{old: pressure})
    fitted = pt.clock_log(t, offset, pressure_hpa=pressure)
    assert abs(fitted["coefficients"]["pressure_s_per_day_per_hpa"] + 0.01) < 1e-3


def test_a_pressure_out_of_range_is_named_by_its_keyword_in_hpa():
    with pytest.raises(ValueError, match=r"^pressure_hpa: must lie between 1 Pa and 1200 hPa, "
                                         r"got -1 hPa$"):
        pt.design(PARTS, pressure_hpa=-1.0)
    with pytest.raises(ValueError, match=r"^pressure_hpa\[1\]: .*\(1 Pa to 1200 hPa\)$"):
        weather_run([1013.25, -1.0])


# --- the body tide's work ------------------------------------------------------

#: 1900-01-02 and 2099-12-30, Unix s.
CENTURIES = (-2_208_902_400.0, 4_102_272_000.0)


def test_tide_times_over_centuries_are_judged_as_the_binary_judges_them():
    """A row every 40 days over two centuries (1,827 rows, 2,437 months of
    K1 means, half a minute) needs force, in the binary's words; ten
    million times (they ran 50 s unasked) too; 21 rows a decade apart
    are computed, each its own tide."""
    args = ["tide", "--latitude", "48.33", "--longitude", "8.33", "--from", "1900-01-02",
            "--to", "2099-12-30", "--every", "40day"]
    out = subprocess.run([str(binary()), *args], capture_output=True, text=True)
    assert out.returncode == 2 and out.stdout == ""
    times = np.arange(CENTURIES[0], CENTURIES[1] + 1.0, 40 * DAY)
    assert len(times) == 1827
    with pytest.raises(ValueError) as refused:
        pt.tide(48.33, 8.33, times)
    said = str(refused.value)
    assert said.startswith("time: 1827 times over 73040 days: about "), said
    assert "force it" in said
    assert out.stderr.strip() == "error: --every: " + said.split(": ", 1)[1]
    many = 1_767_225_600.0 + np.arange(10_000_000, dtype=np.float64)
    with pytest.raises(ValueError, match=r"^time: 10000000 times over 116 days: about "):
        pt.tide(48.33, 8.33, many)
    decades = np.arange(CENTURIES[0], CENTURIES[1] + 1.0, 3650 * DAY)
    rows = pt.tide(48.33, 8.33, decades)
    alone = pt.tide(48.33, 8.33, decades[5:6])
    assert len(rows["gravity_change_nm_s2"]) == 21
    assert rows["gravity_change_nm_s2"][5] == pytest.approx(alone["gravity_change_nm_s2"][0],
                                                           abs=1e-9)
