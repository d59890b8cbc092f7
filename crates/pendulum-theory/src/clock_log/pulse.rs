//! A swing's amplitude from a photogate's pulse: how long the bob's flag
//! blocks a beam at the bottom of the swing.
//!
//! Method: a flag of width `w` (a chord, m) on the pendulum at distance
//! `r` from the pivot blocks the beam while the pendulum's angle is within
//! `±α`, `α = 2 asin(w / 4r)` (the flag's angular width `2α` subtends the
//! chord `w` at `r`). In the exact motion of amplitude `A`, `sin(θ/2) =
//! k sn(ω_n t, k)` with `k = sin(A/2)` (DLMF 22.19.2), so the time from the
//! bottom to `θ` is `F(asin(sin(θ/2)/k) | k²)/ω_n` and the pulse lasts
//! `Δt = 2 F(asin(sin(α/2)/k) | k²)/ω_n`, `ω_n = sqrt(g/l)` with `l` the
//! equivalent simple length (a compound pendulum's `I/md`). `Δt` falls as
//! `A` grows; the amplitude is found by bisection on `k` to 1e-15 and
//! agrees with an independent quadrature of the motion to 1e-9
//! relative (test `clock_log.rs`). To first order this is the speed at
//! the bottom, `w/Δt = 2 ω_n r sin(A/2)`.

use crate::analysis::{require_finite, Refusal};
use crate::elliptic::ellipf;

/// The amplitude (rad) of a swing whose flag of width `flag_width` (m) at
/// `gate_radius` (m) from the pivot blocked the gate for `pulse` s, for a
/// pendulum of equivalent length `length` (m) in gravity `g` (m/s²).
/// Refuses values that are not positive and a pulse longer than the
/// slowest swing that still clears the flag allows.
pub fn amplitude_from_pulse(
    pulse: f64,
    flag_width: f64,
    gate_radius: f64,
    length: f64,
    g: f64,
) -> Result<f64, Refusal> {
    for (name, v) in [
        ("pulse", pulse),
        ("flag_width", flag_width),
        ("gate_radius", gate_radius),
        ("length", length),
        ("g", g),
    ] {
        if require_finite(name, v)? <= 0.0 {
            return Err(Refusal::field(name, "must be positive"));
        }
    }
    if flag_width >= 4.0 * gate_radius {
        return Err(Refusal::field(
            "flag_width",
            "must be less than four times the gate's distance from the pivot",
        ));
    }
    let omega = (g / length).sqrt();
    let alpha = 2.0 * (flag_width / (4.0 * gate_radius)).asin();
    let s = (alpha / 2.0).sin();
    let duration = |k: f64| 2.0 * ellipf((s / k).min(1.0).asin(), k * k) / omega;
    // Swings from just clearing the flag to just below the top.
    let (mut lo, mut hi) = (s * (1.0 + 1e-15), 1.0 - 1e-15);
    if pulse >= duration(lo) {
        return Err(Refusal::field(
            "pulse",
            "is longer than any swing that clears the flag lasts: the flag does not leave the beam (check the flag's width and the gate's distance)",
        ));
    }
    if pulse <= duration(hi) {
        return Err(Refusal::field(
            "pulse",
            "is shorter than a swing from the top takes: check the flag's width and the gate's distance",
        ));
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if duration(mid) > pulse {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi - lo < 1e-15 {
            break;
        }
    }
    Ok(2.0 * (0.5 * (lo + hi)).asin())
}
