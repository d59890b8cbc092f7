"""Shapes, dtypes, broadcasting and bad input."""

import numpy as np
import pytest

import pendulum_theory as pt


def test_scalars_give_floats():
    assert isinstance(pt.ellipk(0.5), float)
    assert isinstance(pt.period(1.0, 0.1), float)
    sn, cn, dn, ph = pt.ellipj(0.3, 0.5)
    assert all(isinstance(x, float) for x in (sn, cn, dn, ph))


def test_shapes_and_broadcasting():
    lengths = np.array([[0.25], [1.0], [4.0]])  # (3, 1)
    amplitudes = np.radians([1.0, 5.0, 10.0, 20.0])  # (4,)
    t = pt.period(lengths, amplitudes)
    assert t.shape == (3, 4) and t.dtype == np.float64
    # A pendulum 4x longer swings 2x slower.
    assert np.allclose(t[2] / t[1], 2.0, rtol=1e-15)
    # Integer, float32, lists and non-contiguous views all work.
    assert pt.ellipk([0, 0]).shape == (2,)
    assert np.allclose(pt.ellipk(np.float32(0.5)), pt.ellipk(0.5), rtol=1e-7)
    m = np.linspace(0, 0.9, 20).reshape(4, 5)
    assert np.array_equal(pt.ellipk(m.T), pt.ellipk(m).T)
    assert pt.ellipk(np.empty((0, 3))).shape == (0, 3)
    assert pt.normal_gravity(np.zeros((2, 2)), [0.0, 1000.0]).shape == (2, 2)


def test_bad_input_raises_the_library_message():
    with pytest.raises(ValueError, match="length"):
        pt.period(-1.0, 0.1)
    with pytest.raises(ValueError, match="amplitude"):
        pt.period(1.0, [0.1, 4.0])
    with pytest.raises(ValueError, match="period"):
        pt.amplitude_for_period(1.0, 1.0)
    with pytest.raises(ValueError, match="latitude"):
        pt.normal_gravity(95.0)
    with pytest.raises(ValueError):
        pt.zeta_from_q(-3)
    with pytest.raises(ValueError):
        pt.period(1.0, 0.1, g=np.nan)
    # Outside [0, 1] the elliptic integrals are NaN, not an error (as SciPy).
    assert np.isnan(pt.ellipk(1.5)) and np.isinf(pt.ellipk(1.0))
    with pytest.raises(ValueError, match="broadcast"):
        pt.period([1.0, 2.0], [0.1, 0.2, 0.3])
