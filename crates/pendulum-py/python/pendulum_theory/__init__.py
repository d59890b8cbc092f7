"""The theory of the clock pendulum, from Python: numpy arrays in and out.

Every function takes scalars or numpy arrays of any shape (broadcast
together as numpy does) and returns a float for scalars, else a float64
array of the broadcast shape. Angles are in radians (``numpy.radians`` is
one call away), lengths in metres, times in seconds, g in m/s². The
weather is as the command line takes it: temperatures in °C, relative
humidities in %, pressures in hPa (``design``'s keyword and
``clock_run``'s weather column and ``clock_log``'s keyword say so:
``pressure_hpa``); a log's amplitudes are in degrees, named so:
``amplitude_deg``.

The computing is done by the Rust library ``pendulum-theory`` without the
GIL: the same code, methods and measured accuracy as the ``pendulum``
command (complete elliptic integrals by the arithmetic-geometric mean,
within 4 ulp of mpmath; the exact period T = 4 sqrt(l/g) K(sin²(A0/2))).
An input the library refuses raises ``ValueError`` with its message.
"""

from __future__ import annotations

import json as _json
import os as _os

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
    "simulate",
    "fit_decay",
    "fit_beats",
    "fit_period",
    "fit_file",
    "lists",
    "fit_photogate",
    "fit_trajectory",
    "FitResult",
    "clock",
    "clock_run",
    "listen",
    "period_table",
    "length",
    "amplitude",
    "damped",
    "train",
    "train_for",
    "design",
    "regulate",
    "compensate",
    "report",
    "stability",
    "tide",
    "clock_log",
]

#: Standard gravity, m/s²: the library's default, as the CLI's.
STANDARD_GRAVITY = _native.STANDARD_GRAVITY


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
    outside [0, 1] (SciPy extends K to m < 0).

    >>> import pendulum_theory as pt
    >>> pt.ellipk([0.0, 0.5]).round(12).tolist()  # π/2, and K(1/2) = Γ(1/4)²/(4√π)
    [1.570796326795, 1.854074677301]
    """
    return _call(_native.ellipk, m)


def ellipe(m):
    """E(m), the complete elliptic integral of the second kind (as
    ``scipy.special.ellipe``), by the AGM (DLMF 19.8.6) with Legendre's
    relation above m = 1/2. Within 4 ulp of mpmath over [0, 1]; NaN
    outside.

    >>> import pendulum_theory as pt
    >>> pt.ellipe([0.0, 0.5, 1.0]).round(12).tolist()  # π/2, E(1/2), 1
    [1.570796326795, 1.350643881048, 1.0]
    """
    return _call(_native.ellipe, m)


def ellipj(u, m):
    """The Jacobi elliptic functions (sn, cn, dn, ph) of ``u`` with
    parameter ``m`` in [0, 1], as ``scipy.special.ellipj`` (ph = am(u)).
    Descending Landen/AGM (DLMF 22.20); within 4 ε(|f| + |u f'|) of mpmath.

    >>> import math
    >>> import pendulum_theory as pt
    >>> sn, cn, dn, ph = pt.ellipj(0.5, 1.0)  # at m = 1: tanh, sech, sech, gd
    >>> round(sn, 12), round(cn, 12), round(dn, 12), round(ph, 12)
    (0.46211715726, 0.88681888397, 0.88681888397, 0.480381079134)
    >>> round(math.tanh(0.5), 12), round(2 * math.atan(math.tanh(0.25)), 12)
    (0.46211715726, 0.480381079134)
    """
    return _call(_native.ellipj, u, m, outputs=4)


def period(length, amplitude, g=STANDARD_GRAVITY):
    """The exact period, s, of a simple pendulum of ``length`` m swinging
    ``amplitude`` rad either side, under ``g`` m/s²: 4 sqrt(l/g)
    K(sin²(A0/2)) (seed section 1-6). Within 4 ulp of mpmath.

    >>> import numpy as np
    >>> import pendulum_theory as pt
    >>> # The seconds pendulum (l = g/π²): 2 s at a small swing, 1.18 times
    >>> # that at 90° (2K(1/2)/π).
    >>> pt.period(0.99362, np.radians([0.0, 2.0, 90.0])).round(6).tolist()
    [1.999999, 2.000151, 2.36068]
    """
    return _call(_native.period, length, amplitude, g)


def circular_error_s_per_day(amplitude):
    """The circular error, s/day lost against a vanishing swing: 86400
    (1 - T0/T) at ``amplitude`` rad, without cancellation (about 86400
    A0²/16 for small swings).

    >>> import math
    >>> import pendulum_theory as pt
    >>> a = math.radians(2.0)
    >>> round(pt.circular_error_s_per_day(a), 4), round(86400 * a**2 / 16, 4)
    (6.5797, 6.5797)
    """
    return _call(_native.circular_error_s_per_day, amplitude)


def length_for_period(period, amplitude=0.0, g=STANDARD_GRAVITY):
    """The length, m, that swings with ``period`` s at ``amplitude`` rad.

    >>> import numpy as np
    >>> import pendulum_theory as pt
    >>> round(pt.length_for_period(2.0), 6)  # g/π²: the seconds pendulum
    0.993621
    >>> pt.length_for_period([1.0, 2.0], np.radians(3.0)).round(6).tolist()
    [0.24832, 0.993281]
    """
    return _call(_native.length_for_period, period, amplitude, g)


def amplitude_for_period(period, length, g=STANDARD_GRAVITY):
    """The amplitude, rad, at which a pendulum of ``length`` m has
    ``period`` s (at least the small-angle period).

    >>> import numpy as np
    >>> import pendulum_theory as pt
    >>> t = pt.period(0.99362, np.radians(3.0))  # the period at 3° gives 3° back
    >>> round(float(np.degrees(pt.amplitude_for_period(t, 0.99362))), 9)
    3.0
    """
    return _call(_native.amplitude_for_period, period, length, g)


def normal_gravity(latitude, height=0.0):
    """Normal gravity, m/s², at geodetic ``latitude`` degrees and ``height``
    m above the WGS 84 ellipsoid: Somigliana's formula (NIMA TR8350.2
    eq. 4-1) with the free-air gradient -3.086e-6 m/s² per metre, as the
    CLI's ``gravity``.

    >>> import pendulum_theory as pt
    >>> pt.normal_gravity([0.0, 45.0, 90.0]).round(7).tolist()  # γ_e, 45°, γ_p
    [9.7803253, 9.8061978, 9.8321849]
    >>> round(pt.normal_gravity(45.0, 1000.0) - pt.normal_gravity(45.0), 9)
    -0.003086
    """
    return _call(_native.normal_gravity, latitude, height)


def _damping(value, what, to):
    return _call(lambda v: _native.damping(v, what, to), value)


def zeta_from_q(q):
    """The damping ratio ζ = 1/(2Q).

    >>> import pendulum_theory as pt
    >>> pt.zeta_from_q([100.0, 10000.0]).tolist()
    [0.005, 5e-05]
    """
    return _damping(q, "q", "zeta")


def q_from_zeta(zeta):
    """The quality factor Q = 1/(2ζ) (inf for ζ = 0).

    >>> import pendulum_theory as pt
    >>> pt.q_from_zeta([0.005, 0.0]).tolist()
    [100.0, inf]
    """
    return _damping(zeta, "zeta", "q")


def log_decrement_from_zeta(zeta):
    """The logarithmic decrement per period, 2πζ/√(1-ζ²) (NaN at or above
    critical damping, where there is no period).

    >>> import math
    >>> import pendulum_theory as pt
    >>> round(pt.log_decrement_from_zeta(0.005), 12)
    0.031416319242
    >>> round(2 * math.pi * 0.005 / math.sqrt(1 - 0.005**2), 12)
    0.031416319242
    """
    return _damping(zeta, "zeta", "log_decrement")


def zeta_from_log_decrement(delta):
    """The damping ratio from the logarithmic decrement: δ/√(4π² + δ²).

    >>> import pendulum_theory as pt
    >>> delta = pt.log_decrement_from_zeta([0.001, 0.005])
    >>> pt.zeta_from_log_decrement(delta).round(12).tolist()
    [0.001, 0.005]
    """
    return _damping(delta, "log_decrement", "zeta")


def decay_time(zeta, length, g=STANDARD_GRAVITY):
    """The time, s, for the amplitude to fall by e: the slowest time
    constant, 1/(ζ ω_n) when underdamped.

    >>> import math
    >>> import pendulum_theory as pt
    >>> # Q = 10,000 (ζ = 5e-5) on a seconds pendulum: 1/(ζ ω_n), 1.8 hours.
    >>> round(pt.decay_time(5e-5, 0.99362), 3)
    6366.193
    >>> round(1 / (5e-5 * math.sqrt(9.80665 / 0.99362)), 3)
    6366.193
    """
    return _call(_native.decay_time, zeta, length, g)


def damped_angle(t, length, amplitude, zeta=0.0, g=STANDARD_GRAVITY):
    """θ(t), rad, of the linear damped pendulum released from rest at
    ``amplitude`` rad (seed section 1-4, all three regimes).

    >>> import pendulum_theory as pt
    >>> t = [0.0, 1.0, 2.0]  # the seconds pendulum's turning points
    >>> pt.damped_angle(t, 0.99362, 0.05).round(6).tolist()
    [0.05, -0.05, 0.05]
    >>> pt.damped_angle(t, 0.99362, 0.05, zeta=0.005).round(6).tolist()
    [0.05, -0.049221, 0.048454]
    """
    return _call(_native.damped_angle, t, length, amplitude, zeta, g)


def exact_angle(t, length, amplitude, g=STANDARD_GRAVITY):
    """θ(t), rad, of the exact undamped pendulum released from rest at
    ``amplitude`` rad: θ = 2 atan2(k cn(ω_n t), k'), k = sin(A0/2).

    >>> import numpy as np
    >>> import pendulum_theory as pt
    >>> a = np.radians(30.0)  # half an exact period on, it is at -30°
    >>> half = pt.period(0.99362, a) / 2
    >>> round(float(np.degrees(pt.exact_angle(half, 0.99362, a))), 9)
    -30.0
    """
    return _call(_native.exact_angle, t, length, amplitude, g)


def simulate(
    length,
    amplitude,
    duration,
    *,
    q=None,
    zeta=None,
    log_decrement=None,
    quadratic_drag=None,
    friction_angle=None,
    drag=None,
    g=None,
    method=None,
    tolerance=None,
    force=False,
):
    """The full nonlinear damped pendulum θ'' + 2ζω θ' + b θ'|θ'| + ω²(sin θ
    + r sign θ') = 0, released from rest at ``amplitude`` rad, for
    ``duration`` s: the CLI's ``simulate``, the same library call (methods
    ``dop853`` (the default), ``vern9``, ``symplectic``, ``exact``,
    ``averaged``; ``tolerance`` relative to the swing, the library's
    default if not given). Damping by ``q``, ``zeta`` or ``log_decrement``
    (none: undamped), quadratic drag b per radian, dry friction angle r
    rad; ``drag`` a dict of the library's drag laws by name and their
    coefficients (``{"three_halves_drag": 0.002}``; the CLI's ``--drag
    NAME=VALUE``). A run estimated at more than a few seconds of computing
    is refused unless ``force``; one of more than a day always.

    Returns ``(time_s, angle_rad, rate_s_per_day, summary)``: every turning
    point's time and signed angle, the rate a clock would keep over the
    half swing that ends there (positive when it gains; NaN at the
    release), and the CLI's JSON summary as a dict.

    >>> import numpy as np
    >>> import pendulum_theory as pt
    >>> t, angle, rate, summary = pt.simulate(0.99362, np.radians(30.0), 5.0)
    >>> summary["method"], summary["swings"]
    ('dop853', 4)
    >>> # Two turning points on: one exact period, 4 √(l/g) K(sin² 15°).
    >>> round(float(t[2]), 6), round(pt.period(0.99362, np.radians(30.0)), 6)
    (2.034816, 2.034816)
    """
    given = [(k, v) for k, v in (("q", q), ("zeta", zeta), ("log_decrement", log_decrement))
             if v is not None]
    if len(given) > 1:
        raise ValueError("give one of q, zeta, log_decrement")
    damping = (given[0][0], float(given[0][1])) if given else None
    t, a, r, summary = _native.simulate(
        float(length), float(amplitude), float(duration), damping, _number(quadratic_drag),
        _number(friction_angle), _drag_laws(drag),
        _number(g), _text(method), _number(tolerance), bool(force))
    return t, a, r, _json.loads(summary)


class FitResult(dict):
    """The result of a fit: a dict with the keys of the CLI's JSON for the
    same fit, and attributes ``.parameters`` and ``.standard_errors`` (of
    the preferred law, or the only one) and ``.preferred`` (its name;
    ``None`` for beats, which have no competing laws).

    >>> import numpy as np
    >>> import pendulum_theory as pt
    >>> t = np.arange(0.0, 600.0, 10.0)
    >>> r = pt.fit_decay(t, 0.1 * np.exp(-t / 200.0))
    >>> r.preferred, round(r.parameters["decay_rate_per_s"], 9), r["points"]
    ('viscous', 0.005, 60)
    """

    def __init__(self, data, parameters, standard_errors, preferred):
        super().__init__(data)
        self.parameters = dict(parameters)
        self.standard_errors = dict(standard_errors)
        self.preferred = preferred

    def __repr__(self):
        return f"FitResult(preferred={self.preferred!r}, parameters={self.parameters!r})"


def _array(x):
    return _np.ascontiguousarray(x, dtype=_np.float64)


def _drag_laws(drag):
    """The ``drag`` keyword, a dict of drag laws by name and their
    coefficients, as the native calls take it; anything else is refused as
    the other keywords are (ValueError naming it)."""
    if drag is None:
        return []
    if not isinstance(drag, dict):
        raise ValueError("drag: give a dict of drag laws by name and their coefficients, "
                         f"e.g. {{'three_halves_drag': 0.002}}, got {type(drag).__name__}")
    laws = []
    for name, value in drag.items():
        if isinstance(value, (bool, _np.bool_)) or not isinstance(value, (int, float, _np.number)):
            raise ValueError(f"drag {name}: give a number, got {value!r}")
        laws.append((str(name), float(value)))
    return laws


def _number(x):
    """A keyword's number as a float (``None`` stays ``None``: the library
    chooses the default). ``True`` and ``False`` are refused where the
    function is called (:func:`_refusing_bools`)."""
    return None if x is None else float(x)


def _holds_bool(value):
    """Whether ``value`` is ``True`` or ``False``, or a list, tuple or array
    holding one (a design's part dicts are the library's to read: their
    ``massless = true`` is a flag)."""
    if isinstance(value, (bool, _np.bool_)):
        return True
    if isinstance(value, _np.ndarray):
        return value.dtype == bool or (value.dtype == object and
                                       any(_holds_bool(v) for v in value.ravel()))
    if isinstance(value, (list, tuple)):
        return any(_holds_bool(v) for v in value)
    return False


#: Keywords renamed with their unit (the old name is refused, pointing to
#: the new): a pressure was Pa in ``design`` and hPa on the command line.
_RENAMED = {
    "design": {"pressure": "pressure_hpa: a pressure in hPa, as the CLI's --pressure "
                           "(the keyword pressure took Pa)"},
    "clock_log": {"pressure": "pressure_hpa: the log's pressures in hPa, as its "
                              "pressure_hpa column",
                  "amplitude": "amplitude_deg: the log's amplitudes in degrees, as its "
                               "amplitude_deg column (other amplitudes are radians)"},
}


def _refusing_bools(f):
    """``f`` refusing ``True`` or ``False`` for any argument whose default
    is not itself ``True`` or ``False`` (Python takes ``True`` for 1:
    ``beat_error=True`` would be a beat error of a second), naming it as
    the library names a field."""
    import functools
    import inspect
    signature = inspect.signature(f)
    flags = {n for n, p in signature.parameters.items() if isinstance(p.default, bool)}

    renamed = _RENAMED.get(f.__name__, {})

    @functools.wraps(f)
    def checked(*args, **kwargs):
        for key in kwargs:
            if key in renamed:
                raise TypeError(f"{f.__name__}() takes no keyword '{key}'; give "
                                f"{renamed[key]}")
        try:
            bound = signature.bind_partial(*args, **kwargs)
        except TypeError:
            return f(*args, **kwargs)
        for name, value in bound.arguments.items():
            if signature.parameters[name].kind == inspect.Parameter.VAR_KEYWORD:
                items = value.items()
            else:
                items = [(name, value)]
            for key, v in items:
                if key not in flags and _holds_bool(v):
                    raise ValueError(f"{key}: must be a number or a name, not True or False")
        return f(*args, **kwargs)
    return checked


def _count(x):
    """A keyword's whole number, held within a 64-bit integer (the
    library refuses what is out of its range, as ValueError; a count past
    2**63 is as far out as 2**63)."""
    if x is None:
        return None
    return max(-(2**63), min(int(x), 2**63 - 1))


def _teeth(name, xs):
    """A list of whole numbers (teeth, leaves); a fraction is refused,
    as the CLI refuses it, not rounded."""
    if xs is None:
        return None
    out = []
    for x in xs:
        v = float(x)
        if isinstance(x, bool) or v != v or abs(v) == float("inf") or v != int(v):
            raise ValueError(f"{name}: counts must be whole numbers, got {x!r}")
        out.append(max(-(2**63), min(int(x), 2**63 - 1)))
    return out


def _text(x):
    return None if x is None else str(x)


def _as_length_uncertainty(call):
    """``call()``, its refusal of the library's ``length_standard_error``
    named by this module's argument, ``length_uncertainty``."""
    try:
        return call()
    except ValueError as e:
        text = str(e)
        if text.startswith("length_standard_error"):
            raise ValueError("length_uncertainty" + text[len("length_standard_error"):]) from None
        raise


def fit_decay(time, amplitude, model="all", *, period=None, length=None, g=None, mass=None,
              force=False):
    """Fits the amplitude-decay laws (viscous, coulomb, quadratic,
    viscous+coulomb, viscous+quadratic, coulomb+quadratic,
    viscous+coulomb+quadratic (once ``full``, still taken);
    ``model="all"`` for every one; and, when named, those of the other drag
    laws of ``simulate``'s list: three_halves, viscous+three_halves,
    coulomb+three_halves, viscous+coulomb+three_halves)
    to ``amplitude`` (rad) at ``time`` (s), every rate held at least 0: the
    CLI's ``fit decay``, the same library call. With ``period`` (s) or
    ``length`` (m; ``g`` m/s², standard gravity if not given) the rates
    become ζ, Q, the friction angle and the drag; with ``mass`` (kg) too,
    the energy each law says is lost. Each law's ``q_factor`` is Q over
    the record (the energy lost per cycle, whatever the law: what
    ``fit_trajectory`` gives for the same record), ``q_viscous`` its
    viscous part alone (amplitudes give no g: the length's uncertainty,
    the CLI's ``--length-uncertainty``, goes in ``fit_trajectory``'s and
    ``fit_period``'s). Returns the
    CLI's JSON as a dict (points, omega_rad_s, omega_source, models,
    preferred, warnings), every key and number the same.

    >>> import numpy as np
    >>> import pendulum_theory as pt
    >>> # A 2 s pendulum of Q = 500 read every 10 s: A = 0.1 e^(-ζωt), ζ = 1/(2Q).
    >>> t = np.arange(0.0, 600.0, 10.0)
    >>> r = pt.fit_decay(t, 0.1 * np.exp(-np.pi * t / 1000.0), period=2.0)
    >>> r.preferred, round(r.parameters["zeta"], 9)
    ('viscous', 0.001)
    >>> round(r["models"][0]["q_viscous"], 6)
    500.0
    """
    d = _json.loads(_native.fit_decay(
        _array(time), _array(amplitude), _text(model), _number(period), _number(length),
        _number(g), _number(mass), bool(force)))
    best = next((m for m in d["models"] if m["model"] == d["preferred"]), {})
    return FitResult(d, best.get("parameters", {}), best.get("standard_errors", {}),
                     d["preferred"])


def fit_trajectory(time, angle=None, model="auto", *, angular_velocity=None, length=None,
                   length_uncertainty=None, force=False, drag_law=None):
    """Fits section 1-4's closed form (``"linear"``) or the nonlinear
    damped equation integrated inside the fit (``"nonlinear"``; ``"auto"``:
    nonlinear above a 5° swing) to ``angle`` (rad) at ``time`` (s), or by
    the models' derivative to a gyroscope's ``angular_velocity`` (rad/s)
    instead (one array, or one column per sensor axis, shape (n, 3): the
    swing's axis is found among them): the CLI's ``fit trajectory``, the
    same library call; with ``length`` (m), g, whose standard error takes
    ``length_uncertainty`` (m, the CLI's ``--length-uncertainty``) and
    lists its parts (``standard_error_parts``). ``q_factor`` is Q over the
    record (the energy lost per cycle, whatever the damping law),
    ``q_viscous`` the viscous part alone. ``drag_law`` (a name of
    ``simulate``'s ``drag`` laws, the CLI's ``--drag-law``) is the drag the
    nonlinear fit tries beside viscous damping and dry friction (quadratic
    drag unnamed). Returns the CLI's JSON as a
    dict (points, model, model_requested, observed, parameters,
    standard_errors, residual_rms_rad or residual_rms_rad_s,
    gyroscope_axis, length_m, length_source, warnings).

    >>> import numpy as np
    >>> import pendulum_theory as pt
    >>> # 0.5 m, g = 9.81, ζ = 0.002, released at 0.01 rad, filmed at 50 Hz.
    >>> w, z = np.sqrt(9.81 / 0.5), 0.002
    >>> wd = w * np.sqrt(1 - z * z)
    >>> t = np.arange(1000) / 50.0
    >>> angle = 0.01 * np.exp(-z * w * t) * (np.cos(wd * t) + z * w / wd * np.sin(wd * t))
    >>> r = pt.fit_trajectory(t, angle, length=0.5)
    >>> r["model"], round(r["q_viscous"], 6), round(r.parameters["g_m_s2"], 3)
    ('linear', 250.0, 9.81)
    """
    rates = None
    if angular_velocity is not None:
        a = _np.asarray(angular_velocity, dtype=float)
        if a.ndim == 2:
            rates = [_np.ascontiguousarray(a[:, j]) for j in range(a.shape[1])]
        else:
            rates = [_array(a)]
    d = _json.loads(_as_length_uncertainty(lambda: _native.fit_trajectory(
        _array(time), None if angle is None else _array(angle), _text(model), _number(length),
        bool(force), rates, _number(length_uncertainty),
        None if drag_law is None else _text(drag_law))))
    return FitResult(d, d["parameters"], d["standard_errors"], d["model"])


def _known(length, parts, nut_pitch, nut_tpi, nut_divisions, crutch, amplitude):
    """The advice's keywords, as the native calls take them."""
    return dict(length=_number(length), parts=None if parts is None else _parts(parts),
                nut_pitch=_number(nut_pitch), nut_tpi=_number(nut_tpi),
                nut_divisions=_count(nut_divisions), crutch=_number(crutch),
                amplitude=_number(amplitude))


def fit_beats(time, *, bph=None, period=None, length=None, parts=None, nut_pitch=None,
              nut_tpi=None, nut_divisions=None, crutch=None, amplitude=None):
    """What a timegrapher shows, from one time per beat (s): the CLI's
    ``fit beats``, the same library call. The rate is against ``bph`` or
    ``period`` (s), else the nearest standard beat within 2%. Returns the
    CLI's JSON as a dict (beats, mean_beat_s, beats_per_hour,
    nominal_beat_s, rate_s_per_day, beat_error_ms, jitter_ms, repaired,
    allan_deviation, advice). ``advice`` is what to do (the bob, the nut,
    the crutch), figured with what is known of the clock: ``length`` (m)
    or a design's ``parts``, the nut's ``nut_pitch`` (m) or ``nut_tpi``,
    ``nut_divisions``, ``crutch`` (m, the crutch pin below the pivot) and
    ``amplitude`` (rad), as the CLI's flags of those names.

    >>> import numpy as np
    >>> import pendulum_theory as pt
    >>> # A seconds clock gaining 1 s a day, every other tick 2 ms late.
    >>> k = np.arange(600)
    >>> r = pt.fit_beats(k / (1 + 1 / 86400) + 0.002 * (k % 2), bph=3600)
    >>> round(r["rate_s_per_day"], 6), round(r["beat_error_ms"], 6)
    (1.0, 2.0)
    """
    d = _json.loads(_native.fit_beats(
        _array(time), _number(bph), _number(period),
        **_known(length, parts, nut_pitch, nut_tpi, nut_divisions, crutch, amplitude)))
    keys = ["rate_s_per_day", "beat_error_ms", "jitter_ms", "beats_per_hour"]
    return FitResult(d, {k: d[k] for k in keys}, {}, None)


def fit_period(period, *, period_standard_error=None, amplitude=None, length=None,
               pendulum_length=None, pendulum_length_standard_error=None, bob_radius=None,
               length_uncertainty=None):
    """Fits a table of periods (s): against ``amplitude`` (rad) with the
    exact law ``T0 (2/π) K(sin²(A/2))`` (and g with ``pendulum_length``,
    m), or against ``length`` (m) with ``T² = 4π²(L + offset)/g``;
    weighted by ``period_standard_error`` (s) when given. The CLI's ``fit
    period``, the same library call. Returns the CLI's JSON as a dict
    (rows, against, weighted, parameters, standard_errors, series,
    residual_rms_s, chi_square, warnings). ``length_uncertainty`` is
    ``pendulum_length_standard_error`` by the name the other fits use.

    >>> import numpy as np
    >>> import pendulum_theory as pt
    >>> length = np.array([0.25, 0.5, 0.75, 1.0])  # T = 2π √(L/g), g = 9.81
    >>> r = pt.fit_period(2 * np.pi * np.sqrt(length / 9.81), length=length)
    >>> r["against"], round(r.parameters["g_m_s2"], 9), round(r.parameters["length_offset_m"], 9)
    ('length', 9.81, 0.0)
    """
    if length_uncertainty is not None:
        if pendulum_length_standard_error is not None:
            raise ValueError("pendulum_length_standard_error: give it or length_uncertainty, "
                             "not both")
        pendulum_length_standard_error = length_uncertainty
    def optional(x):
        return None if x is None else _array(x)
    d = _json.loads(_native.fit_period(
        _array(period), optional(period_standard_error), optional(amplitude), optional(length),
        _number(pendulum_length), _number(pendulum_length_standard_error), _number(bob_radius)))
    return FitResult(d, d["parameters"], d["standard_errors"], None)


# fit_file's keywords and the request keys they are (pendulum_data::lab):
# SI values, each key named with its unit as the command's --json is.
_FILE_KEYS = {
    "columns": "columns", "angle_unit": "angle_unit", "frame_rate": "frame_rate_hz",
    "run": "run", "pivot": "pivot", "y_down": "y_down", "scale": "scale_m",
    "model": "model", "period": "period_s", "length": "length_m",
    "length_uncertainty": "length_uncertainty_m", "mass": "mass_kg", "g": "g_m_s2",
    "latitude": "latitude_deg", "height": "height_m", "start": "from_s", "stop": "to_s",
    "bob_radius": "bob_radius_m", "force": "force",
}


def lists():
    """The library's lists where it is meant to grow: each escapement,
    stability deviation, drag law and file format read whole, with its
    name and help, as the command line's help gives them.

    >>> [e["name"] for e in lists()["escapements"]]
    ['impulse', 'deadbeat', 'recoil', 'constant-force', 'free']
    >>> [d["key"] for d in lists()["deviations"]]
    ['adev', 'mdev', 'tdev', 'hdev', 'totdev', 'mtie_s']
    """
    return _json.loads(_native.lists())


def fit_file(path, fit, *, columns=None, angle_unit=None, frame_rate=None, run=None,
             pivot=None, y_down=False, scale=None, model=None, period=None, length=None,
             length_uncertainty=None, mass=None, g=None, latitude=None, height=None,
             start=None, stop=None, bob_radius=None, force=False):
    """Reads a measurement file (a Tracker project or export, a phyphox
    CSV or workbook, any table the command line reads) and fits it as
    ``pendulum fit <fit> FILE --json`` does, ``fit`` being ``"decay"``,
    ``"trajectory"`` or ``"period"``: the same reader and fit (the page's
    lab's, ``pendulum_data::lab``), the keywords the command's flags in SI
    units (``length`` m, ``period`` s, ``mass`` kg, ``g`` m/s²,
    ``frame_rate`` Hz, ``scale`` m; ``latitude`` in degrees, ``height`` m;
    ``start``/``stop`` s are ``--from``/``--to``; ``pivot`` ``"X,Y"`` in
    the file's units or ``"fit"``; ``columns`` a list of names or one
    comma-separated string; ``angle_unit`` ``"deg"`` or ``"rad"``).
    Returns the command's JSON as a dict, every key and number the same,
    with two keys beside: ``figure`` (its ``--plot`` as panels of series)
    and ``notes`` (what the reader left out, which the command says on
    standard error); each warning is ``{"code", "message", "figure"}``, as in
    every result. A refusal raises ``ValueError`` with the
    command's sentence.

    >>> import pendulum_theory as pt
    >>> r = pt.fit_file("examples/rundown.csv", "decay", length=0.994)
    >>> r["file"], r["preferred"] in {m["model"] for m in r["models"]}
    ('examples/rundown.csv', True)
    """
    # The keywords, as given (every one of them is a request key).
    given = {key: value for key, value in locals().items() if key in _FILE_KEYS}
    name = _os.fspath(path)
    if not isinstance(name, str):
        name = name.decode()
    request = {"fit": _text(fit), "file_name": name}
    for key, value in given.items():
        if value is None or (key in ("y_down", "force") and value is False):
            continue
        if key == "columns" and not isinstance(value, str):
            value = ",".join(str(c) for c in value)
        elif key == "pivot" and not isinstance(value, str):
            value = ",".join(repr(float(v)) for v in value)
        elif key in ("y_down", "force"):
            value = bool(value)
        elif key == "run":
            value = _count(value)
        elif key not in ("angle_unit", "model", "pivot", "columns"):
            value = _number(value)
            # JSON has no NaN or infinity: refused here in the library's words.
            if value != value:
                raise ValueError(f"{key}: must be a finite number, got a value that is not "
                                 "a number")
            if value in (float("inf"), float("-inf")):
                raise ValueError(f"{key}: must be a finite number, got an infinite value")
        request[_FILE_KEYS[key]] = value
    try:
        with open(name, "rb") as f:
            data = f.read()
    except OSError as e:
        raise ValueError(f"{name}: cannot read it: {e.strerror}") from None
    reply = _json.loads(_native.fit_file(_json.dumps(request), data))
    if "error" in reply:
        raise ValueError(reply["error"]["message"])
    out = reply["ok"]
    for key in ("figure", "notes"):
        out[key] = reply[key]
    return out


def fit_photogate(time, *, gate=None, select=None, bob_diameter=None, bph=None, period=None):
    """A light gate's log: event times (s), with each event's ``gate``
    (numbers, one per gate) when it holds several; ``select`` the gate to
    read (the first logged by default). The two edges of each shadow are
    paired into a pass at its middle; the passes are a beat log (rate
    against ``bph`` or ``period``), and with ``bob_diameter`` (m) the
    shadows give the bob's speed at the gate. The CLI's ``fit beats`` on a
    gate log, the same library call; returns its JSON as a dict
    (photogate, beats, mean_beat_s, beat_error_ms, …).

    >>> import numpy as np
    >>> import pendulum_theory as pt
    >>> # A bob of 50 mm shadowing the gate for 24 ms, once a second.
    >>> k = np.arange(1, 301)
    >>> edges = np.sort(np.concatenate([k - 0.012, k + 0.012]))
    >>> r = pt.fit_photogate(edges, bob_diameter=0.05, bph=3600)
    >>> r["photogate"]["passes"], round(r["photogate"]["gate_speed_start_m_s"], 6)
    (300, 2.083333)
    >>> round(r["rate_s_per_day"], 6), round(r["beat_error_ms"], 6)
    (0.0, 0.0)
    """
    d = _json.loads(_native.fit_photogate(
        _array(time), None if gate is None else _array(gate),
        None if select is None else int(select), _number(bob_diameter), _number(bph),
        _number(period)))
    keys = ["rate_s_per_day", "beat_error_ms", "jitter_ms", "beats_per_hour"]
    return FitResult(d, {k: d[k] for k in keys}, {}, None)


def _clock(length, *, parts=None, drive_energy=None, drive_torque=None, q=None, escapement=None,
           lift_angle=None, mass=None, friction=None, recoil=None, impulse_angle=None,
           every_beats=None, beat_error=None, out_of_beat=None, g=None, drive_factor=None,
           drive_range=None, steps=None, run=None, drag=None):
    factors = None if drive_factor is None else [
        float(f) for f in _np.atleast_1d(_np.asarray(drive_factor, dtype=_np.float64)).ravel()]
    span = None if drive_range is None else (float(drive_range[0]), float(drive_range[1]))
    text, columns = _native.clock(
        _number(length), None if parts is None else _parts(parts), _number(g), _number(mass), _number(q), _text(escapement),
        _number(lift_angle), _number(drive_torque), _number(drive_energy), _number(friction),
        _number(recoil), _number(impulse_angle), _count(every_beats), _number(beat_error),
        _number(out_of_beat), factors, span, _count(steps), run,
        _drag_laws(drag))
    return _json.loads(text), columns


def clock(
    length=None,
    *,
    parts=None,
    drive_energy=None,
    drive_torque=None,
    q=None,
    escapement=None,
    lift_angle=None,
    mass=None,
    friction=None,
    recoil=None,
    impulse_angle=None,
    every_beats=None,
    beat_error=None,
    out_of_beat=None,
    g=None,
    drive_factor=None,
    drive_range=None,
    steps=None,
    drag=None,
):
    """A pendulum kept going by an escapement (the CLI's ``clock``, the
    same library call): ``escapement`` is a name of
    ``lists()["escapements"]`` (impulse, deadbeat, recoil, constant-force,
    free); the drive is ``drive_energy`` (J per beat) or
    ``drive_torque`` (N m at the pallets); the pendulum a simple one of
    ``length`` m or a design of ``parts`` (see :func:`design`); angles in
    radians; a keyword
    left out is the library's default (``pendulum clock --help`` lists
    them). Out of beat: ``beat_error`` (s, half the difference of the tick
    and tock intervals) or ``out_of_beat`` (rad, the escapement's offset
    from the rest), the CLI's ``--beat-error``. ``drag``: drag laws beside
    the viscous damping of ``q``, a dict as :func:`simulate` takes
    (``{"three_halves_drag": 0.002}``, the CLI's ``--drag``). Returns the command's
    ``--json`` object as a dict: the clock
    (escapement, q, length_m, mass_kg, lift_angle_rad, the drive,
    minimum_drive_factor, out_of_beat_deg, out_of_beat_rate_s_per_day), ``steady`` (amplitude_rad, period_s, rate_s_per_day,
    its circular and escapement parts, energy_per_beat_j, power_w, ...)
    and, with ``drive_factor`` (factors) or ``drive_range=(a, b)`` and
    ``steps``, ``isochronism``: one dict per factor, ``stops`` where the
    pendulum stops. A drive too weak raises ValueError ("the pendulum
    stops: ...").

    >>> import math
    >>> import pendulum_theory as pt
    >>> # A seconds pendulum, 5 kg, Q = 10,000, deadbeat (the defaults), 20 µJ a beat.
    >>> s = pt.clock(0.99362, drive_energy=20e-6)["steady"]
    >>> round(s["amplitude_deg"], 3), round(s["rate_s_per_day"], 3)
    (2.563, -10.805)
    >>> # A beat's loss π E/Q, E = m g l (1 - cos A), is what the pallets give.
    >>> e = 5 * 9.80665 * 0.99362 * (1 - math.cos(s["amplitude_rad"]))
    >>> round(math.pi * e / 10000 / s["energy_per_beat_j"], 3)
    1.0
    """
    result, _ = _clock(length, parts=parts, drive_energy=drive_energy, drive_torque=drive_torque, q=q,
                       escapement=escapement, lift_angle=lift_angle, mass=mass, friction=friction,
                       recoil=recoil, impulse_angle=impulse_angle, every_beats=every_beats,
                       beat_error=beat_error, out_of_beat=out_of_beat, g=g,
                       drive_factor=drive_factor, drive_range=drive_range, steps=steps,
                       drag=drag)
    return result


def clock_run(length, duration, *, every=None, drive_schedule=None, rate_schedule=None,
              weather=None, gas=None, force=False, **clock_keywords):
    """A long run of the clock (the CLI's ``clock --duration``), started in
    its steady state and regulated to it: a row at every turning point, or
    every ``every`` s (then many beats per step: a year in a fraction of a
    second); ``clock_keywords`` are those of :func:`clock` (the drive, the
    escapement, ...). ``drive_schedule`` is ``(times_s, factors)``, linear between,
    held beyond. ``rate_schedule`` is ``(times_s, rate_change_s_per_day)``,
    a change of rate from outside (positive: gaining), as the CLI's drive
    file makes from temperature and pressure with a design: for a
    coefficient of -0.5 s/day per °C and a 10 °C warm spell, ``([0, 86400,
    86401], [0, 0, -5])``, the drive file's ``rate_change_s_per_day``
    (above -86400: a clock losing a day a day has stopped); or, for a
    clock of ``parts``, ``weather`` is a dict of the drive file's columns,
    ``time_s`` and any of ``temperature_c``, ``pressure_hpa`` (hPa),
    ``humidity_percent`` and ``gradient_k_per_m`` (the vertical
    temperature gradient, warmer upwards), and the design's own
    coefficients move the rate. Returns a dict of arrays (time_s, beats,
    amplitude_rad, rate_s_per_day, time_error_s, drive_factor) and the
    command's ``--json`` object (its ``long_run`` the run's summary).

    >>> import pendulum_theory as pt
    >>> # A day, a row an hour; the clock loses 5 s/day from noon on.
    >>> rows, result = pt.clock_run(0.99362, 86400.0, every=3600.0, drive_energy=20e-6,
    ...                             rate_schedule=([0, 43200, 43201], [0, 0, -5]))
    >>> len(rows["time_s"]), round(float(rows["rate_s_per_day"][-1]), 6)
    (25, -5.0)
    >>> round(float(rows["time_error_s"][-1]), 2)  # half a day at -5 s/day
    -2.5
    """
    def pairs(schedule):
        if schedule is None:
            return None
        return [float(x) for x in schedule[0]], [float(x) for x in schedule[1]]

    def column(values, scale=1.0):
        return None if values is None else [float(x) * scale for x in values]

    climate = None if weather is None else _weather(weather, column)
    run = (float(duration), _number(every), pairs(drive_schedule), pairs(rate_schedule),
           climate, bool(force), _text(gas))
    result, columns = _clock(length, run=run, **clock_keywords)
    names = ["time_s", "beats", "amplitude_rad", "rate_s_per_day", "time_error_s", "drive_factor"]
    return dict(zip(names, columns)), result


#: The columns of ``clock_run``'s weather, as the drive file names them,
#: and the factor to the library's unit (pressures in Pa).
_WEATHER = {"time_s": 1.0, "temperature_c": 1.0, "pressure_hpa": 100.0,
            "humidity_percent": 1.0, "gradient_k_per_m": 1.0}


def _weather(weather, column):
    """``clock_run``'s weather (a dict of named columns) as the library's
    (times, temperatures °C, pressures Pa, humidities %, gradients K/m)."""
    names = ", ".join(_WEATHER)
    if not hasattr(weather, "keys"):
        raise ValueError(f"weather: give a dict of named columns ({names}: the drive file's "
                         "names), not a sequence (whose third entry was pressures in Pa)")
    unknown = [k for k in weather.keys() if k not in _WEATHER]
    if unknown:
        hint = " (pressures go in hPa as pressure_hpa)" if \
            any(str(k).startswith("pressure") for k in unknown) else ""
        raise ValueError(f"weather: no column {unknown[0]!r}{hint}; the columns are {names}")
    if "time_s" not in weather:
        raise ValueError(f"weather: give its times as time_s, beside any of {names}")
    return tuple(column(weather.get(k), f) for k, f in _WEATHER.items())


def listen(samples, sample_rate, *, bph=None, period=None, sample_rate_error_ppm=None,
           lift_angle=None, oscillator=None, every=None, length=None, parts=None,
           nut_pitch=None, nut_tpi=None, nut_divisions=None, crutch=None, amplitude=None):
    """Listens to a clock in a recording (the CLI's ``listen``, the same
    library call): ``samples`` one channel (float, full scale ±1, as a
    sound file decodes to), ``sample_rate`` in Hz; ``bph`` or ``period``
    (s) the beat it should keep, ``lift_angle`` (rad) for the amplitude,
    ``oscillator`` ``"pendulum"`` or ``"balance"`` (default: a balance
    above 10,800 beats an hour), ``every`` (s) the length of the windows
    the recording is followed in over time (the command's ``--every``:
    ``windows`` and ``window_totals`` in the result).
    Returns the command's ``--json`` object as a dict (without its
    ``file`` and ``channel``) and the ticks kept as a dict of arrays
    (time_s, side, amplitude). Its ``findings`` list what the recording
    shows (``out_of_beat``, ``periodic_error``, ``arc_falls``,
    ``rate_wanders``, ``noisy``, ``clipped``, ``hum``, each with its
    figures), as the command's. Its ``advice`` takes ``length``,
    ``parts``, ``nut_pitch``, ``nut_tpi``, ``nut_divisions``, ``crutch``
    and ``amplitude`` as :func:`fit_beats` does.

    >>> import numpy as np
    >>> import pendulum_theory as pt
    >>> # 30 s of a seconds clock gaining 12 s a day, 1.5 ms out of beat: a
    >>> # 3 kHz click a beat in noise, at 44.1 kHz.
    >>> rate = 44100
    >>> x = 0.003 * np.random.default_rng(1).standard_normal(30 * rate)
    >>> n = np.arange(200)
    >>> click = np.exp(-n / 40) * np.sin(2 * np.pi * 3000 * n / rate)
    >>> for k in range(29):
    ...     i = round((0.5 + k / (1 + 12 / 86400) + 0.0015 * (k % 2)) * rate)
    ...     x[i:i + 200] += click
    >>> r, ticks = pt.listen(x.astype(np.float32), rate, bph=3600)
    >>> r["beats"], round(r["rate_s_per_day"], 1), round(r["beat_error_ms"], 1)
    (29, 12.0, 1.5)
    """
    result, (time, side, level) = _native.listen(
        _np.ascontiguousarray(samples, dtype=_np.float32), float(sample_rate), _number(bph),
        _number(period), _number(sample_rate_error_ppm), _number(lift_angle),
        _text(oscillator), _number(every),
        **_known(length, parts, nut_pitch, nut_tpi, nut_divisions, crutch, amplitude))
    return _json.loads(result), {"time_s": time, "side": side, "amplitude": level}


def period_table(length, amplitude=None, *, amplitude_range=None, steps=None, g=None,
                 series_terms=None, step=None):
    """The command's ``period`` (the same library call): at one
    ``amplitude`` (rad) a dict, over ``amplitude_range=(from, to)`` (rad;
    ``steps`` rows spaced evenly in degrees, or one every ``step`` rad, or
    by default a round step of degrees) a list of dicts, with the
    command's ``--json`` keys (period_s, small_angle_period_s,
    period_ratio, beats_per_hour, circular_error, circular_error_s_per_day,
    the power series to ``series_terms`` terms, ...; not its ``g_source``).
    For arrays of periods use :func:`period`.

    >>> import numpy as np
    >>> import pendulum_theory as pt
    >>> r = pt.period_table(0.99362, np.radians(2.0))  # about 86400 A²/16 s/day
    >>> round(r["period_s"], 6), round(r["circular_error_s_per_day"], 4)
    (2.000151, 6.5797)
    >>> rows = pt.period_table(0.99362, amplitude_range=(np.radians(1), np.radians(10)), steps=10)
    >>> [round(row["amplitude_deg"], 6) for row in rows][:3]
    [1.0, 2.0, 3.0]
    """
    span = None if amplitude_range is None else (float(amplitude_range[0]),
                                                 float(amplitude_range[1]))
    return _json.loads(_native.period_table(
        float(length), _number(g), _number(amplitude), span,
        _count(steps), _count(series_terms), _number(step)))


def length(period=None, *, bph=None, amplitude=None, g=None):
    """The command's ``length`` (the same library call): the length for a
    ``period`` (s) or a beat rate ``bph`` at ``amplitude`` (rad, default
    0). Returns its ``--json`` object as a dict (without ``g_source``).
    For arrays use :func:`length_for_period`.

    >>> import pendulum_theory as pt
    >>> r = pt.length(bph=3600)  # g/π² for a 2 s period
    >>> round(r["length_m"], 6), r["period_s"]
    (0.993621, 2.0)
    """
    return _json.loads(_native.length(_number(period), _number(bph), _number(amplitude),
                                      _number(g)))


def amplitude(length, period, *, period_uncertainty=None, g=None):
    """The command's ``amplitude`` (the same library call): the amplitude
    (rad) a pendulum of ``length`` m swings at to keep ``period`` s, its
    conditioning, and with ``period_uncertainty`` (s) its interval.
    Returns its ``--json`` object as a dict (without ``g_source``). For
    arrays use :func:`amplitude_for_period`.

    >>> import math
    >>> import pendulum_theory as pt
    >>> t = pt.period(0.99362, math.radians(3.0))  # ± 10 µs: the interval
    >>> r = pt.amplitude(0.99362, t, period_uncertainty=1e-5)
    >>> round(r["amplitude_deg"], 6), round(math.degrees(r["amplitude_uncertainty_rad"]), 4)
    (3.0, 0.0438)
    """
    return _json.loads(_native.amplitude(float(length), float(period),
                                         _number(period_uncertainty), _number(g)))


def damped(length, amplitude, *, zeta=None, q=None, log_decrement=None, decay_time=None,
           damping_coefficient=None, friction_angle=None, mass=None, extrema=None, g=None,
           force=False):
    """The command's ``damped`` (the same library call): the damped
    pendulum of the seed's section 1-4 released at ``amplitude`` rad, its
    damping by one of ``zeta``, ``q``, ``log_decrement``, ``decay_time``
    (s) or ``damping_coefficient`` (N s, with ``mass`` kg), dry friction
    ``friction_angle`` rad, the first ``extrema`` turning points. Returns
    its ``--json`` object as a dict. For arrays of angles use
    :func:`damped_angle`.

    >>> import math
    >>> import pendulum_theory as pt
    >>> d = pt.damped(0.99362, 0.05, q=100, extrema=2)
    >>> d["zeta"], d["regime"]  # ζ = 1/(2Q)
    (0.005, 'underdamped')
    >>> # A period on, the swing is e^-δ of itself, δ = 2πζ/√(1 - ζ²).
    >>> round(d["extrema"][2]["angle_rad"], 9), round(0.05 * math.exp(-d["log_decrement"]), 9)
    (0.048453602, 0.048453602)
    """
    return _json.loads(_native.damped(
        float(length), float(amplitude),
        _damping_given(zeta, q, log_decrement, decay_time, damping_coefficient),
        _number(friction_angle), _number(mass), _count(extrema),
        _number(g), bool(force)))


def _damping_given(zeta, q, log_decrement, decay_time, damping_coefficient):
    """The one damping given, as the library's (form, value), or None."""
    given = [(k, v) for k, v in (("zeta", zeta), ("q", q), ("log_decrement", log_decrement),
                                 ("decay_time", decay_time),
                                 ("damping_coefficient", damping_coefficient))
             if v is not None]
    if len(given) > 1:
        raise ValueError("damping: give one of zeta, q, log_decrement, decay_time, "
                         "damping_coefficient")
    return (given[0][0], float(given[0][1])) if given else None


def report(*, length=None, parts=None, amplitude=None, zeta=None, q=None, log_decrement=None,
           decay_time=None, damping_coefficient=None, mass=None, g=None):
    """The numbers of the command's ``report`` (the same library call): a
    pendulum of ``length`` m (default a seconds pendulum) or a design of
    ``parts`` (see :func:`design`) at the working ``amplitude`` rad, with
    one damping as :func:`damped` takes it (default Q = 10,000) and a bob
    of ``mass`` kg: the exact period, the damped pendulum and its energy
    budget, the design's datasheet and the nonlinear run-down until the
    amplitude halves. Returns its ``--json`` object as a dict; the
    run-down's turning points are under ``"rundown_points"`` as arrays.

    >>> import math
    >>> import pendulum_theory as pt
    >>> # Q = 1000 at 3°: the run-down lasts until the swing halves, ln 2/(ζ ω_n).
    >>> r = pt.report(length=0.99362, q=1000)
    >>> round(r["rundown"]["wanted_s"], 6)
    441.270893
    >>> round(math.log(2) * 2 * 1000 / math.sqrt(9.80665 / 0.99362), 6)
    441.270893
    """
    text, times, amplitudes, rates = _native.report(
        _number(length), None if parts is None else _parts(parts), _number(amplitude),
        _damping_given(zeta, q, log_decrement, decay_time, damping_coefficient), _number(mass),
        _number(g))
    result = _json.loads(text)
    result["rundown_points"] = {"time_s": times, "amplitude_rad": amplitudes,
                                "rate_s_per_day": rates}
    return result


def _counts(values):
    return [_count(v) for v in values]


def train(wheels, pinions, *, arbor_turns_per_hour=None, g=None):
    """The command's ``train`` (the same library call): the beats per hour
    of wheels (the last the escape wheel) and pinions, the period and the
    simple pendulum it needs. Returns its ``--json`` object as a dict.

    >>> import pendulum_theory as pt
    >>> # Centre wheel 64, third 60, escape wheel 30, pinions of 8.
    >>> r = pt.train([64, 60, 30], [8, 8])
    >>> r["beats_per_hour"], r["period_s"], round(r["length_m"], 6)
    (3600.0, 2.0, 0.993621)
    """
    return _json.loads(_native.train(_counts(wheels), _counts(pinions),
                                     _number(arbor_turns_per_hour), _number(g)))


def train_for(bph, *, escape_teeth=None, tolerance=None):
    """The command's ``train --bph``: the trains (centre, third and escape
    wheel, two pinions) that give ``bph`` within ``tolerance``, closest
    first, as a list of dicts.

    >>> import pendulum_theory as pt
    >>> best = pt.train_for(3600)[0]
    >>> best["wheels"], best["pinions"], best["beats_per_hour"]
    ([96, 40, 30], [8, 8], 3600.0)
    """
    return _json.loads(_native.train_for(
        float(bph), _count(escape_teeth),
        _number(tolerance)))


def _finite_or_none(value):
    """``value`` with every non-finite float in it made ``None``, as the
    command line's TOML reader makes a ``nan`` or ``inf`` (JSON holds
    neither): the library then refuses it naming the part and the field."""
    if isinstance(value, dict):
        return {k: _finite_or_none(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_finite_or_none(v) for v in value]
    if isinstance(value, (float, _np.floating)) and not _np.isfinite(value):
        return None
    if isinstance(value, _np.generic):
        return value.item()
    return value


def _parts(parts):
    """A design's parts as the library reads them: a list of part dicts
    (or ``{"part": [...]}``, the TOML file's shape), sizes in SI units."""
    if not isinstance(parts, dict):
        parts = {"part": list(parts)}
    return _json.dumps(_finite_or_none(parts))


def design(parts, *, g=None, pressure_hpa=None, temperature=None, humidity=None,
           regulated_at=None, gas=None, pivot_q=None, amplitude=None):
    """The command's ``design`` (the same library call): a pendulum of
    ``parts`` (dicts with the design file's fields: name, shape,
    material, length, diameter, ..., centre or rests_on; sizes as numbers
    in metres and kilograms) in ``gas`` ("air", "nitrogen" or "helium",
    default air) at ``pressure_hpa`` hPa (as the CLI's ``--pressure``),
    ``temperature`` °C and relative
    ``humidity`` (%, 0 to 100, air only, as the CLI's ``--humidity`` and
    the weather of :func:`clock_run` and :func:`clock_log`), regulated at ``regulated_at`` °C;
    ``pivot_q`` the Q of its pivot's own losses and ``amplitude`` the
    semi-arc (rad) it swings here. Returns its ``--json`` object as a dict
    (without ``file``).

    >>> import pendulum_theory as pt
    >>> # A steel rod alone, 1.5 m long, hung by its end: 2l/3 + r²/(2l) = 1 m,
    >>> # and -86400 α/2 s/day per °C (steel's α is 11.5e-6 per K here).
    >>> rod = {"name": "rod", "shape": "rod", "material": "steel", "length": 1.5,
    ...        "diameter": 0.01, "centre": 0.75}
    >>> d = pt.design([rod])
    >>> round(d["equivalent_length_m"], 6), round(d["temperature_coefficient_s_per_day_per_c"], 4)
    (1.000008, -0.4968)
    """
    humidity = None if humidity is None else _number(humidity) / 100.0
    pressure = None if pressure_hpa is None else _number(pressure_hpa) * 100.0
    return _json.loads(_native.design(_parts(parts), _number(g), pressure,
                                      _number(temperature), humidity,
                                      _number(regulated_at), _text(gas), _number(pivot_q),
                                      _number(amplitude)))


def regulate(rate, *, length=None, parts=None, part=None, nut_pitch=None, nut_tpi=None,
             nut_divisions=None, tray=None, bph=None):
    """The command's ``regulate`` (the same library call): a clock gaining
    ``rate`` s/day (negative: losing) with a simple pendulum of ``length``
    m or a design of ``parts`` (see :func:`design`; the part moved
    ``part``, default its nut): how far to move the bob (m, positive
    down), in turns and divisions of a nut of ``nut_pitch`` m or
    ``nut_tpi`` threads per inch, or the mass for a tray at ``tray`` m
    below the pivot; or, given only ``bph`` (beats an hour), for the
    simple pendulum of that beat. Returns its ``--json`` object as a dict.

    >>> import pendulum_theory as pt
    >>> # Gaining 10 s a day: lower the bob 2 l × 10/86400, on a 0.5 mm thread.
    >>> r = pt.regulate(10, length=0.99362, nut_pitch=0.5e-3)
    >>> round(r["shift_m"] * 1e3, 4), round(r["nut_turns"], 3)
    (0.23, 0.46)
    """
    return _json.loads(_native.regulate(
        float(rate), _number(length), None if parts is None else _parts(parts), _text(part),
        _number(nut_pitch), _number(nut_tpi),
        _count(nut_divisions), _number(tray), bph=_number(bph)))


def compensate(parts, compensator=None, *, part=None, jar_material=None, jar_diameter=None,
               jar_wall=None, tube_diameter=None, tube_bore=None):
    """The command's ``compensate`` (the same library call): the
    temperature coefficient of a design of ``parts`` (see :func:`design`)
    and, with a ``compensator`` (a tube's material such as ``"zinc"``,
    ``"collar"``, ``"gridiron"`` or ``"mercury"``), its size; sizes in
    metres. Returns its ``--json`` object as a dict.

    >>> import pendulum_theory as pt
    >>> # A brass bob on a steel rod's nut, and the zinc tube that cancels it.
    >>> parts = [
    ...     {"name": "rod", "shape": "rod", "material": "steel", "length": 1.1,
    ...      "diameter": 0.008, "centre": 0.55},
    ...     {"name": "nut", "shape": "cylinder", "material": "steel", "length": 0.012,
    ...      "diameter": 0.016, "centre": 1.077, "pitch": 0.7e-3},
    ...     {"name": "bob", "shape": "cylinder", "material": "brass", "length": 0.14,
    ...      "diameter": 0.08, "bore": 0.0085, "rests_on": "nut"},
    ... ]
    >>> c = pt.compensate(parts, "zinc")
    >>> round(c["temperature_coefficient_s_per_day_per_c"], 3), round(c["tube_length_m"], 3)
    (-0.476, 0.706)
    >>> abs(c["compensated_coefficient_s_per_day_per_c"]) < 1e-9
    True
    """
    return _json.loads(_native.compensate(
        _parts(parts), _text(compensator), _text(part), _text(jar_material),
        _number(jar_diameter), _number(jar_wall), _number(tube_diameter), _number(tube_bore)))


def stability(data, tau0, *, kind="phase", all_taus=False, force=False, outliers="keep"):
    """The frequency stability of a series sampled every ``tau0`` s: phase
    (time error, s) or fractional frequency (``kind="frequency"``); NaN
    marks a gap. The CLI's ``stability``, the same library call: the
    overlapping Allan, modified Allan, time and overlapping Hadamard
    deviations at octave averaging times (every one with ``all_taus``),
    each with its 68% interval (Greenhall's EDF) and the noise type
    (lag-1 autocorrelation), after NIST SP 1065. Jumps and glitches (a
    missed pulse) are warned of with how much they raise the shortest τ's
    deviation; ``outliers="remove"`` takes them out. A periodic signal
    that dominates some τ is named (``periodic``), its rows without a
    noise type. Returns a dict (kind, tau0_s, phase_points, stability: a
    dict per averaging time, best, warnings, periodic).

    >>> import numpy as np
    >>> import pendulum_theory as pt
    >>> # A frequency drifting steadily, y = D t: σ_y(τ) = D τ/√2 (SP 1065).
    >>> s = pt.stability(1e-9 * np.arange(256), 1.0, kind="frequency")
    >>> row = s["stability"][2]
    >>> row["tau_s"], round(row["adev"] * 1e9, 9), round(4 / 2**0.5, 9)
    (4.0, 2.828427125, 2.828427125)
    """
    return _json.loads(_native.stability(_array(data), float(tau0), str(kind), bool(all_taus),
                                         bool(force), str(outliers)))


def tide(latitude, longitude, time, *, height=0.0, force=False):
    """The Earth's body tide at a place (degrees, m) at Unix times ``time``
    (s, UTC): the CLI's ``tide``, the same library call. Times whose work
    is estimated at more than a few seconds (300,000 of them, or fewer a
    month or more apart over decades) raise ValueError unless ``force``.
    Returns a dict of arrays: time_unix_s, gravity_change_nm_s2 (positive:
    g larger) and rate_s_per_day (a pendulum's, +Δg/2g of a day).

    >>> import numpy as np
    >>> import pendulum_theory as pt
    >>> # Greenwich, hourly through 2024-01-01 (UTC).
    >>> r = pt.tide(51.4779, 0.0, 1704067200 + 3600 * np.arange(25), height=46.0)
    >>> round(float(np.ptp(r["gravity_change_nm_s2"])))  # nm/s², a day's range
    1323
    >>> bool(np.all(np.abs(r["rate_s_per_day"]) < 0.02))  # Δg/2g of a day
    True
    """
    rows = _json.loads(_native.tide(float(latitude), float(longitude), _array(time),
                                    float(height), bool(force)))
    keys = ["time_unix_s", "gravity_change_nm_s2", "rate_s_per_day"]
    return {k: _np.array([r[k] for r in rows], dtype=_np.float64) for k in keys}


def clock_log(time, values, *, kind="offset", temperature=None, pressure_hpa=None, humidity=None,
              amplitude_deg=None, pulse_width=None, flag_width=None, gate_radius=None, epoch=None, latitude=None, longitude=None, height=0.0,
              tides=False, events=None, bin=None, beat=None, bph=None, period=None,
              force=False, stability=True, wheels=None, pinions=None, arbor_turns_per_hour=None,
              length=None, parts=None, nut_pitch=None, nut_tpi=None, nut_divisions=None):
    """A clock's log, the CLI's ``log``, the same library call: ``time``
    (s, increasing; ``epoch`` the Unix time of 0, for the tides),
    ``values`` offsets (s, ``kind="offset"``), rates (s/day,
    ``"rate"``) or half periods (s, ``"half_periods"``); weather beside
    them (``temperature`` °C, ``pressure_hpa``, ``humidity`` %,
    ``amplitude_deg``; NaN where not read); a photogate's
    ``pulse_width`` (s) with ``flag_width`` and ``gate_radius`` (m) gives
    the amplitude exactly; ``wheels`` and ``pinions`` (the CLI's
    ``--train W,…:P,…``) mark the wheels' periods and fold the rate over
    each. The pendulum's ``length`` (m) or a design's ``parts``, and the
    nut's ``nut_pitch`` (m), ``nut_tpi`` or ``nut_divisions``, turn the
    rate at the log's end into the ``advice`` (else the simple pendulum of
    the log's beat, said; none when the log has no beat). Returns the
    CLI's JSON as a dict (rate_s_per_day, drift_s_per_day_per_day,
    coefficients, standard_errors, terms, temperature_lag_s, stability,
    residual_stability, spectrum, folds, swing, warnings, advice, …).

    >>> import numpy as np
    >>> import pendulum_theory as pt
    >>> # Nine days of hourly offsets (s): gaining 2 s a day at 20 °C, -0.5 s a
    >>> # day per °C, the room swinging ±3 °C every three days.
    >>> w, t = 2 * np.pi / (3 * 86400), 3600.0 * np.arange(216)
    >>> offset = (2 * t + 1.5 * (np.cos(w * t) - 1) / w) / 86400
    >>> log = pt.clock_log(t, offset, temperature=20 + 3 * np.sin(w * t))
    >>> round(log["rate_s_per_day"], 2), round(log["coefficients"]["temperature_s_per_day_per_c"], 2)
    (2.0, -0.5)
    """
    def optional(x):
        return None if x is None else _array(x)
    return _json.loads(_native.clock_log(
        _array(time), _array(values), str(kind), optional(temperature), optional(pressure_hpa),
        optional(humidity), optional(amplitude_deg), optional(pulse_width), _number(flag_width),
        _number(gate_radius), _number(epoch), _number(latitude),
        _number(longitude), float(height), bool(tides), optional(events), _number(bin),
        _number(beat), _number(bph), _number(period), bool(force), bool(stability),
        _teeth("wheels", wheels), _teeth("pinions", pinions),
        _number(arbor_turns_per_hour),
        **{k: v for k, v in _known(length, parts, nut_pitch, nut_tpi, nut_divisions, None,
                                   None).items() if k not in ("crutch", "amplitude")}))


# Every public function refuses a boolean where it takes a number.
for _name in __all__:
    _f = globals().get(_name)
    if callable(_f) and getattr(_f, "__module__", None) == __name__ and \
            type(_f).__name__ == "function":
        globals()[_name] = _refusing_bools(_f)
del _name, _f
