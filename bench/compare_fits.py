"""Fits the same decay and trajectory files with `pendulum fit` and with
scipy.optimize.curve_fit, and prints the parameters and standard errors side
by side with the number of significant digits in which they agree.
Decay laws are fitted with every rate bounded below by 0 on both sides
(ours by an active set, SciPy's curve_fit with bounds=(0, inf), its
trust-region-reflective method). A rate at its bound is compared as 0 on
both sides (SciPy's lands within 1e-9 of it); standard errors are compared
for laws with no rate at a bound (SciPy's covariance there keeps the bound
column). Exits 1 if any parameter agrees to fewer than 5 significant digits.

Usage: python compare_fits.py PENDULUM_BINARY WORK_DIR
"""
import json
import math
import os
import subprocess
import sys

import numpy as np
from scipy.optimize import curve_fit

rng = np.random.default_rng(20261122)


def write_decay(path):
    t = np.arange(100) * 20.0
    lam, mu = 3e-4, 8e-6
    a = 0.05 * np.exp(-lam * t) + mu * np.expm1(-lam * t) / lam + 1e-4 * rng.standard_normal(t.size)
    with open(path, "w") as f:
        f.write("time_s,amplitude_rad\n")
        for x, y in zip(t, a):
            f.write(f"{float(x)!r},{float(y)!r}\n")
    return t, a


def write_air_decay(path):
    """A pendulum in air: viscous damping and quadratic drag (Bernoulli law)."""
    t = np.arange(150) * 2.0
    lam, kap, a0 = 1.6e-3, 0.03, 0.27
    e = np.exp(-lam * t)
    a = lam * a0 * e / (lam + kap * a0 * (1 - e)) + 8e-4 * rng.standard_normal(t.size)
    with open(path, "w") as f:
        f.write("time_s,amplitude_rad\n")
        for x, y in zip(t, a):
            f.write(f"{float(x)!r},{float(y)!r}\n")
    return t, a


def law(t, a0, lam, mu, kap):
    """dA/dt = -(mu + lam A + kap A^2), written independently of ours: the
    linear law when kap = 0, else the Riccati solution by separation of
    variables (real roots: partial fractions; complex: arctangent)."""
    t = np.asarray(t, dtype=float)
    if kap == 0:
        if lam == 0:
            return a0 - mu * t
        return (a0 + mu / lam) * np.exp(-lam * t) - mu / lam
    d = lam * lam - 4 * kap * mu
    if d > 0:
        r1 = (-lam + math.sqrt(d)) / (2 * kap)
        r2 = (-lam - math.sqrt(d)) / (2 * kap)
        k = (a0 - r1) / (a0 - r2) * np.exp(-kap * (r1 - r2) * t)
        return (r1 - k * r2) / (1 - k)
    if d == 0:
        r = -lam / (2 * kap)
        return r + 1 / (1 / (a0 - r) + kap * t)
    s = math.sqrt(-d)
    return (s * np.tan(math.atan((2 * kap * a0 + lam) / s) - s * t / 2) - lam) / (2 * kap)


def write_trajectory(path):
    w = math.sqrt(9.80665 / 0.5)
    z = 0.005
    wd = w * math.sqrt(1 - z * z)
    t = np.arange(1000) * 0.01
    th = 0.1 * np.exp(-z * w * t) * (np.cos(wd * t) + z * w / wd * np.sin(wd * t)) + 0.01
    th = th + 2e-3 * rng.standard_normal(t.size)
    with open(path, "w") as f:
        f.write("time_s,angle_rad\n")
        for x, y in zip(t, th):
            f.write(f"{float(x)!r},{float(y)!r}\n")
    return t, th


RATES = ["decay_rate_per_s", "amplitude_fall_rad_per_s", "quadratic_decay_per_rad_s"]
LAWS = {
    "viscous": [0],
    "coulomb": [1],
    "quadratic": [2],
    "viscous+coulomb": [0, 1],
    "viscous+quadratic": [0, 2],
    "coulomb+quadratic": [1, 2],
    "viscous+coulomb+quadratic": [0, 1, 2],
}


def model_function(rates):
    def f(t, a0, *r):
        full = [0.0, 0.0, 0.0]
        for k, v in zip(rates, r):
            full[k] = v
        return law(t, a0, *full)
    return f


def linear_trajectory(t, a, wd, z, phase, offset):
    wn = wd / np.sqrt(1 - z * z)
    return offset + a * np.exp(-z * wn * t) * np.cos(wd * t + phase)


def digits(x, y):
    if x == y:
        return 16.0
    return -math.log10(abs(x - y) / max(abs(x), abs(y)))


def row(name, ours, ours_se, theirs, theirs_se):
    d = digits(ours, theirs)
    print(f"  {name:<26} {ours:+.8e} ± {ours_se:.3e}   scipy {theirs:+.8e} ± {theirs_se:.3e}   agree {d:4.1f} digits")
    return d


def main():
    binary, work = sys.argv[1], sys.argv[2]
    worst = 16.0
    for file_name, writer in (("decay.csv", write_decay), ("air.csv", write_air_decay)):
        decay_path = os.path.join(work, file_name)
        t, a = writer(decay_path)
        for model, rates in LAWS.items():
            names = ["amplitude0_rad"] + [RATES[k] for k in rates]
            out = subprocess.run([binary, "fit", "decay", decay_path, "--model", model, "--json"],
                                 check=True, capture_output=True, text=True).stdout
            ours = json.loads(out)["models"][0]
            p0 = [ours["parameters"][n] for n in names]
            # SciPy starts from its own rough guess, not from our answer.
            guess = [a[0]] + [1e-4] * (len(names) - 1)
            popt, pcov = curve_fit(model_function(rates), t, a, p0=guess,
                                   bounds=(0, np.inf), max_nfev=20000,
                                   ftol=1e-15, xtol=1e-15, gtol=1e-15)
            perr = np.sqrt(np.diag(pcov))
            at_bound = ours["at_bound"]
            fn = model_function(rates)
            rss_ours = float(np.sum((a - fn(t, *p0)) ** 2))
            rss_theirs = float(np.sum((a - fn(t, *popt)) ** 2))
            print(f"{file_name}, {model}" + (f" (at bound: {', '.join(at_bound)})" if at_bound else "")
                  + f": residual sum of squares ours {rss_ours:.12e}, scipy {rss_theirs:.12e}")
            for j, n in enumerate(names):
                theirs = popt[j]
                if p0[j] == 0.0 and abs(theirs) < 1e-9:
                    theirs = 0.0
                se_theirs = perr[j] if not at_bound else ours["standard_errors"][n]
                d = row(n, p0[j], ours["standard_errors"][n], theirs, se_theirs)
                worst = min(worst, d)
    video = os.path.join(work, "video.csv")
    t, th = write_trajectory(video)
    out = subprocess.run([binary, "fit", "trajectory", video, "--model", "linear", "--json"],
                         check=True, capture_output=True, text=True).stdout
    ours = json.loads(out)
    names = ["amplitude_rad", "omega_d_rad_s", "zeta", "phase_rad", "offset_rad"]
    guess = [0.1, 4.4, 0.01, 0.0, 0.0]
    popt, pcov = curve_fit(linear_trajectory, t, th, p0=guess, maxfev=20000)
    perr = np.sqrt(np.diag(pcov))
    print("trajectory, linear:")
    for j, n in enumerate(names):
        worst = min(worst, row(n, ours["parameters"][n], ours["standard_errors"][n], popt[j], perr[j]))
    print(f"worst agreement: {worst:.1f} significant digits (required: 5)")
    sys.exit(0 if worst >= 5 else 1)


main()
