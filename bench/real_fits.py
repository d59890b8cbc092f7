"""Real records through `pendulum fit`, each figure beside an independent
SciPy fit of the same record, with the warnings each fit gives: a warning
on a figure that agrees is a defect (issue 44). Prints a Markdown table.

Records:
* the published period tables of crates/pendulum-cli/tests/data/period/
  (SciPy's figures: reference.csv, made by tools/reference/period_tables.py);
* crates/pendulum-cli/tests/data/encoder-stops.csv (a real encoder record):
  the linear model by curve_fit;
* Tracker projects and exports of a real pendulum (github.com/JLefebvre55/
  PHY180-Pendulum, MIT licence; fetched into TRACKS_DIR, not committed):
  the nonlinear viscous equation integrated by solve_ivp inside curve_fit
  (the model `fit trajectory` reports on them), its parameters released
  from rest at a crest before the first sample.

Agreement: |ours - scipy| against the larger of the two standard errors
(both are fits of one model to one record: they differ by the fits'
tolerances and by ours widening its errors for correlated residuals).

Usage: python bench/real_fits.py PENDULUM_BINARY [TRACKS_DIR]
"""
import csv
import json
import math
import os
import subprocess
import sys

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import curve_fit

ROOT = os.path.join(os.path.dirname(__file__), "..")
DATA = os.path.join(ROOT, "crates", "pendulum-cli", "tests", "data")
rows = []


def run(binary, args):
    out = subprocess.run([binary, *args, "--json"], capture_output=True, text=True)
    if out.returncode != 0:
        return None, out.stderr.strip()
    return json.loads(out.stdout), None


def codes(v):
    if "warning_codes" in v:
        return list(v["warning_codes"])
    return [w["code"] for w in v.get("warnings", [])]


def add(record, fit, name, ours, ours_se, theirs, theirs_se, warnings):
    scale = max(ours_se, theirs_se)
    z = abs(ours - theirs) / scale if scale > 0 else float("inf")
    rows.append((record, fit, name, ours, ours_se, theirs, theirs_se, z, warnings))


def periods(binary):
    reference = os.path.join(DATA, "period", "reference.csv")
    with open(reference) as f:
        lines = [l for l in f if not l.startswith("#")]
    for r in csv.DictReader(lines):
        file, name = r["file"], r["parameter"]
        args = ["fit", "period", os.path.join(DATA, "period", file)]
        if file == "silveira1986.csv":
            args += ["--length", "2.87m"]
        if file == "amedeker2022.csv":
            args += ["--length", "1m"]
        v, err = run(binary, args)
        add(file, "period", name, v["parameters"][name], v["standard_errors"][name],
            float(r["value"]), float(r["standard_error"]), codes(v))


def linear(t, a, wd, z, phase, offset):
    wn = wd / np.sqrt(1 - z * z)
    return offset + a * np.exp(-z * wn * t) * np.cos(wd * t + phase)


def encoder(binary):
    path = os.path.join(DATA, "encoder-stops.csv")
    v, err = run(binary, ["fit", "trajectory", path, "--columns", "time_s,angle_deg"])
    d = np.genfromtxt(path, delimiter=";", comments="#")
    t, th = d[:, 0] - d[0, 0], np.radians(d[:, 1])
    p = v["parameters"]
    guess = [p["amplitude_rad"] * 0.9, p["omega_d_rad_s"] * 1.1, 0.1, 0.0, 0.0]
    popt, pcov = curve_fit(linear, t, th, p0=guess, maxfev=20000)
    perr = np.sqrt(np.diag(pcov))
    for j, name in [(1, "omega_d_rad_s"), (2, "zeta")]:
        add("encoder-stops.csv", "trajectory (linear)", name, p[name],
            v["standard_errors"][name], popt[j], perr[j], codes(v))


def released(t, a, wn, zeta, lead, offset):
    """Released from rest at a at -lead s, viscous: theta'' = -wn^2 sin theta - 2 zeta wn theta'."""
    span = t[-1] + lead
    sol = solve_ivp(lambda _s, y: [y[1], -wn * wn * math.sin(y[0]) - 2 * zeta * wn * y[1]],
                    [0, span], [a, 0.0], method="DOP853", rtol=1e-10, atol=1e-12,
                    dense_output=True)
    return offset + sol.sol(np.abs(t + lead))[0]


def track(binary, label, args, time, angle):
    v, err = run(binary, ["fit", "trajectory", *args])
    if v is None:
        rows.append((label, "trajectory", "refused", 0, 0, 0, 0, 0, [err]))
        return
    p, e = v["parameters"], v["standard_errors"]
    if v["model"] != "nonlinear" or v["damping_law"] != "viscous":
        rows.append((label, "trajectory", f"{v['model']} {v['damping_law']} (not compared)",
                     0, 0, 0, 0, 0, codes(v)))
        return
    wn = p["omega_n_rad_s"]
    lead = p["phase_rad"] / wn  # a start for SciPy's own search
    guess = [p["amplitude_rad"], wn * 0.999, max(p["zeta"], 1e-4), lead, 0.0]
    popt, pcov = curve_fit(released, time, angle, p0=guess, maxfev=4000)
    perr = np.sqrt(np.diag(pcov))
    for j, name in [(0, "amplitude_rad"), (1, "omega_n_rad_s"), (2, "zeta"),
                    (4, "offset_rad")]:
        add(label, "trajectory", name, p[name], e[name], popt[j], perr[j], codes(v))


def tracks(binary, folder):
    if not folder or not os.path.isdir(folder):
        return
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name)
        if name.endswith(".trk") and "fullPeriod" not in name:
            # The positions read here, about the pivot the binary fitted.
            v, _ = run(binary, ["fit", "trajectory", path, "--pivot", "fit"])
            if v is None:
                continue
            pivot = v["pivot"]
            t, x, y = read_trk(path)
            angle = np.arctan2(x - pivot["x"], pivot["y"] - y)
            track(binary, name, [path, "--pivot", "fit"], t - t[0], angle)
        elif "q4b_data" in name and name.endswith(".txt"):
            d = np.loadtxt(path, skiprows=1)
            track(binary, name, [path, "--columns", "time_s,angle_rad,dt,da"],
                  d[:, 0] - d[0, 0], d[:, 1])


def read_trk(path):
    """The first point mass's frames of a Tracker project, in world units
    (the coordinate system of its first frame: these projects have one)."""
    import re
    text = open(path).read()
    dt = float(re.search(r'"delta_t" type="double">([\d.eE+-]+)', text).group(1)) / 1000
    get = lambda key: float(re.search(rf'"{key}" type="double">([\d.eE+-]+)', text).group(1))
    xo, yo, ang, sx, sy = (get(k) for k in ["xorigin", "yorigin", "angle", "xscale", "yscale"])
    frames = re.findall(r'<property name="\[(\d+)\]" type="object">\s*<object class="org'
                        r'\.opensourcephysics\.cabrillo\.tracker\.PointMass\$FrameData">\s*'
                        r'<property name="x" type="double">([\d.eE+-]+)</property>\s*'
                        r'<property name="y" type="double">([\d.eE+-]+)</property>', text)
    k = np.array([int(f[0]) for f in frames], dtype=float)
    px = np.array([float(f[1]) for f in frames])
    py = np.array([float(f[2]) for f in frames])
    dx, dy = px - xo, py - yo
    c, s = math.cos(ang), math.sin(ang)
    return k * dt, (c * dx - s * dy) / sx, -(s * dx + c * dy) / sy


def main():
    binary = sys.argv[1]
    periods(binary)
    encoder(binary)
    tracks(binary, sys.argv[2] if len(sys.argv) > 2 else None)
    print("| record | fit | figure | ours ± SE | SciPy ± SE | apart (SE) | warnings |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        record, fit, name, ours, ose, theirs, tse, z, warnings = r
        if ose == 0 and tse == 0 and z == 0:
            print(f"| {record} | {fit} | {name} | | | | {', '.join(warnings) or 'none'} |")
            continue
        print(f"| {record} | {fit} | {name} | {ours:.6g} ± {ose:.2g} | {theirs:.6g} ± {tse:.2g} "
              f"| {z:.2f} | {', '.join(warnings) or 'none'} |")


main()
