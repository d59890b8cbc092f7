//! Accuracy against independent reference values.
//!
//! The data files in `tests/data/` were made by `tools/reference/make_reference.py`
//! with mpmath at 40 digits from the exact double inputs; each value is stored
//! as a pair of doubles `hi + lo`, so errors are measured in ulp of the true
//! value without rounding the reference first. The allowed errors are in one
//! table, [`ALLOWED_ULP`]; each test prints the maximum it measured
//! (`cargo test --release -p pendulum-theory --test all reference:: -- --nocapture`).

use pendulum_theory::elliptic::{
    ellip_e_minus_complement_k, ellipe, ellipe_modulus, ellipf, ellipk, ellipk_modulus, jacobi,
};
use pendulum_theory::lift::{amplitude_from_lift, crossing_fraction};
use pendulum_theory::period::{circular_error, circular_error_slope, period_ratio};
use pendulum_theory::{Amplitude, Pendulum};

/// Allowed error, in ulp of the true value, per quantity. One table, so a
/// loosened tolerance shows up in review.
mod allowed {
    /// K(m) from m, and K at an amplitude (through k' = cos(A0/2)).
    pub const ELLIPK: f64 = 4.0;
    /// E(m) and E at an amplitude.
    pub const ELLIPE: f64 = 4.0;
    /// E - k'^2 K, the cancellation-free difference.
    pub const E_MINUS_KC2K: f64 = 4.0;
    /// The period T = 4 sqrt(l/g) K and the ratio T/T0.
    pub const PERIOD: f64 = 4.0;
    /// The circular error 1 - T0/T.
    pub const CIRCULAR_ERROR: f64 = 4.0;
    /// Its slope d(1 - T0/T)/dA0. Exception, explained: the inputs
    /// k = sin(A0/2) and k' = cos(A0/2) each carry up to an ulp from the
    /// platform's sin and cos before the AGM starts, and near 180° the
    /// slope's relative sensitivity to k' is about 1.3, so up to 2 ulp
    /// come from the inputs alone (measured: 4.69 at A0 = 3.003 rad).
    pub const CIRCULAR_ERROR_SLOPE: f64 = 5.0;
    /// sn, cn, dn: in units of ε (|f| + |u f'(u)|) (see the jacobi module docs).
    pub const JACOBI: f64 = 4.0;
    /// F(φ|m), the incomplete integral of the first kind.
    pub const ELLIPF: f64 = 4.0;
    /// The lift crossing fraction F(ψ|k²) / (2K(k²)), a quotient of two
    /// values of up to 4 ulp each (measured: 4.2).
    pub const LIFT_FRACTION: f64 = 8.0;
}
use allowed as ALLOWED_ULP;

use crate::common;
use common::{check_all, ulp_error, Reference, Worst};

#[test]
fn complete_integrals_from_parameter() {
    let mut wk = Worst::new("K(m)");
    for r in Reference::load("ellipk.csv", 3).rows {
        wk.see(ulp_error(ellipk(r[0]), r[1], r[2]), r[0]);
    }
    let mut we = Worst::new("E(m)");
    for r in Reference::load("ellipe.csv", 3).rows {
        we.see(ulp_error(ellipe(r[0]), r[1], r[2]), r[0]);
    }
    check_all(&[(&wk, ALLOWED_ULP::ELLIPK), (&we, ALLOWED_ULP::ELLIPE)]);
}

#[test]
fn everything_at_an_amplitude() {
    let data = Reference::load("amplitude.csv", 13);
    let mut wk = Worst::new("K(sin^2(A0/2)), A0 in (0,179.9]");
    let mut we = Worst::new("E(sin^2(A0/2))");
    let mut wd = Worst::new("E - k'^2 K");
    let mut wr = Worst::new("T/T0");
    let mut wc = Worst::new("1 - T0/T");
    let mut ws = Worst::new("d(1 - T0/T)/dA0");
    for r in data.rows {
        let a = Amplitude::from_radians(r[0]).unwrap();
        let q = a.modulus();
        wk.see(ulp_error(ellipk_modulus(&q), r[1], r[2]), r[0]);
        we.see(ulp_error(ellipe_modulus(&q), r[3], r[4]), r[0]);
        wd.see(ulp_error(ellip_e_minus_complement_k(&q), r[5], r[6]), r[0]);
        wr.see(ulp_error(period_ratio(a), r[7], r[8]), r[0]);
        wc.see(ulp_error(circular_error(a), r[9], r[10]), r[0]);
        ws.see(ulp_error(circular_error_slope(a), r[11], r[12]), r[0]);
    }
    check_all(&[
        (&wk, ALLOWED_ULP::ELLIPK),
        (&we, ALLOWED_ULP::ELLIPE),
        (&wd, ALLOWED_ULP::E_MINUS_KC2K),
        (&wr, ALLOWED_ULP::PERIOD),
        (&wc, ALLOWED_ULP::CIRCULAR_ERROR),
        (&ws, ALLOWED_ULP::CIRCULAR_ERROR_SLOPE),
    ]);
}

#[test]
fn period_of_pendulums() {
    let mut w = Worst::new("T = 4 sqrt(l/g) K");
    for r in Reference::load("period.csv", 5).rows {
        let p = Pendulum::new(r[1], r[2]).unwrap();
        let a = Amplitude::from_radians(r[0]).unwrap();
        w.see(ulp_error(p.period(a), r[3], r[4]), r[0]);
    }
    check_all(&[(&w, ALLOWED_ULP::PERIOD)]);
}

#[test]
fn jacobi_functions() {
    let mut worst = [
        Worst::new("sn (in ε(|sn| + |u sn'|))"),
        Worst::new("cn (in ε(|cn| + |u cn'|))"),
        Worst::new("dn (in ε(|dn| + |u dn'|))"),
    ];
    for r in Reference::load("jacobi.csv", 8).rows {
        let (u, m) = (r[0], r[1]);
        let v = jacobi(u, m);
        let (sn, cn, dn) = (r[2] + r[3], r[4] + r[5], r[6] + r[7]);
        let derivatives = [cn * dn, sn * dn, m * sn * cn];
        let got = [v.sn, v.cn, v.dn];
        for (i, w) in worst.iter_mut().enumerate() {
            let (hi, lo) = (r[2 + 2 * i], r[3 + 2 * i]);
            let scale = f64::EPSILON * (hi.abs() + (u * derivatives[i]).abs());
            w.see(((got[i] - hi) - lo).abs() / scale, u);
        }
    }
    let results: Vec<(&Worst, f64)> = worst.iter().map(|w| (w, ALLOWED_ULP::JACOBI)).collect();
    check_all(&results);
}

#[test]
fn incomplete_integral_of_the_first_kind() {
    let mut w = Worst::new("F(phi|m)");
    for r in Reference::load("ellipf.csv", 4).rows {
        w.see(ulp_error(ellipf(r[0], r[1]), r[2], r[3]), r[0]);
    }
    check_all(&[(&w, ALLOWED_ULP::ELLIPF)]);
}

/// The lift crossing fraction against mpmath, and the amplitude recovered
/// from it (the inversion `pendulum listen --lift-angle` uses).
#[test]
fn amplitude_from_the_lift_crossing() {
    let mut w = Worst::new("lift fraction");
    let mut worst_amplitude: f64 = 0.0;
    for r in Reference::load("lift.csv", 4).rows {
        let (lift, amplitude) = (r[0], r[1]);
        w.see(
            ulp_error(crossing_fraction(lift, amplitude), r[2], r[3]),
            amplitude,
        );
        let period = 2.0;
        let found = amplitude_from_lift(lift, (r[2] + r[3]) * period, period).unwrap();
        worst_amplitude = worst_amplitude.max((found.amplitude - amplitude).abs() / amplitude);
    }
    eprintln!("amplitude from the exact fraction: worst relative error {worst_amplitude:.2e}");
    assert!(worst_amplitude < 1e-12);
    check_all(&[(&w, ALLOWED_ULP::LIFT_FRACTION)]);
}
