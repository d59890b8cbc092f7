"""Runs the teaching pack's notebooks and checks their key figures
against the command line's.

    python examples/notebooks/check.py

Needs nbclient, nbformat, ipykernel and matplotlib beside the package
(`pip install ./crates/pendulum-py nbclient nbformat ipykernel
matplotlib`). The folder of the interpreter this runs under is put first
on the PATH, so that the notebooks' kernel (`python3`) and the `pendulum`
command are that environment's.

For each notebook: checks that it is what make.py writes (no outputs
stored), executes it with nbclient (kernel python3, 120 s a cell, in the
notebook's folder), reads the dict `KEY` its last cell makes, and runs
`pendulum ... --json` on the same file (the path in the notebook's first
cell, from the notebook's folder) with the flags of make.PARAMETERS. Each
figure must equal the command's to 1e-9 relative. Exits 1 with one line a
failure.
"""

import ast
import json
import math
import os
import pathlib
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.dont_write_bytecode = True  # no __pycache__ beside the notebooks
import make  # noqa: E402  (the notebooks' parameters)

TOLERANCE = 1e-9
CELL_TIMEOUT_S = 120


class Failure(Exception):
    """One failure, said in one line."""


def first_cell_paths(nb):
    """The string assignments of a notebook's first cell (DATA, ...)."""
    source = nb.cells[0].source
    paths = {}
    for node in ast.parse(source).body:
        if (isinstance(node, ast.Assign) and len(node.targets) == 1
                and isinstance(node.targets[0], ast.Name)
                and isinstance(node.value, ast.Constant) and isinstance(node.value.value, str)):
            paths[node.targets[0].id] = node.value.value
    if "DATA" not in paths:
        raise Failure("its first cell sets no DATA = \"...\"")
    return paths


def execute(path):
    """Executes the notebook at `path` in its folder; its KEY, and the
    paths of its first cell."""
    import nbformat
    from nbclient import NotebookClient
    from nbclient.exceptions import CellExecutionError, CellTimeoutError

    nb = nbformat.read(path, as_version=4)
    for i, cell in enumerate(nb.cells):
        if cell.cell_type == "code" and (cell.outputs or cell.execution_count is not None):
            raise Failure(f"cell {i} has outputs stored: run make.py")
    paths = first_cell_paths(nb)
    nb.cells.append(nbformat.v4.new_code_cell(
        "import json as _json\nprint('__KEY__' + _json.dumps(KEY, allow_nan=True))"))
    client = NotebookClient(nb, timeout=CELL_TIMEOUT_S, kernel_name="python3",
                            resources={"metadata": {"path": str(path.parent)}})
    try:
        client.execute()
    except CellTimeoutError:
        raise Failure(f"a cell ran longer than {CELL_TIMEOUT_S} s") from None
    except CellExecutionError as e:
        where = next((i for i, c in enumerate(nb.cells) if c.cell_type == "code"
                      and any(o.get("output_type") == "error" for o in c.get("outputs", []))), "?")
        raise Failure(f"cell {where} raised {e.ename}: {e.evalue}") from None
    for output in nb.cells[-1].outputs:
        if output.get("output_type") == "stream":
            for line in output.get("text", "").splitlines():
                if line.startswith("__KEY__"):
                    return json.loads(line[len("__KEY__"):]), paths
    raise Failure("its last cell made no KEY")


def pendulum(args, cwd):
    """The JSON of `pendulum ARGS`, run in `cwd`, and the command as text."""
    command = "pendulum " + " ".join(args)
    try:
        out = subprocess.run(["pendulum", *args], cwd=cwd, capture_output=True, text=True,
                             timeout=600)
    except FileNotFoundError:
        raise Failure("no `pendulum` command on the PATH (pip install ./crates/pendulum-py)") from None
    if out.returncode != 0:
        reason = (out.stderr.strip().splitlines() or ["no message"])[-1]
        raise Failure(f"`{command}` failed: {reason}")
    return json.loads(out.stdout), command


def metres(value):
    return f"{value!r}m"


def law(result, name):
    """The fitted law `name` of a decay fit's JSON."""
    return next(m for m in result["models"] if m["model"] == name)


def large_amplitude(paths, folder):
    p = make.PARAMETERS["large-amplitude.ipynb"]
    args = ["fit", "period", paths["DATA"]]
    if p["LENGTH_M"] is not None:
        args += ["--length", metres(p["LENGTH_M"])]
        if p["LENGTH_UNCERTAINTY_M"] is not None:
            args += ["--length-uncertainty", metres(p["LENGTH_UNCERTAINTY_M"])]
    fit, command = pendulum(args + ["--json"], folder)
    figures, errors = fit["parameters"], fit["standard_errors"]
    expected = {
        "small_angle_period_s": (figures["small_angle_period_s"], command),
        "small_angle_period_standard_error_s": (errors["small_angle_period_s"], command),
        "g_m_s2": (figures.get("g_m_s2"), command),
        "g_standard_error_m_s2": (errors.get("g_m_s2"), command),
        "circular_error_coefficient": (figures.get("circular_error_coefficient"), command),
        "circular_error_coefficient_standard_error":
            (errors.get("circular_error_coefficient"), command),
    }
    length = metres(p["LENGTH_M"] or 1.0)
    small, _ = pendulum(["period", "--length", length, "--amplitude", "0deg", "--json"], folder)
    one, command = pendulum(["amplitude", "--period", f"{1.01 * small['small_angle_period_s']!r}s",
                             "--length", length, "--json"], folder)
    expected["one_percent_amplitude_deg"] = (one["amplitude_deg"], command)
    return expected


def damping(paths, folder):
    p = make.PARAMETERS["damping.ipynb"]
    known = []
    if p["LENGTH_M"] is not None:
        known += ["--length", metres(p["LENGTH_M"])]
    decay_known = known + (["--mass", f"{p['MASS_KG']!r}kg"] if p["MASS_KG"] is not None else [])
    decay, command = pendulum(["fit", "decay", paths["DATA"], *decay_known, "--json"], folder)
    best = law(decay, decay["preferred"])
    expected = {
        "preferred": (decay["preferred"], command),
        "runner_up_delta_bic": (decay["runner_up"]["delta_bic"], command),
        "q": (best["q_factor"], command),
        "q_standard_error": (best["q_factor_standard_error"], command),
    }
    track, command = pendulum(["fit", "trajectory", paths["DATA"], "--pivot", "fit", *known,
                               "--json"], folder)
    expected.update({
        "trajectory_q": (track["q_factor"], command),
        "trajectory_q_standard_error": (track["q_factor_standard_error"], command),
        "trajectory_g_m_s2": (track["parameters"].get("g_m_s2"), command),
    })
    clock, command = pendulum(["fit", "decay", paths["RUNDOWN"],
                               "--length", metres(p["RUNDOWN_LENGTH_M"]),
                               "--mass", f"{p['RUNDOWN_MASS_KG']!r}kg", "--json"], folder)
    clock_best = law(clock, clock["preferred"])
    expected.update({
        "rundown_preferred": (clock["preferred"], command),
        "rundown_q": (clock_best["q_factor"], command),
        "rundown_q_standard_error": (clock_best["q_factor_standard_error"], command),
        "rundown_power_w": (clock_best.get("power_w"), command),
    })
    return expected


def read_columns(path, names):
    """As the notebook reads them: the named columns of a comma-separated
    file whose lines starting with # are comments."""
    import csv
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.lstrip().startswith("#")))
    return [[float(row[name]) for row in rows] for name in names]


def g_from_lengths(paths, folder):
    p = make.PARAMETERS["g-from-lengths.ipynb"]
    fit, command = pendulum(["fit", "period", paths["DATA"], "--json"], folder)
    figures, errors = fit["parameters"], fit["standard_errors"]
    expected = {
        "g_m_s2": (figures["g_m_s2"], command),
        "g_standard_error_m_s2": (errors["g_m_s2"], command),
        "length_offset_m": (figures["length_offset_m"], command),
        "length_offset_standard_error_m": (errors["length_offset_m"], command),
        "chi_square": (fit.get("chi_square"), command),
    }
    # The lengths' uncertainty carried into each period's (the notebook's
    # section 2), written as the table's period_err_s: the command line
    # fits that table.
    length, period, error = read_columns(folder / paths["DATA"],
                                         ["length_m", "period_s", "period_err_s"])
    offset = figures["length_offset_m"]
    combined = [math.sqrt(e**2 + (t * p["LENGTH_UNCERTAINTY_M"] / (2 * (l + offset)))**2)
                for l, t, e in zip(length, period, error)]
    with tempfile.TemporaryDirectory() as scratch:
        table = pathlib.Path(scratch) / "lengths-carried.csv"
        table.write_text("length_m,period_s,period_err_s\n" + "".join(
            f"{l!r},{t!r},{e!r}\n" for l, t, e in zip(length, period, combined)))
        every, command = pendulum(["fit", "period", str(table), "--json"], folder)
    g, g_se = every["parameters"]["g_m_s2"], every["standard_errors"]["g_m_s2"]
    command += f" (the periods' uncertainties with the lengths' {p['LENGTH_UNCERTAINTY_M']} m)"
    expected.update({
        "g_lengths_carried_m_s2": (g, command),
        "g_lengths_carried_standard_error_m_s2": (g_se, command),
        "g_total_standard_error_m_s2": (math.hypot(g_se, g * p["TAPE_SCALE_UNCERTAINTY"]),
                                        command + f" and the tape's {p['TAPE_SCALE_UNCERTAINTY']}"),
    })
    return expected


CHECKS = {
    "large-amplitude.ipynb": large_amplitude,
    "damping.ipynb": damping,
    "g-from-lengths.ipynb": g_from_lengths,
}


def differs(a, b):
    """Why the notebook's `a` is not the command's `b`, or None."""
    if isinstance(a, (int, float)) and isinstance(b, (int, float)) \
            and not isinstance(a, bool) and not isinstance(b, bool):
        if a == b or (math.isnan(a) and math.isnan(b)):
            return None
        relative = abs(a - b) / max(abs(a), abs(b))
        return None if relative <= TOLERANCE else f"relative difference {relative:.2g}"
    return None if a == b else "not equal"


def main():
    bin_dir = os.path.dirname(sys.executable)
    os.environ["PATH"] = bin_dir + os.pathsep + os.environ.get("PATH", "")
    failures = []
    for name in make.stale():
        failures.append(f"{name}: not what make.py writes (edit make.py, then run python "
                        "examples/notebooks/make.py)")
    for name, check in CHECKS.items():
        path = HERE / name
        try:
            key, paths = execute(path)
            expected = check(paths, HERE)
        except Failure as e:
            failures.append(f"{name}: {e}")
            continue
        except Exception as e:  # a check that could not run is a failure, said in a line
            failures.append(f"{name}: {type(e).__name__}: {e}")
            continue
        missing = sorted(set(expected) - set(key))
        extra = sorted(set(key) - set(expected))
        if missing:
            failures.append(f"{name}: KEY lacks {', '.join(missing)}")
        if extra:
            failures.append(f"{name}: KEY has {', '.join(extra)}, which nothing checks")
        print(f"{name}")
        for k, (value, command) in expected.items():
            if k not in key:
                continue
            why = differs(key[k], value)
            mark = "ok  " if why is None else "FAIL"
            print(f"  {mark} {k:42s} notebook {key[k]!r:24s} command {value!r}")
            if why is not None:
                failures.append(f"{name}: {k} = {key[k]!r}, `{command}` gives {value!r} ({why})")
    for failure in failures:
        print(failure, file=sys.stderr)
    if failures:
        return 1
    print(f"all {len(CHECKS)} notebooks ran; every key figure equals the command line's "
          f"to {TOLERANCE:g} relative")
    return 0


if __name__ == "__main__":
    sys.exit(main())
