//! The exact period of the simple pendulum at any amplitude (seed section 1-6).
//!
//! `T = 4 sqrt(l/g) K(sin²(A0/2))`. Writing `K = π / (2 AGM(1, k'))` with
//! `k' = cos(A0/2)` (DLMF 19.8.5) gives the three forms used here:
//!
//! * the period ratio `T/T0 = 1 / AGM(1, k')`;
//! * the circular error `1 - T0/T = 1 - AGM(1, k')`, the fraction of time a
//!   clock loses against one swinging at vanishing amplitude, computed from
//!   the deficits of the AGM so that it keeps full relative accuracy at
//!   amplitudes of 1e-6 rad (where it is 6e-14);
//! * the slope of the circular error, `(k/2) dAGM(1, k')/dk'`, equal to
//!   `M² (E - k'²K) / (π k k')` with `M = AGM(1, k')` (DLMF 19.4.1), but
//!   computed by differentiating the AGM iteration, free of cancellation.
//!
//! Measured accuracy against mpmath at 40 digits (`tests/all/reference.rs`), over
//! amplitudes from 1e-8 to 179.9 degrees: the ratio and the period within
//! 3.2 ulp, the circular error within 3.3 ulp and its slope within 4.7 ulp.
//!
//! The seed's power series `T/T0 = Σ [(2n-1)!!/(2n)!!]² m^n` is here too
//! ([`period_ratio_series`]), with its truncation error, and the inverses:
//! the length for a period ([`length_for_period`]) and the amplitude a
//! measured period implies ([`amplitude_for_period`]).

pub mod inverse;
pub mod table;

use crate::elliptic::{agm_deficit, agm_with_derivative, ellipk_modulus};
use crate::error::{require_positive, InputError, Problem, Quantity};
use crate::pendulum::{Amplitude, Pendulum};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

// The period is a property of the pendulum, computed here: the pendulum
// module knows nothing of the period's theory (no import cycle).
impl Pendulum {
    /// The exact period at `amplitude`, `T = 4 sqrt(l/g) K(sin²(A0/2))`
    /// (seed section 1-6): the small-angle period times [`period_ratio`];
    /// the same accuracy (at most 4 ulp in the ratio, one rounding more).
    ///
    /// # Examples
    ///
    /// ```
    /// use pendulum_theory::{Amplitude, Pendulum};
    ///
    /// // The seconds pendulum, l = g/π² = 0.99362 m: 2 s at a small swing.
    /// let p = Pendulum::with_standard_gravity(0.99362)?;
    /// assert!((p.period(Amplitude::from_degrees(0.01)?) - 2.0).abs() < 1e-5);
    /// // At 90° either side the period is 2K(1/2)/π = 1.1803406 times as long.
    /// let ratio = p.period(Amplitude::from_degrees(90.0)?) / p.small_angle_period();
    /// assert!((ratio - 1.180_340_599_016).abs() < 1e-11);
    /// # Ok::<(), pendulum_theory::InputError>(())
    /// ```
    #[inline]
    pub fn period(&self, amplitude: Amplitude) -> f64 {
        self.small_angle_period() * period_ratio(amplitude)
    }
}

/// The period ratio `T/T0 = 2K(m)/π = 1/AGM(1, cos(A0/2))`.
///
/// 1 at zero amplitude, 1.0019 at 10°, 1.18 at 90°, and unbounded (like
/// `(2/π) ln(8/(π - A0))`) towards 180°. Measured error at most 4 ulp.
#[inline]
pub fn period_ratio(amplitude: Amplitude) -> f64 {
    ellipk_modulus(&amplitude.modulus()) / FRAC_PI_2
}

/// The circular error `1 - T0/T = 1 - AGM(1, cos(A0/2))`, dimensionless.
///
/// About `A0²/16` for small amplitudes. Computed without cancellation by
/// iterating the deficits of the AGM (see the module documentation), so it
/// keeps its relative accuracy down to amplitudes where it underflows
/// (`A0` near 1e-154 rad). Measured error at most 4 ulp.
pub fn circular_error(amplitude: Amplitude) -> f64 {
    let q = amplitude.modulus();
    agm_deficit(q.k(), q.k_prime())
}

/// Below this amplitude (rad) the slope's two-term Taylor series,
/// `A0/8 - A0³/768`, is exact to double precision: the next term is
/// `A0⁵/~10⁵` relative `A0⁴/~10⁴`, under 1e-32.
const SLOPE_SERIES_BELOW: f64 = 1e-7;

/// The derivative of the circular error with respect to amplitude, per
/// radian: `d(1 - T0/T)/dA0 = -dAGM(1, k')/dA0 = (k/2) dAGM(1, k')/dk'`,
/// since `dk'/dA0 = -k/2`.
///
/// The AGM's derivative comes from differentiating its iteration step by
/// step, a sum of positive terms; this equals
/// `M² (E - k'²K) / (π k k')` (DLMF 19.4.1) without forming `E - k'²K`,
/// which cancels at small amplitudes, or dividing by `k'`.
/// Measured error at most 4.7 ulp (near 180°, where an ulp of error in
/// `cos(A0/2)` alone moves the result by 1.3 ulp).
pub fn circular_error_slope(amplitude: Amplitude) -> f64 {
    let a = amplitude.radians();
    if a < SLOPE_SERIES_BELOW {
        return a / 8.0 * (1.0 - a * a / 96.0);
    }
    let q = amplitude.modulus();
    let (_, derivative) = agm_with_derivative(q.k_prime());
    0.5 * q.k() * derivative
}

/// The coefficient `c_n = [(2n-1)!! / (2n)!!]²` of the seed's series
/// `T/T0 = Σ_{n≥0} c_n m^n` (seed section 1-6; `c_0 = 1`, `c_1 = 1/4`,
/// `c_2 = 9/64`, `c_3 = 225/2304`, `c_4 = 11025/147456`; the seed prints
/// the last as 10125/147456, a misprint). Correctly rounded up to `n = 16`
/// (from the exact fraction), within `n/2` ulp above.
pub fn series_coefficient(n: u32) -> f64 {
    if let Some((num, den)) = series_coefficient_fraction(n) {
        return num as f64 / den as f64;
    }
    let mut c = 1.0_f64;
    for j in 1..=n {
        let r = f64::from(2 * j - 1) / f64::from(2 * j);
        c *= r * r;
    }
    c
}

/// The exact coefficient `[(2n-1)!!]² / [(2n)!!]²`, unreduced as the seed
/// writes it (`225/2304` for `n = 3`), for `n <= 16`; `None` above, where
/// the denominator no longer fits in 128 bits.
pub fn series_coefficient_fraction(n: u32) -> Option<(u128, u128)> {
    let (mut odd, mut even) = (1_u128, 1_u128);
    for j in 1..=u128::from(n) {
        odd = odd.checked_mul(2 * j - 1)?;
        even = even.checked_mul(2 * j)?;
    }
    Some((odd.checked_mul(odd)?, even.checked_mul(even)?))
}

/// The series truncated to `terms` terms, and how far it is from the exact value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SeriesEstimate {
    /// Number of terms kept (`c_0 .. c_{terms-1}`).
    pub terms: u32,
    /// The truncated sum, an estimate of `T/T0`.
    pub period_ratio: f64,
    /// `(T_series - T)/T`: negative, since every dropped term is positive.
    pub relative_error: f64,
    /// An upper bound on `|T_series - T| / T0` from the first dropped term:
    /// `c_N m^N / (1 - m)`, valid because `c_n` never increases.
    pub truncation_bound: f64,
}

/// The most terms [`period_ratio_series`] accepts.
pub const MAX_SERIES_TERMS: u32 = 100_000;

/// How many dropped terms are summed one by one before the tail is taken as
/// the difference from the exact value instead.
const TAIL_TERMS: u32 = 200_000;

/// The seed's series for `T/T0` to `terms` terms, with its error.
///
/// The error is the sum of the dropped terms, summed directly so that it
/// keeps its relative accuracy even when it is 1e-30; only when the terms
/// shrink too slowly (`m` above about 0.9998, amplitudes beyond 178°) is it
/// taken as `2K/π` minus the partial sum, which is then far from small.
pub fn period_ratio_series(amplitude: Amplitude, terms: u32) -> Result<SeriesEstimate, InputError> {
    if terms == 0 || terms > MAX_SERIES_TERMS {
        let problem = if terms == 0 {
            Problem::BelowMinimum { minimum: 1.0 }
        } else {
            Problem::AboveMaximum {
                maximum: f64::from(MAX_SERIES_TERMS),
            }
        };
        return Err(InputError::new(
            Quantity::SeriesTerms,
            f64::from(terms),
            problem,
        ));
    }
    let q = amplitude.modulus();
    let m = q.m();
    let mut coefficient = 1.0_f64;
    let mut power = 1.0_f64;
    let mut partial = 0.0_f64;
    for n in 0..terms {
        if n > 0 {
            coefficient *= coefficient_step(n);
            power *= m;
        }
        partial += coefficient * power;
    }
    let first_dropped = coefficient * coefficient_step(terms) * power * m;
    let truncation_bound = first_dropped / q.m_complement();
    let exact = period_ratio(amplitude);
    let tail = dropped_sum(coefficient, power, m, terms).unwrap_or(exact - partial);
    Ok(SeriesEstimate {
        terms,
        period_ratio: partial,
        relative_error: -tail / exact,
        truncation_bound,
    })
}

/// `c_n / c_{n-1} = ((2n-1)/(2n))²`.
fn coefficient_step(n: u32) -> f64 {
    let r = (2.0 * f64::from(n) - 1.0) / (2.0 * f64::from(n));
    r * r
}

/// `Σ_{n≥N} c_n m^n` given `c_{N-1}` and `m^{N-1}`, or `None` if it has not
/// converged within [`TAIL_TERMS`] terms.
fn dropped_sum(last_coefficient: f64, last_power: f64, m: f64, terms: u32) -> Option<f64> {
    let (mut coefficient, mut power) = (last_coefficient, last_power);
    let mut tail = 0.0_f64;
    for n in terms..terms.saturating_add(TAIL_TERMS) {
        coefficient *= coefficient_step(n);
        power *= m;
        let term = coefficient * power;
        tail += term;
        if term <= 0.25 * f64::EPSILON * tail || term == 0.0 {
            return Some(tail);
        }
    }
    None
}

/// The length whose period is `period_s` at `amplitude` under `g_m_s2`:
/// `l = g (T AGM(1, k') / 2π)²`, the exact period formula solved for `l`.
pub fn length_for_period(
    period_s: f64,
    amplitude: Amplitude,
    g_m_s2: f64,
) -> Result<f64, InputError> {
    let period = require_positive(Quantity::Period, period_s)?;
    let g = require_positive(Quantity::Gravity, g_m_s2)?;
    let small_angle_period = period / period_ratio(amplitude);
    let root = small_angle_period / TAU;
    let length = g * root * root;
    if !length.is_finite() || length == 0.0 {
        // Periods beyond about 1e150 s (or below 1e-150 s) give lengths
        // outside the range of double precision.
        return Err(InputError::new(
            Quantity::Period,
            period,
            Problem::ResultOverflows {
                result: "the length",
            },
        ));
    }
    Ok(length)
}

/// Seconds in an hour, for beat rates.
const SECONDS_PER_HOUR: f64 = 3600.0;

/// The period of a clock beating `beats_per_hour` times an hour: each beat
/// is half a period, so `T = 7200 / bph` s.
pub fn period_for_beat_rate(beats_per_hour: f64) -> Result<f64, InputError> {
    let period = 2.0 * SECONDS_PER_HOUR / require_positive(Quantity::BeatRate, beats_per_hour)?;
    if !period.is_finite() {
        return Err(InputError::new(
            Quantity::BeatRate,
            beats_per_hour,
            Problem::ResultOverflows {
                result: "the period",
            },
        ));
    }
    Ok(period)
}

/// Beats per hour of a clock with period `period_s`: `7200 / T`.
pub fn beats_per_hour(period_s: f64) -> f64 {
    2.0 * SECONDS_PER_HOUR / period_s
}

/// The beat (half a period) of a clock with period `period_s`, which must
/// be positive.
pub fn beat_of_period(period_s: f64) -> Result<f64, InputError> {
    Ok(0.5 * require_positive(Quantity::Period, period_s)?)
}

/// The amplitude that a measured period implies, with how well it is determined.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AmplitudeEstimate {
    /// The amplitude.
    pub amplitude: Amplitude,
    /// `|d ln A0 / d ln T|`: the relative error of the amplitude per unit
    /// relative error of the period. About `8/A0²` for small amplitudes
    /// (1e13 at 1e-6 rad: a period known to 1e-16 then fixes A0 to 1e-3),
    /// small near 180°. Infinite when the period equals `T0`.
    pub condition_number: f64,
}

/// Solves `T(A0) = period_s` for the amplitude of `pendulum`.
///
/// Method: Newton's iteration on the circular error `1 - T0/T` (or, past
/// 1/2, on `T0/T` itself, which then keeps more digits), safeguarded by
/// bisection on `[0, π)`. The target `1 - T0/T` is formed as `(T - T0)/T`;
/// the rounding of `T0` in that difference is the whole of the
/// ill-conditioning at small amplitudes, and `condition_number` says how
/// much it matters.
pub fn amplitude_for_period(
    pendulum: &Pendulum,
    period_s: f64,
) -> Result<AmplitudeEstimate, InputError> {
    let period = require_positive(Quantity::Period, period_s)?;
    let small_angle_period = pendulum.small_angle_period();
    if period < small_angle_period {
        return Err(InputError::new(
            Quantity::Period,
            period,
            Problem::PeriodBelowSmallAngle { small_angle_period },
        ));
    }
    let deficit = (period - small_angle_period) / period;
    let ratio = small_angle_period / period;
    let radians = solve_amplitude(deficit, ratio);
    let amplitude = Amplitude::from_radians(radians)?;
    Ok(AmplitudeEstimate {
        amplitude,
        condition_number: amplitude_condition_number(amplitude),
    })
}

/// `|d ln A0 / d ln T| = (1 - c) / (A0 dc/dA0)`, with `c` the circular
/// error: `T = T0 / (1 - c)` so `d ln T = dc / (1 - c)`.
pub fn amplitude_condition_number(amplitude: Amplitude) -> f64 {
    let a = amplitude.radians();
    if a == 0.0 {
        return f64::INFINITY;
    }
    (1.0 - circular_error(amplitude)) / (a * circular_error_slope(amplitude))
}

/// Finds `A0` in `[0, π)` with `1 - AGM(1, cos(A0/2)) = deficit`
/// (equivalently `AGM = ratio`).
fn solve_amplitude(deficit: f64, ratio: f64) -> f64 {
    if deficit <= 0.0 {
        return 0.0;
    }
    let use_ratio = deficit > 0.5;
    // f(A) increases with A in both forms.
    let residual = |a: f64| {
        let amp = Amplitude::from_radians(a).expect("bracketed in [0, π)");
        if use_ratio {
            ratio - (1.0 - circular_error(amp))
        } else {
            circular_error(amp) - deficit
        }
    };
    let (mut low, mut high) = (0.0_f64, PI.next_down());
    let mut a = initial_amplitude(deficit, ratio).clamp(low, high);
    for _ in 0..200 {
        let f = residual(a);
        if f == 0.0 {
            return a;
        }
        if f > 0.0 {
            high = a;
        } else {
            low = a;
        }
        let slope = circular_error_slope(Amplitude::from_radians(a).expect("in range"));
        let newton = a - f / slope;
        let next = if newton > low && newton < high && slope > 0.0 {
            newton
        } else {
            0.5 * (low + high)
        };
        if (next - a).abs() <= f64::EPSILON * a || high - low <= f64::EPSILON * high {
            return next;
        }
        a = next;
    }
    a
}

/// A starting point: `c ≈ A0²/16` for small amplitudes; near 180°,
/// `AGM(1, k') ≈ π / (2 ln(4/k'))` gives `k' ≈ 4 exp(-π / (2 AGM))`.
fn initial_amplitude(deficit: f64, ratio: f64) -> f64 {
    if deficit < 0.1 {
        4.0 * deficit.sqrt()
    } else {
        let k_prime = (4.0 * (-FRAC_PI_2 / ratio).exp()).min(1.0);
        2.0 * k_prime.acos()
    }
}

/// Everything the seed's section 1-6 says about one pendulum at one amplitude.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PeriodAnalysis {
    /// The pendulum.
    pub pendulum: Pendulum,
    /// The amplitude.
    pub amplitude: Amplitude,
    /// The exact period `T`, s.
    pub period_s: f64,
    /// The small-angle period `T0 = 2π sqrt(l/g)`, s.
    pub small_angle_period_s: f64,
    /// `T/T0`.
    pub period_ratio: f64,
    /// Beats per hour, `7200/T` (a beat is half a period).
    pub beats_per_hour: f64,
    /// `1 - T0/T`, dimensionless.
    pub circular_error: f64,
    /// `d(1 - T0/T)/dA0`, per radian.
    pub circular_error_slope_per_rad: f64,
    /// The seed's power series to the requested number of terms.
    pub series: SeriesEstimate,
}

/// The beat the clock is meant to keep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Nominal {
    /// Beats per hour (field `bph`).
    BeatsPerHour(f64),
    /// The pendulum's full period, s (field `period`).
    Period(f64),
}

impl Nominal {
    /// The beat given as a beat rate (`bph`) or a period, or neither;
    /// both is refused (the command line's flags conflict, Python and the
    /// page say so in these words).
    pub fn given(
        bph: Option<f64>,
        period: Option<f64>,
    ) -> Result<Option<Self>, crate::analysis::Refusal> {
        match (bph, period) {
            (Some(_), Some(_)) => Err(crate::analysis::Refusal::data(
                "give bph or period, not both",
            )),
            (Some(b), None) => Ok(Some(Nominal::BeatsPerHour(b))),
            (None, Some(p)) => Ok(Some(Nominal::Period(p))),
            (None, None) => Ok(None),
        }
    }

    /// The input's field name.
    pub fn field(self) -> &'static str {
        match self {
            Nominal::BeatsPerHour(_) => "bph",
            Nominal::Period(_) => "period",
        }
    }

    /// The nominal beat, s, or the refusal of the value.
    pub fn beat(self) -> Result<f64, crate::analysis::Refusal> {
        match self {
            Nominal::BeatsPerHour(b) => period_for_beat_rate(b)
                .and_then(beat_of_period)
                .map_err(|e| crate::analysis::Refusal::input("bph", &e)),
            Nominal::Period(p) => {
                beat_of_period(p).map_err(|e| crate::analysis::Refusal::input("period", &e))
            }
        }
    }
}

/// Seconds in a day, for rates in s/day.
pub const SECONDS_PER_DAY: f64 = 86_400.0;

impl PeriodAnalysis {
    /// Analyses `pendulum` swinging at `amplitude`, with the series to `series_terms` terms.
    pub fn new(
        pendulum: Pendulum,
        amplitude: Amplitude,
        series_terms: u32,
    ) -> Result<Self, InputError> {
        let small_angle_period_s = pendulum.small_angle_period();
        let ratio = period_ratio(amplitude);
        let period_s = small_angle_period_s * ratio;
        Ok(Self {
            pendulum,
            amplitude,
            period_s,
            small_angle_period_s,
            period_ratio: ratio,
            beats_per_hour: beats_per_hour(period_s),
            circular_error: circular_error(amplitude),
            circular_error_slope_per_rad: circular_error_slope(amplitude),
            series: period_ratio_series(amplitude, series_terms)?,
        })
    }

    /// What the clock loses per day against one at vanishing amplitude, s/day.
    pub fn circular_error_s_per_day(&self) -> f64 {
        SECONDS_PER_DAY * self.circular_error
    }

    /// The change of [`Self::circular_error_s_per_day`] per degree of amplitude.
    pub fn circular_error_s_per_day_per_deg(&self) -> f64 {
        SECONDS_PER_DAY * self.circular_error_slope_per_rad * PI / 180.0
    }

    /// The period the truncated series predicts, s.
    pub fn series_period_s(&self) -> f64 {
        self.small_angle_period_s * self.series.period_ratio
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn deg(d: f64) -> Amplitude {
        Amplitude::from_degrees(d).unwrap()
    }

    #[test]
    fn seed_coefficients_with_the_misprint_corrected() {
        assert_eq!(series_coefficient_fraction(0), Some((1, 1)));
        assert_eq!(series_coefficient_fraction(1), Some((1, 4)));
        assert_eq!(series_coefficient_fraction(2), Some((9, 64)));
        assert_eq!(series_coefficient_fraction(3), Some((225, 2304)));
        assert_eq!(series_coefficient_fraction(4), Some((11025, 147456)));
        assert!(series_coefficient_fraction(16).is_some());
        assert!(series_coefficient_fraction(17).is_none());
        assert_eq!(series_coefficient(4), 11025.0 / 147456.0);
    }

    #[test]
    fn series_converges_to_exact() {
        let a = deg(60.0);
        let s = period_ratio_series(a, 60).unwrap();
        assert!((s.period_ratio - period_ratio(a)).abs() < 4.0 * f64::EPSILON);
        let s3 = period_ratio_series(a, 3).unwrap();
        assert!(s3.relative_error < 0.0);
        let actual = (s3.period_ratio - period_ratio(a)) / period_ratio(a);
        assert!((s3.relative_error - actual).abs() < 1e-12);
        assert!(-s3.relative_error * period_ratio(a) <= s3.truncation_bound);
    }

    #[test]
    fn series_refuses_zero_terms() {
        assert!(period_ratio_series(deg(5.0), 0).is_err());
        assert!(period_ratio_series(deg(5.0), MAX_SERIES_TERMS + 1).is_err());
    }

    #[test]
    fn amplitude_inversion_round_trips() {
        let p = Pendulum::with_standard_gravity(0.99362).unwrap();
        for &d in &[1e-3, 0.5, 3.0, 45.0, 90.0, 150.0, 179.0, 179.99] {
            let a = deg(d);
            let est = amplitude_for_period(&p, p.period(a)).unwrap();
            let err = (est.amplitude.radians() - a.radians()).abs() / a.radians();
            let allowed = 8.0 * f64::EPSILON * est.condition_number.max(1.0);
            assert!(
                err <= allowed,
                "{d} deg: rel err {err:e}, allowed {allowed:e}"
            );
        }
    }

    #[test]
    fn period_below_small_angle_is_refused() {
        let p = Pendulum::with_standard_gravity(1.0).unwrap();
        let e = amplitude_for_period(&p, 0.99 * p.small_angle_period()).unwrap_err();
        assert_eq!(e.quantity, Quantity::Period);
    }
}
