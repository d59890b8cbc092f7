"""Fits the same decay and trajectory files with `pendulum fit` and with
scipy.optimize.curve_fit, and prints the parameters and standard errors side
by side with the number of significant digits in which they agree.
Exits 1 if any parameter agrees to fewer than 4 significant digits.

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


MODELS = {
    "viscous": (lambda t, a0, lam: a0 * np.exp(-lam * t), ["amplitude0_rad", "decay_rate_per_s"]),
    "coulomb": (lambda t, a0, mu: a0 - mu * t, ["amplitude0_rad", "amplitude_fall_rad_per_s"]),
    "quadratic": (lambda t, a0, k: a0 / (1 + k * a0 * t), ["amplitude0_rad", "quadratic_decay_per_rad_s"]),
    "viscous+coulomb": (
        lambda t, a0, lam, mu: a0 * np.exp(-lam * t) + mu * np.expm1(-lam * t) / lam,
        ["amplitude0_rad", "decay_rate_per_s", "amplitude_fall_rad_per_s"],
    ),
}


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
    decay_path = os.path.join(work, "decay.csv")
    t, a = write_decay(decay_path)
    for model, (fn, names) in MODELS.items():
        out = subprocess.run([binary, "fit", "decay", decay_path, "--model", model, "--json"],
                             check=True, capture_output=True, text=True).stdout
        ours = json.loads(out)["models"][0]
        p0 = [ours["parameters"][n] for n in names]
        # SciPy starts from its own rough guess, not from our answer.
        guess = [a[0]] + [1e-4] * (len(names) - 1)
        popt, pcov = curve_fit(fn, t, a, p0=guess, maxfev=20000)
        perr = np.sqrt(np.diag(pcov))
        print(f"decay, {model}:")
        for j, n in enumerate(names):
            worst = min(worst, row(n, p0[j], ours["standard_errors"][n], popt[j], perr[j]))
    video = os.path.join(work, "video.csv")
    t, th = write_trajectory(video)
    out = subprocess.run([binary, "fit", "trajectory", video, "--json"], check=True, capture_output=True, text=True).stdout
    ours = json.loads(out)
    names = ["amplitude_rad", "omega_d_rad_s", "zeta", "phase_rad", "offset_rad"]
    guess = [0.1, 4.4, 0.01, 0.0, 0.0]
    popt, pcov = curve_fit(linear_trajectory, t, th, p0=guess, maxfev=20000)
    perr = np.sqrt(np.diag(pcov))
    print("trajectory, linear:")
    for j, n in enumerate(names):
        worst = min(worst, row(n, ours["parameters"][n], ours["standard_errors"][n], popt[j], perr[j]))
    print(f"worst agreement: {worst:.1f} significant digits (required: 4)")
    sys.exit(0 if worst >= 4 else 1)


main()
