#!/usr/bin/env bash
# A year of a clock's log every 3 s (10,512,000 rows: time, offset,
# temperature, pressure) read, fitted (the rate model with its lag search
# and the tide) and its stability computed by `pendulum log`, with the
# wall and user time and the peak resident memory from /usr/bin/time -v;
# beside it allantools (the field's reference library) computing only the
# overlapping Allan deviation of the same offsets at octave τ.
# Run from the repository root: bash bench/log.sh [python with numpy and allantools]
set -euo pipefail
python=${1:-python3}
cargo build --release -q
bin=target/release/pendulum
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$python" - "$dir/year.csv" <<'PY'
import math, sys
import numpy as np
rng = np.random.default_rng(26)
n = 365 * 28800
t = np.arange(n) * 3.0
day = t / 86400.0
temp = 18 + 4 * np.sin(2 * np.pi * (day - 100) / 365.25) + 1.5 * np.sin(2 * np.pi * (day - 0.375))
knots = np.arange(0, t[-1] + 7200, 3600.0)
pressure = 1013 + np.interp(t, knots, np.cumsum(rng.normal(0, 0.5, len(knots))))
rate = 0.3 - 0.25 * (temp - 18) - 0.01 * (pressure - 1013) + rng.normal(0, 0.7, n)
x = np.concatenate([[0.0], np.cumsum(rate[1:] * 3.0 / 86400.0)]) + rng.normal(0, 2e-5, n)
with open(sys.argv[1], "w") as f:
    f.write("time_s,offset_s,temperature_c,pressure_hpa\n")
    for i in range(0, n, 100000):
        block = np.column_stack([t[i:i + 100000], x[i:i + 100000], temp[i:i + 100000],
                                 pressure[i:i + 100000]])
        np.savetxt(f, block, fmt=["%.0f", "%.7f", "%.3f", "%.2f"], delimiter=",")
PY
ls -l "$dir/year.csv" | awk '{printf "file: %.0f MB, ", $5 / 1e6}'
wc -l < "$dir/year.csv" | awk '{print $1 - 1, "rows"}'
/usr/bin/time -f "pendulum log (read, fit, stability): %e s wall, %U s user, %M kB peak" \
  "$bin" log "$dir/year.csv" --latitude 48.33 --longitude 8.33 --start 2026-01-01 --tides --json >"$dir/out.json"
"$python" - "$dir/out.json" <<'PY'
import json, sys
v = json.load(open(sys.argv[1]))
c, e = v["coefficients"], v["standard_errors"]
print("  rate %.4f s/day, temperature %.4f ± %.4f s/day/°C (truth -0.25), pressure %.5f ± %.5f (truth -0.01), "
      "lag %.0f s (truth 0), %d stability rows"
      % (v["rate_s_per_day"], c["temperature_s_per_day_per_c"], e["temperature_s_per_day_per_c"],
         c["pressure_s_per_day_per_hpa"], e["pressure_s_per_day_per_hpa"], v["temperature_lag_s"] or 0,
         len(v["stability"])))
PY
/usr/bin/time -f "allantools oadev alone (octave τ, from memory): %e s wall, %U s user, %M kB peak" \
  "$python" - "$dir/year.csv" <<'PY'
import sys
import numpy as np
import allantools
x = np.loadtxt(sys.argv[1], delimiter=",", skiprows=1, usecols=1)
taus, devs, _, _ = allantools.oadev(x, rate=1 / 3.0, data_type="phase", taus="octave")
print("  allantools: %d octave τ, oadev(3 s) = %.4e" % (len(taus), devs[0]))
PY
