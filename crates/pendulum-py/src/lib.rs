//! Python bindings of `pendulum-theory`: glue only. Each function takes
//! `float64` arrays of one shape (the Python package `pendulum_theory`
//! broadcasts them as views, so a scalar costs nothing), computes without
//! the GIL (on every core for large arrays) and returns a new array. An
//! input the library refuses raises `ValueError` with the library's
//! message.

use ndarray::{ArrayD, Zip};
use numpy::{IntoPyArray, PyArrayDyn, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pendulum_theory::analysis::Refusal;
use pendulum_theory::damped::DampedPendulum;
use pendulum_theory::damping::Damping;
use pendulum_theory::elliptic::{ellipe as ellipe_m, ellipk as ellipk_m, jacobi};
use pendulum_theory::error::InputError;
use pendulum_theory::exact::ExactSwing;
use pendulum_theory::period::{
    amplitude_for_period as theory_amplitude, circular_error, length_for_period,
};
use pendulum_theory::simulation;
use pendulum_theory::{Amplitude, Pendulum};
use pyo3::exceptions::{PyMemoryError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::sync::atomic::{AtomicBool, Ordering};

/// Seconds in a day.
const DAY: f64 = 86_400.0;

type Array<'py> = Bound<'py, PyArrayDyn<f64>>;
type Array1<'py> = Bound<'py, numpy::PyArray1<f64>>;
type In<'py> = PyReadonlyArrayDyn<'py, f64>;

/// Arrays this long and longer are computed on every core.
const PARALLEL_FROM: usize = 1 << 14;

/// Applies `f` elementwise over arrays of one shape (numpy's broadcast
/// views, strides of zero included: nothing is copied), without the GIL,
/// on every core for large arrays. A value `f` refuses is NaN in that
/// pass; if any was, a second pass in order finds the first refusal and
/// raises it as `ValueError` with the library's message.
macro_rules! elementwise {
    ($py:expr, [$x0:ident $(, $x:ident)*], $f:expr) => {{
        let f = $f;
        let $x0 = $x0.as_array();
        $(let $x = $x.as_array();)*
        if false $(|| $x.shape() != $x0.shape())* {
            return Err(PyValueError::new_err("arrays must have one shape"));
        }
        // An allocation the system refuses is MemoryError, not an abort.
        let n = $x0.len();
        let mut storage: Vec<f64> = Vec::new();
        if storage.try_reserve_exact(n).is_err() {
            return Err(PyMemoryError::new_err(format!(
                "{n} results do not fit in memory"
            )));
        }
        storage.resize(n, 0.0);
        let mut out = ArrayD::<f64>::from_shape_vec($x0.raw_dim(), storage)
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        let failed = AtomicBool::new(false);
        let parallel = out.len() >= PARALLEL_FROM;
        $py.detach(|| {
            let zip = Zip::from(&mut out).and(&$x0)$(.and(&$x))*;
            let each = |o: &mut f64, $x0: &f64 $(, $x: &f64)*| {
                *o = match f(*$x0 $(, *$x)*) {
                    Ok(v) => v,
                    Err(_) => {
                        failed.store(true, Ordering::Relaxed);
                        f64::NAN
                    }
                }
            };
            if parallel {
                zip.par_for_each(each);
            } else {
                zip.for_each(each);
            }
        });
        if failed.load(Ordering::Relaxed) {
            let mut message: Option<String> = None;
            Zip::from(&$x0)$(.and(&$x))*.for_each(|$x0: &f64 $(, $x: &f64)*| {
                if message.is_none() {
                    if let Err(e) = f(*$x0 $(, *$x)*) {
                        message = Some(e.to_string());
                    }
                }
            });
            return Err(PyValueError::new_err(message.unwrap_or_default()));
        }
        PyResult::Ok(out.into_pyarray($py))
    }};
}

/// A function that cannot fail.
fn always(v: f64) -> Result<f64, InputError> {
    Ok(v)
}

#[pyfunction]
fn ellipk<'py>(py: Python<'py>, m: In<'py>) -> PyResult<Array<'py>> {
    elementwise!(py, [m], |m: f64| always(ellipk_m(m)))
}

#[pyfunction]
fn ellipe<'py>(py: Python<'py>, m: In<'py>) -> PyResult<Array<'py>> {
    elementwise!(py, [m], |m: f64| always(ellipe_m(m)))
}

/// am(u) from sn and cn: atan2(sn, cn) continued through its branches (am
/// - π u/(2K) stays within (-π/2, π/2)); gd(u) at m = 1.
fn amplitude_of(u: f64, m: f64, sn: f64, cn: f64) -> f64 {
    let linear = std::f64::consts::PI * u / (2.0 * ellipk_m(m));
    let principal = sn.atan2(cn);
    if linear.is_finite() {
        principal + std::f64::consts::TAU * ((linear - principal) / std::f64::consts::TAU).round()
    } else {
        principal
    }
}

/// sn, cn, dn and the amplitude φ = am(u), as SciPy's `ellipj`.
#[pyfunction]
fn ellipj<'py>(
    py: Python<'py>,
    u: In<'py>,
    m: In<'py>,
) -> PyResult<(Array<'py>, Array<'py>, Array<'py>, Array<'py>)> {
    let sn = {
        let (u, m) = (u.clone(), m.clone());
        elementwise!(py, [u, m], |u: f64, m: f64| always(jacobi(u, m).sn))?
    };
    let cn = {
        let (u, m) = (u.clone(), m.clone());
        elementwise!(py, [u, m], |u: f64, m: f64| always(jacobi(u, m).cn))?
    };
    let dn = {
        let (u, m) = (u.clone(), m.clone());
        elementwise!(py, [u, m], |u: f64, m: f64| always(jacobi(u, m).dn))?
    };
    let ph = elementwise!(py, [u, m], |u: f64, m: f64| {
        let v = jacobi(u, m);
        always(amplitude_of(u, m, v.sn, v.cn))
    })?;
    Ok((sn, cn, dn, ph))
}

#[pyfunction]
#[pyo3(name = "period")]
fn period_of<'py>(
    py: Python<'py>,
    length: In<'py>,
    amplitude: In<'py>,
    g: In<'py>,
) -> PyResult<Array<'py>> {
    elementwise!(py, [length, amplitude, g], |l: f64, a: f64, g: f64| {
        Ok::<_, InputError>(Pendulum::new(l, g)?.period(Amplitude::from_radians(a)?))
    })
}

#[pyfunction]
fn circular_error_s_per_day<'py>(py: Python<'py>, amplitude: In<'py>) -> PyResult<Array<'py>> {
    elementwise!(py, [amplitude], |a: f64| {
        Ok::<_, InputError>(DAY * circular_error(Amplitude::from_radians(a)?))
    })
}

#[pyfunction]
#[pyo3(name = "length_for_period")]
fn length_of<'py>(
    py: Python<'py>,
    period: In<'py>,
    amplitude: In<'py>,
    g: In<'py>,
) -> PyResult<Array<'py>> {
    elementwise!(py, [period, amplitude, g], |t: f64, a: f64, g: f64| {
        length_for_period(t, Amplitude::from_radians(a)?, g)
    })
}

#[pyfunction]
fn amplitude_for_period<'py>(
    py: Python<'py>,
    period: In<'py>,
    length: In<'py>,
    g: In<'py>,
) -> PyResult<Array<'py>> {
    elementwise!(py, [period, length, g], |t: f64, l: f64, g: f64| {
        Ok::<_, InputError>(
            theory_amplitude(&Pendulum::new(l, g)?, t)?
                .amplitude
                .radians(),
        )
    })
}

#[pyfunction]
fn normal_gravity<'py>(
    py: Python<'py>,
    latitude: In<'py>,
    height: In<'py>,
) -> PyResult<Array<'py>> {
    elementwise!(
        py,
        [latitude, height],
        pendulum_theory::gravity::normal_gravity
    )
}

/// One damping description to another: `what` names the input and `to`
/// the output, each `zeta`, `q` or `log_decrement`.
#[pyfunction]
fn damping<'py>(py: Python<'py>, value: In<'py>, what: &str, to: &str) -> PyResult<Array<'py>> {
    let from: fn(f64) -> Result<Damping, InputError> = match what {
        "zeta" => Damping::from_zeta,
        "q" => Damping::from_q,
        "log_decrement" => Damping::from_log_decrement,
        _ => return Err(PyValueError::new_err(format!("unknown damping '{what}'"))),
    };
    let into: fn(&Damping) -> f64 = match to {
        "zeta" => |d| d.zeta(),
        "q" => |d| d.q_factor(),
        "log_decrement" => |d| d.log_decrement().unwrap_or(f64::NAN),
        _ => return Err(PyValueError::new_err(format!("unknown damping '{to}'"))),
    };
    elementwise!(py, [value], |v: f64| from(v).map(|d| into(&d)))
}

/// The decay time of the amplitude, s.
#[pyfunction]
fn decay_time<'py>(
    py: Python<'py>,
    zeta: In<'py>,
    length: In<'py>,
    g: In<'py>,
) -> PyResult<Array<'py>> {
    elementwise!(py, [zeta, length, g], |z: f64, l: f64, g: f64| {
        Ok::<_, InputError>(Damping::from_zeta(z)?.decay_time(&Pendulum::new(l, g)?))
    })
}

/// θ(t) of section 1-4's damped linear pendulum released from rest.
#[pyfunction]
fn damped_angle<'py>(
    py: Python<'py>,
    t: In<'py>,
    length: In<'py>,
    amplitude: In<'py>,
    zeta: In<'py>,
    g: In<'py>,
) -> PyResult<Array<'py>> {
    elementwise!(
        py,
        [t, length, amplitude, zeta, g],
        |t: f64, l: f64, a: f64, z: f64, g: f64| {
            let d = DampedPendulum::new(Pendulum::new(l, g)?, Damping::from_zeta(z)?);
            Ok::<_, InputError>(d.state_at(a, 0.0, t).angle)
        }
    )
}

/// θ(t) of the exact undamped pendulum released from rest (Jacobi form).
#[pyfunction]
fn exact_angle<'py>(
    py: Python<'py>,
    t: In<'py>,
    length: In<'py>,
    amplitude: In<'py>,
    g: In<'py>,
) -> PyResult<Array<'py>> {
    elementwise!(
        py,
        [t, length, amplitude, g],
        |t: f64, l: f64, a: f64, g: f64| {
            let swing = ExactSwing::new(&Pendulum::new(l, g)?, Amplitude::from_radians(a)?);
            Ok::<_, InputError>(swing.state_at_jacobi(t).angle)
        }
    )
}

/// Collects the turning points of a run: time, signed angle, and the rate
/// a clock would keep at that half swing.
struct Turns {
    pendulum: Pendulum,
    time: Vec<f64>,
    angle: Vec<f64>,
    rate: Vec<f64>,
}

impl simulation::Observer for Turns {
    fn turning_point(&mut self, p: &simulation::TurningPoint) -> simulation::Action {
        let rate = match self.time.last() {
            Some(&previous) => simulation::half_swing_rate(&self.pendulum, p.time - previous),
            None => f64::NAN,
        };
        self.time.push(p.time);
        self.angle.push(p.angle);
        self.rate.push(rate);
        simulation::Action::Continue
    }
}

/// The full nonlinear damped pendulum released from rest (the CLI's
/// `simulate`, the same library call): every turning point's time, signed
/// angle and rate (NaN at the release), and the summary as JSON.
#[pyfunction]
#[pyo3(signature = (length, amplitude, duration, damping, quadratic_drag, friction_angle, g, method, tolerance, force))]
#[allow(clippy::too_many_arguments, clippy::type_complexity)]
fn simulate<'py>(
    py: Python<'py>,
    length: f64,
    amplitude: f64,
    duration: f64,
    damping: Option<(String, f64)>,
    quadratic_drag: Option<f64>,
    friction_angle: Option<f64>,
    g: Option<f64>,
    method: Option<String>,
    tolerance: Option<f64>,
    force: bool,
) -> PyResult<(Array1<'py>, Array1<'py>, Array1<'py>, String)> {
    use simulation::analysis::{damping_of, prepare, SimulationInput};
    let refused = |r: Refusal| PyValueError::new_err(r.to_string());
    let damping = damping
        .map(|(field, value)| damping_of(&field, value))
        .transpose()
        .map_err(refused)?;
    let prepared = prepare(&SimulationInput {
        length,
        g,
        amplitude,
        duration,
        damping,
        quadratic_drag,
        friction_angle,
        method,
        tolerance,
        sample_interval: None,
        force,
    })
    .map_err(refused)?;
    let mut turns = Turns {
        pendulum: prepared.model.pendulum,
        time: Vec::new(),
        angle: Vec::new(),
        rate: Vec::new(),
    };
    let summary = answer(py.detach(|| prepared.run(&mut turns)))?;
    Ok((
        turns.time.into_pyarray(py),
        turns.angle.into_pyarray(py),
        turns.rate.into_pyarray(py),
        summary,
    ))
}

/// The contiguous values of a one-dimensional array.
fn values<'a>(a: &'a PyReadonlyArrayDyn<'_, f64>, name: &str) -> PyResult<&'a [f64]> {
    if a.ndim() != 1 {
        return Err(PyValueError::new_err(format!(
            "{name}: must be one-dimensional"
        )));
    }
    a.as_slice()
        .map_err(|_| PyValueError::new_err(format!("{name}: must be contiguous")))
}

/// The library's result as JSON (the command line's `--json`, key for key
/// and bit for bit), or its refusal as `ValueError`.
fn answer<T: serde::Serialize>(result: Result<T, Refusal>) -> PyResult<String> {
    let value = result.map_err(|r| PyValueError::new_err(r.to_string()))?;
    serde_json::to_string(&value).map_err(|e| PyValueError::new_err(e.to_string()))
}

/// The run-down analysis (the CLI's `fit decay`) as JSON.
#[pyfunction]
#[pyo3(signature = (time, amplitude, model, period, length, g, mass, force))]
#[allow(clippy::too_many_arguments)]
fn fit_decay(
    py: Python<'_>,
    time: In<'_>,
    amplitude: In<'_>,
    model: Option<&str>,
    period: Option<f64>,
    length: Option<f64>,
    g: Option<f64>,
    mass: Option<f64>,
    force: bool,
) -> PyResult<String> {
    use pendulum_theory::fitting::rundown::{analyse, RunDownInput};
    let (time, amplitude) = (values(&time, "time")?, values(&amplitude, "amplitude")?);
    answer(py.detach(|| {
        analyse(&RunDownInput {
            time,
            amplitude,
            model,
            period,
            turning_half_period: None,
            length,
            g,
            mass,
            force,
        })
    }))
}

/// The beat-log analysis (the CLI's `fit beats`) as JSON.
#[pyfunction]
#[pyo3(signature = (time, bph, period))]
fn fit_beats(
    py: Python<'_>,
    time: In<'_>,
    bph: Option<f64>,
    period: Option<f64>,
) -> PyResult<String> {
    use pendulum_theory::fitting::beat_log::{analyse, Nominal};
    let time = values(&time, "time")?;
    let nominal = match (bph, period) {
        (Some(_), Some(_)) => return Err(PyValueError::new_err("give bph or period, not both")),
        (Some(b), None) => Some(Nominal::BeatsPerHour(b)),
        (None, Some(p)) => Some(Nominal::Period(p)),
        (None, None) => None,
    };
    answer(py.detach(|| analyse(time, nominal)))
}

/// The tracked-swing analysis (the CLI's `fit trajectory`) as JSON.
#[pyfunction]
#[pyo3(signature = (time, angle, model, length, force))]
fn fit_trajectory(
    py: Python<'_>,
    time: In<'_>,
    angle: In<'_>,
    model: Option<&str>,
    length: Option<f64>,
    force: bool,
) -> PyResult<String> {
    use pendulum_theory::fitting::tracked::{analyse, LengthSource, TrackInput};
    let (time, angle) = (values(&time, "time")?, values(&angle, "angle")?);
    answer(py.detach(|| {
        analyse(&TrackInput {
            time,
            angle,
            model,
            length: length.map(|l| (l, LengthSource::Given)),
            force,
        })
    }))
}

/// A clock's description as the Python package passes it: length, g,
/// mass, q, escapement, lift angle, drive torque, drive energy, friction,
/// recoil, impulse angle, beats between a free pendulum's impulses.
type ClockArgs = (
    f64,
    f64,
    f64,
    f64,
    String,
    f64,
    Option<f64>,
    Option<f64>,
    f64,
    f64,
    f64,
    u64,
);

/// A clock from its description (see `pendulum_theory.clock`).
fn make_clock(args: ClockArgs) -> PyResult<pendulum_theory::clock::Clock> {
    let (
        length,
        g,
        mass,
        q,
        escapement,
        lift_angle,
        drive_torque,
        drive_energy,
        friction,
        recoil,
        impulse_angle,
        every_beats,
    ) = args;
    let escapement = escapement.as_str();
    use pendulum_theory::clock::escapement::spec::{Drive, Kind, Spec};
    let error = |e: &dyn std::fmt::Display| PyValueError::new_err(e.to_string());
    let pendulum = Pendulum::new(length, g).map_err(|e| error(&e))?;
    if !(mass > 0.0 && mass.is_finite()) {
        return Err(PyValueError::new_err(format!(
            "mass: must be positive, got {mass} kg"
        )));
    }
    if !(q > 0.5 && q.is_finite()) {
        return Err(PyValueError::new_err(format!(
            "q: must exceed 0.5 (an underdamped pendulum), got {q}"
        )));
    }
    let kind = Kind::from_name(escapement).ok_or_else(|| {
        PyValueError::new_err(format!(
            "escapement: '{escapement}' is not one of impulse, deadbeat, recoil, constant-force, free"
        ))
    })?;
    let drive = match (drive_torque, drive_energy) {
        (Some(t), None) => Drive::Torque(t),
        (None, Some(e)) => Drive::Energy(e),
        _ => {
            return Err(PyValueError::new_err(
                "drive: give drive_torque (N m) or drive_energy (J per beat), one of them",
            ))
        }
    };
    let scale = mass * g * length;
    let spec = Spec {
        kind,
        lift: lift_angle,
        drive,
        friction,
        recoil,
        angle: impulse_angle,
        every: every_beats,
    };
    Ok(pendulum_theory::clock::Clock {
        pendulum,
        q,
        escapement: spec.build(scale).map_err(|e| error(&e))?,
        torque_scale: scale,
    })
}

/// The steady states of a clock at each drive factor (the CLI's `clock`
/// and its isochronism curve): one dict per factor with the CLI's keys, or
/// `{"drive_factor": f, "stops": True}`.
#[pyfunction]
fn clock_steady<'py>(
    py: Python<'py>,
    spec: ClockArgs,
    factors: Vec<f64>,
) -> PyResult<Vec<Bound<'py, PyDict>>> {
    use pendulum_theory::clock::{ClockError, HalfSwingMethod};
    let clock = make_clock(spec)?;
    let results: Vec<_> = py.detach(|| {
        factors
            .iter()
            .map(|&f| clock.steady(HalfSwingMethod::Direct, f))
            .collect()
    });
    let mut out = Vec::new();
    for (f, r) in factors.iter().zip(results) {
        let d = PyDict::new(py);
        d.set_item("drive_factor", *f)?;
        match r {
            Ok(s) => {
                d.set_item("stops", false)?;
                d.set_item("amplitude_rad", s.amplitude)?;
                d.set_item("period_s", s.period)?;
                d.set_item("free_period_s", s.free_period)?;
                d.set_item("small_angle_period_s", s.small_angle_period)?;
                d.set_item("rate_s_per_day", s.rate)?;
                d.set_item("circular_rate_s_per_day", s.circular_rate)?;
                d.set_item("circular_error_s_per_day", -s.circular_rate)?;
                d.set_item("escapement_rate_s_per_day", s.escapement_rate)?;
                d.set_item(
                    "escapement_rate_airy_s_per_day",
                    s.escapement_rate_first_order,
                )?;
                d.set_item("energy_per_beat_j", s.energy_per_beat)?;
                d.set_item("power_w", s.power)?;
            }
            // One drive that stops the clock is an error; on a curve, a point.
            Err(e @ ClockError::Stops { .. }) if factors.len() == 1 => {
                return Err(PyValueError::new_err(format!("drive: {e}")))
            }
            Err(ClockError::Stops { .. }) => d.set_item("stops", true)?,
            Err(e) => return Err(PyValueError::new_err(format!("drive: {e}"))),
        }
        out.push(d);
    }
    Ok(out)
}

/// A long run of a clock (the CLI's `clock --duration`): rows at every
/// turning point or every `every` s, the drive factor from a schedule
/// (times, factors; linear between, held beyond) and a rate change from
/// outside (times, s/day: a temperature or pressure coefficient times the
/// change), against the clock as regulated at the start.
#[pyfunction]
#[pyo3(signature = (spec, duration, every, schedule_time, schedule_factor, rate_time, rate_change, force))]
#[allow(clippy::type_complexity, clippy::too_many_arguments)]
fn clock_run<'py>(
    py: Python<'py>,
    spec: ClockArgs,
    duration: f64,
    every: Option<f64>,
    schedule_time: Vec<f64>,
    schedule_factor: Vec<f64>,
    rate_time: Vec<f64>,
    rate_change: Vec<f64>,
    force: bool,
) -> PyResult<(Vec<Array1<'py>>, Bound<'py, PyDict>)> {
    use pendulum_theory::clock::long_run::{period_factor, piecewise_linear, run, LongRun};
    use pendulum_theory::clock::plan::{check_schedule, plan_run, MAX_RATE_S_PER_DAY};
    use pendulum_theory::clock::HalfSwingMethod;
    let clock = make_clock(spec)?;
    let refused = |r: Refusal| PyValueError::new_err(r.to_string());
    check_schedule(
        "drive_schedule",
        &schedule_time,
        &schedule_factor,
        0.0..=f64::MAX,
        "a drive factor of at least 0",
    )
    .map_err(refused)?;
    check_schedule(
        "rate_schedule",
        &rate_time,
        &rate_change,
        -MAX_RATE_S_PER_DAY..=MAX_RATE_S_PER_DAY,
        "a rate change within a day per day (86400 s/day)",
    )
    .map_err(refused)?;
    let drive = |t: f64| piecewise_linear(&schedule_time, &schedule_factor, t);
    let stretch = |t: f64| {
        if rate_time.is_empty() {
            1.0
        } else {
            period_factor(piecewise_linear(&rate_time, &rate_change, t))
        }
    };
    let start = clock
        .steady(HalfSwingMethod::Averaged, drive(0.0))
        .map_err(|e| PyValueError::new_err(format!("drive: {e}")))?;
    plan_run(&clock, start.period, duration, every, force).map_err(refused)?;
    let mut columns: [Vec<f64>; 6] = Default::default();
    let finish = py.detach(|| {
        run(
            &clock,
            &drive,
            &stretch,
            &LongRun::from_steady(&start, duration, every),
            &mut |r| {
                for (c, v) in columns.iter_mut().zip([
                    r.time,
                    r.beats as f64,
                    r.amplitude,
                    r.rate,
                    r.time_error,
                    r.drive,
                ]) {
                    c.push(v);
                }
                true
            },
        )
    });
    match finish.ending {
        pendulum_theory::clock::long_run::Ending::OverTheTop => {
            return Err(PyValueError::new_err(format!(
                "drive_schedule: {} days into the run the drive ({} × the given) carries the \
                 pendulum over the top; give less drive",
                finish.last.time / 86_400.0,
                finish.last.drive
            )))
        }
        pendulum_theory::clock::long_run::Ending::RateOutOfRange => {
            return Err(PyValueError::new_err(format!(
                "rate_schedule: {} days into the run the rate moves by a day per day or more: \
                 no clock runs so",
                finish.last.time / 86_400.0
            )))
        }
        _ => {}
    }
    let summary = PyDict::new(py);
    summary.set_item("duration_s", finish.last.time)?;
    summary.set_item("beats", finish.last.beats)?;
    summary.set_item("final_amplitude_rad", finish.last.amplitude)?;
    summary.set_item("final_rate_s_per_day", finish.last.rate)?;
    summary.set_item("time_error_s", finish.last.time_error)?;
    summary.set_item("stopped", finish.stopped)?;
    summary.set_item("ending", finish.ending.name())?;
    summary.set_item("nominal_period_s", start.period)?;
    Ok((
        columns.into_iter().map(|c| c.into_pyarray(py)).collect(),
        summary,
    ))
}

/// The extension module behind the `pendulum_theory` package.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(ellipk, m)?)?;
    m.add_function(wrap_pyfunction!(ellipe, m)?)?;
    m.add_function(wrap_pyfunction!(ellipj, m)?)?;
    m.add_function(wrap_pyfunction!(period_of, m)?)?;
    m.add_function(wrap_pyfunction!(circular_error_s_per_day, m)?)?;
    m.add_function(wrap_pyfunction!(length_of, m)?)?;
    m.add_function(wrap_pyfunction!(amplitude_for_period, m)?)?;
    m.add_function(wrap_pyfunction!(normal_gravity, m)?)?;
    m.add_function(wrap_pyfunction!(damping, m)?)?;
    m.add_function(wrap_pyfunction!(decay_time, m)?)?;
    m.add_function(wrap_pyfunction!(damped_angle, m)?)?;
    m.add_function(wrap_pyfunction!(exact_angle, m)?)?;
    m.add_function(wrap_pyfunction!(simulate, m)?)?;
    m.add_function(wrap_pyfunction!(fit_decay, m)?)?;
    m.add_function(wrap_pyfunction!(fit_beats, m)?)?;
    m.add_function(wrap_pyfunction!(fit_trajectory, m)?)?;
    m.add_function(wrap_pyfunction!(clock_steady, m)?)?;
    m.add_function(wrap_pyfunction!(clock_run, m)?)?;
    Ok(())
}
