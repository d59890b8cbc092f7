#!/usr/bin/env python3
"""Reference fits of the published period tables in
crates/pendulum-cli/tests/data/period/, by SciPy, for `fit period`'s tests.

Against amplitude: scipy.optimize.curve_fit of T = T0 (2/pi) K(sin^2(A/2))
(scipy.special.ellipk, parameter m), and of T = T0 F(A) (1 + d A^2) for the
circular-error coefficient c = 1/16 + d (its standard error by the delta
method from curve_fit's covariance). Against length: curve_fit of
T^2 = a + b L, g = 4 pi^2 / b, offset a / b. Unweighted, with the
covariance scaled by the residual variance (curve_fit's default), as the
tool does for tables without uncertainties.

Run from the repository root:  python3 tools/reference/period_tables.py
Needs: numpy, scipy. The output (reference.csv beside the tables) is
committed; CI needs no Python for these tests.
"""
import math
import os

import numpy as np
import scipy
from scipy.optimize import curve_fit
from scipy.special import ellipk

HERE = os.path.join(os.path.dirname(__file__), "..", "..", "crates", "pendulum-cli", "tests", "data", "period")


def read(name):
    rows = [l.strip().split(",") for l in open(os.path.join(HERE, name)) if l.strip() and not l.startswith("#")]
    header = rows[0]
    data = np.array([[float(v) for v in r] for r in rows[1:]])
    return header, data


def ratio(a):
    return ellipk(np.sin(a / 2) ** 2) * 2 / math.pi


def against_amplitude(name, length=None):
    header, data = read(name)
    a = np.radians(data[:, header.index("amplitude_deg")])
    t = data[:, header.index("period_s")]
    (t0,), cov = curve_fit(lambda a, t0: t0 * ratio(a), a, t, p0=[t.mean()])
    se = math.sqrt(cov[0][0])
    out = [(name, "small_angle_period_s", t0, se)]
    if length is not None:
        g = 4 * math.pi ** 2 * length / t0 ** 2
        out.append((name, "g_m_s2", g, g * 2 * se / t0))
    (p0, p1), c = curve_fit(lambda a, p0, p1: ratio(a) * (p0 + p1 * a * a), a, t, p0=[t.mean(), 0.0])
    d = p1 / p0
    var = (c[1][1] - 2 * d * c[0][1] + d * d * c[0][0]) / p0 ** 2
    out.append((name, "circular_error_coefficient", 1 / 16 + d, math.sqrt(var)))
    return out


def against_length(name):
    header, data = read(name)
    length = data[:, [i for i, h in enumerate(header) if "length" in h][0]]
    t = data[:, header.index("period_s")]
    (a, b), c = curve_fit(lambda l, a, b: a + b * l, length, t ** 2, p0=[0.0, 4.0])
    g = 4 * math.pi ** 2 / b
    d = a / b
    var = (c[0][0] - 2 * d * c[0][1] + d * d * c[1][1]) / b ** 2
    return [(name, "g_m_s2", g, g * math.sqrt(c[1][1]) / b), (name, "length_offset_m", d, math.sqrt(var))]


def main():
    rows = []
    rows += against_amplitude("silveira1986.csv", 2.87)
    rows += against_amplitude("amedeker2022.csv", 1.0)
    rows += against_amplitude("sardjito2020.csv")
    rows += against_length("hidayat2023.csv")
    path = os.path.join(HERE, "reference.csv")
    with open(path, "w") as f:
        f.write("# made by tools/reference/period_tables.py with scipy %s (curve_fit, unweighted)\n" % scipy.__version__)
        f.write("file,parameter,value,standard_error\n")
        for name, p, v, se in rows:
            f.write(f"{name},{p},{float(v)!r},{float(se)!r}\n")
    print("wrote", path, len(rows), "rows")


if __name__ == "__main__":
    main()
