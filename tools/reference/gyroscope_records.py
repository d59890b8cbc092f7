#!/usr/bin/env python3
"""Gyroscope records of a swinging phone in phyphox's export layouts, made
independently of the tool (SciPy's DOP853 at rtol 1e-11), for the tests
of `fit trajectory` on angular velocities:
crates/pendulum-cli/tests/data/gyroscope/.

Each record is the pendulum theta'' + 2 zeta wn theta' + b theta'|theta'|
+ wn^2 (sin theta + r sgn theta') = 0 released from rest at A0, seen by a
three-axis gyroscope whose axes are turned against the pivot's (the swing's
rate shared among them), with white noise on each axis, a zero offset
(bias) per axis, and a small wobble about another axis. The truth is
written to truth.json beside the records: g, the length, wn, zeta, the
release angle, the first crest after the first sample (time from the first
sample, amplitude), the axis.

Layouts (phyphox 1.1-1.2):
 * gyroscope-comma.csv: "CSV (Comma, decimal point)", quoted headers,
   `Gyroscope x (rad/s)` ... `Absolute (rad/s)`, 1.234567890E-1 numbers,
   no newline after the last row, times from a small offset.
 * rotation-semicolon.csv: "CSV (Semicolon, decimal comma)" of the
   Pendulum experiment (`Rotation x (rad/s)`, no Absolute column).
 * gyroscope.xls: the Excel export, BIFF8 (xlwt), sheets `Raw Data`,
   `Metadata Device`, `Metadata Time`; the phone held still for its first
   second.

Run from the repository root:  python3 tools/reference/gyroscope_records.py
Needs: numpy, scipy, xlwt. The output is committed; CI needs no Python for
these tests.
"""
import json
import math
import os

import numpy as np
from scipy.integrate import solve_ivp

HERE = os.path.join(os.path.dirname(__file__), "..", "..", "crates", "pendulum-cli", "tests", "data", "gyroscope")
G = 9.81


def rotation(axis, angle):
    """Rodrigues: the matrix turning by `angle` about unit `axis`."""
    a = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * k @ k


def record(name, *, length, a0_deg, zeta, b=0.0, r=0.0, rate, seconds, lead, noise, held=0.0,
           tilt=(0.0, 0.0), seed):
    rng = np.random.default_rng(seed)
    wn = math.sqrt(G / length)

    def f(_t, y):
        th, w = y
        return [w, -2 * zeta * wn * w - b * w * abs(w) - wn ** 2 * (math.sin(th) + r * math.tanh(w / 1e-5))]

    t0 = 0.0123 + 0.004 * rng.random()
    t = t0 + np.arange(int(seconds * rate)) / rate
    since = t - t[0] - held + lead  # time since the release
    sol = solve_ivp(f, [0, since[-1] + 1], [math.radians(a0_deg), 0.0], method="DOP853",
                    rtol=1e-11, atol=1e-13, dense_output=True)
    omega = np.where(since >= 0, sol.sol(np.maximum(since, 0))[1], 0.0)
    # The swing about the sensor's y axis turned by the tilt; a wobble
    # about its z axis.
    turn = rotation([1, 0, 0], tilt[0]) @ rotation([0, 0, 1], tilt[1])
    axis = turn @ np.array([0.0, 1.0, 0.0])
    other = turn @ np.array([0.0, 0.0, 1.0])
    wobble = 0.01 * np.sin(2 * math.pi * 2.7 * t)
    bias = rng.normal(0, 0.003, 3)
    rates = omega[:, None] * axis + wobble[:, None] * other + bias + rng.normal(0, noise, (len(t), 3))
    # The first crest after the first sample fitted: the first turning
    # point of the motion at or after `since[0]` (events of theta' = 0).
    ev = lambda _t, y: y[1]
    crest = solve_ivp(f, [0, since[-1] + 1], [math.radians(a0_deg), 0.0], method="DOP853",
                      rtol=1e-11, atol=1e-13, events=ev)
    after = max(since[0], 0.0)
    turning = [(x, y[0]) for x, y in zip(crest.t_events[0], crest.y_events[0]) if x > 1e-9]
    times = [0.0] + [x for x, _ in turning]
    angles = [math.radians(a0_deg)] + [y for _, y in turning]
    k = next(i for i, x in enumerate(times) if x >= after - 1e-9)
    truth = dict(length_m=length, g_m_s2=G, omega_n_rad_s=wn, zeta=zeta,
                 quadratic_drag_per_rad=b, friction_angle_rad=r,
                 release_angle_rad=math.radians(a0_deg),
                 first_crest_time_s=times[k] - since[0] if held == 0 else held,
                 first_crest_amplitude_rad=abs(angles[k]),
                 axis=list(axis), rows=len(t), held_s=held)
    return t, rates, truth


def number(x, decimal="."):
    s = "%.9E" % x
    mantissa, exponent = s.split("E")
    s = "%sE%d" % (mantissa, int(exponent))
    return s.replace(".", decimal)


def main():
    os.makedirs(HERE, exist_ok=True)
    truths = {}
    # 1: a phone on two strings, 30°, viscous, 100 Hz, 20 s, tilted axes.
    t, w, truth = record("gyroscope-comma.csv", length=0.45, a0_deg=30, zeta=0.002, rate=100,
                         seconds=20, lead=0.31, noise=0.01, tilt=(0.35, 0.2), seed=1)
    with open(os.path.join(HERE, "gyroscope-comma.csv"), "w", newline="") as out:
        out.write(",".join('"%s"' % h for h in ["Time (s)", "Gyroscope x (rad/s)", "Gyroscope y (rad/s)",
                                                 "Gyroscope z (rad/s)", "Absolute (rad/s)"]))
        for i in range(len(t)):
            row = [t[i], *w[i], float(np.linalg.norm(w[i]))]
            out.write("\n" + ",".join(number(v) for v in row))
    truths["gyroscope-comma.csv"] = truth
    # 2: the Pendulum experiment's rotation, 60°, quadratic drag, 50 Hz, 15 s.
    t, w, truth = record("rotation-semicolon.csv", length=0.8, a0_deg=60, zeta=0.0005, b=0.02,
                         rate=50, seconds=15, lead=1.1, noise=0.02, tilt=(0.0, -0.5), seed=2)
    with open(os.path.join(HERE, "rotation-semicolon.csv"), "w", newline="") as out:
        out.write(";".join('"%s"' % h for h in ["Time (s)", "Rotation x (rad/s)", "Rotation y (rad/s)",
                                                 "Rotation z (rad/s)"]) + "\n")
        for i in range(len(t)):
            out.write(";".join(number(v, ",") for v in [t[i], *w[i]]) + "\n")
    truths["rotation-semicolon.csv"] = truth
    # 3: the Excel export, 20°, held still for a second, 100 Hz, 12 s.
    import xlwt
    t, w, truth = record("gyroscope.xls", length=0.3, a0_deg=20, zeta=0.003, rate=100, seconds=12,
                         lead=0.0, noise=0.01, held=1.0, tilt=(0.1, 0.0), seed=3)
    book = xlwt.Workbook()
    raw = book.add_sheet("Raw Data")
    for j, h in enumerate(["Time (s)", "Gyroscope x (rad/s)", "Gyroscope y (rad/s)", "Gyroscope z (rad/s)",
                           "Absolute (rad/s)"]):
        raw.write(0, j, h)
    for i in range(len(t)):
        for j, v in enumerate([t[i], *w[i], float(np.linalg.norm(w[i]))]):
            raw.write(i + 1, j, float(v))
    device = book.add_sheet("Metadata Device")
    for i, (k, v) in enumerate([("property", "value"), ("version", "1.2.0"), ("model", "generated")]):
        device.write(i, 0, k)
        device.write(i, 1, v)
    times = book.add_sheet("Metadata Time")
    for j, h in enumerate(["event", "experiment time", "system time", "system time text"]):
        times.write(0, j, h)
    times.write(1, 0, "START")
    times.write(1, 1, 0.0)
    times.write(1, 2, 1785170901.062)
    times.write(1, 3, "2026-07-27 11:48:21.062 UTC-05:00")
    book.save(os.path.join(HERE, "gyroscope.xls"))
    truths["gyroscope.xls"] = truth
    with open(os.path.join(HERE, "truth.json"), "w") as out:
        json.dump(truths, out, indent=1, sort_keys=True)
        out.write("\n")


if __name__ == "__main__":
    main()
