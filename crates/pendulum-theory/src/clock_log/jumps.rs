//! Jumps and outliers of a log, before its rate is taken.
//!
//! Offsets: [`crate::stability::find_accidents`] (the finder `stability`
//! uses) finds the steps that stay and the samples read wrong and then
//! right; a glitch's samples are left out (the rate over the interval
//! that spans them is whole), a jump is taken back from every later
//! sample. A jump within 2% of a whole number of beats (the beat given,
//! or the smallest jump when every jump is such a multiple of it) is the
//! reference slipping a tick: a [`Wrap`]; another is named as a jump.
//! Rates: a rate beyond [`crate::stability::outliers::SIGMAS`] robust
//! standard deviations of its neighbours' is left out.

use crate::stability::outliers::{find_accidents, frequency_outliers, Accident, AccidentKind};

/// A jump of an offset series that is a whole beat: the reference's tick
/// compared with the clock's next tick slips by one beat.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Wrap {
    /// The log's time of the first sample after the jump, s.
    pub time_s: f64,
    /// The jump undone, s (a multiple of the beat).
    pub jump_s: f64,
}

/// What the cleaning did.
#[derive(Clone, Debug, Default)]
pub(crate) struct Cleaned {
    /// Samples to leave out.
    pub drop: Vec<bool>,
    /// Whole-beat slips undone.
    pub wraps: Vec<Wrap>,
    /// Other jumps undone and glitches left out.
    pub accidents: Vec<Accident>,
}

/// Cleans offsets `x` in place (jumps taken back) and says which samples
/// to leave out.
pub(crate) fn clean_offsets(times: &[f64], x: &mut [f64], beat: Option<f64>) -> Cleaned {
    let found = find_accidents(times, x);
    let mut cleaned = Cleaned {
        drop: vec![false; x.len()],
        ..Cleaned::default()
    };
    let jumps: Vec<f64> = found
        .iter()
        .filter(|a| a.kind == AccidentKind::Jump)
        .map(|a| a.size_s.abs())
        .collect();
    let whole = |size: f64, beat: f64| {
        let k = (size / beat).round();
        k >= 1.0 && (size / beat - k).abs() < 0.02 * k
    };
    let beat = beat.or_else(|| {
        let smallest = jumps.iter().copied().reduce(f64::min)?;
        jumps
            .iter()
            .all(|&s| whole(s, smallest))
            .then_some(smallest)
    });
    for a in found {
        match a.kind {
            AccidentKind::Glitch => {
                for d in &mut cleaned.drop[a.first_sample..a.first_sample + a.samples] {
                    *d = true;
                }
                cleaned.accidents.push(a);
            }
            AccidentKind::Jump => {
                let size = match beat {
                    Some(b) if whole(a.size_s.abs(), b) => {
                        let size = (a.size_s / b).round() * b;
                        cleaned.wraps.push(Wrap {
                            time_s: a.time_s,
                            jump_s: size,
                        });
                        size
                    }
                    _ => {
                        let size = a.size_s;
                        cleaned.accidents.push(a.clone());
                        size
                    }
                };
                for v in &mut x[a.first_sample..] {
                    *v -= size;
                }
            }
        }
    }
    cleaned
}

/// The rates (s/day) out of line with their neighbours: each one's index
/// and how far it is off, s/day ([`frequency_outliers`], the finder
/// `stability` uses on frequency data).
pub(crate) fn rate_outliers(rates: &[f64]) -> Vec<(usize, f64)> {
    frequency_outliers(rates)
}
