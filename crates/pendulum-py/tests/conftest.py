import csv
import math
import pathlib

import numpy as np
import pytest

DATA = pathlib.Path(__file__).resolve().parents[2] / "pendulum-theory" / "tests" / "data"


def load(name):
    """The mpmath reference rows of one of the Rust tests' files, as floats."""
    with open(DATA / name) as f:
        lines = [line for line in f if not line.startswith("#")]
    reader = csv.reader(lines)
    header = next(reader)
    rows = np.array([[float(x) for x in row] for row in reader])
    return header, rows


def ulp_error(value, hi, lo):
    """|value - (hi + lo)| in ulp of the true value, as the Rust tests measure it."""
    value, hi, lo = (np.asarray(x, dtype=np.float64) for x in (value, hi, lo))
    ulp = np.nextafter(np.abs(hi), np.inf) - np.abs(hi)
    return np.abs((value - hi) - lo) / ulp


@pytest.fixture
def reference():
    return load
