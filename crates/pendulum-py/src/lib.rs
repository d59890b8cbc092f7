//! Python bindings of `pendulum-theory`: glue only. Each function takes
//! `float64` arrays of one shape (the Python package `pendulum_theory`
//! broadcasts them as views, so a scalar costs nothing), computes without
//! the GIL (on every core for large arrays) and returns a new array. An
//! input the library refuses raises `ValueError` with the library's
//! message.

use ndarray::{ArrayD, Zip};
use numpy::{IntoPyArray, PyArrayDyn, PyReadonlyArrayDyn};
use pendulum_theory::damped::DampedPendulum;
use pendulum_theory::damping::Damping;
use pendulum_theory::elliptic::{ellipe as ellipe_m, ellipk as ellipk_m, jacobi};
use pendulum_theory::error::InputError;
use pendulum_theory::exact::ExactSwing;
use pendulum_theory::period::{
    amplitude_for_period as theory_amplitude, circular_error, length_for_period,
};
use pendulum_theory::{Amplitude, Pendulum};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};

/// Seconds in a day.
const DAY: f64 = 86_400.0;

type Array<'py> = Bound<'py, PyArrayDyn<f64>>;
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
        let mut out = ArrayD::<f64>::zeros($x0.raw_dim());
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
    Ok(())
}
