#!/usr/bin/env python3
"""Reference values for pendulum-theory's accuracy tests, from mpmath.

Every input is a double, written with repr() so that Rust parses back the
very same double; every output is computed from that exact double at 40
significant digits and written as a pair of doubles (hi, lo) with
hi + lo equal to the true value to about 1e-32 relative, so the tests can
measure errors in ulp without rounding the reference first.

Run from the repository root:  python3 tools/reference/make_reference.py
Needs: mpmath (pip install mpmath). The output is committed; CI needs no Python.
"""
import math
import os
import random

import mpmath as mp

mp.mp.dps = 40
OUT = os.path.join(os.path.dirname(__file__), "..", "..", "crates", "pendulum-theory", "tests", "data")
RNG = random.Random(20261122)


def split(x):
    """(hi, lo) doubles with hi + lo = x to ~2^-106 relative."""
    hi = float(x)
    lo = float(x - mp.mpf(hi))
    return repr(hi), repr(lo)


def write(name, header, rows):
    path = os.path.join(OUT, name)
    with open(path, "w") as f:
        f.write("# made by tools/reference/make_reference.py with mpmath %s at %d digits\n" % (mp.__version__, mp.mp.dps))
        f.write(",".join(header) + "\n")
        for row in rows:
            f.write(",".join(row) + "\n")
    print("wrote", path, len(rows), "rows")


def parameters():
    """m in [0, 1): uniform, near 0, near 1 (down to 1 - 2^-52), and special points."""
    ms = [0.0, 0.5, 0.25, 0.75, 0.9, 0.99]
    ms += [RNG.random() for _ in range(300)]
    ms += [10.0 ** RNG.uniform(-300, -1) for _ in range(100)]
    ms += [1.0 - 2.0 ** -RNG.uniform(1, 52) for _ in range(100)]
    return ms


def amplitudes():
    """Amplitudes in radians over (0, 179.9] degrees: tiny, small, uniform, near the top."""
    top = math.radians(179.9)
    amps = [top, math.radians(10.0), math.radians(90.0), math.radians(2.0), math.radians(3.0)]
    amps += [10.0 ** RNG.uniform(-10, -1) for _ in range(150)]
    amps += [math.radians(RNG.uniform(0.0, 15.0)) for _ in range(100)]
    amps += [RNG.uniform(0.0, top) for _ in range(200)]
    amps += [top - RNG.uniform(0.0, 0.2) for _ in range(50)]
    return [a for a in amps if 0.0 < a <= top]


def complete(ms):
    rows_k, rows_e = [], []
    for m in ms:
        mm = mp.mpf(m)
        rows_k.append((repr(m),) + split(mp.ellipk(mm)))
        rows_e.append((repr(m),) + split(mp.ellipe(mm)))
    write("ellipk.csv", ["m", "k_hi", "k_lo"], rows_k)
    write("ellipe.csv", ["m", "e_hi", "e_lo"], rows_e)


def by_amplitude(amps):
    rows = []
    for a in amps:
        half = mp.mpf(a) / 2
        k, kp = mp.sin(half), mp.cos(half)
        m = k * k
        kk, ee = mp.ellipk(m), mp.ellipe(m)
        diff = ee - kp * kp * kk
        ratio = 2 * kk / mp.pi
        circ = 1 - mp.pi / (2 * kk)
        slope = mp.pi * diff / (4 * kk * kk * k * kp)
        rows.append((repr(a),) + split(kk) + split(ee) + split(diff) + split(ratio) + split(circ) + split(slope))
    # The slope formula, checked once against numerical differentiation.
    for a in (1e-3, 0.5, 2.0, 3.1):
        f = lambda x: 1 - mp.pi / (2 * mp.ellipk(mp.sin(x / 2) ** 2))
        half = mp.mpf(a) / 2
        k, kp = mp.sin(half), mp.cos(half)
        kk, ee = mp.ellipk(k * k), mp.ellipe(k * k)
        analytic = mp.pi * (ee - kp * kp * kk) / (4 * kk * kk * k * kp)
        assert abs(mp.diff(f, mp.mpf(a)) / analytic - 1) < mp.mpf(10) ** -30
    write("amplitude.csv",
          ["amplitude_rad", "k_hi", "k_lo", "e_hi", "e_lo", "e_minus_kc2k_hi", "e_minus_kc2k_lo",
           "ratio_hi", "ratio_lo", "circular_error_hi", "circular_error_lo", "slope_hi", "slope_lo"], rows)


def periods(amps):
    rows = []
    for i, a in enumerate(amps):
        length = 0.99362 if i % 3 == 0 else RNG.uniform(0.01, 100.0)
        g = 9.80665 if i % 2 == 0 else RNG.uniform(9.78, 9.84)
        m = mp.sin(mp.mpf(a) / 2) ** 2
        t = 4 * mp.sqrt(mp.mpf(length) / mp.mpf(g)) * mp.ellipk(m)
        rows.append((repr(a), repr(length), repr(g)) + split(t))
    write("period.csv", ["amplitude_rad", "length_m", "g_m_s2", "period_hi", "period_lo"], rows)


def jacobi():
    rows = []
    ms = [RNG.random() for _ in range(150)] + [1.0 - 10.0 ** -RNG.uniform(1, 15) for _ in range(50)]
    ms += [10.0 ** -RNG.uniform(1, 15) for _ in range(30)]
    for m in ms:
        for u in (RNG.uniform(-2.0, 2.0), RNG.uniform(-20.0, 20.0), RNG.uniform(0, 60.0)):
            mm, uu = mp.mpf(m), mp.mpf(u)
            sn = mp.ellipfun("sn", uu, m=mm)
            cn = mp.ellipfun("cn", uu, m=mm)
            dn = mp.ellipfun("dn", uu, m=mm)
            rows.append((repr(u), repr(m)) + split(sn) + split(cn) + split(dn))
    write("jacobi.csv", ["u", "m", "sn_hi", "sn_lo", "cn_hi", "cn_lo", "dn_hi", "dn_lo"], rows)


G0 = 9.80665
ZETAS = [1e-7, 1e-5, 1e-3, 0.01, 0.1, 0.5, 0.9, 0.999, 1.0 - 1e-12, 1.0, 1.0 + 1e-12, 1.001, 2.0, 10.0]


def damped_state(zeta, length, theta0, v0, t):
    """theta(t), theta'(t) of theta'' + 2 zeta w theta' + w^2 theta = 0 from the
    roots of the characteristic equation, in complex arithmetic: a different
    route from the library's real sinc/sinhc form."""
    w = mp.sqrt(mp.mpf(G0) / mp.mpf(length))
    z, t, th0, v0 = mp.mpf(zeta), mp.mpf(t), mp.mpf(theta0), mp.mpf(v0)
    if z == 1:
        e = mp.exp(-w * t)
        b = v0 + w * th0
        return (th0 + b * t) * e, (b - w * (th0 + b * t)) * e
    root = mp.sqrt(mp.mpc(z * z - 1))
    r1, r2 = w * (-z + root), w * (-z - root)
    a = (v0 - r2 * th0) / (r1 - r2)
    b = th0 - a
    theta = a * mp.exp(r1 * t) + b * mp.exp(r2 * t)
    vel = a * r1 * mp.exp(r1 * t) + b * r2 * mp.exp(r2 * t)
    return mp.re(theta), mp.re(vel)


def damped():
    rows = []
    for zeta in ZETAS:
        for theta0, v0 in ((0.05, 0.0), (0.03, 0.1), (-0.2, -0.5)):
            length = RNG.uniform(0.1, 10.0)
            w = math.sqrt(G0 / length)
            period = 2 * math.pi / w
            span = period * (300.0 if zeta < 0.01 else 10.0)
            for t in [0.0, RNG.uniform(0, period)] + [RNG.uniform(0, span) for _ in range(4)]:
                th, v = damped_state(zeta, length, theta0, v0, t)
                rows.append((repr(zeta), repr(length), repr(theta0), repr(v0), repr(t)) + split(th) + split(v))
    write("damped.csv", ["zeta", "length_m", "theta0_rad", "v0_rad_s", "t_s",
                         "theta_hi", "theta_lo", "v_hi", "v_lo"], rows)


def conversions():
    """From zeta: Q, log decrement, c for a mass, decay time, half-life."""
    rows = []
    zetas = [10.0 ** RNG.uniform(-7, 1) for _ in range(200)] + ZETAS
    for zeta in zetas:
        length, mass = RNG.uniform(0.1, 10.0), RNG.uniform(0.05, 20.0)
        z = mp.mpf(zeta)
        w = mp.sqrt(mp.mpf(G0) / mp.mpf(length))
        q = 1 / (2 * z)
        delta = 2 * mp.pi * z / mp.sqrt(1 - z * z) if z < 1 else mp.mpf(0)
        c = 2 * mp.mpf(mass) * z * mp.sqrt(mp.mpf(G0) * mp.mpf(length))
        tau = 1 / (z * w)
        rows.append((repr(zeta), repr(length), repr(mass)) + split(q) + split(delta) + split(c) + split(tau) + split(tau * mp.log(2)))
    write("damping_conversions.csv", ["zeta", "length_m", "mass_kg", "q_hi", "q_lo", "log_decrement_hi", "log_decrement_lo",
                                      "c_hi", "c_lo", "tau_hi", "tau_lo", "half_life_hi", "half_life_lo"], rows)


def exact_motion():
    """The undamped pendulum from rest at A0: theta = 2 asin(k sn(K - w t | m)),
    theta' = -2 k k' w sd(w t | m) (DLMF 22.19), at 40 digits."""
    rows = []
    amps = [math.radians(d) for d in (1e-3, 0.5, 3.0, 10.0, 45.0, 90.0, 120.0, 150.0)]
    amps += [math.radians(RNG.uniform(0.0, 150.0)) for _ in range(12)]
    for a in amps:
        length = RNG.uniform(0.2, 5.0)
        w = mp.sqrt(mp.mpf(G0) / mp.mpf(length))
        half = mp.mpf(a) / 2
        k, kp = mp.sin(half), mp.cos(half)
        m = k * k
        kk = mp.ellipk(m)
        period = float(4 * kk / w)
        for t in [0.0] + [RNG.uniform(0, 2 * period) for _ in range(15)]:
            u = w * mp.mpf(t)
            theta = 2 * mp.asin(k * mp.ellipfun("sn", kk - u, m=m))
            vel = -2 * k * kp * w * mp.ellipfun("sn", u, m=m) / mp.ellipfun("dn", u, m=m)
            rows.append((repr(a), repr(length), repr(t)) + split(theta) + split(vel))
    write("exact.csv", ["amplitude_rad", "length_m", "t_s", "theta_hi", "theta_lo", "v_hi", "v_lo"], rows)


def incomplete_and_lift():
    """F(phi|m) (DLMF 19.2.4) on [0, pi/2] x [0, 1), and the lift crossing:
    the fraction of a period a pendulum of amplitude A takes to cross
    [-L/2, L/2], F(psi|k^2) / (2 K(k^2)) with k = sin(A/2) and
    sin(psi) = sin(L/4) / k."""
    rows = []
    for _ in range(400):
        phi = RNG.uniform(0.0, math.pi / 2)
        m = RNG.random() if RNG.random() < 0.7 else 1.0 - 10.0 ** -RNG.uniform(1, 12)
        f = mp.ellipf(mp.mpf(phi), mp.mpf(m))
        rows.append((repr(phi), repr(m)) + split(f))
    for phi in (0.0, 1e-300, 1e-8, math.pi / 2):
        for m in (0.0, 0.5, 0.999999):
            rows.append((repr(phi), repr(m)) + split(mp.ellipf(mp.mpf(phi), mp.mpf(m))))
    write("ellipf.csv", ["phi_rad", "m", "f_hi", "f_lo"], rows)
    rows = []
    for _ in range(300):
        lift = math.radians(RNG.uniform(0.5, 12.0))
        amplitude = RNG.uniform(lift / 2 * 1.001, math.radians(RNG.choice([5.0, 20.0, 90.0, 170.0])) + lift)
        k = mp.sin(mp.mpf(amplitude) / 2)
        psi = mp.asin(mp.sin(mp.mpf(lift) / 4) / k)
        ratio = mp.ellipf(psi, k * k) / (2 * mp.ellipk(k * k))
        rows.append((repr(lift), repr(amplitude)) + split(ratio))
    write("lift.csv", ["lift_rad", "amplitude_rad", "ratio_hi", "ratio_lo"], rows)


def main():
    os.makedirs(OUT, exist_ok=True)
    complete(parameters())
    amps = amplitudes()
    by_amplitude(amps)
    periods(amps)
    jacobi()
    damped()
    conversions()
    exact_motion()
    incomplete_and_lift()


if __name__ == "__main__":
    main()
