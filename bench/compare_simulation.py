"""Runs the simulation comparison of bench/compare_scipy.sh: each tool as a
separate process (start-up included), timed from this script with
time.perf_counter (best of several runs for the fast ones), and the final
amplitude error against a converged reference.

Usage: python compare_simulation.py PENDULUM_BINARY [BOOST_BINARY]
"""
import json
import math
import os
import subprocess
import sys
import time

DURATION = "2000.3414"  # 1000 periods of the seconds pendulum at 3 degrees
COMMON = ["simulate", "--length", "0.99362m", "--amplitude", "3deg", "--q", "1e6",
          "--duration", DURATION + "s", "--json"]
HERE = os.path.dirname(os.path.abspath(__file__))


def timed(cmd, repeats):
    best, out = math.inf, ""
    for _ in range(repeats):
        start = time.perf_counter()
        out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
        best = min(best, time.perf_counter() - start)
    return best, out


def main():
    pendulum = sys.argv[1]
    boost = sys.argv[2] if len(sys.argv) > 2 else None
    swings = "/tmp/pendulum-bench-swings.csv"
    ref_out = subprocess.run([pendulum] + COMMON + ["--method", "symplectic", "--tolerance", "1e-14"],
                             check=True, capture_output=True, text=True).stdout
    reference = json.loads(ref_out)["final_amplitude_rad"]
    print(f"reference final amplitude (symplectic, tol 1e-14): {reference!r} rad")
    rows = []
    for tol in ("1e-8", "1e-10", "1e-12"):
        for method in ("dop853", "vern9", "symplectic"):
            cmd = [pendulum] + COMMON + ["--method", method, "--tolerance", tol, "--swings", swings]
            seconds, out = timed(cmd, 10)
            rows.append((f"pendulum {method}", tol, seconds, json.loads(out)["final_amplitude_rad"]))
        seconds, out = timed([sys.executable, os.path.join(HERE, "simulate_scipy.py"), tol, DURATION], 1)
        rows.append(("scipy DOP853", tol, seconds, float(out.split()[4])))
        if boost:
            for stepper in ("dopri5", "rkf78"):
                seconds, out = timed([boost, stepper, tol, DURATION], 10)
                rows.append((f"boost {stepper}", tol, seconds, float(out.split()[4])))
    for name, tol, seconds, amplitude in rows:
        error = abs(amplitude - reference) / reference
        print(f"{name:<22} tol {float(tol):.0e} {seconds * 1e3:9.2f} ms   final amplitude error {error:.2e}")
    if os.path.exists(swings):
        os.remove(swings)


main()
