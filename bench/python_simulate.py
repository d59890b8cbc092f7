"""The 1,000-period simulation called from Python against the `pendulum`
binary doing the same (every turning point kept; the binary writes them
to a CSV file, as a user would ask it): best of seven wall times.
Run with the package installed and the binary built (cargo build --release)."""

import json
import math
import pathlib
import subprocess
import tempfile
import time

import pendulum_theory as pt

root = pathlib.Path(__file__).resolve().parents[1]
binary = root / "target" / "release" / "pendulum"
duration = 1000 * 2.0  # 1,000 periods of the seconds pendulum


def python_run():
    return pt.simulate(0.99362, math.radians(3), duration, q=1e4, method="dop853", tolerance=1e-10)


def binary_run(folder):
    subprocess.run(
        [str(binary), "simulate", "--length", "0.99362m", "--amplitude", "3deg", "--q", "1e4",
         "--duration", f"{duration}s", "--swings", f"{folder}/s.csv", "--quiet"],
        check=True, capture_output=True,
    )


def best(f, n=7):
    out = []
    for _ in range(n):
        t = time.perf_counter()
        f()
        out.append(time.perf_counter() - t)
    return min(out)


def binary_inside(folder):
    out = subprocess.run(
        [str(binary), "simulate", "--length", "0.99362m", "--amplitude", "3deg", "--q", "1e4",
         "--duration", f"{duration}s", "--swings", f"{folder}/s.csv", "--json"],
        check=True, capture_output=True, text=True,
    )
    return json.loads(out.stdout)["elapsed_s"]


with tempfile.TemporaryDirectory() as folder:
    tb = best(lambda: binary_run(folder))
    inside = min(binary_inside(folder) for _ in range(7))
tp = best(python_run)
print(f"1,000 periods (dop853, 1e-10, 2,000 turning points): Python {tp * 1e3:.1f} ms, "
      f"binary {tb * 1e3:.1f} ms (Python / binary = {tp / tb:.2f}); "
      f"the binary's own simulation time (elapsed_s, no process start) {inside * 1e3:.1f} ms")
