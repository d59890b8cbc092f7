"""Writes the teaching pack's notebooks from the plain text below.

    python examples/notebooks/make.py          # (re)writes the three .ipynb files
    python examples/notebooks/make.py --check  # exits 1 if a notebook is not what this file writes

The notebooks are nbformat 4 JSON with no outputs, one source line per
JSON line, so that a change to a cell is a change of a few lines in the
diff. Edit the cells here, never the .ipynb files (check.py refuses a
notebook that differs from what this file writes).

PARAMETERS are each notebook's second cell (what is known of the
pendulum); check.py runs the `pendulum` command with the same values.
"""

import hashlib
import json
import pathlib
import re
import sys
import textwrap

HERE = pathlib.Path(__file__).resolve().parent

#: What each notebook takes as known, by notebook: the values written into
#: its parameter cell, and the flags check.py gives the command line.
PARAMETERS = {
    "large-amplitude.ipynb": {
        "DATA": "../../crates/pendulum-cli/tests/data/period/silveira1986.csv",
        "LENGTH_M": 2.87,
        "LENGTH_UNCERTAINTY_M": 0.01,
    },
    "damping.ipynb": {
        "DATA": "../../crates/pendulum-cli/tests/data/real/pendulum_fullPeriod.trk",
        "RUNDOWN": "../rundown.csv",
        "LENGTH_M": None,
        "MASS_KG": None,
        "RUNDOWN_LENGTH_M": 0.99362,
        "RUNDOWN_MASS_KG": 5.0,
    },
    "g-from-lengths.ipynb": {
        "DATA": "lengths.csv",
        "LENGTH_UNCERTAINTY_M": 0.002,
        "TAPE_SCALE_UNCERTAINTY": 0.0005,
    },
}


def quoted(path):
    """A path as a Python string in double quotes."""
    return json.dumps(path, ensure_ascii=False)


def md(text):
    return ("markdown", textwrap.dedent(text).strip("\n"))


def code(text):
    return ("code", textwrap.dedent(text).strip("\n"))


# The helpers every notebook defines (each notebook stands alone: a
# student may copy one away from the others).
HELPERS = code('''
    import math

    import matplotlib.pyplot as plt
    import numpy as np

    import pendulum_theory as pt


    def messages(items):
        """The sentences of a fit's warnings (a list of sentences, or of
        {"code": ..., "message": ...})."""
        return [w["message"] if isinstance(w, dict) else str(w) for w in items]


    def say(result):
        """Prints what the reader left out of the file and what the fit warns of."""
        for note in result.get("notes", []):
            print("note:", note)
        for sentence in messages(result.get("warnings", [])):
            print("WARNING:", sentence)


    def draw(figure, height=3.2, xlim=None):
        """Draws the panels of a fit's figure (what the command's --plot draws),
        one matplotlib figure a panel; xlim=(a, b) shows that part of the x axis alone."""
        for panel in figure["panels"]:
            fig, ax = plt.subplots(figsize=(9, height))
            if xlim is not None:
                ax.set_xlim(*xlim)
            for s in panel["series"]:
                if not s["points"]:
                    continue
                x, y = np.array([[np.nan if v is None else v for v in p] for p in s["points"]]).T
                if s["style"] == "dots":
                    ax.plot(x, y, ".", ms=3, label=s["label"])
                else:
                    width = {"strong": 2.5, "light": 0.8}.get(s["weight"], 1.5)
                    ax.plot(x, y, "-", lw=width, label=s["label"])
            ax.set(title=panel["title"], xlabel=panel["x_label"], ylabel=panel["y_label"],
                   xscale=panel["x_scale"], yscale=panel["y_scale"])
            ax.grid(alpha=0.3)
            ax.legend(fontsize=7)
            plt.show()
''')


def parameters(name, comments):
    """The parameter cell of notebook `name`: each value of PARAMETERS
    but DATA (and RUNDOWN), with its comment."""
    lines = []
    for key, value in PARAMETERS[name].items():
        if key in ("DATA", "RUNDOWN"):
            continue
        lines.append(f"{key} = {value!r}".ljust(32) + f"# {comments[key]}")
    return code("\n".join(lines))


# ---------------------------------------------------------------------------
# The period at large amplitude
# ---------------------------------------------------------------------------

LARGE = [
    code(f'''
        # The period at large amplitude. Put your own file's path here (relative to this notebook's
        # folder, or absolute): a table of periods against amplitudes, e.g. the columns
        # amplitude_deg,period_s (comma, semicolon or tab separated; a period_err_s column if you have one).
        DATA = {quoted(PARAMETERS["large-amplitude.ipynb"]["DATA"])}
    '''),
    md('''
        # The period at large amplitude

        A pendulum's period grows with its amplitude. A simple pendulum of length $l$ (m, from the
        pivot to the bob's centre) under gravity $g$ (m/s²), released from rest at the amplitude $A_0$
        (rad: the largest angle from the vertical, one side), has the period (s, there and back: two
        swings)

        $$T = 4\\sqrt{l/g}\\;K\\!\\left(\\sin^2\\tfrac{A_0}{2}\\right),$$

        where $K(m)$ is the complete elliptic integral of the first kind with parameter $m$. As
        $A_0 \\to 0$, $K \\to \\pi/2$ and $T \\to T_0 = 2\\pi\\sqrt{l/g}$: the small-angle law. The ratio
        $T/T_0 = \\tfrac{2}{\\pi}K(\\sin^2\\tfrac{A_0}{2}) = 1 + \\tfrac{A_0^2}{16} + \\tfrac{11A_0^4}{3072} + \\dots$
        ($A_0$ in radians) depends on the amplitude alone, not on $l$ or $g$.

        This notebook: (1) the two laws side by side, where the small-angle law is 1 % short, and what
        the difference costs a clock (the circular error); (2) a table of measured periods fitted by the
        exact law, giving $T_0$, $g$ and the coefficient of $A_0^2$ with their standard errors (every ±
        here is one standard error); (3) questions for you, marked **Question**.

        The example file is a published table: F. Lang da Silveira (1986), 42 periods of a simple
        pendulum 2.87 m long, each one oscillation timed by hand with a stopwatch, at amplitudes from
        0.7° to 24.8°.

        ## What you know of your pendulum

        Give your pendulum's length and its standard uncertainty (m). With no length (`None`) the fit
        still gives $T_0$ and the coefficient of $A_0^2$, but no $g$.
    '''),
    parameters("large-amplitude.ipynb", {
        "LENGTH_M": "the pendulum's length, m: pivot to the bob's centre (None: no g)",
        "LENGTH_UNCERTAINTY_M": "its standard uncertainty, m (the paper gives none: 1 cm is our assumption)",
    }),
    HELPERS,
    md('''
        ## 1. The exact law and the small-angle law

        Both periods at standard gravity (9.80665 m/s²) for your length (1 m if you gave none); their
        ratio is the same for every length.
    '''),
    code('''
        L = LENGTH_M or 1.0
        T0 = pt.period(L, 0.0)                  # 2π√(l/g), s
        amplitude = np.radians(np.linspace(0.0, 160.0, 321))
        ratio = pt.period(L, amplitude) / T0    # the exact T/T0

        fig, ax = plt.subplots(figsize=(8, 4))
        ax.plot(np.degrees(amplitude), ratio, label="exact: (2/π) K(sin²(A0/2))")
        ax.plot(np.degrees(amplitude), 1 + amplitude**2 / 16, "--", label="first correction: 1 + A0²/16")
        ax.axhline(1.0, color="grey", lw=1, label="small-angle law: T = T0")
        ax.set(xlabel="amplitude A0 (°)", ylabel="T / T0",
               title=f"The period against the amplitude (T0 = {T0:.4f} s for l = {L} m)")
        ax.grid(alpha=0.3)
        ax.legend()
        plt.show()
    '''),
    md('''
        ### Where the small-angle law fails by 1 %

        The small-angle law always gives too short a period. The amplitude at which the exact period
        is 1.01 $T_0$ (the small-angle law 1 % short of it) follows from the exact law by
        `pt.amplitude_for_period`; the first correction alone, $A_0^2/16 = 0.01$, puts it at
        $A_0 = 0.4$ rad.
    '''),
    code('''
        one_percent = pt.amplitude_for_period(1.01 * T0, L)        # rad
        one_permille = pt.amplitude_for_period(1.001 * T0, L)
        print(f"T = 1.01 T0  at A0 = {math.degrees(one_percent):.2f}°")
        print(f"T = 1.001 T0 at A0 = {math.degrees(one_permille):.2f}°")
        print(f"A0²/16 = 0.01 at A0 = 0.4 rad = {math.degrees(0.4):.2f}°")
    '''),
    md('''
        **Question (before the lab).** Your timing of one period will be good to some fraction of
        it (a stopwatch by hand: about 0.1 s in 2 s, 5 %; twenty periods timed at once: 0.25 %). Up to
        which amplitude is the small-angle law within that fraction? So how large must the swings be
        for the exact law to show in your measurements?

        ### The circular error

        A clock counts swings. If its pendulum swings at $A_0$ the clock loses, against the same
        pendulum swinging a vanishing arc, the circular error $86\\,400\\,(1 - T_0/T)$ s a day (about
        $86\\,400\\,A_0^2/16$ for small swings). A clock is set to time at its own amplitude, so
        what matters is how much the error changes when the amplitude does (the drive weakens, the oil
        thickens).
    '''),
    code('''
        print(" A0     circular error     its change for 0.1° more swing")
        for degrees in [1, 2, 3, 5, 10, 25]:
            e = pt.circular_error_s_per_day(math.radians(degrees))
            change = pt.circular_error_s_per_day(math.radians(degrees + 0.1)) - e
            print(f"{degrees:3d}°   {e:9.2f} s/day       {change:6.2f} s/day")
    '''),
    md('''
        **Question.** A longcase clock keeps time with its pendulum swinging 2° either side. As the oil
        thickens the swing falls to 1.8°. Does the clock gain or lose, and by how many seconds a day?

        ## 2. Your measured periods

        `pt.fit_file` reads the file as the command `pendulum fit period FILE --json` reads it (the
        same reader: comma, semicolon or tab separated, decimal points or commas, a header naming
        each column and its unit, such as `amplitude_deg`, `release_angle (rad)`, `period_s`,
        `T (s)`; a column of each period's standard uncertainty, `period_err_s`, if you have one)
        and fits $T = T_0\\,\\tfrac{2}{\\pi}K(\\sin^2\\tfrac{A}{2})$ with $T_0$ the one free parameter;
        with your length, $g = 4\\pi^2 l / T_0^2$. A file it cannot read raises `ValueError` with the
        reason.
    '''),
    code('''
        r = pt.fit_file(DATA, "period", length=LENGTH_M,
                        length_uncertainty=LENGTH_UNCERTAINTY_M if LENGTH_M else None)
        if r["against"] != "amplitude":
            raise ValueError(f"{DATA}: its periods are against lengths: use g-from-lengths.ipynb")
        weighted = "weighted by their uncertainties" if r["weighted"] else "unweighted (no uncertainties in the file)"
        print(f"{r['file']}: {r['rows']} periods, columns {r['format']['columns_used']}, {weighted}")
        say(r)

        # The measured points, as the fit's figure holds them: amplitude in degrees, period in seconds.
        panel = r["figure"]["panels"][0]
        assert panel["x_label"] == "amplitude (°)" and panel["y_label"] == "period (s)", panel
        measured = next(s for s in panel["series"] if s["label"] == "measured")
        amplitude_deg, period_s = np.array(measured["points"], dtype=float).T
    '''),
    code('''
        p, se = r["parameters"], r["standard_errors"]
        t0, t0_se = p["small_angle_period_s"], se["small_angle_period_s"]
        print(f"T0, the exact law fitted       {t0:.4f} ± {t0_se:.4f} s")
        if "g_m_s2" in p:
            parts = r["standard_error_parts"]["g_m_s2"]
            length_part = "not given" if parts["length"] is None else f"{parts['length']:.3f}"
            print(f"g = 4π² l / T0²                {p['g_m_s2']:.3f} ± {se['g_m_s2']:.3f} m/s²"
                  f"  (the periods' part {parts['fit']:.3f}, the length's {length_part})")
        c = p.get("circular_error_coefficient")
        if c is not None:
            c_se = se["circular_error_coefficient"]
            theory = r["circular_error_coefficient_theory"]
            print(f"coefficient of A0² in T/T0     {c:.4f} ± {c_se:.4f}"
                  f"  (the law's {theory}: {(c - theory) / c_se:+.1f} standard errors from it)")
        print(f"residual rms                   {1000 * r['residual_rms_s']:.1f} ms")
    '''),
    md('''
        $T_0$ is fitted with the exact law taken as true. The coefficient tests the law itself: the
        table is fitted a second time as $T = T_0\\,\\tfrac{2}{\\pi}K(\\sin^2\\tfrac{A}{2})\\,(1 + d\\,A^2)$
        and the coefficient is $1/16 + d$. Equal to 1/16 within its standard errors: the periods grow
        with the amplitude as the law says. If it is far from 1/16 the fit warns, with the likely
        causes.
    '''),
    code('''
        grid = np.radians(np.linspace(0.0, 1.1 * amplitude_deg.max(), 200))
        law = lambda a: t0 * pt.period(1.0, a) / pt.period(1.0, 0.0)   # T0 (2/π) K(sin²(A/2))

        fig, (ax, bx) = plt.subplots(2, 1, figsize=(8, 6), sharex=True,
                                     gridspec_kw={"height_ratios": [3, 1]})
        ax.plot(amplitude_deg, period_s, ".", color="grey", label="measured")
        levels = np.unique(amplitude_deg)
        if len(levels) < len(amplitude_deg):      # repeated amplitudes: their means
            groups = [period_s[amplitude_deg == v] for v in levels]
            means = [g.mean() for g in groups]
            errors = [g.std(ddof=1) / math.sqrt(len(g)) if len(g) > 1 else np.nan for g in groups]
            ax.errorbar(levels, means, yerr=errors, fmt="o", color="C3", capsize=3,
                        label="mean at each amplitude ± its standard error")
        ax.plot(np.degrees(grid), law(grid), label="exact law, T0 fitted")
        ax.axhline(t0, ls="--", color="C1", label="small-angle law: T = T0")
        ax.set(ylabel="period (s)", title="Measured periods against the exact law")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        bx.plot(amplitude_deg, 1000 * (period_s - law(np.radians(amplitude_deg))), ".", color="grey")
        bx.axhline(0.0, color="k", lw=0.8)
        bx.set(xlabel="amplitude (°)", ylabel="measured − law (ms)")
        bx.grid(alpha=0.3)
        plt.show()
    '''),
    md('''
        ### The same fit from numbers typed in: `fit_period`

        Periods you have in a list, not a file, go to `pt.fit_period` (amplitudes in radians, the
        length and its uncertainty in metres): the same fit, the same numbers.
    '''),
    code('''
        typed = pt.fit_period(period_s, amplitude=np.radians(amplitude_deg),
                              pendulum_length=LENGTH_M,
                              length_uncertainty=LENGTH_UNCERTAINTY_M if LENGTH_M else None)
        print(f"T0 from the file {t0:.12f} s, from the arrays {typed.parameters['small_angle_period_s']:.12f} s")
    '''),
    md('''
        ### The circular error the table shows

        At the table's largest amplitude the exact law says how much longer than $T_0$ the period is;
        the measured coefficient says, to first order in $A^2$, how much longer the periods were.
    '''),
    code('''
        a_max = math.radians(amplitude_deg.max())
        print(f"largest amplitude {amplitude_deg.max():.1f}°")
        print(f"  the law:  T/T0 - 1 = {100 * (law(a_max) / t0 - 1):.2f} %,"
              f" a clock loses {pt.circular_error_s_per_day(a_max):.0f} s/day")
        if c is not None:
            print(f"  the data: c A0²    = {100 * c * a_max**2:.2f} ± {100 * c_se * a_max**2:.2f} %")
    '''),
    md('''
        ## 3. Questions

        **Question (before).** One period timed by hand scatters by about 0.04 s (this table's
        residual rms). At 25° the period is 1.2 % longer than $T_0$, about 0.04 s at 3.4 s. How many
        timings at each amplitude make that difference three standard errors of the mean? What does
        timing ten periods at once change, and what does it cost (think of the amplitude during those
        ten periods)?

        **Question (during).** How do you measure the amplitude: at the release, or the swing while
        you time it? The swing falls while you count. Which amplitude belongs with the period you
        timed?

        **Question (after).** How many standard errors is your coefficient from 1/16? Name one mistake
        that makes it too large and one that makes it too small. Then put
        `DATA = "../../crates/pendulum-cli/tests/data/period/sardjito2020.csv"` (a rigid pendulum
        timed up to 45°, no length: leave `LENGTH_M = None`) in the first cell, run the notebook again,
        and read the fit's warning.

        **Question (after).** Compare your $g$ with the normal gravity where you measured,
        `pt.normal_gravity(latitude_deg, height_m)` (for the example, take Porto Alegre, where its
        author taught: 30.0° S, about 10 m; the paper does not say). Is the difference within two
        standard errors? Which part of $g$'s standard error
        (the periods' or the length's) would you reduce first, and how?

        ## The same with the command line

        From the repository's top folder (`pendulum` is installed with the Python package):

        ```sh
        pendulum fit period crates/pendulum-cli/tests/data/period/silveira1986.csv --length 2.87m --length-uncertainty 1cm --json
        pendulum amplitude --period 2.02647s --length 1m
        ```

        The first prints the figures of section 2 (the same numbers); the second the amplitude at which
        a 1 m pendulum's period is 1.01 $T_0$.

        ## Key figures

        The last cell keeps this notebook's results in `KEY` (`examples/notebooks/check.py` compares
        them with the command line's).
    '''),
    code('''
        KEY = {
            "small_angle_period_s": t0,
            "small_angle_period_standard_error_s": t0_se,
            "g_m_s2": p.get("g_m_s2"),
            "g_standard_error_m_s2": se.get("g_m_s2"),
            "circular_error_coefficient": p.get("circular_error_coefficient"),
            "circular_error_coefficient_standard_error": se.get("circular_error_coefficient"),
            "one_percent_amplitude_deg": math.degrees(one_percent),
        }
        KEY
    '''),
]


# ---------------------------------------------------------------------------
# Damping and Q
# ---------------------------------------------------------------------------

DAMPING = [
    code(f'''
        # Damping and Q from a run-down. Put your own file's path here (relative to this notebook's
        # folder, or absolute): a Tracker project (.trk) or export (.txt, .csv), a table of amplitudes
        # against time (time_s,amplitude_deg), or any track of an angle or of x and y against time.
        DATA = {quoted(PARAMETERS["damping.ipynb"]["DATA"])}
        # A second example: a clock's seconds pendulum, its amplitude read every minute for two hours.
        RUNDOWN = {quoted(PARAMETERS["damping.ipynb"]["RUNDOWN"])}
    '''),
    md('''
        # Damping and Q

        A free pendulum's swing dies away. How it dies tells what takes its energy, and how fast tells
        its quality factor $Q$: $2\\pi$ times the energy stored over the energy lost in one period.
        This notebook fits the rival damping laws to a run-down, says which the data prefer and by how
        much, and gives $Q$ with its standard error (every ± here is one standard error).

        The example file is a real Tracker project (J. Lefebvre, 2020, MIT licence: see
        `crates/pendulum-cli/tests/data/real/README.md`): a pendulum released at about 80° and filmed
        for 6½ minutes at 60 frames a second, the bob marked every 5th frame, 4,502 points.

        ## What you know of your pendulum

        Neither is needed for a track: the angular frequency $\\omega$ (rad/s) that turns the rates into
        $\\zeta$ and $Q$ comes from the times of its turning points. A table of amplitudes has no
        turning times: without its length (for $\\omega = \\sqrt{g/l}$) it gives the rates, not $\\zeta$ or $Q$. With the length a track also gives $g$ from its turning
        points' times; with the mass, the energy lost per period (J) and the power (W).
    '''),
    parameters("damping.ipynb", {
        "LENGTH_M": "the pendulum's length, m (a track's ω comes from its turning points)",
        "MASS_KG": "the bob's mass, kg (None: no energy figures)",
        "RUNDOWN_LENGTH_M": "the second example's length, m: a seconds pendulum",
        "RUNDOWN_MASS_KG": "its bob's mass, kg",
    }),
    HELPERS,
    md('''
        ## 1. The rival laws

        Each law says how the amplitude $A$ (rad) falls with the time $t$ (s), averaged over a swing:
        $dA/dt = -(\\mu + \\lambda A + \\kappa A^2)$ with some of the three rates zero. Each rate is a
        kind of loss:

        | law | $A(t)$ | the loss | its rate, and the physical figure |
        |---|---|---|---|
        | `viscous` | $A_0 e^{-\\lambda t}$ | a force proportional to the speed (slow air, the suspension's inner friction) | $\\lambda$ (1/s, `decay_rate_per_s`); $\\zeta = \\lambda/\\omega$ (`zeta`) |
        | `coulomb` | $A_0 - \\mu t$ | a force of constant size: dry friction at the pivot | $\\mu$ (rad/s, `amplitude_fall_rad_per_s`); the friction angle $r = \\pi\\mu/(2\\omega)$ rad (`friction_angle_rad`) |
        | `quadratic` | $A_0/(1 + \\kappa A_0 t)$ | a force proportional to the square of the speed: air drag on a fast bob | $\\kappa$ (1/(rad s), `quadratic_decay_per_rad_s`); $b = 3\\pi\\kappa/(4\\omega)$ per rad (`quadratic_drag_per_rad`) |

        and their combinations (`viscous+coulomb`, `viscous+quadratic`, `coulomb+quadratic`,
        `viscous+coulomb+quadratic`). Every rate is held at 0 or above: damping never gives energy.

        **$Q$ over the record** (`q_factor`) is the figure to quote, whatever the law: the energy of a
        swing of amplitude $A$ is $mgl(1 - \\cos A)$, and over the record, from the fitted law's
        amplitude $A(t_0)$ at its first time to $A(t_n)$ at its last,
        $Q = \\omega\\,(t_n - t_0)\\,/\\,\\ln\\!\\big[(1 - \\cos A(t_0))/(1 - \\cos A(t_n))\\big]$. For viscous
        damping alone this is $1/(2\\zeta)$; with friction or drag the loss depends on the amplitude,
        and `q_viscous` $= 1/(2\\zeta)$ is then the viscous part alone, not the pendulum's $Q$.

        **Question (before).** A heavy bob on a thread, released at 80°: which loss do you expect to
        dominate early, when it swings fast, and which late, when the swing is a few degrees?

        ## 2. The fit

        `pt.fit_file(DATA, "decay")` reads the file as `pendulum fit decay FILE --json` does: a
        Tracker project is read as it is (its first point mass, in the project's units, against the
        clip's time); a track's turning points (the largest angle of each swing) are found and their
        amplitudes fitted.
    '''),
    code('''
        def q_text(m):
            """A law's Q over the record with its standard error, or what the data bound it by."""
            if m.get("q_factor") is not None:
                return f"{m['q_factor']:.1f} ± {m['q_factor_standard_error']:.1f}"
            if m.get("q_factor_lower_bound") is not None:
                return f"> {m['q_factor_lower_bound']:.0f} (no measurable loss)"
            return "none"


        try:
            r = pt.fit_file(DATA, "decay", length=LENGTH_M, mass=MASS_KG)
        except ValueError as refusal:      # a phone's gyroscope gives rates, no amplitudes: see section 3
            r = None
            print("no decay fit:", refusal)
        if r is not None:
            print(f"{r['file']}: {r['format']['rows']} rows read, columns {r['format']['columns_used']}"
                  + (f", Tracker track {r['format']['tracker_track']!r}" if r["format"].get("tracker_track") else ""))
            if r["omega_rad_s"] is None:
                print(f"{r['points']} amplitudes fitted; no ω: give LENGTH_M for ζ and Q")
            else:
                print(f"{r['points']} amplitudes fitted; ω = {r['omega_rad_s']:.5f} rad/s "
                      f"(period {2 * math.pi / r['omega_rad_s']:.5f} s) from the {r['omega_source'].replace('_', ' ')}")
            if r.get("zero_offset_rad") is not None:
                print(f"the track's zero (where it hangs at rest) was {math.degrees(r['zero_offset_rad']):.3f}°: removed")
            say(r)

            best_bic = min(m["bic"] for m in r["models"] if m.get("bic") is not None)
            print()
            print(f"{'law':28s}{'Q over the record':>22s}{'residual rms':>15s}{'ΔBIC':>9s}{'weight':>10s}")
            for m in r["models"]:
                if m.get("bic") is None:
                    print(f"{m['model']:28s}  not fitted: {m.get('failed', '')}")
                    continue
                flag = "  <- preferred" if m["model"] == r["preferred"] else (
                    f"  ({', '.join(m['at_bound'])} at 0)" if m["at_bound"] else "")
                print(f"{m['model']:28s}{q_text(m):>22s}{math.degrees(m['residual_rms']):>13.3f} °"
                      f"{m['bic'] - best_bic:9.1f}{m['akaike_weight']:10.2g}{flag}")
    '''),
    md('''
        How to read the table:

        * **ΔBIC** is each law's Bayesian information criterion less the lowest:
          $\\mathrm{BIC} = n \\ln(\\mathrm{RSS}/n) + k \\ln n$ for $n$ amplitudes, $k$ parameters and the
          residual sum of squares RSS. A law with more rates fits at least as well; the $k \\ln n$
          makes it pay for them. The lowest BIC is preferred. Against the next best law, a ΔBIC
          under 2 means the data hardly choose; over 10, they choose clearly.
        * **weight** is the Akaike weight: the share of belief the data give each law among these.
        * A law with a rate **at 0** is a simpler law already in the list, and is never preferred.
        * **$Q$ over the record** is nearly the same in every law that fits well: read $Q$ before
          reading a law into the data.
    '''),
    code('''
        best = None if r is None else next(m for m in r["models"] if m["model"] == r["preferred"])
        if best is not None:
            runner = r["runner_up"]
            print(f"preferred: {r['preferred']}" + ("" if runner is None else
                  f"; the next best, {runner['model']}, has ΔBIC {runner['delta_bic']:.1f}"))
            print(f"Q over the record = {q_text(best)}")
            for name, value in best["parameters"].items():
                print(f"  {name:28s} {value:.6g} ± {best['standard_errors'][name]:.2g}")
            draw(r["figure"])
    '''),
    md('''
        **Question (after).** Look at the residuals of the `viscous` law alone (draw them: each law's
        curve is in the figure). Is there a pattern? What does a pattern in the residuals say that the
        residual rms does not?

        ## 3. The whole track: `fit trajectory`

        The decay fit uses one number per swing, its amplitude. The trajectory fit uses every point of
        the track: it integrates the nonlinear equation of the damped pendulum inside the fit
        (`model` `auto`: nonlinear above a 5° swing), with the pivot found as the centre of the arc the
        bob traces (`pivot="fit"`), whose radius is the length. It gives $Q$ over the record again,
        and $g$. This fit takes about ten seconds on the example.
    '''),
    code('''
        try:
            track = pt.fit_file(DATA, "trajectory", pivot="fit", length=LENGTH_M)
        except ValueError as refusal:        # a table of amplitudes has no track
            track = None
            print("no trajectory fit:", refusal)
        if track is not None:
            tp, tse = track["parameters"], track["standard_errors"]
            print(f"{track['points']} points, {track['model']} model, damping law {track['damping_law']}")
            print(f"Q over the record = {q_text(track)}"
                  + ("" if best is None else f"   (the decay fit: {q_text(best)})"))
            if "g_m_s2" in tp:
                print(f"length = {track['length_m']:.4f} m ({track['length_source'].replace('_', ' ')})")
                parts = track["standard_error_parts"]["g_m_s2"]
                length_part = "not given" if parts["length"] is None else f"{parts['length']:.2g}"
                print(f"g = {tp['g_m_s2']:.4f} ± {tse['g_m_s2']:.2g} m/s²"
                      f"  (the fit's part {parts['fit']:.2g}, the length's {length_part})")
            print(f"the residuals are {track['residual_to_noise']:.0f} times the sample-to-sample noise;"
                  f" the standard errors are widened {track['standard_error_inflation']:.2f} times for it")
            say(track)
            draw(track["figure"])
            draw(track["figure"], xlim=(0.0, 15.0))     # the first 15 s: the start the warning speaks of
    '''),
    md('''
        ### What the warnings mean

        A warning is a sentence the fit adds when a figure is not what it seems; the command line
        prints the same sentences. Those you may meet here:

        * **the fitted curve's first crest is off the data's** (`first_crest_off`): the fitted motion
          does not follow the record's start, often a release by hand or a push. `amplitude_rad` is then
          the model's release amplitude, not the swing you recorded; leave the start out with
          `start=` seconds (the command's `--from`). On the example it stays with `start=5`: the
          fitted motion misses the first swings by more than their errors, and the residuals, many
          times the tracking noise, show a pattern the model leaves.
        * **zeta not determined**: the swing decays too little over the record to measure the damping:
          record longer.
        * **samples left out** (`samples_left_out`): the track is in pieces (the tracker lost the bob);
          the longest run was fitted, the rest named.
        * **the amplitudes look like radians** (`angles_look_like_radians`): a column declared in
          degrees never reaches a degree; check its unit.
        * **g far from standard gravity**: a unit is wrong (times in ms, a length in mm, a radius in
          pixels), or the length is not the pendulum's.

        The **notes** (`notes`) say what the reader left out of the file (rows it could not read,
        repeated rows); the fit is of the rest.

        ## 4. A clock's pendulum: `rundown.csv`

        A seconds pendulum (0.99362 m, 5 kg) with its amplitude read every minute for two hours. The
        length gives $\\omega$; the mass gives the energy lost per period and the power the clock's
        escapement must give back to keep it swinging.
    '''),
    code('''
        clock = pt.fit_file(RUNDOWN, "decay", length=RUNDOWN_LENGTH_M, mass=RUNDOWN_MASS_KG)
        say(clock)
        clock_best = next(m for m in clock["models"] if m["model"] == clock["preferred"])
        print(f"{clock['points']} amplitudes; preferred {clock['preferred']}"
              f" (ΔBIC {clock['runner_up']['delta_bic']:.0f} to {clock['runner_up']['model']})")
        print(f"Q over the record = {q_text(clock_best)}")
        if clock_best.get("q_viscous") is not None:
            print(f"q_viscous = 1/(2ζ) = {clock_best['q_viscous']:.0f} ± {clock_best['q_viscous_standard_error']:.0f}"
                  " (the viscous part alone)")
        if clock_best.get("power_w") is not None:
            print(f"at the first amplitude: energy lost {clock_best['energy_loss_per_period_j'] * 1e6:.1f} µJ"
                  f" per period, power {clock_best['power_w'] * 1e6:.1f} µW")
        draw(clock["figure"])
    '''),
    md('''
        **Question (after).** The clock's weight (5 kg here too) falls 1 m in all. If the escapement
        gave back exactly the power lost, how many days would the clock run on one winding? (A real
        train and escapement lose more: a week is usual.)

        **Question (after).** The decay fit and the trajectory fit of the Tracker file give two values
        of $Q$. Are they consistent within their standard errors? They are not independent: why not?

        ## The same with the command line

        From the repository's top folder:

        ```sh
        pendulum fit decay crates/pendulum-cli/tests/data/real/pendulum_fullPeriod.trk --json
        pendulum fit trajectory crates/pendulum-cli/tests/data/real/pendulum_fullPeriod.trk --pivot fit --json
        pendulum fit decay examples/rundown.csv --length 0.99362m --mass 5kg --json
        ```

        (without `--json`: the same figures as a table; with `--plot decay.svg`: the figure).

        ## Key figures
    '''),
    code('''
        KEY = {
            "preferred": None if r is None else r["preferred"],
            "runner_up_delta_bic": None if r is None or r["runner_up"] is None else r["runner_up"]["delta_bic"],
            "q": None if best is None else best.get("q_factor"),
            "q_standard_error": None if best is None else best.get("q_factor_standard_error"),
            "trajectory_q": None if track is None else track["q_factor"],
            "trajectory_q_standard_error": None if track is None else track["q_factor_standard_error"],
            "trajectory_g_m_s2": None if track is None else track["parameters"].get("g_m_s2"),
            "rundown_preferred": clock["preferred"],
            "rundown_q": clock_best["q_factor"],
            "rundown_q_standard_error": clock_best["q_factor_standard_error"],
            "rundown_power_w": clock_best.get("power_w"),
        }
        KEY
    '''),
]


# ---------------------------------------------------------------------------
# g from periods against lengths
# ---------------------------------------------------------------------------

LENGTHS = [
    code(f'''
        # g from periods measured at several lengths. Put your own file's path here (relative to this
        # notebook's folder, or absolute): a table with the columns length_m, period_s and period_err_s
        # (each period's standard uncertainty, s).
        DATA = {quoted(PARAMETERS["g-from-lengths.ipynb"]["DATA"])}
    '''),
    md('''
        # $g$ from a table of lengths

        For small swings a simple pendulum's period (s, there and back) is
        $T = 2\\pi\\sqrt{(L + \\delta)/g}$, where $L$ (m) is the length you measured and $\\delta$ (m) the
        offset from where you measured to where the pendulum's length really ends (for a ball on a
        thread measured to the top of the ball: its radius, and a little more). Squared,

        $$T^2 = \\frac{4\\pi^2}{g}\\,L + \\frac{4\\pi^2}{g}\\,\\delta:$$

        a straight line in $L$ whose slope gives $g$ and whose intercept gives $\\delta$. So $g$ does
        not need you to know where the bob's centre is: only that you measured every length to the
        same point.

        This notebook fits that line with every uncertainty carried: each period's, then each
        length's, then the tape's scale (every ± here is one standard error).

        **The example file `lengths.csv` is made up, not measured**: a realistic table of ten lengths
        from 0.3 m to 1.2 m, each measured with a tape to the top of a 50 mm ball (standard
        uncertainty 2 mm), each period the time of 20 periods by hand divided by 20 (standard
        uncertainty 0.005 s), made with $g$ = 9.81 m/s² and $\\delta$ = 25 mm plus random errors of
        those sizes (its header says how).

        ## What you know of your measurement
    '''),
    parameters("g-from-lengths.ipynb", {
        "LENGTH_UNCERTAINTY_M": "each length's standard uncertainty, m (reading the tape)",
        "TAPE_SCALE_UNCERTAINTY": "the tape's scale, relative (a class II tape: 0.5 mm a metre)",
    }),
    HELPERS,
    md('''
        ## 1. The fit with the periods' uncertainties

        `pt.fit_file(DATA, "period")` reads the table as `pendulum fit period FILE --json` does and
        fits $T^2$ against $L$, each period weighted by its uncertainty ($\\sigma_{T^2} = 2T\\sigma_T$).
        With uncertainties given, $\\chi^2$ says whether they match the scatter: about the number of
        degrees of freedom (rows less 2) if they do. A $\\chi^2$ too large for them makes the fit warn
        and widen the standard errors by the Birge ratio $\\sqrt{\\chi^2/\\nu}$.
    '''),
    code('''
        r = pt.fit_file(DATA, "period")
        if r["against"] != "length":
            raise ValueError(f"{DATA}: its periods are against amplitude: use large-amplitude.ipynb")
        weighted = "weighted by their uncertainties" if r["weighted"] else "unweighted (no uncertainties in the file)"
        print(f"{r['file']}: {r['rows']} periods, columns {r['format']['columns_used']}, {weighted}")
        say(r)
        p, se = r["parameters"], r["standard_errors"]
        print(f"g       = {p['g_m_s2']:.3f} ± {se['g_m_s2']:.3f} m/s²")
        print(f"offset δ = {1000 * p['length_offset_m']:.1f} ± {1000 * se['length_offset_m']:.1f} mm")
        if r.get("chi_square") is not None:
            print(f"χ² = {r['chi_square']:.2f} for {r['degrees_of_freedom']} degrees of freedom"
                  f" (probability of a larger one {r['chi_square_probability']:.2f})")
    '''),
    md('''
        ## 2. The lengths' uncertainty

        The fit above takes the lengths as exact. Each length read off the tape is uncertain by
        $\\sigma_L$, and an error $dL$ in a length moves its period's place on the line as an error
        $dT = \\frac{dT}{dL}\\,dL = \\frac{T}{2(L + \\delta)}\\,dL$ in the period would. So each period
        carries the combined uncertainty

        $$\\sigma_{T,\\text{all}} = \\sqrt{\\sigma_T^2 + \\left(\\frac{T\\,\\sigma_L}{2(L + \\delta)}\\right)^2}$$

        (the "effective variance", with $\\delta$ from the fit above), and the table is fitted again
        with it by `pt.fit_period`, which takes arrays. This step reads the columns itself, so your
        file must be comma-separated with the header names `length_m`, `period_s` and `period_err_s`.

        Not every error in the lengths is of this kind. An error common to every length (measuring to
        the top of the ball, a hook of unknown size) goes into $\\delta$ and leaves $g$ alone. An error
        of the tape's scale (a tape 0.05 % long) makes every length 0.05 % wrong and $g$ 0.05 % wrong
        with them: it is added to $g$'s relative standard error at the end.
    '''),
    code('''
        import csv

        def read_columns(path, names):
            """The named columns of a comma-separated file whose lines starting with # are comments."""
            with open(path, newline="") as f:
                reader = csv.DictReader(line for line in f if not line.lstrip().startswith("#"))
                rows = list(reader)
            missing = [name for name in names if name not in (reader.fieldnames or [])]
            if missing:
                raise ValueError(f"{path}: this step needs the columns {', '.join(names)} in a"
                                 f" comma-separated file; it has {reader.fieldnames}")
            return [np.array([float(row[name]) for row in rows]) for name in names]

        length_m, period_s, period_err_s = read_columns(DATA, ["length_m", "period_s", "period_err_s"])
        from_length = period_s * LENGTH_UNCERTAINTY_M / (2 * (length_m + p["length_offset_m"]))
        period_err_all_s = np.sqrt(period_err_s**2 + from_length**2)

        every = pt.fit_period(period_s, length=length_m, period_standard_error=period_err_all_s)
        g_all, g_all_se = every.parameters["g_m_s2"], every.standard_errors["g_m_s2"]
        g_total_se = math.hypot(g_all_se, g_all * TAPE_SCALE_UNCERTAINTY)
        say(every)
        print(f"each period's uncertainty from its length: {1000 * from_length.min():.1f} to"
              f" {1000 * from_length.max():.1f} ms (the period's own: {1000 * period_err_s.mean():.1f} ms)")
        print(f"g, the periods' uncertainty alone:      {p['g_m_s2']:.3f} ± {se['g_m_s2']:.3f} m/s²")
        print(f"g, the lengths' carried too:             {g_all:.3f} ± {g_all_se:.3f} m/s²")
        print(f"g, and the tape's scale ({100 * TAPE_SCALE_UNCERTAINTY:.2f} %):        "
              f"{g_all:.3f} ± {g_total_se:.3f} m/s²")
        print(f"offset δ = {1000 * every.parameters['length_offset_m']:.1f} ± "
              f"{1000 * every.standard_errors['length_offset_m']:.1f} mm;"
              f" χ² = {every['chi_square']:.2f} for {every['degrees_of_freedom']} degrees of freedom")
    '''),
    code('''
        fig, (ax, bx) = plt.subplots(2, 1, figsize=(8, 6), sharex=True,
                                     gridspec_kw={"height_ratios": [3, 1]})
        grid = np.linspace(min(0.0, length_m.min()), 1.05 * length_m.max(), 100)
        slope = 4 * math.pi**2 / g_all
        ax.errorbar(length_m, period_s**2, xerr=LENGTH_UNCERTAINTY_M, yerr=2 * period_s * period_err_s,
                    fmt="o", ms=4, capsize=3, label="measured: T² ± 2Tσ_T, L ± σ_L")
        ax.plot(grid, slope * (grid + every.parameters["length_offset_m"]),
                label=f"fitted: g = {g_all:.3f} m/s², δ = {1000 * every.parameters['length_offset_m']:.1f} mm")
        ax.set(ylabel="T² (s²)", title="The square of the period against the length")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fitted = 2 * math.pi * np.sqrt((length_m + every.parameters["length_offset_m"]) / g_all)
        bx.errorbar(length_m, 1000 * (period_s - fitted), yerr=1000 * period_err_all_s, fmt="o", ms=4, capsize=3)
        bx.axhline(0.0, color="k", lw=0.8)
        bx.set(xlabel="length L (m): pivot to the top of the ball", ylabel="T − fitted (ms)")
        bx.grid(alpha=0.3)
        plt.show()
    '''),
    md('''
        The line meets $T^2 = 0$ at $L = -\\delta$: there the measured length would be zero if the
        pendulum's length were measured from its true end.

        ## 3. Against the local $g$

        Normal gravity, $g$ on the WGS 84 ellipsoid at a latitude and height (good to a few parts in
        10,000 where no local anomaly says otherwise), is `pt.normal_gravity(latitude_deg, height_m)`.
        Put your own place here.
    '''),
    code('''
        LATITUDE_DEG, HEIGHT_M = 48.0, 200.0      # where you measured: latitude, degrees north; height, m
        g_here = pt.normal_gravity(LATITUDE_DEG, HEIGHT_M)
        print(f"normal gravity at {LATITUDE_DEG}°, {HEIGHT_M} m: {g_here:.4f} m/s²")
        print(f"measured - normal = {g_all - g_here:+.3f} m/s², {(g_all - g_here) / g_total_se:+.1f} standard errors")
    '''),
    md('''
        ## 4. Questions

        **Question (before).** You have a tape read to 1 mm and a stopwatch. Which lengths would you
        choose, and how many periods would you time at each, to measure $g$ to 0.5 %?

        **Question (after).** Print `1000 * from_length` (ms): the part of each period's uncertainty
        that comes from its length. Why is it larger for the short pendulum than for the long one?
        Against the period's own 5 ms, is it worth a better tape or a better stopwatch?

        **Question (during).** Why time 20 periods rather than one? Why start and stop the watch as the
        bob passes the lowest point rather than at a turning point?

        **Question (after).** The fit found $\\delta$. What did you expect it to be, from how you
        measured the lengths? Is the fitted value within two standard errors of that?

        **Question (after).** Every swing here was under 5°. At 5° the period is 0.05 % longer than
        $T_0$. Had it been left in, by how much would $g$ be wrong, and in which direction? (A column
        `amplitude_deg` in the file lets the fit correct each period by the exact law.)

        **Question (after).** Put
        `DATA = "../../crates/pendulum-cli/tests/data/period/hidayat2023.csv"` (a published table,
        R. Hidayat et al. 2023, with no uncertainties) in the first cell and run section 1 again. With
        no uncertainties the standard errors come from the scatter alone. What does the offset say
        about the 6 cm ball? (Section 2 needs `period_err_s`: it stops there.)

        ## The same with the command line

        From the repository's top folder:

        ```sh
        pendulum fit period examples/notebooks/lengths.csv --json
        pendulum fit period crates/pendulum-cli/tests/data/period/hidayat2023.csv
        ```

        The command line fits with the periods' uncertainties (section 1); the lengths' it does not
        take: write the combined uncertainty of section 2 into the file's `period_err_s` column to
        fit it there.

        ## Key figures
    '''),
    code('''
        KEY = {
            "g_m_s2": p["g_m_s2"],
            "g_standard_error_m_s2": se["g_m_s2"],
            "length_offset_m": p["length_offset_m"],
            "length_offset_standard_error_m": se["length_offset_m"],
            "chi_square": r.get("chi_square"),
            "g_lengths_carried_m_s2": g_all,
            "g_lengths_carried_standard_error_m_s2": g_all_se,
            "g_total_standard_error_m_s2": g_total_se,
        }
        KEY
    '''),
]

NOTEBOOKS = {
    "large-amplitude.ipynb": LARGE,
    "damping.ipynb": DAMPING,
    "g-from-lengths.ipynb": LENGTHS,
}


def cell_id(stem, kind, source, taken):
    """A cell id that stays put when other cells are added or edited
    below their first line: the notebook's name and a hash of the cell's
    first line."""
    first = source.split("\n", 1)[0]
    base = f"{stem}-{hashlib.sha1((kind + first).encode()).hexdigest()[:8]}"
    ident, n = base, 1
    while ident in taken:
        n += 1
        ident = f"{base}-{n}"
    taken.add(ident)
    return ident


def notebook(name, cells):
    stem = re.sub(r"[^a-z0-9]+", "-", name.removesuffix(".ipynb"))
    taken = set()
    out = []
    for kind, source in cells:
        cell = {
            "cell_type": kind,
            "id": cell_id(stem, kind, source, taken),
            "metadata": {},
            "source": source.splitlines(keepends=True),
        }
        if kind == "code":
            cell["execution_count"] = None
            cell["outputs"] = []
        out.append(cell)
    nb = {
        "cells": out,
        "metadata": {
            "kernelspec": {
                "display_name": "Python 3 (ipykernel)",
                "language": "python",
                "name": "python3",
            },
            "language_info": {"name": "python"},
        },
        "nbformat": 4,
        "nbformat_minor": 5,
    }
    return json.dumps(nb, indent=1, sort_keys=True, ensure_ascii=False) + "\n"


def stale():
    """The notebooks that are not what this file writes."""
    return [name for name, cells in NOTEBOOKS.items()
            if not (HERE / name).exists()
            or (HERE / name).read_text(encoding="utf-8") != notebook(name, cells)]


def main(argv):
    if "--check" in argv:
        names = stale()
        for name in names:
            print(f"{name}: not what make.py writes: run python examples/notebooks/make.py",
                  file=sys.stderr)
        return 1 if names else 0
    for name, cells in NOTEBOOKS.items():
        text = notebook(name, cells)
        try:
            import nbformat
        except ImportError:
            pass
        else:
            nbformat.validate(nbformat.reads(text, as_version=4))
        (HERE / name).write_text(text, encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
