"""SciPy's chi-square tail probabilities, chi2.sf(x, nu), for the test of
pendulum_theory::fitting::period_table::chi_square_probability (the values
are written into that test). Usage: python tools/reference/chi_square.py"""
from scipy.stats import chi2

for x, nu in [(13.5, 4), (20.515, 5), (3.0, 10), (100.0, 60), (0.5, 1), (1e-3, 2), (250.0, 30),
              (7.0, 7)]:
    print(f"({x}, {nu}, {float(chi2.sf(x, nu))!r}),")
