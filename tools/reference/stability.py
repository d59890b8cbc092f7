#!/usr/bin/env python3
"""Reference stability statistics for crates/pendulum-theory/tests/all/stability.rs,
computed by allantools (https://github.com/aewallin/allantools, the
library the time-and-frequency community checks against Stable32).

Writes crates/pendulum-theory/tests/data/stability/NAME.csv for four seeded
noise types (1000 phase points each, tau0 = 1 s): the series itself
(`phase_s` column) in one file and, in NAME_devs.csv, each statistic
(the Allan, modified Allan, time, Hadamard and total deviations and the
MTIE) at
octave averaging factors m = 1, 2, 4, ... as allantools computes it from
the phase data; in NAME_ci.csv, for the overlapping Allan, modified Allan
and overlapping Hadamard deviations, the noise type allantools identifies
(lag-1 autocorrelation), Greenhall's equivalent degrees of freedom and
the 1-sigma interval.

Run from the repository root: python3 tools/reference/stability.py
(needs numpy and allantools: pip install numpy allantools; the committed
files were made with allantools 2024.06 and numpy 2.4.6)."""
import csv
import os

import allantools
import numpy as np

OUT = "crates/pendulum-theory/tests/data/stability"
N = 1000


def series():
    """Seeded phase series of the four noise types a clock shows."""
    rng = np.random.default_rng(20261124)
    white_pm = rng.standard_normal(N) * 1e-9
    white_fm = np.concatenate([[0.0], np.cumsum(rng.standard_normal(N - 1) * 1e-9)])
    rw_fm = np.concatenate([[0.0], np.cumsum(np.cumsum(rng.standard_normal(N - 1) * 1e-11))])
    # Flicker frequency: 1/f frequency noise by spectral shaping of white
    # noise (Kasdin's method in the frequency domain), summed into phase.
    white = rng.standard_normal(2 * N)
    spectrum = np.fft.rfft(white)
    f = np.fft.rfftfreq(2 * N)
    f[0] = f[1]
    flicker_y = np.fft.irfft(spectrum / np.sqrt(f), 2 * N)[: N - 1] * 1e-10
    flicker_fm = np.concatenate([[0.0], np.cumsum(flicker_y)])
    return {"white_pm": white_pm, "white_fm": white_fm, "flicker_fm": flicker_fm,
            "random_walk_fm": rw_fm}


STATISTICS = {"adev": allantools.adev, "oadev": allantools.oadev, "mdev": allantools.mdev,
              "tdev": allantools.tdev, "hdev": allantools.hdev, "ohdev": allantools.ohdev,
              "totdev": allantools.totdev, "mtie": allantools.mtie}


def main():
    os.makedirs(OUT, exist_ok=True)
    for name, x in series().items():
        with open(f"{OUT}/{name}.csv", "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["phase_s"])
            for v in x:
                w.writerow([repr(float(v))])
        taus = [2 ** k for k in range(0, 9)]
        with open(f"{OUT}/{name}_devs.csv", "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["statistic", "m", "value"])
            for stat, fn in STATISTICS.items():
                t, d, _, _ = fn(x, rate=1.0, data_type="phase", taus=taus)
                for tau, dev in zip(t, d):
                    w.writerow([stat, int(round(tau)), repr(float(dev))])
        write_intervals(name, x, taus)
    print("wrote", OUT)


INTERVALS = {"oadev": allantools.oadev, "mdev": allantools.mdev, "ohdev": allantools.ohdev}


def write_intervals(name, x, taus):
    """NAME_ci.csv: per statistic and octave m, the noise type allantools
    identifies (lag-1 autocorrelation, Riley & Greenhall 2004), Greenhall's
    equivalent degrees of freedom and the 1-sigma (68.27 %) interval, as
    allantools.confidence_interval_noiseID computes them."""
    with open(f"{OUT}/{name}_ci.csv", "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["statistic", "m", "alpha", "edf", "low", "high"])
        for stat, fn in INTERVALS.items():
            t, d, _, _ = fn(x, rate=1.0, data_type="phase", taus=taus)
            for tau, dev in zip(t, d):
                m = int(round(tau))
                dmax = 3 if stat == "ohdev" else 2
                if len(x[::m]) < 30:
                    continue
                alpha = allantools.ci.autocorr_noise_id(x, m, data_type="phase", dmax=dmax)[0]
                d_ = 3 if stat == "ohdev" else 2
                if alpha + 2 * d_ <= 1:
                    continue
                edf = allantools.ci.edf_greenhall(alpha=alpha, d=d_, m=m, N=len(x),
                                                  overlapping=True, modified=(stat == "mdev"))
                lo, hi = allantools.ci.confidence_interval(dev, edf)
                w.writerow([stat, m, alpha, repr(float(edf)), repr(float(lo)), repr(float(hi))])


if __name__ == "__main__":
    main()
