"""The theory of the clock pendulum, from Python: numpy arrays in and out.

Every function takes scalars or numpy arrays of any shape (broadcast
together as numpy does) and returns a float for scalars, else a float64
array of the broadcast shape. Angles are in radians (``numpy.radians`` is
one call away), lengths in metres, times in seconds, g in m/s².

The computing is done by the Rust library ``pendulum-theory`` without the
GIL: the same code, methods and measured accuracy as the ``pendulum``
command (complete elliptic integrals by the arithmetic-geometric mean,
within 4 ulp of mpmath; the exact period T = 4 sqrt(l/g) K(sin²(A0/2))).
An input the library refuses raises ``ValueError`` with its message.
"""

from __future__ import annotations

import numpy as _np

from . import _native

__all__ = [
    "STANDARD_GRAVITY",
    "ellipk",
    "ellipe",
    "ellipj",
    "period",
    "circular_error_s_per_day",
    "length_for_period",
    "amplitude_for_period",
    "normal_gravity",
    "zeta_from_q",
    "q_from_zeta",
    "log_decrement_from_zeta",
    "zeta_from_log_decrement",
    "decay_time",
    "damped_angle",
    "exact_angle",
]

#: Standard gravity, m/s² (the CLI's default).
STANDARD_GRAVITY = 9.80665


def _call(function, *args, outputs=1):
    """Broadcasts ``args`` (as views: a scalar is not copied out to the
    shape), calls ``function`` on them, and gives floats back for scalars."""
    arrays = _np.broadcast_arrays(*[_np.asarray(a, dtype=_np.float64) for a in args])
    scalar = arrays[0].ndim == 0
    result = function(*arrays)
    results = result if outputs > 1 else (result,)
    shaped = tuple(float(r) if scalar else r for r in results)
    return shaped if outputs > 1 else shaped[0]


def ellipk(m):
    """K(m), the complete elliptic integral of the first kind, in the
    parameter convention (as ``scipy.special.ellipk``): π / (2 AGM(1, √(1-m)))
    (DLMF 19.8.5). Within 4 ulp of mpmath over [0, 1); inf at m = 1; NaN
    outside [0, 1] (SciPy extends K to m < 0)."""
    return _call(_native.ellipk, m)


def ellipe(m):
    """E(m), the complete elliptic integral of the second kind (as
    ``scipy.special.ellipe``), by the AGM (DLMF 19.8.6) with Legendre's
    relation above m = 1/2. Within 4 ulp of mpmath over [0, 1]; NaN
    outside."""
    return _call(_native.ellipe, m)


def ellipj(u, m):
    """The Jacobi elliptic functions (sn, cn, dn, ph) of ``u`` with
    parameter ``m`` in [0, 1], as ``scipy.special.ellipj`` (ph = am(u)).
    Descending Landen/AGM (DLMF 22.20); within 4 ε(|f| + |u f'|) of mpmath."""
    return _call(_native.ellipj, u, m, outputs=4)


def period(length, amplitude, g=STANDARD_GRAVITY):
    """The exact period, s, of a simple pendulum of ``length`` m swinging
    ``amplitude`` rad either side, under ``g`` m/s²: 4 sqrt(l/g)
    K(sin²(A0/2)) (seed section 1-6). Within 4 ulp of mpmath."""
    return _call(_native.period, length, amplitude, g)


def circular_error_s_per_day(amplitude):
    """The circular error, s/day lost against a vanishing swing: 86400
    (1 - T0/T) at ``amplitude`` rad, without cancellation (about 86400
    A0²/16 for small swings)."""
    return _call(_native.circular_error_s_per_day, amplitude)


def length_for_period(period, amplitude=0.0, g=STANDARD_GRAVITY):
    """The length, m, that swings with ``period`` s at ``amplitude`` rad."""
    return _call(_native.length_for_period, period, amplitude, g)


def amplitude_for_period(period, length, g=STANDARD_GRAVITY):
    """The amplitude, rad, at which a pendulum of ``length`` m has
    ``period`` s (at least the small-angle period)."""
    return _call(_native.amplitude_for_period, period, length, g)


def normal_gravity(latitude, height=0.0):
    """Normal gravity, m/s², at geodetic ``latitude`` degrees and ``height``
    m above the WGS 84 ellipsoid: Somigliana's formula (NIMA TR8350.2
    eq. 4-1) with the free-air gradient -3.086e-6 m/s² per metre, as the
    CLI's ``gravity``."""
    return _call(_native.normal_gravity, latitude, height)


def _damping(value, what, to):
    return _call(lambda v: _native.damping(v, what, to), value)


def zeta_from_q(q):
    """The damping ratio ζ = 1/(2Q)."""
    return _damping(q, "q", "zeta")


def q_from_zeta(zeta):
    """The quality factor Q = 1/(2ζ) (inf for ζ = 0)."""
    return _damping(zeta, "zeta", "q")


def log_decrement_from_zeta(zeta):
    """The logarithmic decrement per period, 2πζ/√(1-ζ²) (NaN at or above
    critical damping, where there is no period)."""
    return _damping(zeta, "zeta", "log_decrement")


def zeta_from_log_decrement(delta):
    """The damping ratio from the logarithmic decrement: δ/√(4π² + δ²)."""
    return _damping(delta, "log_decrement", "zeta")


def decay_time(zeta, length, g=STANDARD_GRAVITY):
    """The time, s, for the amplitude to fall by e: the slowest time
    constant, 1/(ζ ω_n) when underdamped."""
    return _call(_native.decay_time, zeta, length, g)


def damped_angle(t, length, amplitude, zeta=0.0, g=STANDARD_GRAVITY):
    """θ(t), rad, of the linear damped pendulum released from rest at
    ``amplitude`` rad (seed section 1-4, all three regimes)."""
    return _call(_native.damped_angle, t, length, amplitude, zeta, g)


def exact_angle(t, length, amplitude, g=STANDARD_GRAVITY):
    """θ(t), rad, of the exact undamped pendulum released from rest at
    ``amplitude`` rad: θ = 2 atan2(k cn(ω_n t), k'), k = sin(A0/2)."""
    return _call(_native.exact_angle, t, length, amplitude, g)
