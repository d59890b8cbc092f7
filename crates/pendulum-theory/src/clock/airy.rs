//! The escapement error to first order: Airy's integral.
//!
//! For a half swing of the free pendulum with energy `E` (scaled: `E =
//! v²/2 + 1 - cos θ = 2k²`, `k = sin(A/2)`), let a small torque `a(θ)`
//! change the energy along the path by `δE(θ)`, measured from the half
//! swing's mean energy. The half swing's duration is `dΦ/dE` for `Φ(E) =
//! ∫ sqrt(2(E + δE(θ) - 1 + cos θ)) dθ` over the path (its integrand
//! vanishes at both ends), and to first order in `δE`
//!
//! `T_half = 2 K(k) + d/dE ∫ δE(θ) dθ / v(θ; E)`,
//!
//! where the second term is the escapement's (the first, the free
//! pendulum's exact half period). With `sin(θ/2) = k sin φ` the integral
//! is `J(E) = ∫_{-π/2}^{π/2} δE(θ(φ)) dφ / sqrt(1 - k² sin² φ)`, smooth at
//! the ends; it is computed by Gauss-Legendre quadrature split at the
//! escapement's edges (where `δE` has a kink, or a step for an impulse) and
//! differentiated by a central difference in `E` (relative step 1e-4:
//! truncation about 1e-8 of the result, rounding about 1e-12).
//!
//! In the small-angle limit (`θ = A sin φ`, `dθ/v = dφ`) the term becomes
//! `(1/A²) ∫ a(θ) θ dτ` over the half swing: Airy's result (1830) that only
//! the part of the torque in phase with the displacement moves the period,
//! an impulse before the bottom (`θ < 0` travelling towards `+θ`, `a > 0`)
//! shortening it, one after lengthening it, and one symmetric about the
//! bottom leaving it alone. [`small_angle_time_shift`] is that form, for
//! the tests; [`time_shift`] keeps the pendulum's nonlinearity.
//!
//! Damping changes the energy symmetrically about the bottom, so it moves
//! the half period only at second order (its `δE` is odd in `θ`, its
//! integral against the even weight zero); it is left out of `δE`.

use super::escapement::Escapement;
use crate::elliptic::{ellipk_modulus, Modulus};
use std::sync::OnceLock;

/// `(P_n(z), P_{n-1}(z))` by the three-term recurrence.
fn legendre(n: usize, z: f64) -> (f64, f64) {
    let (mut p0, mut p1) = (1.0, z);
    for j in 2..=n {
        let p2 = ((2 * j - 1) as f64 * z * p1 - (j - 1) as f64 * p0) / j as f64;
        p0 = p1;
        p1 = p2;
    }
    (p1, p0)
}

/// Gauss-Legendre nodes and weights on [-1, 1], 24 points (the roots of
/// P_24 by Newton's method from Tricomi's estimate; exact for polynomials
/// of degree 47).
fn gauss_legendre() -> &'static ([f64; 24], [f64; 24]) {
    static RULE: OnceLock<([f64; 24], [f64; 24])> = OnceLock::new();
    RULE.get_or_init(|| {
        const N: usize = 24;
        let n = N as f64;
        let mut x = [0.0; N];
        let mut w = [0.0; N];
        for i in 0..N {
            let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (n + 0.5)).cos();
            for _ in 0..100 {
                let (p, q) = legendre(N, z);
                let dz = p / (n * (z * p - q) / (z * z - 1.0));
                z -= dz;
                if dz.abs() < 1e-16 {
                    break;
                }
            }
            let (p, q) = legendre(N, z);
            let dp = n * (z * p - q) / (z * z - 1.0);
            x[i] = z;
            w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
        }
        (x, w)
    })
}

/// `∫ f` over `[a, b]` by the 24-point rule.
pub(crate) fn integrate(f: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    let (x, w) = gauss_legendre();
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    let mut sum = 0.0;
    for i in 0..24 {
        sum += w[i] * f(mid + half * x[i]);
    }
    sum * half
}

/// The energy the escapement has given by `theta` on a half swing from
/// `-a`, over `m g l` (its work, and the kicks of the edges passed).
fn given_by(
    escapement: &dyn Escapement,
    edges: &[f64],
    a: f64,
    theta: f64,
    beat: u64,
    drive: f64,
) -> f64 {
    if theta >= -a {
        escapement.energy(a, theta, beat, drive)
    } else {
        // Before the start (for the derivative's wider orbit): the first
        // zone's torque continued.
        let zone = super::escapement::zone_of(edges, theta);
        -escapement.work_on(zone, theta, -a, beat, drive)
    }
}

/// The escapement's change of the half swing's duration, scaled time, to
/// first order, at amplitude `a` rad on beat `beat` (see the module notes).
pub fn time_shift(escapement: &dyn Escapement, a: f64, beat: u64, drive: f64) -> f64 {
    let edges = escapement.edges_on(beat);
    let total = escapement.energy(a, a, beat, drive);
    let delta = |theta: f64| given_by(escapement, &edges, a, theta, beat, drive) - 0.5 * total;
    let j = |energy: f64| -> f64 {
        let k = (0.5 * energy).sqrt();
        let m = k * k;
        // Split where the edges fall in φ.
        let mut cuts = vec![-std::f64::consts::FRAC_PI_2];
        for &e in &edges {
            let s = (0.5 * e).sin() / k;
            if s.abs() < 1.0 {
                cuts.push(s.asin());
            }
        }
        cuts.push(std::f64::consts::FRAC_PI_2);
        cuts.windows(2)
            .map(|w| {
                integrate(
                    |phi| {
                        let s = k * phi.sin();
                        let theta = 2.0 * s.asin();
                        delta(theta) / (1.0 - m * phi.sin().powi(2)).sqrt()
                    },
                    w[0],
                    w[1],
                )
            })
            .sum()
    };
    let energy = 2.0 * (0.5 * a).sin().powi(2);
    let h = 1e-4 * energy;
    (j(energy + h) - j(energy - h)) / (2.0 * h)
}

/// Airy's small-angle form of [`time_shift`]: `(1/A²) ∫ δE'(θ) θ dτ`
/// over the half swing `θ = -A cos τ`, `τ` from 0 to π, with impulses as
/// steps of `δE` (integrated by parts: `(1/A²) ∫ δE(θ) dθ/dτ ...`); here
/// as `d/dE` of `∫ δE(A sin φ) dφ`, the same quadrature with `dθ/v = dφ`.
pub fn small_angle_time_shift(escapement: &dyn Escapement, a: f64, beat: u64, drive: f64) -> f64 {
    let edges = escapement.edges_on(beat);
    let total = escapement.energy(a, a, beat, drive);
    let delta = |theta: f64| given_by(escapement, &edges, a, theta, beat, drive) - 0.5 * total;
    let j = |amp: f64| -> f64 {
        let mut cuts = vec![-std::f64::consts::FRAC_PI_2];
        for &e in &edges {
            let s = e / amp;
            if s.abs() < 1.0 {
                cuts.push(s.asin());
            }
        }
        cuts.push(std::f64::consts::FRAC_PI_2);
        cuts.windows(2)
            .map(|w| integrate(|phi| delta(amp * phi.sin()), w[0], w[1]))
            .sum()
    };
    // E = A²/2 in the small-angle limit: d/dE = (1/A) d/dA.
    let h = 1e-4 * a;
    (j(a + h) - j(a - h)) / (2.0 * h) / a
}

/// The free pendulum's half period at amplitude `a`, scaled: `2 K(sin(a/2))`.
pub fn free_half_period(a: f64) -> f64 {
    Modulus::from_modular_angle(0.5 * a).map_or(f64::NAN, |m| 2.0 * ellipk_modulus(&m))
}
