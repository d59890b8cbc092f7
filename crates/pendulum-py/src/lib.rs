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
use pendulum_theory::period::SECONDS_PER_DAY as DAY;
use pendulum_theory::period::{
    amplitude_for_period as theory_amplitude, circular_error, length_for_period,
};
use pendulum_theory::simulation;
use pendulum_theory::{Amplitude, Pendulum};
use pyo3::exceptions::{PyMemoryError, PyValueError};
use pyo3::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};

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

/// The damping given as `(form, value)`, read by the library (a form it
/// does not know is its `ValueError`).
fn given_damping(
    damping: Option<(String, f64)>,
) -> PyResult<Option<pendulum_theory::damped::analysis::DampingGiven>> {
    damping
        .map(|(f, v)| pendulum_theory::damped::analysis::DampingGiven::parse(&f, v))
        .transpose()
        .map_err(refusal)
}

/// A library refusal as Python's `ValueError`, in the library's words.
fn refusal(r: Refusal) -> PyErr {
    PyValueError::new_err(r.to_string())
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
#[pyo3(signature = (length, amplitude, duration, damping, quadratic_drag, friction_angle, drag, g, method, tolerance, force))]
#[allow(clippy::too_many_arguments, clippy::type_complexity)]
fn simulate<'py>(
    py: Python<'py>,
    length: f64,
    amplitude: f64,
    duration: f64,
    damping: Option<(String, f64)>,
    quadratic_drag: Option<f64>,
    friction_angle: Option<f64>,
    drag: Vec<(String, f64)>,
    g: Option<f64>,
    method: Option<String>,
    tolerance: Option<f64>,
    force: bool,
) -> PyResult<(Array1<'py>, Array1<'py>, Array1<'py>, String)> {
    use simulation::analysis::{damping_of, method_of, parse_drag_law, prepare, SimulationInput};
    let damping = damping
        .map(|(field, value)| damping_of(&field, value))
        .transpose()
        .map_err(refusal)?;
    let drag = drag
        .iter()
        .map(|(name, k)| Ok((parse_drag_law(name)?, *k)))
        .collect::<Result<Vec<_>, Refusal>>()
        .map_err(refusal)?;
    let method = method
        .as_deref()
        .map(method_of)
        .transpose()
        .map_err(refusal)?;
    let prepared = prepare(&SimulationInput {
        length,
        g,
        amplitude,
        duration,
        damping,
        quadratic_drag,
        friction_angle,
        drag,
        method,
        tolerance,
        sample_interval: None,
        force,
        elastic_share: None,
    })
    .map_err(refusal)?;
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

/// A count from Python (a 64-bit integer) in the library's type: out of
/// its range it is its nearest end, which the library refuses by name.
fn count<T: TryFrom<i64> + num_bounds::Bounded>(n: i64) -> T {
    T::try_from(n).unwrap_or(if n < 0 {
        T::min_value()
    } else {
        T::max_value()
    })
}

/// The bounds of the integer types counts come in.
mod num_bounds {
    /// An integer type's least and greatest values.
    pub trait Bounded {
        /// The least.
        fn min_value() -> Self;
        /// The greatest.
        fn max_value() -> Self;
    }
    macro_rules! bounded {
        ($($t:ty),*) => {$(impl Bounded for $t {
            fn min_value() -> Self { <$t>::MIN }
            fn max_value() -> Self { <$t>::MAX }
        })*};
    }
    bounded!(u32, u64, usize);
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

/// The stability analysis (the CLI's `stability`) as JSON.
#[pyfunction]
#[pyo3(signature = (data, tau0, kind, all_taus, force, outliers))]
fn stability(
    py: Python<'_>,
    data: In<'_>,
    tau0: f64,
    kind: &str,
    all_taus: bool,
    force: bool,
    outliers: &str,
) -> PyResult<String> {
    use pendulum_theory::stability::{stability, DataKind, Outliers, StabilityInput, Taus};
    let kind = match kind {
        "phase" => DataKind::Phase,
        "frequency" => DataKind::Frequency,
        other => {
            return Err(PyValueError::new_err(format!(
                "kind: must be 'phase' or 'frequency', got '{other}'"
            )))
        }
    };
    let input = StabilityInput {
        data: values(&data, "data")?.to_vec(),
        kind,
        tau0_s: tau0,
        taus: if all_taus { Taus::All } else { Taus::Octave },
        force,
        outliers: match outliers {
            "keep" => Outliers::Keep,
            "remove" => Outliers::Remove,
            other => {
                return Err(PyValueError::new_err(format!(
                    "outliers: must be 'keep' or 'remove', got '{other}'"
                )))
            }
        },
    };
    answer(py.detach(|| stability(&input)))
}

/// The body tide (the CLI's `tide`) at Unix times, as JSON rows; times
/// whose work is more than a few seconds need `force`.
#[pyfunction]
#[pyo3(signature = (latitude, longitude, time, height, force))]
fn tide(
    py: Python<'_>,
    latitude: f64,
    longitude: f64,
    time: In<'_>,
    height: f64,
    force: bool,
) -> PyResult<String> {
    use pendulum_theory::tide::{at, Station};
    let station = Station {
        latitude_deg: latitude,
        longitude_deg: longitude,
        height_m: height,
    };
    let time = values(&time, "time")?;
    answer(py.detach(|| at(station, time, force)))
}

/// The clock-log analysis (the CLI's `log`) as JSON.
#[pyfunction]
#[pyo3(signature = (time, values_, kind, temperature, pressure, humidity, amplitude, pulse_width, flag_width, gate_radius, epoch, latitude, longitude, height, tides, events, bin, beat, bph, period, force, stability, wheels, pinions, arbor_turns_per_hour, length, parts, nut_pitch, nut_tpi, nut_divisions))]
#[allow(clippy::too_many_arguments)]
fn clock_log(
    py: Python<'_>,
    time: In<'_>,
    values_: In<'_>,
    kind: &str,
    temperature: Option<In<'_>>,
    pressure: Option<In<'_>>,
    humidity: Option<In<'_>>,
    amplitude: Option<In<'_>>,
    pulse_width: Option<In<'_>>,
    flag_width: Option<f64>,
    gate_radius: Option<f64>,
    epoch: Option<f64>,
    latitude: Option<f64>,
    longitude: Option<f64>,
    height: f64,
    tides: bool,
    events: Option<In<'_>>,
    bin: Option<f64>,
    beat: Option<f64>,
    bph: Option<f64>,
    period: Option<f64>,
    force: bool,
    stability: bool,
    wheels: Option<Vec<i64>>,
    pinions: Option<Vec<i64>>,
    arbor_turns_per_hour: Option<f64>,
    length: Option<f64>,
    parts: Option<&str>,
    nut_pitch: Option<f64>,
    nut_tpi: Option<f64>,
    nut_divisions: Option<i64>,
) -> PyResult<String> {
    use pendulum_theory::clock_log::{analyse, LogColumn, LogInput, LogKind, TrainInput};
    let known = known_of(length, parts, nut_pitch, nut_tpi, nut_divisions, None, None)?;
    use pendulum_theory::tide::Station;
    let kind = match kind {
        "offset" => LogKind::Offset,
        "rate" => LogKind::Rate,
        "half_periods" => LogKind::HalfPeriods,
        other => {
            return Err(PyValueError::new_err(format!(
                "kind: must be 'offset', 'rate' or 'half_periods', got '{other}'"
            )))
        }
    };
    let owned = |a: &Option<In<'_>>, name: &str| -> PyResult<Option<Vec<f64>>> {
        a.as_ref()
            .map(|a| values(a, name).map(<[f64]>::to_vec))
            .transpose()
    };
    let station = match (latitude, longitude) {
        (Some(lat), Some(lon)) => Some(Station {
            latitude_deg: lat,
            longitude_deg: lon,
            height_m: height,
        }),
        _ => None,
    };
    let input = LogInput {
        time_s: values(&time, "time")?.to_vec(),
        epoch_unix_s: epoch,
        kind: Some(kind),
        values: values(&values_, "values")?.to_vec(),
        // The keywords' units (°C, hPa, %, degrees) to the library's SI.
        columns: [
            ("temperature", owned(&temperature, "temperature")?, 1.0),
            ("pressure", owned(&pressure, "pressure")?, 100.0),
            ("humidity", owned(&humidity, "humidity")?, 1.0),
            (
                "amplitude",
                owned(&amplitude, "amplitude")?,
                1f64.to_radians(),
            ),
        ]
        .into_iter()
        .filter_map(|(name, v, scale)| {
            v.map(|v| LogColumn::new(name, v.iter().map(|x| x * scale).collect()))
        })
        .collect(),
        pulse_width_s: owned(&pulse_width, "pulse_width")?,
        flag_width_m: flag_width,
        gate_radius_m: gate_radius,
        nominal: nominal_of(bph, period)?,
        beat_s: beat,
        station,
        tides,
        events_s: owned(&events, "events")?.unwrap_or_default(),
        bin_s: bin,
        design: None,
        force,
        skip_stability: !stability,
        // A count that is not a positive u32 becomes 0, which the library
        // refuses by name.
        train: wheels.map(|w| {
            let counts = |c: &[i64]| -> Vec<u32> {
                c.iter().map(|&x| u32::try_from(x).unwrap_or(0)).collect()
            };
            TrainInput {
                wheels: counts(&w),
                pinions: counts(pinions.as_deref().unwrap_or(&[])),
                arbor_turns_per_hour,
            }
        }),
    };
    answer(py.detach(|| {
        analyse(&input).and_then(|mut r| {
            r.advise(&known)?;
            Ok(r)
        })
    }))
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
    use pendulum_theory::fitting::rundown::{analyse, parse_model, RunDownInput};
    let model = model
        .map(parse_model)
        .transpose()
        .map_err(refusal)?
        .flatten();
    let (time, amplitude) = (values(&time, "time")?, values(&amplitude, "amplitude")?);
    answer(py.detach(|| {
        analyse(&RunDownInput {
            time,
            amplitude,
            model,
            period,
            turning_half_period: None,
            turning_count: None,
            length,
            length_standard_error: None,
            g,
            mass,
            declared_degrees: false,
            force,
        })
    }))
}

/// The period-table analysis (the CLI's `fit period`) as JSON.
#[pyfunction]
#[pyo3(signature = (period, period_standard_error, amplitude, length, pendulum_length, pendulum_length_standard_error, bob_radius))]
#[allow(clippy::too_many_arguments)]
fn fit_period(
    py: Python<'_>,
    period: In<'_>,
    period_standard_error: Option<In<'_>>,
    amplitude: Option<In<'_>>,
    length: Option<In<'_>>,
    pendulum_length: Option<f64>,
    pendulum_length_standard_error: Option<f64>,
    bob_radius: Option<f64>,
) -> PyResult<String> {
    use pendulum_theory::fitting::period_table::{analyse, PeriodTableInput};
    let period = values(&period, "period")?;
    let error = period_standard_error
        .as_ref()
        .map(|a| values(a, "period_standard_error"))
        .transpose()?;
    let amplitude = amplitude
        .as_ref()
        .map(|a| values(a, "amplitude"))
        .transpose()?;
    let length = length.as_ref().map(|a| values(a, "length")).transpose()?;
    answer(py.detach(|| {
        analyse(&PeriodTableInput {
            period,
            period_standard_error: error,
            amplitude,
            length,
            pendulum_length,
            pendulum_length_standard_error,
            bob_radius,
            force: false,
        })
    }))
}

/// A photogate log's analysis (the CLI's `fit beats` on a gate log) as
/// JSON.
#[pyfunction]
#[pyo3(signature = (time, gate, select, bob_diameter, bph, period))]
fn fit_photogate(
    py: Python<'_>,
    time: In<'_>,
    gate: Option<In<'_>>,
    select: Option<usize>,
    bob_diameter: Option<f64>,
    bph: Option<f64>,
    period: Option<f64>,
) -> PyResult<String> {
    use pendulum_theory::fitting::photogate::{analyse, GateInput};
    let time = values(&time, "time")?;
    let gate = gate.as_ref().map(|g| values(g, "gate")).transpose()?;
    let nominal = nominal_of(bph, period)?;
    answer(py.detach(|| {
        analyse(&GateInput {
            time,
            gate,
            select,
            bob_diameter,
            nominal,
        })
    }))
}

/// What the caller knows of the clock, for the advice (the CLI's
/// `--length`, `--design`, `--nut-*`, `--crutch`, `--amplitude`), checked
/// as the CLI checks it before anything is measured.
#[allow(clippy::too_many_arguments)]
fn known_of(
    length: Option<f64>,
    parts: Option<&str>,
    nut_pitch: Option<f64>,
    nut_tpi: Option<f64>,
    nut_divisions: Option<i64>,
    crutch: Option<f64>,
    amplitude: Option<f64>,
) -> PyResult<pendulum_theory::advice::Known> {
    use pendulum_theory::compound::regulate::{Nut, Regulated};
    let pendulum = match (length, parts) {
        (Some(_), Some(_)) => {
            return Err(PyValueError::new_err(
                "length: give the length or the design's parts, not both",
            ))
        }
        (Some(l), None) => Some(Regulated::Length(l)),
        (None, Some(p)) => Some(Regulated::Design(design_of(p)?, None)),
        (None, None) => None,
    };
    let known = pendulum_theory::advice::Known {
        pendulum,
        nut: Nut {
            pitch: nut_pitch,
            tpi: nut_tpi,
            divisions: nut_divisions.map(count::<u32>),
        },
        crutch_m: crutch,
        amplitude_rad: amplitude,
    };
    pendulum_theory::advice::check(&known).map_err(|r| PyValueError::new_err(r.to_string()))?;
    Ok(known)
}

/// The beat-log analysis (the CLI's `fit beats`) as JSON.
#[pyfunction]
#[pyo3(signature = (time, bph, period, length=None, parts=None, nut_pitch=None, nut_tpi=None, nut_divisions=None, crutch=None, amplitude=None))]
#[allow(clippy::too_many_arguments)]
fn fit_beats(
    py: Python<'_>,
    time: In<'_>,
    bph: Option<f64>,
    period: Option<f64>,
    length: Option<f64>,
    parts: Option<&str>,
    nut_pitch: Option<f64>,
    nut_tpi: Option<f64>,
    nut_divisions: Option<i64>,
    crutch: Option<f64>,
    amplitude: Option<f64>,
) -> PyResult<String> {
    let known = known_of(
        length,
        parts,
        nut_pitch,
        nut_tpi,
        nut_divisions,
        crutch,
        amplitude,
    )?;
    use pendulum_theory::fitting::beat_log::analyse;
    let time = values(&time, "time")?;
    let nominal = nominal_of(bph, period)?;
    answer(py.detach(|| {
        analyse(time, nominal).and_then(|mut beats| {
            beats.advise(&known, None, None, None)?;
            Ok(beats)
        })
    }))
}

/// The tracked-swing analysis (the CLI's `fit trajectory`) as JSON.
#[pyfunction]
#[pyo3(signature = (time, angle, model, length, force, angular_velocity, length_uncertainty=None, drag_law=None))]
#[allow(clippy::too_many_arguments)]
fn fit_trajectory(
    py: Python<'_>,
    time: In<'_>,
    angle: Option<In<'_>>,
    model: Option<&str>,
    length: Option<f64>,
    force: bool,
    angular_velocity: Option<Vec<In<'_>>>,
    length_uncertainty: Option<f64>,
    drag_law: Option<&str>,
) -> PyResult<String> {
    use pendulum_theory::fitting::tracked::{
        analyse, parse_drag_law, parse_model, LengthSource, TrackInput,
    };
    let model = model
        .map(parse_model)
        .transpose()
        .map_err(refusal)?
        .flatten();
    let drag_law = drag_law
        .map(parse_drag_law)
        .transpose()
        .map_err(refusal)?
        .flatten();
    let time = values(&time, "time")?;
    let angle = angle.as_ref().map(|a| values(a, "angle")).transpose()?;
    // One array per gyroscope axis.
    let rate = angular_velocity
        .as_ref()
        .map(|axes| {
            axes.iter()
                .map(|a| values(a, "angular_velocity"))
                .collect::<PyResult<Vec<&[f64]>>>()
        })
        .transpose()?;
    if angle.is_none() && rate.is_none() {
        return Err(PyValueError::new_err(
            "angle: give the angle (or the angular_velocity) at each time",
        ));
    }
    answer(py.detach(|| {
        analyse(&TrackInput {
            time,
            angle: angle.unwrap_or(&[]),
            angular_velocity: rate.as_deref().unwrap_or(&[]),
            model,
            drag_law,
            length: length.map(|l| (l, LengthSource::Given)),
            length_standard_error: length_uncertainty,
            force,
            angle_from_positions: false,
            declared_degrees: false,
        })
    }))
}

/// `refusal` naming its input by the Python keyword (`keys`: the
/// library's field, the keyword) where the keyword carries its unit
/// (`pressure_hpa`) and the library's field does not.
fn keyed(refusal: Refusal, keys: &[(&str, &'static str)]) -> Refusal {
    use pendulum_theory::analysis::Place;
    let key = |field: &'static str| {
        keys.iter()
            .find(|(f, _)| *f == field)
            .map_or(field, |k| k.1)
    };
    Refusal {
        place: match refusal.place {
            Place::Field(f) => Place::Field(key(f)),
            Place::Sample(f, i) => Place::Sample(key(f), i),
            Place::Data => Place::Data,
        },
        reason: refusal.reason,
    }
}

/// The weather's columns: the library's fields, the keys of Python's
/// `clock_run(weather=)` (the drive file's column names).
const WEATHER_KEYS: [(&str, &str); 3] = [
    ("pressure", "pressure_hpa"),
    ("humidity", "humidity_percent"),
    ("gradient", "gradient_k_per_m"),
];

/// A long run as the Python package passes it: duration, row interval,
/// drive schedule (times, factors), rate schedule (times, s/day), weather
/// (times, temperatures °C, pressures Pa: the package's `pressure_hpa`
/// times 100, as the drive file's reader makes them; humidities %,
/// gradients K/m), force.
type RunArgs = (
    f64,
    Option<f64>,
    Option<(Vec<f64>, Vec<f64>)>,
    Option<(Vec<f64>, Vec<f64>)>,
    Option<Weather>,
    bool,
    Option<String>,
);

/// The weather as the Python package passes it: times, and any of
/// temperatures (°C), pressures (Pa), relative humidities (%) and vertical
/// gradients (K/m).
type Weather = (
    Vec<f64>,
    Option<Vec<f64>>,
    Option<Vec<f64>>,
    Option<Vec<f64>>,
    Option<Vec<f64>>,
);

/// A long run's rows, column by column.
#[derive(Default)]
struct Columns([Vec<f64>; 6]);

impl pendulum_theory::clock::analysis::RunSink for Columns {
    fn row(&mut self, r: &pendulum_theory::clock::long_run::Row) -> bool {
        let values = [
            r.time,
            r.beats as f64,
            r.amplitude,
            r.rate,
            r.time_error,
            r.drive,
        ];
        for (c, v) in self.0.iter_mut().zip(values) {
            c.push(v);
        }
        true
    }
}

/// The clock analysis (the CLI's `clock`): its JSON, and a long run's
/// rows (time_s, beats, amplitude_rad, rate_s_per_day, time_error_s,
/// drive_factor) when one was asked for. `None` is the library's default.
#[pyfunction]
#[pyo3(signature = (length, parts, g, mass, q, escapement, lift_angle, drive_torque, drive_energy, friction, recoil, impulse_angle, every_beats, beat_error, out_of_beat, drive_factor, drive_range, steps, run, drag=Vec::new()))]
#[allow(clippy::too_many_arguments)]
fn clock<'py>(
    py: Python<'py>,
    length: Option<f64>,
    parts: Option<&str>,
    g: Option<f64>,
    mass: Option<f64>,
    q: Option<f64>,
    escapement: Option<String>,
    lift_angle: Option<f64>,
    drive_torque: Option<f64>,
    drive_energy: Option<f64>,
    friction: Option<f64>,
    recoil: Option<f64>,
    impulse_angle: Option<f64>,
    every_beats: Option<i64>,
    beat_error: Option<f64>,
    out_of_beat: Option<f64>,
    drive_factor: Option<Vec<f64>>,
    drive_range: Option<(f64, f64)>,
    steps: Option<i64>,
    run: Option<RunArgs>,
    drag: Vec<(String, f64)>,
) -> PyResult<(String, Option<Vec<Array1<'py>>>)> {
    use pendulum_theory::clock::analysis::{
        analyse, drive_of, escapement_named, BeatError, ClockInput, ClockPendulum, DriveFactors,
        RunInput, Schedule,
    };
    let refused = |r: Refusal| PyValueError::new_err(r.to_string());
    let schedule =
        |s: Option<(Vec<f64>, Vec<f64>)>| s.map(|(time, value)| Schedule { time, value });
    let run_gas = match run.as_ref().and_then(|r| r.6.as_deref()) {
        Some(name) => Some(pendulum_theory::gas::Gas::parse(name).map_err(refused)?),
        None => None,
    };
    let isochronism = match (drive_factor, drive_range) {
        (Some(f), _) => Some(DriveFactors::List(f)),
        (None, Some((from, to))) => Some(DriveFactors::Range {
            from,
            to,
            steps: steps.map(count::<usize>),
        }),
        (None, None) => None,
    };
    let pendulum = match (length, parts) {
        (Some(l), None) => ClockPendulum::Length(l),
        (None, Some(p)) => ClockPendulum::Design(design_of(p)?.pendulum),
        _ => {
            return Err(PyValueError::new_err(
                "length: give the length or the design's parts, one of them",
            ))
        }
    };
    let drag = drag
        .iter()
        .map(|(name, k)| {
            Ok((
                pendulum_theory::simulation::analysis::parse_drag_law(name)?,
                *k,
            ))
        })
        .collect::<Result<Vec<_>, Refusal>>()
        .map_err(refused)?;
    let input = ClockInput {
        pendulum,
        g,
        mass,
        q,
        drag,
        escapement: escapement
            .as_deref()
            .map(escapement_named)
            .transpose()
            .map_err(refused)?,
        lift_angle,
        drive: drive_of(drive_torque, drive_energy).map_err(refused)?,
        friction,
        recoil,
        impulse_angle,
        every_beats: every_beats.map(count::<u64>),
        beat_error: match (beat_error, out_of_beat) {
            (Some(_), Some(_)) => {
                return Err(PyValueError::new_err(
                    "beat_error: give the beat error or the angle out of beat, not both",
                ))
            }
            (Some(b), None) => Some(BeatError::Time(b)),
            (None, Some(a)) => Some(BeatError::Angle(a)),
            (None, None) => None,
        },
        isochronism,
        run: run.map(
            |(duration, every, drive, rate, weather, force, _)| RunInput {
                duration,
                every,
                drive_schedule: schedule(drive),
                weather: weather.map(
                    |(time, temperature_c, pressure_pa, humidity_percent, gradient_k_per_m)| {
                        pendulum_theory::clock::analysis::Weather {
                            time,
                            temperature_c,
                            pressure_pa,
                            humidity_percent,
                            gradient_k_per_m,
                        }
                    },
                ),
                rate_schedule: schedule(rate),
                force,
                gas: run_gas,
            },
        ),
    };
    let mut rows = Columns::default();
    let result = py.detach(|| analyse(&input, &mut rows));
    let text = answer(result.map_err(|r| keyed(r, &WEATHER_KEYS)))?;
    let columns = input
        .run
        .is_some()
        .then(|| rows.0.into_iter().map(|c| c.into_pyarray(py)).collect());
    Ok((text, columns))
}

/// Listening to a recording in memory (the CLI's `listen`) as JSON, and
/// the ticks kept (time_s, side, amplitude).
#[pyfunction]
#[pyo3(signature = (samples, sample_rate, bph, period, sample_rate_error_ppm, lift_angle, oscillator=None, every=None, length=None, parts=None, nut_pitch=None, nut_tpi=None, nut_divisions=None, crutch=None, amplitude=None))]
#[allow(clippy::type_complexity, clippy::too_many_arguments)]
fn listen<'py>(
    py: Python<'py>,
    samples: numpy::PyReadonlyArray1<'py, f32>,
    sample_rate: f64,
    bph: Option<f64>,
    period: Option<f64>,
    sample_rate_error_ppm: Option<f64>,
    lift_angle: Option<f64>,
    oscillator: Option<&str>,
    every: Option<f64>,
    length: Option<f64>,
    parts: Option<&str>,
    nut_pitch: Option<f64>,
    nut_tpi: Option<f64>,
    nut_divisions: Option<i64>,
    crutch: Option<f64>,
    amplitude: Option<f64>,
) -> PyResult<(String, [Array1<'py>; 3])> {
    let known = known_of(
        length,
        parts,
        nut_pitch,
        nut_tpi,
        nut_divisions,
        crutch,
        amplitude,
    )?;
    use pendulum_theory::listening::analysis::{listen_to_samples, ListenInput, Oscillator};
    let samples = samples
        .as_slice()
        .map_err(|_| PyValueError::new_err("samples: must be contiguous"))?;
    let input = ListenInput {
        nominal: nominal_of(bph, period)?,
        sample_rate_error_ppm,
        lift_angle,
        oscillator: oscillator
            .map(Oscillator::parse)
            .transpose()
            .map_err(|r| PyValueError::new_err(r.to_string()))?,
        every,
    };
    let result = py.detach(|| {
        listen_to_samples(samples, sample_rate, &input).and_then(|mut heard| {
            heard.advise(&known)?;
            Ok(heard)
        })
    });
    let ticks = result.as_ref().map(|r| r.ticks.clone()).unwrap_or_default();
    let text = answer(result)?;
    let column = |f: &dyn Fn(&pendulum_theory::listening::detect::Tick) -> f64| {
        ticks.iter().map(f).collect::<Vec<f64>>().into_pyarray(py)
    };
    Ok((
        text,
        [
            column(&|t| t.time),
            column(&|t| f64::from(t.side)),
            column(&|t| t.amplitude),
        ],
    ))
}

/// The period at one amplitude or over a range (the CLI's `period`) as
/// JSON: one row, or a list of rows.
#[pyfunction]
#[pyo3(signature = (length, g, amplitude, amplitude_range, steps, series_terms, step))]
fn period_table(
    length: f64,
    g: Option<f64>,
    amplitude: Option<f64>,
    amplitude_range: Option<(f64, f64)>,
    steps: Option<i64>,
    series_terms: Option<i64>,
    step: Option<f64>,
) -> PyResult<String> {
    use pendulum_theory::period::table::{table, Amplitudes, PeriodInput};
    let amplitudes = match (amplitude, amplitude_range) {
        (Some(a), None) => Amplitudes::One(a),
        (None, Some((from, to))) => Amplitudes::Range {
            from,
            to,
            steps,
            step,
        },
        _ => {
            return Err(PyValueError::new_err(
                "amplitude: give one amplitude or amplitude_range=(from, to)",
            ))
        }
    };
    let input = PeriodInput {
        length,
        g,
        amplitudes,
        series_terms,
        elastic_share: None,
    };
    match table(&input) {
        Ok(rows) if matches!(amplitudes, Amplitudes::One(_)) => answer(Ok(rows[0])),
        result => answer(result),
    }
}

/// The nominal beat from `bph` or `period` (s), at most one of them: the
/// CLI refuses both, and so does every function here that takes them.
fn nominal_of(
    bph: Option<f64>,
    period: Option<f64>,
) -> PyResult<Option<pendulum_theory::period::Nominal>> {
    pendulum_theory::period::Nominal::given(bph, period)
        .map_err(|r| PyValueError::new_err(r.to_string()))
}

/// The length for a period or a beat rate (the CLI's `length`) as JSON.
#[pyfunction]
#[pyo3(signature = (period, bph, amplitude, g))]
fn length(
    period: Option<f64>,
    bph: Option<f64>,
    amplitude: Option<f64>,
    g: Option<f64>,
) -> PyResult<String> {
    use pendulum_theory::fitting::beat_log::Nominal;
    let nominal = match (period, bph) {
        (Some(p), None) => Nominal::Period(p),
        (None, Some(b)) => Nominal::BeatsPerHour(b),
        _ => {
            return Err(PyValueError::new_err(
                "period: give the period or the beat rate (bph), one of them",
            ))
        }
    };
    answer(pendulum_theory::period::inverse::length(
        nominal, amplitude, g,
    ))
}

/// The amplitude a period implies (the CLI's `amplitude`) as JSON.
#[pyfunction]
#[pyo3(signature = (length, period, period_uncertainty, g))]
fn amplitude(
    length: f64,
    period: f64,
    period_uncertainty: Option<f64>,
    g: Option<f64>,
) -> PyResult<String> {
    answer(pendulum_theory::period::inverse::amplitude(
        length,
        g,
        period,
        period_uncertainty,
        None,
    ))
}

/// The damped pendulum (the CLI's `damped`) as JSON.
#[pyfunction]
#[pyo3(signature = (length, amplitude, damping, friction_angle, mass, extrema, g, force))]
#[allow(clippy::too_many_arguments)]
fn damped(
    length: f64,
    amplitude: f64,
    damping: Option<(String, f64)>,
    friction_angle: Option<f64>,
    mass: Option<f64>,
    extrema: Option<i64>,
    g: Option<f64>,
    force: bool,
) -> PyResult<String> {
    use pendulum_theory::damped::analysis::{damped, DampedInput};
    let damping = given_damping(damping)?;
    answer(damped(&DampedInput {
        length,
        g,
        amplitude,
        damping,
        friction_angle,
        mass,
        extrema: extrema.map(count::<u64>),
        force,
    }))
}

/// A going train's beat and pendulum (the CLI's `train`) as JSON.
#[pyfunction]
#[pyo3(signature = (wheels, pinions, arbor_turns_per_hour, g))]
fn train(
    wheels: Vec<i64>,
    pinions: Vec<i64>,
    arbor_turns_per_hour: Option<f64>,
    g: Option<f64>,
) -> PyResult<String> {
    let counts = |v: Vec<i64>| -> Vec<u32> { v.into_iter().map(count::<u32>).collect() };
    answer(pendulum_theory::train::analysis::train(
        &counts(wheels),
        &counts(pinions),
        arbor_turns_per_hour,
        g,
        None,
    ))
}

/// The trains that give a beat (the CLI's `train --bph`) as JSON.
#[pyfunction]
#[pyo3(signature = (bph, escape_teeth, tolerance))]
fn train_for(bph: f64, escape_teeth: Option<i64>, tolerance: Option<f64>) -> PyResult<String> {
    answer(pendulum_theory::train::analysis::train_for(
        bph,
        escape_teeth.map(count::<u32>),
        tolerance,
    ))
}

/// A pendulum's report (the CLI's `report --json`) as JSON, with the
/// run-down's turning points as arrays (time s, amplitude rad, rate s/day).
#[pyfunction]
#[pyo3(signature = (length, parts, amplitude, damping, mass, g))]
#[allow(clippy::type_complexity)]
fn report<'py>(
    py: Python<'py>,
    length: Option<f64>,
    parts: Option<&str>,
    amplitude: Option<f64>,
    damping: Option<(String, f64)>,
    mass: Option<f64>,
    g: Option<f64>,
) -> PyResult<(String, Array1<'py>, Array1<'py>, Array1<'py>)> {
    use pendulum_theory::report::{report, ReportInput};
    let damping = given_damping(damping)?;
    let input = ReportInput {
        length,
        design: parts.map(design_of).transpose()?,
        g,
        amplitude,
        damping,
        mass,
    };
    // Ctrl-C during the run-down: KeyboardInterrupt, not a refusal.
    let mut interrupted = None;
    let result = report(&input, &mut || match py.check_signals() {
        Ok(()) => true,
        Err(e) => {
            interrupted = Some(e);
            false
        }
    });
    if let Some(e) = interrupted {
        return Err(e);
    }
    let r = result.map_err(|r| PyValueError::new_err(r.to_string()))?;
    let column = |f: fn(&pendulum_theory::report::RundownPoint) -> f64| {
        r.rundown.points.iter().map(f).collect::<Vec<f64>>()
    };
    let (t, a, rate) = (
        column(|p| p.time_s),
        column(|p| p.amplitude_rad),
        column(|p| p.rate_s_per_day),
    );
    Ok((
        answer(Ok(&r))?,
        t.into_pyarray(py),
        a.into_pyarray(py),
        rate.into_pyarray(py),
    ))
}

/// A design from its parts as JSON text (`{"part": [...]}`, sizes in SI
/// units: Python reads no units).
fn design_of(parts: &str) -> PyResult<pendulum_theory::compound::description::Design> {
    use pendulum_theory::compound::description::{design, Unit};
    let value: serde_json::Value =
        serde_json::from_str(parts).map_err(|e| PyValueError::new_err(format!("parts: {e}")))?;
    let no_units = |text: &str, _: Unit| -> Result<f64, String> {
        Err(format!(
            "'{text}': give a number in SI units (metres, kilograms)"
        ))
    };
    design(&value, &no_units).map_err(|r| PyValueError::new_err(r.to_string()))
}

/// A design's datasheet (the CLI's `design`) as JSON: `pressure` in Pa
/// (the package's `pressure_hpa` times 100, as the command line makes
/// `--pressure`).
#[pyfunction]
#[pyo3(signature = (parts, g, pressure, temperature, humidity, regulated_at, gas, pivot_q, amplitude))]
#[allow(clippy::too_many_arguments)]
fn design(
    parts: &str,
    g: Option<f64>,
    pressure: Option<f64>,
    temperature: Option<f64>,
    humidity: Option<f64>,
    regulated_at: Option<f64>,
    gas: Option<&str>,
    pivot_q: Option<f64>,
    amplitude: Option<f64>,
) -> PyResult<String> {
    use pendulum_theory::compound::datasheet::{datasheet, Air};
    let design = design_of(parts)?;
    let gas = gas
        .map(pendulum_theory::gas::Gas::parse)
        .transpose()
        .map_err(|r| PyValueError::new_err(r.to_string()))?;
    let sheet = datasheet(
        &design,
        g,
        &Air {
            pressure_pa: pressure,
            temperature_c: temperature,
            humidity,
            regulated_at_c: regulated_at,
            gas,
            pivot_q,
            amplitude_rad: amplitude,
        },
    );
    answer(sheet.map_err(|r| keyed(r, &[("pressure", "pressure_hpa")])))
}

/// Regulation (the CLI's `regulate`) as JSON.
#[pyfunction]
#[pyo3(signature = (rate, length, parts, part, nut_pitch, nut_tpi, nut_divisions, tray, bph=None))]
#[allow(clippy::too_many_arguments)]
fn regulate(
    rate: f64,
    length: Option<f64>,
    parts: Option<&str>,
    part: Option<String>,
    nut_pitch: Option<f64>,
    nut_tpi: Option<f64>,
    nut_divisions: Option<i64>,
    tray: Option<f64>,
    bph: Option<f64>,
) -> PyResult<String> {
    use pendulum_theory::compound::regulate::{regulate, Nut, Regulated};
    let pendulum = match (length, parts, bph) {
        (Some(l), None, None) => Regulated::Length(l),
        (None, Some(p), None) => Regulated::Design(design_of(p)?, part),
        (None, None, Some(b)) => Regulated::Length(
            pendulum_theory::advice::length_for_bph(b)
                .map_err(|r| PyValueError::new_err(r.to_string()))?,
        ),
        _ => {
            return Err(PyValueError::new_err(
                "length: give the length, the design's parts or the bph, one of them",
            ))
        }
    };
    let nut = Nut {
        pitch: nut_pitch,
        tpi: nut_tpi,
        divisions: nut_divisions.map(count::<u32>),
    };
    answer(regulate(&pendulum, rate, nut, tray))
}

/// Temperature compensation (the CLI's `compensate`) as JSON.
#[pyfunction]
#[pyo3(signature = (parts, compensator, part, jar_material, jar_diameter, jar_wall, tube_diameter, tube_bore))]
#[allow(clippy::too_many_arguments)]
fn compensate(
    parts: &str,
    compensator: Option<String>,
    part: Option<String>,
    jar_material: Option<String>,
    jar_diameter: Option<f64>,
    jar_wall: Option<f64>,
    tube_diameter: Option<f64>,
    tube_bore: Option<f64>,
) -> PyResult<String> {
    use pendulum_theory::compound::compensate::{compensate, CompensateInput};
    let design = design_of(parts)?;
    answer(compensate(
        &design,
        &CompensateInput {
            compensator,
            part,
            jar_material,
            jar_diameter,
            jar_wall,
            tube_diameter,
            tube_bore,
        },
    ))
}

/// The extension module behind the `pendulum_theory` package.
/// The `pendulum` command on `argv` (its name first), as the binary
/// runs it: its output on the process's standard output and error, its
/// exit status returned. The package's console script calls it once per
/// process (it installs the process's Ctrl-C handler).
#[pyfunction]
fn cli(py: Python<'_>, argv: Vec<std::ffi::OsString>) -> u8 {
    py.detach(|| pendulum_cli::run(argv))
}

/// The library's lists where it is meant to grow, as JSON: each
/// escapement, stability deviation, drag law and file format read whole,
/// with its name and help (what the command line's help lists).
#[pyfunction]
fn lists() -> String {
    use pendulum_theory::clock::escapement::spec::ESCAPEMENTS;
    use pendulum_theory::stability::DEVIATIONS;
    let escapements: Vec<_> = ESCAPEMENTS
        .iter()
        .map(|e| serde_json::json!({"name": e.name, "help": e.help}))
        .collect();
    let deviations: Vec<_> = DEVIATIONS
        .iter()
        .map(|d| serde_json::json!({"key": d.key, "name": d.name, "help": d.help, "unit": d.unit}))
        .collect();
    let drag_laws: Vec<_> = pendulum_theory::forces::DRAG_LAWS
        .iter()
        .map(|l| serde_json::json!({"name": l.name(), "help": l.describe()}))
        .collect();
    let formats: Vec<_> = pendulum_data::formats::FORMATS
        .iter()
        .map(|f| serde_json::json!({"name": f.name, "extensions": f.extensions}))
        .collect();
    serde_json::json!({
        "escapements": escapements,
        "deviations": deviations,
        "drag_laws": drag_laws,
        "file_formats": formats,
    })
    .to_string()
}

/// A measurement file's bytes fitted as `pendulum fit decay|trajectory|
/// period FILE --json` fits it, the options a JSON request (the page's
/// lab's keys: `pendulum_data::lab`); the reply is JSON, `{"ok": …,
/// "figure": …, "warnings": …, "notes": …}` or `{"error": …}`.
#[pyfunction]
fn fit_file(py: Python<'_>, request: &str, bytes: &[u8]) -> String {
    py.detach(|| pendulum_data::lab::fit(request.as_bytes(), bytes))
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(cli, m)?)?;
    m.add_function(wrap_pyfunction!(fit_file, m)?)?;
    m.add_function(wrap_pyfunction!(lists, m)?)?;
    m.add(
        "STANDARD_GRAVITY",
        pendulum_theory::pendulum::STANDARD_GRAVITY,
    )?;
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
    m.add_function(wrap_pyfunction!(fit_period, m)?)?;
    m.add_function(wrap_pyfunction!(fit_photogate, m)?)?;
    m.add_function(wrap_pyfunction!(fit_trajectory, m)?)?;
    m.add_function(wrap_pyfunction!(clock, m)?)?;
    m.add_function(wrap_pyfunction!(listen, m)?)?;
    m.add_function(wrap_pyfunction!(period_table, m)?)?;
    m.add_function(wrap_pyfunction!(length, m)?)?;
    m.add_function(wrap_pyfunction!(amplitude, m)?)?;
    m.add_function(wrap_pyfunction!(damped, m)?)?;
    m.add_function(wrap_pyfunction!(train, m)?)?;
    m.add_function(wrap_pyfunction!(train_for, m)?)?;
    m.add_function(wrap_pyfunction!(design, m)?)?;
    m.add_function(wrap_pyfunction!(regulate, m)?)?;
    m.add_function(wrap_pyfunction!(compensate, m)?)?;
    m.add_function(wrap_pyfunction!(report, m)?)?;
    m.add_function(wrap_pyfunction!(stability, m)?)?;
    m.add_function(wrap_pyfunction!(tide, m)?)?;
    m.add_function(wrap_pyfunction!(clock_log, m)?)?;
    Ok(())
}
