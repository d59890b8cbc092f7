#!/usr/bin/env python3
"""Reference Lomb-Scargle periodograms for crates/pendulum-theory/tests/all/clock_log.rs,
computed by SciPy's scipy.signal.lombscargle with floating_mean=True (the
generalised periodogram of Zechmeister & Kuerster 2009: a sinusoid and a
constant fitted by least squares at each frequency).

Writes crates/pendulum-theory/tests/data/clock_log/lombscargle_series.csv
(a seeded rate series on a regular grid of 600 s with gaps: NaN where a
sample is missing) and lombscargle.csv: at frequencies on the grid
`pendulum_theory::clock_log::spectrum::gridded` evaluates (k / (L * 600 s),
L = 1024, the next power of two above twice the series), the normalised
power (normalize=True: the share of the variance explained) and the fitted
amplitude (normalize="amplitude").

Run from the repository root: python3 tools/reference/lombscargle.py
(needs numpy and scipy >= 1.15; the committed files were made with
SciPy 1.17.1 and numpy 2.4)."""
import csv
import os

import numpy as np
from scipy.signal import lombscargle

OUT = "crates/pendulum-theory/tests/data/clock_log"
N, STEP = 500, 600.0


def main():
    rng = np.random.default_rng(20261124)
    t = np.arange(N) * STEP
    # A daily cycle, a semidiurnal one, an offset, a trend and red noise:
    # what a clock's rate in s/day looks like.
    y = (0.3 + 0.2 * np.sin(2 * np.pi * t / 86400 + 0.4)
         + 0.05 * np.cos(2 * np.pi * t / 44714.0) + 1e-7 * t
         + 0.02 * rng.standard_normal(N) + np.cumsum(0.002 * rng.standard_normal(N)))
    keep = np.ones(N, bool)
    for start in rng.integers(0, N - 20, 6):  # six gaps of up to 20 samples
        keep[start:start + rng.integers(3, 20)] = False
    y[~keep] = np.nan
    length = 1024
    ks = np.arange(3, length // 2 + 1, 3)
    f = ks / (length * STEP)
    w = 2 * np.pi * f
    tk, yk = t[keep], y[keep]
    power = lombscargle(tk, yk, w, normalize=True, floating_mean=True)
    # The complex amplitude: its modulus is the sinusoid's amplitude.
    amplitude = np.abs(lombscargle(tk, yk, w, normalize="amplitude", floating_mean=True))
    os.makedirs(OUT, exist_ok=True)
    with open(os.path.join(OUT, "lombscargle_series.csv"), "w", newline="") as fh:
        out = csv.writer(fh)
        out.writerow(["time_s", "rate_s_per_day"])
        for a, b in zip(t, y):
            out.writerow([f"{a:.1f}", "NaN" if np.isnan(b) else repr(float(b))])
    with open(os.path.join(OUT, "lombscargle.csv"), "w", newline="") as fh:
        out = csv.writer(fh)
        out.writerow(["frequency_hz", "power", "amplitude"])
        for a, b, c in zip(f, power, amplitude):
            out.writerow([repr(float(a)), repr(float(b)), repr(float(c))])


if __name__ == "__main__":
    main()
