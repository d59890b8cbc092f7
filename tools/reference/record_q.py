"""Truth for the one Q (issue 44, item 3): Q over the record, from the
energy a swing loses per cycle between its first and last crests in the
record, Q = pi N / ln(E(A_first) / E(A_last)), E(A) = 1 - cos A, N the half
swings between them, for two records whose motion is known:

* examples/tracker.txt (made by tools/examples/make_example_data.py): a
  1.2 m pendulum released at 15.5 degrees, zeta = 5.5e-4, quadratic drag
  b = 0.025 per radian, 30 frames a second for 120 s;
* drag.csv, written here: a 0.8 m pendulum released at 30 degrees in air,
  zeta = 2e-4 and b = 0.04 per radian (drag dominant: the viscous Q alone is
  2500), 25 frames a second for 80 s, 1 mrad of Gaussian noise (seeded).

The motion is theta'' = -w^2 sin(theta) - 2 zeta w theta' - b theta'|theta'|
integrated by SciPy's DOP853 (rtol 1e-12), its crests found as events of
theta' = 0 (SciPy reports the release at t = 0 as one). Writes drag.csv and
truth.json into crates/pendulum-cli/tests/data/record_q/.

Usage: python tools/reference/record_q.py
"""
import json
import math
import os

import numpy as np
import scipy
from scipy.integrate import solve_ivp

OUT = os.path.join(os.path.dirname(__file__), "..", "..", "crates", "pendulum-cli", "tests",
                   "data", "record_q")


def motion(length, release_deg, zeta, b, span, rate):
    w = math.sqrt(9.80665 / length)

    def f(_t, y):
        return [y[1], -w * w * math.sin(y[0]) - 2 * zeta * w * y[1] - b * y[1] * abs(y[1])]

    def crest(_t, y):
        return y[1]

    frames = np.arange(int(round(span * rate)) + 1) / rate
    sol = solve_ivp(f, [0, frames[-1]], [math.radians(release_deg), 0.0], method="DOP853",
                    rtol=1e-12, atol=1e-14, events=crest, t_eval=frames)
    times, angles = sol.t_events[0], np.abs(sol.y_events[0][:, 0])
    energy = 2 * np.sin(angles / 2) ** 2
    q = math.pi * (len(times) - 1) / math.log(energy[0] / energy[-1])
    return frames, sol.y[0], q, 1 / (2 * zeta), len(times)


def main():
    os.makedirs(OUT, exist_ok=True)
    truth = {"scipy": scipy.__version__}
    _, _, q, qv, crests = motion(1.2, 15.5, 5.5e-4, 0.025, 120.0, 30)
    truth["tracker.txt"] = {"q_factor": q, "q_viscous": qv, "crests": crests}
    t, theta, q, qv, crests = motion(0.8, 30.0, 2e-4, 0.04, 80.0, 25)
    rng = np.random.default_rng(44)
    theta = theta + 1e-3 * rng.standard_normal(theta.size)
    with open(os.path.join(OUT, "drag.csv"), "w") as f:
        f.write("# made by tools/reference/record_q.py: a 0.8 m pendulum in air released at 30 deg\n")
        f.write("# (zeta 2e-4 and quadratic drag 0.04 per rad with 1 mrad noise); its Q in truth.json\n")
        f.write("time_s,angle_rad\n")
        for x, y in zip(t, theta):
            f.write(f"{float(x)!r},{float(y)!r}\n")
    truth["drag.csv"] = {"q_factor": q, "q_viscous": qv, "crests": crests, "length_m": 0.8,
                         "g_m_s2": 9.80665}
    with open(os.path.join(OUT, "truth.json"), "w") as f:
        json.dump(truth, f, indent=1)
        f.write("\n")
    print(json.dumps(truth, indent=1))


main()
