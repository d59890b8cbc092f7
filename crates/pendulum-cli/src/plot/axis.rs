//! Axes: linear or logarithmic scales, ranges that follow the data but not
//! its spikes, and tick labels with the digits they need.
//!
//! Ranges are worked out in *axis units*: the value itself on a linear
//! axis, its base-10 logarithm on a log axis, so one rule serves both.

pub use pendulum_data::figure::Scale;

/// A closed interval in axis units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Span {
    /// The lower end.
    pub lo: f64,
    /// The upper end.
    pub hi: f64,
}

impl Span {
    /// Its width.
    pub fn width(self) -> f64 {
        self.hi - self.lo
    }

    /// Whether `u` lies in it.
    pub fn contains(self, u: f64) -> bool {
        u >= self.lo && u <= self.hi
    }
}

/// Data at least this many points long get robust limits.
const ROBUST_FROM: usize = 20;

/// The axis span for `models` (drawn whole: computed curves have no bad
/// values) and `data` (measured values, where a spike is more likely a
/// bad value than the truth), in axis units, with a margin of 5% of the
/// width either side.
///
/// The data's limits are robust: of n ≥ 20 values, the extremes of those
/// within the 1st and 99th percentiles (by rank) widened by the width
/// between them. A spike beyond is clipped to the frame and counted as
/// off-scale; a tail that continues the bulk is kept.
/// A flat range gets a width of 10% of its value (a unit when it is zero;
/// two decades on a log axis).
pub fn span(scale: Scale, models: &[f64], data: &[f64]) -> Span {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for &u in models {
        lo = lo.min(u);
        hi = hi.max(u);
    }
    if let Some((a, b)) = robust_limits(data) {
        lo = lo.min(a);
        hi = hi.max(b);
    }
    if !lo.is_finite() || !hi.is_finite() {
        return match scale {
            Scale::Linear => Span { lo: 0.0, hi: 1.0 },
            Scale::Log => Span { lo: -1.0, hi: 1.0 },
        };
    }
    let width = hi - lo;
    let flat = width <= 1e-12 * hi.abs().max(lo.abs()).max(f64::MIN_POSITIVE);
    if flat {
        let pad = match scale {
            Scale::Log => 1.0,
            Scale::Linear if lo == 0.0 => 1.0,
            Scale::Linear => 0.05 * lo.abs(),
        };
        return Span {
            lo: lo - pad,
            hi: hi + pad,
        };
    }
    Span {
        lo: lo - 0.05 * width,
        hi: hi + 0.05 * width,
    }
}

/// The robust limits of `values` (see [`span`]); `None` when empty.
fn robust_limits(values: &[f64]) -> Option<(f64, f64)> {
    if values.is_empty() {
        return None;
    }
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let n = sorted.len();
    let (min, max) = (sorted[0], sorted[n - 1]);
    if n < ROBUST_FROM {
        return Some((min, max));
    }
    let k = n / 100;
    let (a, b) = (sorted[k], sorted[n - 1 - k]);
    let w = b - a;
    // The extreme values kept: the frame ends at the data, not at the
    // fence.
    let lo = sorted.iter().copied().find(|&v| v >= a - w).unwrap_or(a);
    let hi = sorted
        .iter()
        .rev()
        .copied()
        .find(|&v| v <= b + w)
        .unwrap_or(b);
    Some((lo, hi))
}

/// The ticks of a log axis spanning `span` (axis units, so decades): 1, 2
/// and 5 times the powers of ten over up to three decades, the powers of
/// ten alone up to ten, every n-th power beyond; and within less than a
/// decade, evenly spaced round values (at least two ticks always).
pub fn log_ticks(span: Span) -> Vec<f64> {
    let decades = span.width();
    let (first, last) = (span.lo.floor() as i32, span.hi.ceil() as i32);
    let mantissas: &[f64] = if decades <= 1.0 {
        &[1.0, 1.5, 2.0, 3.0, 5.0, 7.0]
    } else if decades <= 3.0 {
        &[1.0, 2.0, 5.0]
    } else {
        &[1.0]
    };
    let every = (decades / 10.0).ceil().max(1.0) as i32;
    let (lo, hi) = (10_f64.powf(span.lo), 10_f64.powf(span.hi));
    let ticks: Vec<f64> = (first..=last)
        .filter(|k| k.rem_euclid(every) == 0)
        .flat_map(|k| mantissas.iter().map(move |m| m * 10_f64.powi(k)))
        .filter(|v| *v >= lo * (1.0 - 1e-12) && *v <= hi * (1.0 + 1e-12))
        .collect();
    if ticks.len() >= 2 {
        return ticks;
    }
    // Less than a decade: round steps of 1, 2 or 5 times a power of ten.
    let raw = (hi - lo) / 5.0;
    let power = 10_f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * power)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * power);
    let start = (lo / step).ceil() as i64;
    let end = (hi / step).floor() as i64;
    (start..=end).map(|i| i as f64 * step).collect()
}

/// The offset to take from a linear axis's tick labels when its values
/// differ only far down their digits (the middle more than 10⁴ spans from
/// zero: labels would need eight digits and more to tell ticks apart):
/// the middle rounded to the power of ten just above the span, so the
/// labels show the differences and the axis title the offset. `None` for
/// an axis its labels can show directly.
pub fn label_offset(lo: f64, hi: f64) -> Option<f64> {
    let span = hi - lo;
    let middle = 0.5 * (lo + hi);
    if !(span > 0.0 && span.is_finite() && middle.is_finite()) || middle.abs() <= 1e4 * span {
        return None;
    }
    let step = 10_f64.powf(span.log10().floor() + 1.0);
    Some((middle / step).round() * step)
}

/// An axis offset (from [`label_offset`]) as a plain decimal with the
/// digits down to the power of ten above `span` (`108.06759`, not
/// `1.0806759e2`).
pub fn offset_label(offset: f64, span: f64) -> String {
    let decimals = (-(span.log10().floor() + 1.0)).clamp(0.0, 15.0) as usize;
    let t = format!("{offset:.decimals$}");
    if t.contains('.') {
        t.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        t
    }
}

/// A log axis's tick label, in one form on every log axis of every
/// figure: a power of ten as `10ⁿ` (`10⁻⁴`, `10⁰`, `10³`), another tick
/// as its mantissa times one (`2×10⁻⁴`, `1.5×10²`), three significant
/// digits at most.
pub fn log_tick_label(value: f64) -> String {
    if !(value.is_finite() && value > 0.0) {
        return String::new();
    }
    let t = format!("{value:.2e}");
    let (mantissa, power) = t.split_once('e').unwrap_or((&t, "0"));
    let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
    let superscript = superscript(power);
    if mantissa == "1" {
        format!("10{superscript}")
    } else {
        format!("{mantissa}×10{superscript}")
    }
}

/// A tick label with the digits the axis needs and no more: rounded to a
/// hundredth of the axis's `span` (ticks fall at about a tenth of it), then
/// trailing zeros dropped (`1400`, `2.5`, never `1400.0`), and never `-0`.
/// Values of a million and more, or spans below 1e-4, as a mantissa times
/// a power of ten (`1.5×10⁻⁵`); negative values with a minus sign (`−3`).
pub fn tick_label(value: f64, span: f64) -> String {
    if !value.is_finite() {
        return String::new();
    }
    let magnitude = value.abs();
    let text = if magnitude >= 1e6 || (span > 0.0 && span < 1e-4 && magnitude > 0.0) {
        // Significant digits down to a hundredth of the span.
        let digits = if span > 0.0 && magnitude > 0.0 {
            (magnitude.log10().floor() - (span / 100.0).log10().floor() + 1.0).clamp(1.0, 12.0)
                as usize
        } else {
            3
        };
        let t = format!("{:.*e}", digits.saturating_sub(1), value);
        let (mantissa, exponent) = t.split_once('e').unwrap_or((&t, "0"));
        let mantissa = if mantissa.contains('.') {
            mantissa.trim_end_matches('0').trim_end_matches('.')
        } else {
            mantissa
        };
        let exponent = exponent.trim_start_matches('+');
        let digits = exponent.trim_start_matches('-').trim_start_matches('0');
        let power = superscript(if digits.is_empty() { "0" } else { digits });
        let sign = if exponent.starts_with('-') { "⁻" } else { "" };
        if mantissa == "1" || mantissa == "-1" {
            format!("{}10{sign}{power}", mantissa.trim_end_matches('1'))
        } else {
            format!("{mantissa}×10{sign}{power}")
        }
    } else {
        let decimals = if span > 0.0 {
            (-(span / 100.0).log10()).ceil().clamp(0.0, 12.0) as usize
        } else {
            6
        };
        let t = format!("{value:.decimals$}");
        if t.contains('.') {
            t.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            t
        }
    };
    if text
        .trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        "0".to_string()
    } else {
        // The minus sign, not a hyphen, as in every legend and title.
        text.replacen('-', "−", 1)
    }
}

/// The digits of `digits` as superscripts.
fn superscript(digits: &str) -> String {
    digits
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            '0' => '⁰',
            '1' => '¹',
            '2' => '²',
            '3' => '³',
            '4' => '⁴',
            '5' => '⁵',
            '6' => '⁶',
            '7' => '⁷',
            '8' => '⁸',
            '9' => '⁹',
            other => other,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tick_labels_carry_the_digits_they_need() {
        assert_eq!(tick_label(1400.0, 1000.0), "1400");
        assert_eq!(tick_label(2.5, 2.0), "2.5");
        assert_eq!(tick_label(2.0, 2.0), "2");
        assert_eq!(tick_label(-0.0, 1.0), "0");
        assert_eq!(tick_label(-1e-17, 1.0), "0");
        assert_eq!(tick_label(0.99362, 0.001), "0.99362");
        assert_eq!(tick_label(1.5e-5, 2e-5), "1.5×10⁻⁵");
        assert_eq!(tick_label(2.0e7, 1e7), "2×10⁷");
        assert_eq!(tick_label(1.0e7, 1e7), "10⁷");
        assert_eq!(tick_label(-3.25, 1.0), "−3.25");
        assert_eq!(tick_label(f64::NAN, 1.0), "");
    }

    #[test]
    fn a_spike_in_the_data_is_left_out_of_the_range_but_a_tail_is_kept() {
        // 200 values near 1 and one bad value of 1e6.
        let mut data: Vec<f64> = (0..200).map(|i| 1.0 + 1e-3 * f64::from(i % 7)).collect();
        data.push(1e6);
        let s = span(Scale::Linear, &[], &data);
        assert!(s.hi < 1.1 && s.lo > 0.9, "{s:?}");
        // An exponential decay's first values are its largest: all kept.
        let decay: Vec<f64> = (0..200)
            .map(|i| 3.0 * (-0.01 * f64::from(i)).exp())
            .collect();
        let s = span(Scale::Linear, &[], &decay);
        assert!(s.hi >= 3.0 && s.lo <= decay[199], "{s:?}");
        // Models are drawn whole.
        let s = span(Scale::Linear, &[0.0, 1e6], &data);
        assert!(s.hi >= 1e6);
    }

    #[test]
    fn an_axis_of_tiny_differences_is_labelled_from_an_offset() {
        // 108.06758 s/day varying in its eighth digit.
        let offset = label_offset(108.067_584, 108.067_588_2).unwrap();
        assert!((offset - 108.067_59).abs() < 1e-9, "{offset}");
        let span = 4.2e-6;
        assert_eq!(tick_label(108.067_586 - offset, span), "−4×10⁻⁶");
        assert_eq!(offset_label(offset, span), "108.06759");
        assert_eq!(offset_label(86_400.0, 0.5), "86400");
        // An ordinary axis needs none, nor one about zero.
        assert_eq!(label_offset(0.0, 20.0), None);
        assert_eq!(label_offset(1.0, 1.018), None);
        assert_eq!(label_offset(-1e-9, 1e-9), None);
    }

    #[test]
    fn log_tick_labels_take_one_form() {
        assert_eq!(log_tick_label(1e-4), "10⁻⁴");
        assert_eq!(log_tick_label(3.0 * 1e-5), "3×10⁻⁵");
        assert_eq!(log_tick_label(1.5e-3), "1.5×10⁻³");
        assert_eq!(log_tick_label(0.01), "10⁻²");
        assert_eq!(log_tick_label(20.0), "2×10¹");
        assert_eq!(log_tick_label(1.0), "10⁰");
        assert_eq!(log_tick_label(1e12), "10¹²");
    }

    #[test]
    fn log_ticks_are_round_and_never_repeat() {
        let t = log_ticks(Span { lo: 0.0, hi: 1.85 });
        assert_eq!(t, vec![1.0, 2.0, 5.0, 10.0, 20.0, 50.0]);
        // 13 decades: every second power of ten.
        let t = log_ticks(Span {
            lo: -15.2,
            hi: -1.9,
        });
        let exponents: Vec<i32> = t.iter().map(|v| v.log10().round() as i32).collect();
        assert_eq!(exponents, vec![-14, -12, -10, -8, -6, -4, -2]);
        // 8 decades: every one.
        let t = log_ticks(Span { lo: -9.5, hi: -1.9 });
        assert_eq!(t.len(), 8, "{t:?}");
        let t = log_ticks(Span {
            lo: -30.0,
            hi: 30.0,
        });
        assert!(t.len() <= 11 && t.len() >= 5, "{t:?}");
        // Within a decade: round linear steps.
        let t = log_ticks(Span { lo: 0.1, hi: 0.25 });
        assert!(t.len() >= 2, "{t:?}");
        for w in t.windows(2) {
            assert!(w[1] > w[0]);
        }
    }

    #[test]
    fn flat_and_empty_ranges_get_a_width() {
        let s = span(Scale::Linear, &[2.0, 2.0], &[]);
        assert!(s.lo < 2.0 && s.hi > 2.0);
        let s = span(Scale::Linear, &[0.0], &[]);
        assert_eq!((s.lo, s.hi), (-1.0, 1.0));
        let s = span(Scale::Log, &[], &[]);
        assert!(s.width() > 0.0);
        assert_eq!(Scale::Log.to_axis(-1.0), None);
        assert_eq!(Scale::Log.to_axis(100.0), Some(2.0));
    }
}
