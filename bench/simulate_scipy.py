"""SciPy's solve_ivp(DOP853) on the benchmark problem of bench/compare_scipy.sh:
a seconds pendulum (l = 0.99362 m, g = 9.80665) released at 3 degrees, Q = 1e6,
for DURATION seconds, with every turning point (theta' = 0) located as an event.
Prints: tolerance, solver seconds, turning points, evaluations, final amplitude.
Usage: python simulate_scipy.py TOL DURATION
"""
import math
import sys
import time

from scipy.integrate import solve_ivp

L, G = 0.99362, 9.80665
W = math.sqrt(G / L)
C = 2 * (1 / (2 * 1e6)) * W
A0 = math.radians(3.0)


def rhs(t, y):
    return [y[1], -C * y[1] - W * W * math.sin(y[0])]


def turning(t, y):
    return y[1]


def main():
    tol, duration = float(sys.argv[1]), float(sys.argv[2])
    start = time.perf_counter()
    sol = solve_ivp(rhs, (0.0, duration), [A0, 0.0], method="DOP853", rtol=tol, atol=tol, events=turning)
    elapsed = time.perf_counter() - start
    theta, v = sol.y[0, -1], sol.y[1, -1]
    amplitude = 2 * math.asin(min(1.0, math.sqrt(math.sin(theta / 2) ** 2 + (v / (2 * W)) ** 2)))
    print(f"{tol:.0e} {elapsed:.4f} {len(sol.t_events[0])} {sol.nfev} {amplitude!r}")


main()
