"""A first look at pendulum_theory from Python: the exact period of a
seconds pendulum at a range of swings, the clock's circular error, and the
length that beats seconds where you are."""

import numpy as np

import pendulum_theory as pt

amplitudes = np.radians([1, 2, 3, 5, 10, 30])
periods = pt.period(0.99362, amplitudes)          # s, exact
errors = pt.circular_error_s_per_day(amplitudes)  # s/day lost
for a, t, e in zip(np.degrees(amplitudes), periods, errors):
    print(f"{a:5.1f}°  T = {t:.9f} s  loses {e:8.3f} s/day")

g = pt.normal_gravity(51.4779)                    # Greenwich, m/s²
print(f"g = {g:.6f} m/s²; a seconds pendulum at 3°: {pt.length_for_period(2.0, np.radians(3), g):.6f} m")
print(f"Q = 10,000 is ζ = {pt.zeta_from_q(10_000):g}; its amplitude decays in "
      f"{pt.decay_time(pt.zeta_from_q(10_000), 0.99362) / 3600:.2f} h")
