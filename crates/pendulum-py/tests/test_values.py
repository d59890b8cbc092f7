"""Values against the mpmath reference files the Rust tests use, to the
same ulp bounds (crates/pendulum-theory/tests/all/reference.rs: 4 ulp for K, E
and the period; 4 ε(|f| + |u f'|) for sn, cn, dn), and against SciPy on
random arrays."""

import math

import numpy as np
import pytest
import scipy.special

import pendulum_theory as pt
from conftest import load, ulp_error

ALLOWED_ULP = 4.0


def test_ellipk_and_ellipe_against_mpmath():
    _, k = load("ellipk.csv")
    assert np.max(ulp_error(pt.ellipk(k[:, 0]), k[:, 1], k[:, 2])) <= ALLOWED_ULP
    _, e = load("ellipe.csv")
    assert np.max(ulp_error(pt.ellipe(e[:, 0]), e[:, 1], e[:, 2])) <= ALLOWED_ULP


def test_period_against_mpmath():
    header, rows = load("period.csv")
    assert header[:3] == ["amplitude_rad", "length_m", "g_m_s2"]
    got = pt.period(rows[:, 1], rows[:, 0], rows[:, 2])
    assert np.max(ulp_error(got, rows[:, 3], rows[:, 4])) <= ALLOWED_ULP


def test_jacobi_against_mpmath():
    _, r = load("jacobi.csv")
    u, m = r[:, 0], r[:, 1]
    sn, cn, dn, _ = pt.ellipj(u, m)
    t_sn, t_cn, t_dn = r[:, 2] + r[:, 3], r[:, 4] + r[:, 5], r[:, 6] + r[:, 7]
    derivatives = [t_cn * t_dn, t_sn * t_dn, m * t_sn * t_cn]
    for i, got in enumerate([sn, cn, dn]):
        hi, lo = r[:, 2 + 2 * i], r[:, 3 + 2 * i]
        scale = np.finfo(float).eps * (np.abs(hi) + np.abs(u * derivatives[i]))
        assert np.max(np.abs((got - hi) - lo) / scale) <= 4.0


def test_against_scipy_on_random_arrays():
    rng = np.random.default_rng(20261122)
    m = rng.uniform(0.0, 0.999, size=(50, 40))
    assert np.allclose(pt.ellipk(m), scipy.special.ellipk(m), rtol=4e-15, atol=0)
    assert np.allclose(pt.ellipe(m), scipy.special.ellipe(m), rtol=4e-15, atol=0)
    u = rng.uniform(-20.0, 20.0, size=(50, 40))
    ours = pt.ellipj(u, m)
    theirs = scipy.special.ellipj(u, m)
    for a, b, name in zip(ours, theirs, ["sn", "cn", "dn", "ph"]):
        assert np.allclose(a, b, rtol=1e-12, atol=1e-12), name


def test_the_period_by_hand():
    # Section 1-6: T = 4 sqrt(l/g) K(sin²(A0/2)), with SciPy's K.
    a = np.radians(np.linspace(0.0, 170.0, 1001))
    expected = 4.0 * np.sqrt(0.99362 / 9.80665) * scipy.special.ellipk(np.sin(a / 2) ** 2)
    assert np.allclose(pt.period(0.99362, a), expected, rtol=1e-14, atol=0)
    # The circular error against the same: 86400 (1 - T0/T).
    t0 = 2 * math.pi * math.sqrt(0.99362 / 9.80665)
    assert np.allclose(
        pt.circular_error_s_per_day(a[1:]),
        86400 * (1 - t0 / expected[1:]),
        rtol=1e-9,
        atol=1e-12,
    )


def test_inverses_and_gravity():
    a = np.radians([0.5, 3.0, 30.0, 120.0])
    t = pt.period(0.99362, a)
    assert np.allclose(pt.amplitude_for_period(t, 0.99362), a, rtol=1e-10)
    assert np.allclose(pt.length_for_period(t, a), 0.99362, rtol=1e-14)
    # The seconds pendulum at standard gravity: 0.99362 m (the train test's figure).
    assert abs(pt.length_for_period(2.0) - 0.993621) < 1e-6
    # WGS 84 normal gravity: 9.7803253359 at the equator, 9.8321849379 at the poles.
    assert abs(pt.normal_gravity(0.0) - 9.7803253359) < 1e-9
    assert abs(pt.normal_gravity(90.0) - 9.8321849379) < 1e-9


def test_damping_conversions_and_motion():
    assert pt.zeta_from_q(10_000) == 5e-5
    assert pt.q_from_zeta(5e-5) == pytest.approx(10_000, rel=1e-15)
    z = np.array([1e-4, 0.01, 0.3])
    d = pt.log_decrement_from_zeta(z)
    assert np.allclose(d, 2 * np.pi * z / np.sqrt(1 - z**2), rtol=1e-14)
    assert np.allclose(pt.zeta_from_log_decrement(d), z, rtol=1e-13)
    w = math.sqrt(9.80665 / 0.99362)
    assert pt.decay_time(0.01, 0.99362) == pytest.approx(1 / (0.01 * w), rel=1e-14)
    # Section 1-4, underdamped, from rest: A e^{-ζωt}(cos ω_d t + ζ/√(1-ζ²) sin ω_d t).
    t = np.linspace(0, 20, 201)
    zeta, a0 = 0.02, 0.05
    wd = w * math.sqrt(1 - zeta**2)
    closed = a0 * np.exp(-zeta * w * t) * (
        np.cos(wd * t) + zeta / math.sqrt(1 - zeta**2) * np.sin(wd * t)
    )
    assert np.allclose(pt.damped_angle(t, 0.99362, a0, zeta), closed, rtol=1e-12, atol=1e-15)
    # The exact swing: back at +A0 after one exact period.
    a = math.radians(60)
    period = pt.period(0.99362, a)
    assert pt.exact_angle(period, 0.99362, a) == pytest.approx(a, rel=1e-12)
    assert abs(pt.exact_angle(period / 2, 0.99362, a) + a) < 1e-12
