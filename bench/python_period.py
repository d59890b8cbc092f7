"""pendulum_theory.period over 10^6 amplitudes against numpy + SciPy's
4 sqrt(l/g) ellipk(sin(a/2)²): best of seven, and the largest difference.
Run with the package installed: python bench/python_period.py"""

import time

import numpy as np
import scipy.special

import pendulum_theory as pt

rng = np.random.default_rng(1)
a = rng.uniform(0.0, np.radians(170.0), size=1_000_000)
length, g = 0.99362, 9.80665


def numpy_period():
    return 4.0 * np.sqrt(length / g) * scipy.special.ellipk(np.sin(a / 2) ** 2)


def ours():
    return pt.period(length, a)


def best(f, n=7):
    times = []
    for _ in range(n):
        t = time.perf_counter()
        f()
        times.append(time.perf_counter() - t)
    return min(times)


t_np, t_pt = best(numpy_period), best(ours)
diff = np.max(np.abs(ours() / numpy_period() - 1.0))
print(f"10^6 periods: pendulum_theory {t_pt * 1e3:.1f} ms, numpy + scipy.special.ellipk {t_np * 1e3:.1f} ms "
      f"(ratio {t_np / t_pt:.2f}); largest relative difference {diff:.1e}")
print(f"numpy {np.__version__}, scipy {scipy.__version__}")
