//! A clock's going train: from wheel and pinion counts to the beat, and
//! back.
//!
//! An arbor turning `n` times an hour drives, through wheels of `W_i`
//! teeth meshing with pinions of `p_i` leaves, an escape wheel of `E`
//! teeth; each tooth of the escape wheel passes in two beats (one per
//! pallet), so the beats per hour are `2 E n Π W_i / Π p_i` (e.g. Rawlings,
//! The Science of Clocks and Watches, 3rd ed., 1993, ch. 6). The period
//! of the pendulum is two beats.

pub mod analysis;

/// Beats per hour of a train: wheels `wheels` (the last is the escape
/// wheel), pinions `pinions` (one fewer), the first arbor turning
/// `arbor_turns_per_hour` times an hour. `None` for a mismatched count or
/// a zero.
pub fn beats_per_hour(wheels: &[u32], pinions: &[u32], arbor_turns_per_hour: f64) -> Option<f64> {
    if wheels.len() != pinions.len() + 1
        || wheels.iter().chain(pinions).any(|&c| c == 0)
        || !(arbor_turns_per_hour > 0.0 && arbor_turns_per_hour.is_finite())
    {
        return None;
    }
    let (escape, driving) = wheels.split_last()?;
    let ratio: f64 = driving
        .iter()
        .zip(pinions)
        .map(|(&w, &p)| f64::from(w) / f64::from(p))
        .product();
    Some(2.0 * f64::from(*escape) * ratio * arbor_turns_per_hour)
}

/// The wheels [`trains_for`] tries, teeth.
pub const WHEEL_TEETH: std::ops::RangeInclusive<u32> = 40..=120;
/// The pinions [`trains_for`] tries, leaves.
pub const PINION_LEAVES: std::ops::RangeInclusive<u32> = 6..=16;

/// The wheel and pinion pairs, from common counts, of a two-wheel train
/// (centre wheel, third wheel, then the escape wheel of `escape_teeth`)
/// that give `bph` within `tolerance` (relative), at most `limit`: closest
/// first, then those whose pinions are nearest the commonest 8 leaves,
/// then the larger centre wheel. Wheels of 40 to 120 teeth, pinions of 6
/// to 16 leaves.
pub fn trains_for(
    bph: f64,
    escape_teeth: u32,
    tolerance: f64,
    limit: usize,
) -> Vec<([u32; 3], [u32; 2], f64)> {
    let mut found = Vec::new();
    for w1 in WHEEL_TEETH {
        for p1 in PINION_LEAVES {
            for w2 in WHEEL_TEETH {
                for p2 in PINION_LEAVES {
                    if let Some(b) = beats_per_hour(&[w1, w2, escape_teeth], &[p1, p2], 1.0) {
                        let error = b / bph - 1.0;
                        if error.abs() <= tolerance && w1 >= w2 {
                            found.push(([w1, w2, escape_teeth], [p1, p2], b));
                        }
                    }
                }
            }
        }
    }
    let leaves = |p: &[u32; 2]| p[0].abs_diff(8) + p[1].abs_diff(8);
    found.sort_by(|a, b| {
        (a.2 / bph - 1.0)
            .abs()
            .total_cmp(&(b.2 / bph - 1.0).abs())
            .then(leaves(&a.1).cmp(&leaves(&b.1)))
            .then(b.0.cmp(&a.0))
    });
    found.truncate(limit);
    found
}
