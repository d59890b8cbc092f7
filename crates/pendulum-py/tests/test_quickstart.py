"""The README's Python quickstart runs and prints what it says."""

import pathlib
import subprocess
import sys

SCRIPT = pathlib.Path(__file__).resolve().parents[3] / "examples" / "python" / "quickstart.py"


def test_quickstart_runs():
    out = subprocess.run([sys.executable, str(SCRIPT)], capture_output=True, text=True, check=True)
    lines = out.stdout.splitlines()
    assert len(lines) == 8, out.stdout
    # 3° of swing on the seconds pendulum (T0 = 2.0000 s): T = T0 (1 +
    # A²/16 + ...) = 2.000341 s, and 86400 · 0.000171 = 14.80 s/day lost.
    three = [l for l in lines if l.strip().startswith("3.0°")][0]
    assert "2.00034" in three and "14.80" in three, three
