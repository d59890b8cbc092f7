//! Dropping ticks that sit off the clockwork.

use super::{median, Refined, Tick};
use std::collections::VecDeque;

/// Neighbours of the same side on each side of a tick that predict it.
const REACH: u64 = 20;
/// The midpoints (nearest first) whose median predicts a tick.
const NEAREST: usize = 3;
/// A tick farther than this from its prediction is not the tick, s.
const OFF: f64 = 2e-3;

/// Cleans the ticks against the clockwork's regularity, in two steps:
///
/// * A tick with fewer than three ticks of its side within twenty beats
///   cannot be checked: dropped and counted.
/// * A tick more than 2 ms from where the ticks of its side around it
///   (up to ten before and ten after) put it is a drop sound or a noise
///   burst taken for the tick: dropped and counted. A clock's beats wander
///   by far less than 2 ms from one to the next (the jitter of a good clock
///   is tens of µs), so no real tick is lost.
/// * A tick timed one ringing period off (a cycle slip of the
///   cross-correlation, see [`super::Refined::alternatives`]) is moved to the
///   neighbouring peak of its correlation when that peak is nearer the
///   prediction and at least half as strong.
///
/// The prediction of beat `k` is the median of the nearest three
/// midpoints of the ticks `k - d` and `k + d` of its side (free of the
/// rate and of its slow drift, and of a wheel's periodic error to a few
/// per cent), or, near the ends of the recording, of the ticks of its side
/// carried over at the beat of all ticks (their least-squares slope).
/// Returns the ticks kept, how many were dropped, and how many moved.
/// (A file's ticks all at once; live, as they come: [`Cleaner`], the
/// same rule.)
pub fn clean(mut ticks: Vec<Refined>) -> (Vec<Refined>, usize, usize) {
    if ticks.len() < 8 {
        return (ticks, 0, 0);
    }
    ticks.sort_by_key(|t| t.tick.beat);
    let mut slope = Slope::default();
    ticks.iter().for_each(|t| slope.add(&t.tick));
    let Some(beat) = slope.beat() else {
        return (ticks, 0, 0);
    };
    let mut cleaner = Cleaner {
        beat: Some(beat),
        ..Cleaner::default()
    };
    let mut kept = Vec::with_capacity(ticks.len());
    for t in ticks {
        cleaner.push(t);
        kept.append(&mut cleaner.kept);
    }
    cleaner.finish();
    kept.append(&mut cleaner.kept);
    (kept, cleaner.dropped, cleaner.moved)
}

/// The beat of ticks by least squares of time on beat number, with an
/// intercept for each side (a beat error shifts the tocks against the
/// ticks; one line through both tilts in a short record, and the ticks
/// carried over it would be moved a ringing period wrong): sums kept from
/// the first tick's beat and time, so that they can run over hours.
#[derive(Clone, Copy, Debug, Default)]
struct Slope {
    origin: Option<(u64, f64)>,
    /// Per side: count, sum of k, of t, of k², of k·t.
    sums: [[f64; 5]; 2],
}

impl Slope {
    fn add(&mut self, t: &Tick) {
        let (k0, t0) = *self.origin.get_or_insert((t.beat, t.time));
        let k = t.beat as f64 - k0 as f64;
        let x = t.time - t0;
        let s = &mut self.sums[(t.beat % 2) as usize];
        for (sum, v) in s.iter_mut().zip([1.0, k, x, k * k, k * x]) {
            *sum += v;
        }
    }

    /// The beat, s; `None` while the ticks give no slope.
    fn beat(&self) -> Option<f64> {
        let (sxy, sxx) = self
            .sums
            .iter()
            .filter(|s| s[0] > 0.0)
            .fold((0.0, 0.0), |(a, b), [n, k, x, kk, kx]| {
                (a + kx - k * x / n, b + kk - k * k / n)
            });
        (sxx > 0.0).then(|| sxy / sxx)
    }
}

/// The clean-up of [`clean`] for ticks that come in order of beat: each
/// is decided once the ticks forty beats after it have
/// come (all its prediction can use), and only those beats either way
/// are held. Live, the beat the ticks near a gap are carried at is that
/// of the ticks so far (a file's is that of all its ticks: the same to
/// nanoseconds a beat on a running clock, against the 2 ms a tick may be
/// off).
#[derive(Clone, Debug, Default)]
pub struct Cleaner {
    /// The beat given (a file's), else that of the ticks so far.
    beat: Option<f64>,
    slope: Slope,
    /// The ticks from forty beats before the first not yet decided.
    held: VecDeque<Refined>,
    /// Where the first not yet decided is in `held`.
    undecided: usize,
    kept: Vec<Refined>,
    dropped: usize,
    moved: usize,
}

impl Cleaner {
    /// A clean-up of ticks as they come.
    pub fn new() -> Self {
        Self::default()
    }

    /// The next tick (later in beat than all before).
    pub fn push(&mut self, tick: Refined) {
        self.slope.add(&tick.tick);
        self.held.push_back(tick);
        self.decide(false);
    }

    /// No more ticks: the last are decided.
    pub fn finish(&mut self) {
        self.decide(true);
    }

    /// The ticks kept since the last call, in order of beat.
    pub fn take(&mut self) -> Vec<Refined> {
        std::mem::take(&mut self.kept)
    }

    /// The ticks not yet decided, decided as if none came after them (a
    /// window's last ticks, while the recording goes on).
    pub fn provisional(&self) -> Vec<Refined> {
        let mut ahead = Self {
            kept: Vec::new(),
            ..self.clone()
        };
        ahead.finish();
        ahead.kept
    }

    /// Ticks held (see [`super::OnsetTracker::held`]).
    #[cfg(test)]
    pub(crate) fn held(&self) -> usize {
        self.held.len() + self.kept.len()
    }

    /// Ticks dropped so far.
    pub fn dropped(&self) -> usize {
        self.dropped
    }

    fn decide(&mut self, end: bool) {
        let Some(newest) = self.held.back().map(|t| t.tick.beat) else {
            return;
        };
        let beat = self.beat.or_else(|| self.slope.beat());
        while let Some(t) = self.held.get(self.undecided).copied() {
            if !end && newest <= t.tick.beat + 2 * REACH {
                break;
            }
            self.undecided += 1;
            let Some(p) = self.predict(t.tick.beat, beat) else {
                self.dropped += 1;
                continue;
            };
            let mut t = t;
            let off = (t.tick.time - p).abs();
            if off > OFF {
                self.dropped += 1;
                continue;
            }
            let better = t
                .alternatives
                .iter()
                .flatten()
                .filter(|(a, r)| *r >= 0.5 && (a - p).abs() < 0.5 * off)
                .min_by(|a, b| (a.0 - p).abs().total_cmp(&(b.0 - p).abs()));
            if let Some(&(a, _)) = better {
                t.tick.time = a;
                self.moved += 1;
            }
            self.kept.push(t);
        }
        // (What no tick still to decide can use is let go.)
        let next = self
            .held
            .get(self.undecided)
            .map_or(newest + 1, |t| t.tick.beat);
        while self
            .held
            .front()
            .is_some_and(|t| t.tick.beat + 2 * REACH < next)
        {
            self.held.pop_front();
            self.undecided -= 1;
        }
    }

    /// The time of beat `k` from the held ticks of its side (see
    /// [`clean`]), carried at `beat` near a gap or an end.
    fn predict(&self, k: u64, beat: Option<f64>) -> Option<f64> {
        let time = |j: u64| -> Option<f64> {
            let i = self.held.binary_search_by_key(&j, |t| t.tick.beat).ok()?;
            Some(self.held[i].tick.time)
        };
        // The nearest three: a wheel's periodic error bends the ticks'
        // line, and the midpoints of far neighbours (twenty beats either
        // way, a third of a seconds clock's minute) fall short of a bend's
        // top by half its height, enough to "correct" a tick by a ringing
        // period towards the straight line.
        let mut midpoints: Vec<f64> = (1..=REACH / 2)
            .filter_map(|d| {
                let d = 2 * d;
                Some(0.5 * (time(k.checked_sub(d)?)? + time(k + d)?))
            })
            .take(NEAREST)
            .collect();
        if midpoints.len() >= 3 {
            return Some(median(&mut midpoints));
        }
        let beat = beat?;
        let mut carried: Vec<f64> = (1..=REACH)
            .flat_map(|d| [k.checked_sub(2 * d), Some(k + 2 * d)])
            .flatten()
            .filter_map(|j| time(j).map(|tj| tj + (k as f64 - j as f64) * beat))
            .take(2 * REACH as usize)
            .collect();
        (carried.len() >= 3).then(|| median(&mut carried))
    }
}
