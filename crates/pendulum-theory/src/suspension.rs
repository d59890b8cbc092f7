//! The suspension spring: a thin flat strip clamped in the chops at its
//! top and to the pendulum at its bottom, carrying the pendulum's weight.
//!
//! A strip of bending stiffness `EI` (`I = w t³/12` for width `w` and
//! thickness `t` in the plane of swing) under tension `T` bends only
//! within about `λ = sqrt(EI/T)` of its ends, the bending length: the
//! small deflection `x(z)` of the strip obeys `EI x'''' - T x'' = 0`
//! (Euler-Bernoulli with tension; Timoshenko & Gere, *Theory of Elastic
//! Stability*, 2nd ed., §1.11), so it is a sum of `1`, `z` and `e^{±z/λ}`.
//! Clamped at the top (`x = x' = 0`) and meeting the pendulum at the
//! bottom with displacement `x_L` and slope `θ` (the pendulum's angle), the
//! strip stores the energy `½ (EI ∫x''² + T ∫x'²)` (the second term is the
//! work of lifting the weight as the strip tilts), a quadratic form in
//! `(x_L, θ)` whose coefficients are closed forms in `a = L/λ`
//! ([`Strip::stiffness`]). With the pendulum below (a rigid body of mass
//! `M`, its centre `d` below the strip's bottom, inertia `I_c` about that
//! centre, weight `T = M g`) the small swings are those of two degrees of
//! freedom, `x_L` and `θ`; the lower of their two frequencies is the
//! pendulum's ([`effect`]).
//!
//! What the strip does, against a pendulum rigid about the chops:
//! - it turns about a point about `λ` below the chops (the strip is straight
//!   below its top bend), so the pendulum is shorter: a gain;
//! - its bending adds a restoring torque of its own: `EI ∂ω²/∂EI` is the
//!   elastic share of the restoring stiffness (the "dilution" of the
//!   gravitational suspensions of physics, Saulson, Phys. Rev. D 42, 2437,
//!   1990), about `λ/(2l)` for a pendulum of length `l`;
//! - through the elastic share, the spring's temperature coefficient: `EI`
//!   changes with the modulus's thermoelastic coefficient `β` and with the
//!   strip's expansion (`4α`: width and the cube of the thickness), so the
//!   rate moves by `½ ε (β + 4α)` of a day per kelvin (and `λ` moves the
//!   pivot).
//!
//! Method and error: the strip's energy in closed form (the functions of
//! `a` written without cancellation: `g(u) = u - tanh u` by its Taylor
//! series below `u = 1/4`, to 4e-16), the frequencies of the 2x2 problem
//! by the quadratic formula in the form without cancellation. Against the
//! closed forms of its limits (tests): the point mass on a strip, whose
//! effective length is `L - λ tanh(L/λ)`, to 1e-12; a strip of no
//! stiffness, the rigid body on a string, to 1e-6 at `λ = 10⁻⁹ L`; a strip
//! without tension, the cantilever, and a strip clamped at both ends,
//! González's `T/(L - 2λ)` (Class. Quantum Grav. 17, 4409, 2000). A strip
//! much stiffer than its tension (`λ` beyond `L`) is not a pivot but a
//! cantilever the pendulum bends: the design's datasheet warns of it. The
//! strip's own mass
//! and the elastica's nonlinearity at large angles are left out: the
//! spring's mass is a part of the design, and its bending at 3° is
//! linear to 1e-4.
//!
//! At a finite swing the spring changes the circular error: its torque is
//! linear in the angle where gravity's is `sin θ`, so a pendulum of elastic
//! share `ε` keeps `θ'' = -ω²[(1 - ε) sin θ + ε θ]` and its period grows
//! with the amplitude by `1 - ε` of a rigid pendulum's
//! ([`period_ratio`]): the spring shrinks the circular error. (The
//! elastica's own nonlinearity adds a term of order `ε A²` relative to the
//! elastic torque, `ε² A²/16`-sized in the period: under 1e-8 of it for a
//! regulator's spring at 3°.)

use crate::analysis::{require_finite, Refusal};

/// The period at semi-arc `amplitude` (rad, below π) over the small-swing
/// period of a pendulum whose restoring torque is the share `elastic_share`
/// (ε, 0 to 1) of a linear spring's and the rest gravity's:
/// `θ'' = -ω²[(1 - ε) sin θ + ε θ]`, so
/// `T/T0 = (2/π) ∫₀^{π/2} dφ / sqrt((1 - ε) sinc(u) sinc(v) + ε)` with
/// `θ = A sin φ`, `u = (A + θ)/2`, `v = (A - θ)/2` (the energy integral,
/// written with `cos θ - cos A = 2 sin u sin v` so that nothing cancels).
///
/// Method: the integrand is even and analytic about both ends, so the
/// trapezoidal rule converges geometrically (Trefethen & Weideman, SIAM
/// Review 56, 385, 2014); the number of points doubles from 8 until two
/// estimates agree to 2 ulp (16 to 64 points to 90°). Measured error: ε =
/// 0 is the crate's AGM ([`crate::period::period_ratio`]) within 2 ulp to
/// 150°; ε = 1 is 1; the small-angle slope is `(1 - ε)/16`; against the
/// integrated equation of motion within 1e-12 (`tests/all/suspension.rs`).
pub fn period_ratio(amplitude: f64, elastic_share: f64) -> f64 {
    let a = amplitude.abs();
    let e = elastic_share.clamp(0.0, 1.0);
    if a.is_nan() || a >= std::f64::consts::PI {
        return f64::NAN;
    }
    if a == 0.0 || e == 1.0 {
        return 1.0;
    }
    let sinc = |x: f64| if x == 0.0 { 1.0 } else { x.sin() / x };
    let f = |phi: f64| {
        let theta = a * phi.sin();
        let (u, v) = (0.5 * (a + theta), 0.5 * (a - theta));
        1.0 / ((1.0 - e) * sinc(u) * sinc(v) + e).sqrt()
    };
    let half_pi = std::f64::consts::FRAC_PI_2;
    // Trapezoid on [0, π/2] with n intervals, refined by halving (reusing
    // the points already summed).
    let mut n = 8usize;
    let mut sum = 0.5 * (f(0.0) + f(half_pi))
        + (1..n)
            .map(|k| f(half_pi * k as f64 / n as f64))
            .sum::<f64>();
    let mut estimate = sum / n as f64;
    while n < 1 << 16 {
        let added: f64 = (0..n)
            .map(|k| f(half_pi * (2 * k + 1) as f64 / (2 * n) as f64))
            .sum();
        sum += added;
        n *= 2;
        let next = sum / n as f64;
        let settled = (next - estimate).abs() <= 4.0 * f64::EPSILON * next;
        estimate = next;
        if settled {
            break;
        }
    }
    estimate
}

use crate::error::format_significant;

/// Seconds in a day (the period module builds on this one, so the
/// constant is not taken from it).
const SECONDS_PER_DAY: f64 = 86_400.0;

/// A flat suspension strip (or several side by side: give their summed
/// width).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Strip {
    /// Free length between the chops and the pendulum's block, m.
    pub length: f64,
    /// Width across the plane of swing, m.
    pub width: f64,
    /// Thickness in the plane of swing, m.
    pub thickness: f64,
    /// Young's modulus, Pa.
    pub modulus: f64,
}

/// The pendulum below the strip, as a rigid body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Body {
    /// Mass, kg (its weight is the strip's tension).
    pub mass: f64,
    /// Its centre of mass below the strip's bottom, m (0 with no inertia:
    /// a point mass at the strip's end).
    pub centre: f64,
    /// Moment of inertia about its centre of mass, kg m².
    pub inertia: f64,
}

/// What the strip does to the pendulum.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpringEffect {
    /// The bending length `sqrt(EI/T)`, m.
    pub bending_length: f64,
    /// The strip's bending stiffness `EI`, N m².
    pub bending_stiffness: f64,
    /// The point the pendulum turns about, below the chops, m.
    pub effective_pivot: f64,
    /// The pendulum's angular frequency on the strip, rad/s.
    pub omega: f64,
    /// The same pendulum rigid about the chops, rad/s.
    pub rigid_omega: f64,
    /// The rate against the rigid pendulum, s/day (positive: gaining).
    pub rate: f64,
    /// The elastic share of the restoring stiffness, `∂ ln ω² / ∂ ln EI`.
    pub elastic_share: f64,
    /// The strip's own mode (the pendulum rocking on it), Hz; `None` for
    /// a point mass at the strip's end, which cannot rock.
    pub second_mode_hz: Option<f64>,
}

/// `u - tanh u`, without cancellation: below 1/4 its Taylor series (the
/// coefficients of `tanh`, DLMF 4.33.3 with the Bernoulli numbers, to
/// `u^21`), above it the difference itself; measured against mpmath at 40
/// digits: within 3.5e-16 below 1/4, 8.8e-15 from 1/4 to 4.
fn u_minus_tanh(u: f64) -> f64 {
    if u.abs() >= 0.25 {
        return u - u.tanh();
    }
    const C: [f64; 10] = [
        1.0 / 3.0,
        -2.0 / 15.0,
        17.0 / 315.0,
        -62.0 / 2835.0,
        1382.0 / 155_925.0,
        -21_844.0 / 6_081_075.0,
        929_569.0 / 638_512_875.0,
        -6_404_582.0 / 10_854_718_875.0,
        443_861_162.0 / 1_856_156_927_625.0,
        -18_888_466_084.0 / 194_896_477_400_625.0,
    ];
    let u2 = u * u;
    let mut sum = 0.0;
    for c in C.iter().rev() {
        sum = sum * u2 + c;
    }
    sum * u2 * u
}

impl Strip {
    /// `EI = E w t³ / 12`, N m².
    pub fn bending_stiffness(&self) -> f64 {
        self.modulus * self.width * self.thickness.powi(3) / 12.0
    }

    /// The strip's energy as a quadratic form in its bottom's displacement
    /// `x_L` (m) and slope `θ` (rad) under tension `tension` (N): `[k11,
    /// k12, k22]` of `½ (k11 x_L² + 2 k12 x_L θ + k22 θ²)`. With `u =
    /// L/(2λ)` and `g(u) = u - tanh u`: `k11 = T / (2λ g(u))`, `k12 = -T
    /// tanh(u) / (2 g(u))`, `k22 = T λ g(2u) / (2 tanh(2u) g(u))` (their
    /// limits without tension are the cantilever's `12EI/L³`, `-6EI/L²`,
    /// `4EI/L`).
    pub fn stiffness(&self, tension: f64) -> [f64; 3] {
        let lambda = (self.bending_stiffness() / tension).sqrt();
        let u = 0.5 * self.length / lambda;
        let g = u_minus_tanh(u);
        let t = tension;
        [
            t / (2.0 * lambda * g),
            -t * u.tanh() / (2.0 * g),
            t * lambda * u_minus_tanh(2.0 * u) / (2.0 * (2.0 * u).tanh() * g),
        ]
    }
}

/// The two frequencies² of `det(K - ω² M) = 0` for symmetric 2x2 `K` and
/// `M` (`[a11, a12, a22]`), ascending; the smaller by `2c / (b + sqrt(b² -
/// 4ac))`, free of cancellation; the larger `None` when `M` is singular
/// (one degree of freedom without inertia).
fn frequencies(k: [f64; 3], m: [f64; 3]) -> (f64, Option<f64>) {
    let a = m[0] * m[2] - m[1] * m[1];
    let b = m[0] * k[2] + m[2] * k[0] - 2.0 * m[1] * k[1];
    let c = k[0] * k[2] - k[1] * k[1];
    let root = (b * b - 4.0 * a * c).max(0.0).sqrt();
    let low = 2.0 * c / (b + root);
    let high = (b + root) / (2.0 * a);
    (
        low,
        (a > 1e-12 * m[0] * m[2].max(f64::MIN_POSITIVE) && high.is_finite()).then_some(high),
    )
}

/// The pendulum `body` on `strip` in gravity `g` (see the module notes):
/// its frequency, the point it turns about, its rate against the same
/// pendulum rigid about the chops, and the elastic share.
pub fn effect(strip: &Strip, body: &Body, g: f64) -> Result<SpringEffect, Refusal> {
    let positive = |field: &'static str, v: f64, unit: &str| -> Result<f64, Refusal> {
        let v = require_finite(field, v)?;
        if v > 0.0 {
            Ok(v)
        } else {
            Err(Refusal::field(
                field,
                format!("must be positive, got {} {unit}", format_significant(v, 6)),
            ))
        }
    };
    positive("length", strip.length, "m")?;
    positive("width", strip.width, "m")?;
    positive("thickness", strip.thickness, "m")?;
    positive("modulus", strip.modulus, "Pa")?;
    positive("mass", body.mass, "kg")?;
    positive("g", g, "m/s²")?;
    let not_negative = |field: &'static str, v: f64, unit: &str| -> Result<f64, Refusal> {
        let v = require_finite(field, v)?;
        if v >= 0.0 {
            Ok(v)
        } else {
            Err(Refusal::field(
                field,
                format!(
                    "must not be negative, got {} {unit}",
                    format_significant(v, 6)
                ),
            ))
        }
    };
    let d = not_negative("centre", body.centre, "m")?;
    let i_c = not_negative("inertia", body.inertia, "kg m²")?;
    let m = body.mass;
    let tension = m * g;
    let masses = [m, m * d, m * d * d + i_c];
    let omega2 = |strip: &Strip| -> (f64, Option<f64>, [f64; 3]) {
        let k = strip.stiffness(tension);
        let (low, high) = frequencies([k[0], k[1], k[2] + m * g * d], masses);
        (low, high, k)
    };
    let (low, high, k) = omega2(strip);
    // The low mode's shape: (K - ω² M) v = 0, first row.
    let (k11, k12) = (k[0] - low * masses[0], k[1] - low * masses[1]);
    let x_per_theta = -k12 / k11;
    let length_total = strip.length + d;
    let rigid = m * g * length_total / (i_c + m * length_total * length_total);
    // The elastic share by a central difference in EI (the modulus), 1e-4.
    let h = 1e-4;
    let scaled = |f: f64| Strip {
        modulus: strip.modulus * f,
        ..*strip
    };
    let share = ((omega2(&scaled(1.0 + h)).0).ln() - (omega2(&scaled(1.0 - h)).0).ln())
        / ((1.0 + h).ln() - (1.0 - h).ln());
    let omega = low.sqrt();
    let rigid_omega = rigid.sqrt();
    Ok(SpringEffect {
        bending_length: (strip.bending_stiffness() / tension).sqrt(),
        bending_stiffness: strip.bending_stiffness(),
        effective_pivot: strip.length - x_per_theta,
        omega,
        rigid_omega,
        rate: SECONDS_PER_DAY * (omega / rigid_omega - 1.0),
        elastic_share: share,
        second_mode_hz: high.map(|w2| w2.sqrt() / (2.0 * std::f64::consts::PI)),
    })
}

/// What an analysis that swings a design hanging from a suspension spring
/// as a rigid pendulum of its equivalent length (the same small-swing
/// period; `simulate`, `amplitude`, `fit`) leaves out at semi-arc
/// `amplitude` rad: the spring shrinks the circular error by its elastic
/// share `share` ([`period_ratio`]). `None` when the two circular errors
/// differ by under 1e-3 s/day (a rigid pivot, a vanishing swing, a
/// regulator's spring at a degree), else the warning with both figures.
pub fn rigid_swing_warning(share: f64, amplitude: f64) -> Option<String> {
    if !(share > 0.0 && share < 1.0 && amplitude.is_finite() && amplitude > 0.0) {
        return None;
    }
    let day = SECONDS_PER_DAY;
    let rigid = day * (1.0 - 1.0 / period_ratio(amplitude, 0.0));
    let spring = day * (1.0 - 1.0 / period_ratio(amplitude, share));
    ((rigid - spring).abs() >= 1e-3).then(|| {
        format!(
            "the design hangs from a suspension spring (elastic share {}): this takes it as a rigid \
             pendulum of its equivalent length, whose circular error at {}° is {} s/day \
             where the spring's is {} s/day (`period`, `amplitude` and `clock` with `--design` take the \
             spring's)",
            format_significant(share, 3),
            format_significant(amplitude.to_degrees(), 4),
            format_significant(rigid, 4),
            format_significant(spring, 4)
        )
    })
}

/// A given elastic share checked (none: a rigid pivot, 0): finite, from 0
/// to below 1 (a share of 1 would leave gravity nothing to do), refused by
/// the input's name `elastic_share`.
pub fn elastic_share(given: Option<f64>) -> Result<f64, Refusal> {
    let Some(e) = given else { return Ok(0.0) };
    let e = require_finite("elastic_share", e)?;
    if (0.0..1.0).contains(&e) {
        Ok(e)
    } else {
        Err(Refusal::field(
            "elastic_share",
            format!(
                "must lie from 0 to below 1 (the spring's share of the restoring torque), got {}",
                format_significant(e, 6)
            ),
        ))
    }
}
