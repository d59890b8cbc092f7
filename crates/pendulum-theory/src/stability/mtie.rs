//! The maximum time interval error (MTIE): the largest peak-to-peak
//! excursion of the time error in any window of length `τ`, the figure
//! telecommunication masks are written in (ITU-T Recommendation G.810,
//! "Definitions and terminology for synchronization networks"; NIST
//! SP 1065 section 5.2, its MTIE).

use super::registry::{Deviation, DeviationUnit};
use std::collections::VecDeque;

/// The MTIE's entry in [`super::registry::DEVIATIONS`]: a time, with no
/// interval.
pub const MTIE: Deviation = Deviation {
    key: "mtie_s",
    name: "MTIE",
    help: "the maximum time interval error (ITU-T G.810): the largest peak-to-peak time error in \
           any window of τ, s",
    unit: DeviationUnit::Seconds,
    compute: mtie,
    interval: None,
};

/// The MTIE at `τ = m τ₀` from phase `x`, s: the largest
/// `max − min` of `x` over every window of `m + 1` consecutive points
/// (G.810's definition, as SP 1065 section 5.2 writes it), by
/// monotonic queues of the window's candidates for its maximum and
/// minimum, so the whole is linear in `N` at each `m` (Lemire's
/// streaming maximum). Gaps (NaN) are left out of each window; a window
/// of gaps only has no excursion. `None` with fewer than `m + 1` points.
/// Against allantools 2024.06 (which reads every window whole): equal
/// (a maximum of differences, no rounding) at every octave τ of four
/// 1,000-point noises (tests `stability.rs`).
pub fn mtie(x: &[f64], tau0: f64, m: usize) -> Option<f64> {
    super::deviations::tau(tau0, m)?;
    let width = m.checked_add(1)?;
    if x.len() < width {
        return None;
    }
    // Indices of the window's points, their values decreasing (for the
    // maximum) and increasing (for the minimum).
    let (mut high, mut low) = (VecDeque::new(), VecDeque::new());
    let mut worst: Option<f64> = None;
    for (i, &v) in x.iter().enumerate() {
        if v.is_finite() {
            while high.back().is_some_and(|&j: &usize| x[j] <= v) {
                high.pop_back();
            }
            high.push_back(i);
            while low.back().is_some_and(|&j: &usize| x[j] >= v) {
                low.pop_back();
            }
            low.push_back(i);
        }
        // The window is x[i + 1 − width ..= i].
        let Some(start) = (i + 1).checked_sub(width) else {
            continue;
        };
        for queue in [&mut high, &mut low] {
            while queue.front().is_some_and(|&j| j < start) {
                queue.pop_front();
            }
        }
        if let (Some(&h), Some(&l)) = (high.front(), low.front()) {
            let excursion = x[h] - x[l];
            worst = Some(worst.map_or(excursion, |w: f64| w.max(excursion)));
        }
    }
    worst
}
