"""Issue 44, the data and inputs from Python: a rate schedule that stops
the clock, the body tide's work estimate, and one unit per quantity (the
keywords named with their units where the module had two), each against
the binary where the binary takes the same question."""

import re

import numpy as np
import pytest

import pendulum_theory as pt
from test_parity import check, write_csv

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
    assert "(a clock all but stopped)" in run["warnings"][0]
