//! Sounds that are not ticks (a strike, a chime, the recorder handled, a
//! voice, a door) found on the envelope and cut out, before the beat is
//! looked for and the ticks followed.
//!
//! Method: the envelope in blocks of [`GATE_BLOCK_S`]; a block whose median
//! stands more than [`GATE_LOUD_DB`] above the floor, and above half the
//! ticks' peak ([`TICK_SHARE`]), is loud. Ticks are
//! short: they move a block's median little (a watch's 8 beats a second
//! raise every block's alike, and so the floor), where a bell ringing, a
//! voice or rubbing fills the block. The floor is the 20th percentile of the
//! medians of the last 30 s of blocks not cut (a quantile, so that a strike
//! at the start, given a floor from the first minutes, does not set it).
//! For the beat search its tail is cut too, while blocks stand
//! [`GATE_QUIET_DB`] over the floor (for [`GATE_TAIL_S`] at most). A loud
//! block is cut with one block on
//! either side (a strike's attack
//! inside the block before, its tail in the block after); a cut block's
//! values are the floor, flat: no sound in it, nothing for the tracker to
//! take for a tick, and the tracker, finding no tick there, widens its
//! window and takes the clock up again after it. The values come out two
//! blocks (0.5 s) after they go in.

use std::collections::VecDeque;

/// The gate's block, s.
pub const GATE_BLOCK_S: f64 = 0.25;
/// A block's median over the floor above which it is cut, dB (of the
/// envelope's amplitude).
pub const GATE_LOUD_DB: f64 = 12.0;
/// After a loud block, blocks stay cut while their median stands more
/// than this over the floor, dB: a bell's tail, its partials beating a few
/// times a second, otherwise leaves a rhythm that the beat search takes
/// for the clock's (a strike of six at the default level gave a beat of
/// 0.094 s for a seconds clock).
pub const GATE_QUIET_DB: f64 = 6.0;
/// The longest a tail is cut after the last loud block, s (a room that
/// stays louder after a door is not cut for ever: its floor follows).
pub const GATE_TAIL_S: f64 = 15.0;
/// The share of the ticks' level (see `Gate::tick_level`) a loud
/// block's median must pass as well: −6 dB.
pub const TICK_SHARE: f64 = 0.5;
/// The quantile of the blocks' largest values that is the ticks' level.
const TICK_QUANTILE: f64 = 0.9;
/// Blocks whose medians set the floor (30 s).
const HISTORY: usize = 120;
/// The quantile of the medians that is the floor.
const FLOOR_QUANTILE: f64 = 0.2;

/// The gate, streamed: envelope values in, the same values out (cut ones
/// set to the floor) two blocks later, and the spans cut.
#[derive(Clone, Debug)]
pub struct Gate {
    rate: f64,
    block: usize,
    /// The values of the block being filled.
    filling: Vec<f32>,
    /// Blocks complete but not yet let out: values, loud.
    held: VecDeque<(Vec<f32>, bool)>,
    /// Whether the block let out last was loud.
    last_loud: bool,
    /// Whether loud sounds' tails are cut ([`GATE_QUIET_DB`]).
    tails: bool,
    /// Blocks since the last loud one, while its tail is still cut.
    tail: Option<usize>,
    /// Medians of the last blocks not loud.
    history: VecDeque<f64>,
    /// The largest values of the same blocks.
    tops: VecDeque<f64>,
    /// A floor given beforehand (from the first minutes of the recording).
    seed: Option<f64>,
    /// Blocks let out.
    out_blocks: u64,
    /// The spans cut, in blocks: (first, last + 1).
    spans: Vec<(u64, u64)>,
}

impl Gate {
    /// A gate for an envelope of `rate` values a second; `floor`, when
    /// known beforehand ([`Gate::floor_of`] of the first minutes), keeps a
    /// recording that starts with a strike from taking it for the floor.
    pub fn new(rate: f64, floor: Option<f64>) -> Self {
        Self::cutting(rate, floor, false)
    }

    /// [`Gate::new`], and with `tails` each loud sound's tail cut too
    /// ([`GATE_QUIET_DB`]): for the beat search, which a bell's beating
    /// partials mislead; the ticks are followed through the tail, where
    /// they stand over it.
    pub fn cutting(rate: f64, floor: Option<f64>, tails: bool) -> Self {
        Self {
            rate,
            block: ((GATE_BLOCK_S * rate).round() as usize).max(1),
            filling: Vec::new(),
            held: VecDeque::new(),
            last_loud: false,
            tails,
            tail: None,
            history: VecDeque::new(),
            tops: VecDeque::new(),
            seed: floor.filter(|f| f.is_finite() && *f > 0.0),
            out_blocks: 0,
            spans: Vec::new(),
        }
    }

    /// The floor of a whole envelope `values` at `rate`: the 20th
    /// percentile of its blocks' medians.
    pub fn floor_of(values: &[f32], rate: f64) -> Option<f64> {
        let block = ((GATE_BLOCK_S * rate).round() as usize).max(1);
        quantile(
            values.chunks_exact(block).map(median_of).collect(),
            FLOOR_QUANTILE,
        )
    }

    /// The whole of `values` through a gate (cutting `tails` or not): the
    /// gated values and the spans cut, s.
    pub fn apply(
        values: &[f32],
        rate: f64,
        floor: Option<f64>,
        tails: bool,
    ) -> (Vec<f32>, Vec<(f64, f64)>) {
        let mut gate = Self::cutting(rate, floor, tails);
        let mut out = gate.push(values);
        out.extend(gate.finish());
        let spans = gate.spans_s();
        (out, spans)
    }

    /// The floor now: the quantile of the recent medians, or the floor
    /// given while fewer than eight blocks have come (and the lower of the
    /// two until the history is full: a loud start is not the floor).
    fn floor(&self) -> Option<f64> {
        let own = (self.history.len() >= 8 || self.seed.is_none())
            .then(|| quantile(self.history.iter().copied().collect(), FLOOR_QUANTILE))
            .flatten();
        match (own, self.seed) {
            (Some(o), Some(s)) if self.history.len() < HISTORY => Some(o.min(s)),
            (o, s) => o.or(s),
        }
    }

    /// The ticks' level: the 90th percentile of the largest value of the
    /// last blocks not cut (a seconds clock has a tick in one block of
    /// four, a slow tower clock's 2 s beat in one of eight); `None` before
    /// eight blocks.
    fn tick_level(&self) -> Option<f64> {
        (self.tops.len() >= 8)
            .then(|| quantile(self.tops.iter().copied().collect(), TICK_QUANTILE))
            .flatten()
    }

    /// Feeds envelope values; returns those let out.
    pub fn push(&mut self, values: &[f32]) -> Vec<f32> {
        let mut out = Vec::new();
        for &v in values {
            self.filling.push(v);
            if self.filling.len() == self.block {
                let block = std::mem::take(&mut self.filling);
                let m = median_of(&block);
                let top = block.iter().fold(0.0_f64, |a, &v| a.max(f64::from(v)));
                // (Against the ticks too: a bell's tail under half a
                // tick's peak leaves the ticks to be heard.)
                let loud = self.floor().is_some_and(|f| {
                    m > f * 10f64.powf(GATE_LOUD_DB / 20.0)
                        && self.tick_level().is_none_or(|t| m > TICK_SHARE * t)
                });
                // A loud sound's tail, cut while it stands over the floor
                // (GATE_QUIET_DB), for GATE_TAIL_S at most.
                let longest = (GATE_TAIL_S / GATE_BLOCK_S) as usize;
                let ringing = self.tails
                    && !loud
                    && self.tail.is_some_and(|n| n < longest)
                    && self
                        .floor()
                        .is_some_and(|f| m > f * 10f64.powf(GATE_QUIET_DB / 20.0));
                self.tail = match (loud, ringing) {
                    (true, _) => Some(0),
                    (false, true) => self.tail.map(|n| n + 1),
                    (false, false) => None,
                };
                let loud = loud || ringing;
                if !loud {
                    self.history.push_back(m);
                    self.tops.push_back(top);
                    if self.history.len() > HISTORY {
                        self.history.pop_front();
                        self.tops.pop_front();
                    }
                }
                self.held.push_back((block, loud));
                if self.held.len() == 2 {
                    self.let_out(&mut out);
                }
            }
        }
        out
    }

    /// Lets out the oldest held block, cut if it, the block before or the
    /// block after is loud.
    fn let_out(&mut self, out: &mut Vec<f32>) {
        let Some((mut values, loud)) = self.held.pop_front() else {
            return;
        };
        let next_loud = self.held.front().is_some_and(|b| b.1);
        if loud || next_loud || self.last_loud {
            let floor = self.floor().unwrap_or(0.0) as f32;
            values.iter_mut().for_each(|v| *v = floor);
            let at = self.out_blocks;
            match self.spans.last_mut() {
                Some(span) if span.1 == at => span.1 = at + 1,
                _ => self.spans.push((at, at + 1)),
            }
        }
        self.last_loud = loud;
        self.out_blocks += 1;
        out.extend(values);
    }

    /// Lets out everything held (the end of the recording).
    pub fn finish(&mut self) -> Vec<f32> {
        let mut out = Vec::new();
        while !self.held.is_empty() {
            self.let_out(&mut out);
        }
        // (A last part block: cut if the block before it was loud.)
        let mut rest = std::mem::take(&mut self.filling);
        if self.last_loud && !rest.is_empty() {
            let floor = self.floor().unwrap_or(0.0) as f32;
            rest.iter_mut().for_each(|v| *v = floor);
        }
        out.extend(rest);
        out
    }

    /// The spans cut so far, s.
    pub fn spans_s(&self) -> Vec<(f64, f64)> {
        let seconds = self.block as f64 / self.rate;
        self.spans
            .iter()
            .map(|&(a, b)| (a as f64 * seconds, b as f64 * seconds))
            .collect()
    }
}

/// How far the ticks stand out of an envelope `values` at `rate`: the
/// ticks' level (the 90th percentile of the blocks' largest values) over
/// the floor (the 20th percentile of their medians), as the gate measures
/// both; `None` for fewer than eight blocks or a silent floor. Noise, however
/// loud, has its blocks' peaks a few times their medians; a clock's ticks
/// stand tens of times over the room.
pub fn prominence(values: &[f32], rate: f64) -> Option<f64> {
    let block = ((GATE_BLOCK_S * rate).round() as usize).max(1);
    let blocks: Vec<&[f32]> = values.chunks_exact(block).collect();
    if blocks.len() < 8 {
        return None;
    }
    let tops = blocks
        .iter()
        .map(|b| b.iter().fold(0.0_f64, |a, &v| a.max(f64::from(v))))
        .collect();
    let floor = quantile(
        blocks.iter().map(|b| median_of(b)).collect(),
        FLOOR_QUANTILE,
    )?;
    let ticks = quantile(tops, TICK_QUANTILE)?;
    (floor > 0.0).then(|| ticks / floor)
}

/// The median of a block.
fn median_of(values: &[f32]) -> f64 {
    let mut v: Vec<f64> = values.iter().map(|&x| f64::from(x)).collect();
    super::median(&mut v)
}

/// The `q` quantile of `values` (the nearest rank); `None` if empty.
fn quantile(mut values: Vec<f64>, q: f64) -> Option<f64> {
    if values.is_empty() {
        return None;
    }
    let k = ((values.len() - 1) as f64 * q).round() as usize;
    let (_, v, _) = values.select_nth_unstable_by(k, f64::total_cmp);
    Some(*v)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A flat floor with short ticks, and a loud stretch: the stretch is
    /// cut with a block on either side, the ticks are not, and every
    /// value comes out once, in order.
    #[test]
    fn a_loud_stretch_is_cut_and_ticks_are_not() {
        let rate = 2000.0;
        let mut values: Vec<f32> = (0..120_000)
            .map(|i| if i % 2000 < 10 { 20.0 } else { 1.0 })
            .collect();
        for v in &mut values[60_000..70_000] {
            *v = 50.0;
        }
        let (out, spans) = Gate::apply(&values, rate, None, false);
        assert_eq!(out.len(), values.len());
        assert_eq!(spans, vec![(29.75, 35.25)]);
        assert!(out[..59_500] == values[..59_500]);
        assert!(out[70_500..] == values[70_500..]);
        assert!(out[60_000..70_000].iter().all(|&v| v == 1.0));
    }

    /// A recording that starts loud, given the floor of its first minutes,
    /// is cut from its start.
    #[test]
    fn a_loud_start_is_cut_given_the_floor() {
        let rate = 2000.0;
        let mut values = vec![1.0_f32; 100_000];
        for v in &mut values[..10_000] {
            *v = 30.0;
        }
        let floor = Gate::floor_of(&values, rate);
        assert_eq!(floor, Some(1.0));
        let (_, spans) = Gate::apply(&values, rate, floor, false);
        assert_eq!(spans, vec![(0.0, 5.25)]);
        let (_, unseeded) = Gate::apply(&values, rate, None, false);
        assert!(unseeded.is_empty() || unseeded[0].0 > 0.0);
    }
}
