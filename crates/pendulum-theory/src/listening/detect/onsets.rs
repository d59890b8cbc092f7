//! Each beat's onset on the envelope, streamed.

use super::{median, Coarse};

/// Fraction of the typical tick's rise above the floor at which a sound
/// begins (the envelope's level that separates sounds from the noise).
const SOUND_LEVEL: f64 = 0.3;
/// Fraction of the typical tick's rise a sound must reach to be a tick,
/// in a wide window (before the beat is known, or after a gap) and in the
/// narrow window of a tracked beat (where a noise crest is unlikely, and a
/// weak tick is better refined than lost).
const TICK_LEVEL: [f64; 2] = [0.5, 0.35];
/// The envelope kept before each onset in the drop profile, s.
const PROFILE_BEFORE: f64 = 0.005;
/// The band-pass's settling at the start of a recording, s: no tick is
/// looked for before it.
const SETTLE: f64 = 0.01;

/// Beats the lock folds the envelope over (fewer in a short recording).
const LOCK_CYCLES: usize = 16;
/// Onsets over which the local beat is fitted.
const LOCAL_BEATS: usize = 32;
/// Beats of a side missed in a row (the other side's found) after which
/// its typical peak sinks.
const RELEARN_AFTER: usize = 8;
/// The fraction of its rise over the floor a side's typical peak keeps at
/// each further miss.
const RELEARN: f64 = 0.8;
/// Tick peaks over which the typical peak is the median.
const TYPICAL_PEAKS: usize = 32;

/// Each beat's onset on the envelope, streamed: envelope values go in as
/// the decoder produces them; a beat is decided as soon as the envelope
/// covers its window, and what no later beat can need is let go, so the
/// memory is a few beats of envelope whatever the recording's length.
///
/// Method: the first tick is found on the envelope folded at the beat (the mean
/// of up to 16 beats: its loudest sound, or the earliest sound before it
/// that reaches half its rise; the unlocking comes before the drop, whichever
/// is louder). Each following beat is predicted from the
/// last onset of the same side (tick or tock: the beat error shifts one
/// side) at the local beat (the least-squares slope of the last 32 onsets
/// on their beat numbers, so that a clock far off its nominal rate stays
/// locked). The envelope around the prediction is cut into sounds (runs
/// above the floor plus 30% of the typical tick's rise); a sound is a tick
/// candidate when its peak reaches half that rise (35% in the narrow
/// window of a tracked beat); the candidate whose
/// onset (the crossing of 30% of its own rise, interpolated) is nearest the
/// prediction is the beat's onset. A beat with no candidate is missed.
/// The floor is the median envelope of the last ten seconds, the typical
/// peak of each side the median of its last 32 ticks: both follow a
/// recording whose level changes.
#[derive(Clone, Debug)]
pub struct OnsetTracker {
    rate: f64,
    beat: f64,
    values: Vec<f32>,
    /// Index of `values[0]` in the whole envelope.
    offset: usize,
    /// Every 8th envelope value of the last ten seconds, for the floor.
    floor_sample: std::collections::VecDeque<f32>,
    floor: f64,
    floor_updated: usize,
    locked: Option<f64>,

    onsets: Vec<(u64, f64)>,
    /// The last tick peaks of each side.
    peaks: [std::collections::VecDeque<f64>; 2],
    /// The typical peak of each side (a clock out of beat, or with
    /// unequal pallets, ticks louder on one side).
    typical: [f64; 2],
    missed: usize,
    run_of_misses: usize,
    /// Beats of each side missed in a row.
    side_misses: [usize; 2],
    k: u64,
    done: bool,
    /// Floors seen at each update, for the reported floor.
    floors: Vec<f64>,
    /// The envelope around each side's onsets, summed (for the drop).
    profiles: [Vec<f64>; 2],
    profile_counts: [usize; 2],
    /// The last onset, waiting for the envelope after it: (side, onset s,
    /// its index in `onsets`, its sound's peak).
    pending: Option<(usize, f64, usize, f64)>,
    total: usize,
    /// The envelope's noise: 1.4826 times the median deviation below the
    /// floor of the last ten seconds' values under it.
    spread: f64,
    /// For each onset, the other sound of its beat, once the envelope
    /// around it has come (see [`Neighbours`]).
    neighbours: Vec<Option<Neighbours>>,
    /// Each beat's envelope peak and the floor then: (beat, peak, floor).
    levels: Vec<(u64, f64, f64)>,
    /// Each beat's time from the unlocking to the drop, where both were
    /// heard at the clock's spacing: (beat, s).
    spacings: Vec<(u64, f64)>,
    /// Listening live: the rule of one event a beat, decided beforehand
    /// (on the first seconds), applied beat by beat ([`Self::following`]);
    /// `None` when it is decided on all the beats at the end.
    fixed: Option<Option<EventRule>>,
    /// Live: onsets put through the rule so far.
    applied: usize,
    /// The spans cut out of the envelope as not ticks (by the gate), s:
    /// the lock learns nothing from the beats in them.
    cuts: Vec<(f64, f64)>,
    /// Whether the last value sampled for the floor was in a cut.
    after_cut: bool,
    /// Live: the onsets the rule kept, not yet through the line filters
    /// but for their first `emitted`.
    timed: Vec<(u64, f64)>,
    emitted: usize,
    /// Live: the onsets settled and not yet handed out, and the time of
    /// the last handed out, s.
    settled: Vec<(u64, f64)>,
    horizon: f64,
    /// Each side's times from the unlocking to the drop, s.
    side_delays: [Vec<f64>; 2],
}

/// The rule of one event a beat (see [`OnsetTracker::finish`]): the two
/// sounds' spacing most beats share, and whether each side was followed
/// at its unlocking in all but a few beats.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EventRule {
    /// From the unlocking to the drop, s.
    pub spacing: f64,
    /// Spacings within this of `spacing` are it, s.
    pub tolerance: f64,
    /// Each side followed at its unlocking beat after beat.
    pub steady: [bool; 2],
}

impl EventRule {
    /// A neighbouring sound at the rule's spacing.
    fn matches(&self, x: Option<(f64, f64, f64)>) -> Option<(f64, f64, f64)> {
        x.filter(|(delay, _, _)| (delay - self.spacing).abs() <= self.tolerance)
    }
}

/// Live: onsets settled a batch at a time, once this many more have come
/// ([`LIVE_CONTEXT`] on either side of a batch for the line filters, whose
/// lines reach [`LINE_REACH`] beats of a side either way, one after the
/// other), or [`LIVE_BATCH_S`] of beats if fewer.
const LIVE_BATCH: usize = 16;
/// Live: onsets either side of a batch the line filters see, or
/// [`LIVE_CONTEXT_S`] of beats if fewer (at least one).
const LIVE_CONTEXT: usize = 4 * LINE_REACH + 4;
/// Live: the longest a batch waits to fill, s.
const LIVE_BATCH_S: f64 = 0.5;
/// Live: the longest stretch of beats after a batch its line filters wait
/// for, s: the lines then reach their [`LINE_REACH`] beats before a
/// batch's last beats and fewer after (a median of a side's ten beats
/// before and one or more after keeps to the line as well on a steady
/// clock), so that a seconds clock's beats are handed on within a few
/// seconds, not 60.
const LIVE_CONTEXT_S: f64 = 1.0;

/// Live: the batch and the context for beats of `beat` s ([`LIVE_BATCH`],
/// [`LIVE_CONTEXT`]).
fn live_sizes(beat: f64) -> (usize, usize) {
    let beats = |s: f64| (s / beat).ceil().max(0.0) as usize;
    (
        beats(LIVE_BATCH_S).clamp(1, LIVE_BATCH),
        beats(LIVE_CONTEXT_S).clamp(1, LIVE_CONTEXT),
    )
}

/// The sounds of a beat around the one followed: the earliest sound before
/// it and the loudest after it (within [`PAIR_REACH`] of a beat, 0.25 s at
/// most) that stand out of the noise and apart from it: (delay s, onset
/// s, peak over the floor); and the followed sound's own peak over the
/// floor.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Neighbours {
    earlier: Option<(f64, f64, f64)>,
    later: Option<(f64, f64, f64)>,
    own: f64,
}

/// Beats showing both sounds at one spacing, at least this share of the
/// beats whose surroundings were seen (and at least [`PAIR_COUNT`]), for
/// a clock to be timed on its unlocking: noise puts a second sound at a
/// random spacing, a clock's second sound at its own.
const PAIR_SHARE: f64 = 0.2;
/// Spacings of the two sounds within this (or [`PAIR_SPREAD`] of the
/// spacing) are one spacing, s (the envelope's onsets are good to about
/// half its 0.5 ms step).
const PAIR_TOLERANCE: f64 = 0.0008;
/// The same as a fraction of the spacing.
const PAIR_SPREAD: f64 = 0.05;
/// The fewest beats showing both sounds (half the beats seen in a clip
/// shorter than twice this, but at least three).
const PAIR_COUNT: usize = 8;

/// How far either side of a followed sound the other sound of its beat is
/// looked for, in beats (and at most [`PAIR_REACH_MAX`] s): the drop
/// follows the unlocking by the time across the lift, a few ms in a watch
/// and up to a few tenths of a second in a seconds pendulum.
const PAIR_REACH: f64 = 0.3;
/// The longest reach, s.
const PAIR_REACH_MAX: f64 = 0.25;
/// A neighbouring sound's rise over the floor, at least this fraction of
/// the followed sound's (an unlocking 9 dB below its drop is 0.35).
const PAIR_LEVEL: f64 = 0.25;
/// A neighbouring sound's rise over the floor, at least this many of the
/// envelope's noise standard deviations.
const PAIR_NOISE: f64 = 6.0;
/// The dip between two sounds, at least this fraction of the quieter's
/// rise over the floor: two sounds, not one ringing on.
const PAIR_DIP: f64 = 0.25;

/// What each beat's time is: the unlocking (the first of two sounds) or
/// the beat's one sound.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Timing {
    /// Two sounds a beat stand out, the same time apart: every beat is
    /// timed on the first (the unlocking), the drop measured from it;
    /// a beat whose other sound was not heard is not timed (it could be
    /// either).
    Unlocking,
    /// One sound a beat (or the second too rarely heard to tell which is
    /// which): every beat is timed on the sound followed.
    #[default]
    OneSound,
}

/// A sound in the envelope: its onset (s) and peak.
#[derive(Clone, Copy, Debug)]
struct Sound {
    onset: f64,
    peak: f64,
}

impl OnsetTracker {
    /// A tracker for an envelope of `rate` values per second and a beat of
    /// `beat` s (from [`super::beat_period`], or the nominal one).
    pub fn new(rate: f64, beat: f64) -> Self {
        Self {
            rate,
            beat,
            values: Vec::new(),
            offset: 0,
            floor_sample: std::collections::VecDeque::new(),
            floor: 0.0,
            floor_updated: 0,
            locked: None,

            onsets: Vec::new(),
            peaks: Default::default(),
            typical: [0.0; 2],
            missed: 0,
            run_of_misses: 0,
            side_misses: [0; 2],
            k: 0,
            done: false,
            floors: Vec::new(),
            total: 0,
            profiles: Default::default(),
            profile_counts: [0; 2],
            pending: None,
            spread: 0.0,
            neighbours: Vec::new(),
            levels: Vec::new(),
            spacings: Vec::new(),
            fixed: None,
            applied: 0,
            cuts: Vec::new(),
            after_cut: false,
            timed: Vec::new(),
            emitted: 0,
            settled: Vec::new(),
            horizon: 0.0,
            side_delays: Default::default(),
        }
    }

    /// A tracker for listening live: as [`Self::new`], but each beat is
    /// settled on one event by `rule` (decided on the first seconds of the
    /// recording: [`Coarse::rule`]; `None`: one sound a beat) as soon as
    /// the envelope around it has come, and handed out by
    /// [`Self::take_onsets`], so that the ticks can be refined while the
    /// recording goes on.
    pub fn following(rate: f64, beat: f64, rule: Option<EventRule>) -> Self {
        Self {
            fixed: Some(rule),
            ..Self::new(rate, beat)
        }
    }

    /// The spans cut out of the envelope so far, s (from the gate that
    /// feeds the tracker: [`super::Gate::spans_s`]); given before the
    /// values they cover are pushed.
    pub fn cut(&mut self, spans: &[(f64, f64)]) {
        spans.clone_into(&mut self.cuts);
    }

    /// Live ([`Self::following`]): the onsets settled since the last call,
    /// in order of beat. What is handed out is let go of here (but for
    /// the onsets the local beat and the rule still read): the tracker's
    /// memory does not grow with the hours.
    pub fn take_onsets(&mut self) -> Vec<(u64, f64)> {
        self.settle_ready(false);
        let new = std::mem::take(&mut self.settled);
        if let Some(&(_, t)) = new.last() {
            self.horizon = t;
        }
        let read = self.applied.min(self.pending.map_or(usize::MAX, |p| p.2));
        let done = read.saturating_sub(LOCAL_BEATS);
        if done > 4096 {
            self.onsets.drain(..done);
            self.neighbours.drain(..done);
            self.applied -= done;
            if let Some(p) = &mut self.pending {
                p.2 -= done;
            }
        }
        new
    }

    /// The earliest time a beat not yet handed out can have, s: the last
    /// handed out (beats come in order).
    pub fn horizon(&self) -> f64 {
        self.horizon
    }

    /// Live: entries held a beat each (onsets, their neighbours, those
    /// timed and settled, levels): what must not grow with the hours.
    #[cfg(test)]
    pub(crate) fn held(&self) -> usize {
        self.onsets.len()
            + self.neighbours.len()
            + self.timed.len()
            + self.settled.len()
            + self.levels.len()
    }

    /// Live: the levels of beats before `beat` are not needed (their
    /// windows are done).
    pub fn let_go_levels(&mut self, beat: u64) {
        let done = self.levels.partition_point(|l| l.0 < beat);
        if done > 4096 {
            self.levels.drain(..done);
        }
    }

    /// The tick levels so far: (beat, peak, floor).
    pub fn levels(&self) -> &[(u64, f64, f64)] {
        &self.levels
    }

    /// The spacings from unlocking to drop so far: (beat, s).
    pub fn spacings(&self) -> &[(u64, f64)] {
        &self.spacings
    }

    /// Live: puts the onsets whose surroundings have come through the
    /// fixed rule, and the rule's onsets through the line filters a batch
    /// at a time (all that is left at the `end`).
    fn settle_ready(&mut self, end: bool) {
        let Some(rule) = self.fixed else {
            return;
        };
        let ready = match (end, self.pending) {
            (false, Some((_, _, index, _))) => index,
            _ => self.onsets.len(),
        };
        while self.applied < ready {
            let (k, t) = self.onsets[self.applied];
            let n = self.neighbours[self.applied];
            let kept = match &rule {
                Some(r) => self.settle_one(r, k, t, n),
                None => Some((k, t)),
            };
            self.timed.extend(kept);
            self.applied += 1;
        }
        let Some(rule) = rule else {
            self.settled.append(&mut self.timed);
            return;
        };
        let n = self.timed.len();
        let (batch, context) = live_sizes(self.beat);
        if !end && n < self.emitted + batch + context {
            return;
        }
        let upto = if end { n } else { n - context };
        if upto <= self.emitted {
            return;
        }
        let from = self.timed[self.emitted].0;
        let to = self.timed.get(upto).map(|o| o.0);
        let lo = self.emitted.saturating_sub(LIVE_CONTEXT);
        let kept = one_line_a_side(
            earlier_of_two(self.timed[lo..].to_vec(), rule.spacing),
            0.4 * rule.spacing,
        );
        self.settled.extend(
            kept.into_iter()
                .filter(|&(k, _)| k >= from && to.is_none_or(|e| k < e)),
        );
        self.emitted = upto;
        // (What no later batch sees is let go.)
        if lo > 4096 {
            self.timed.drain(..lo);
            self.emitted -= lo;
        }
    }

    /// Beat `k`, followed at `t` with the neighbours `n`, under `rule`: at
    /// its unlocking (moved there from its drop), or `None` when it cannot
    /// be told which of its two sounds was heard.
    fn settle_one(
        &mut self,
        rule: &EventRule,
        k: u64,
        t: f64,
        n: Option<Neighbours>,
    ) -> Option<(u64, f64)> {
        let side = (k % 2) as usize;
        let Some(n) = n else {
            return Some((k, t));
        };
        if let Some((delay, onset, _)) = rule.matches(n.earlier) {
            self.side_delays[side].push(delay);
            self.spacings.push((k, delay));
            Some((k, onset))
        } else if let Some((delay, _, _)) = rule.matches(n.later) {
            self.side_delays[side].push(delay);
            self.spacings.push((k, delay));
            Some((k, t))
        } else if rule.steady[side] {
            // One sound heard, on a side the tracker followed at its
            // unlocking beat after beat: the same sound as theirs (one
            // that is the drop all the same lies a spacing off its side's
            // line, and the clean-up drops it: super::clean).
            Some((k, t))
        } else {
            // One sound heard on a side followed now at one sound, now at
            // the other: which it is is not known (a recording's level
            // wanders, so loudness cannot tell): not timed, counted as
            // missed.
            None
        }
    }

    /// Feeds envelope values.
    pub fn push(&mut self, values: &[f32]) {
        for (i, &v) in values.iter().enumerate() {
            if (self.total + i) % 8 == 0 {
                // The floor is learnt outside the cuts, and afresh after
                // each: a loud sound's tail raises it for a while, and the
                // ticks stand over the tail, not over the room before it.
                let t = (self.total + i) as f64 / self.rate;
                if self.cuts.iter().any(|&(a, b)| t >= a && t < b) {
                    self.after_cut = true;
                    continue;
                }
                if std::mem::take(&mut self.after_cut) {
                    self.floor_sample.clear();
                    self.floor_updated = 0;
                }
                self.floor_sample.push_back(v);
                if self.floor_sample.len() as f64 > 10.0 * self.rate / 8.0 {
                    self.floor_sample.pop_front();
                }
            }
        }
        self.values.extend_from_slice(values);
        self.total += values.len();
        self.advance(false);
    }

    /// Ends the stream: the onsets found.
    pub fn finish(mut self) -> Coarse {
        self.advance(true);
        self.profile_pending();
        let (rule, paired) = match self.fixed {
            Some(rule) => {
                self.settle_ready(true);
                self.onsets = std::mem::take(&mut self.settled);
                (rule, self.side_drops())
            }
            None => self.settle_events(),
        };
        let timing = match rule {
            Some(_) => Timing::Unlocking,
            None => Timing::OneSound,
        };
        let followed_drops = [0, 1].map(|side| {
            let n = self.profile_counts[side];
            (n >= 4)
                .then(|| {
                    let mean: Vec<f64> = self.profiles[side].iter().map(|v| v / n as f64).collect();
                    second_sound(
                        &mean,
                        self.floor,
                        self.rate,
                        (PROFILE_BEFORE * self.rate).round() as usize,
                    )
                })
                .flatten()
        });
        let drops = match timing {
            Timing::Unlocking => paired,
            Timing::OneSound => followed_drops,
        };
        let mut floors = self.floors.clone();
        let floor = if floors.is_empty() {
            self.current_floor()
        } else {
            median(&mut floors)
        };
        Coarse {
            onsets: self.onsets,
            missed: self.missed,
            floor,
            peak: if self.typical[0] > 0.0 {
                0.5 * (self.typical[0] + self.typical[1])
            } else {
                floor
            },
            drops,
            timing,
            levels: self.levels,
            spacings: self.spacings,
            rule,
        }
    }

    /// Each side's median time from the unlocking to the drop.
    fn side_drops(&mut self) -> [Option<f64>; 2] {
        std::mem::take(&mut self.side_delays).map(|mut v| (v.len() >= 2).then(|| median(&mut v)))
    }

    /// One event a beat: when most beats show two sounds the same time
    /// apart (the unlocking, then the drop), every beat is moved to the
    /// first of its two (a beat followed at its drop goes back to its
    /// unlocking) and a beat with one sound heard is left out (it could be
    /// either, and a mixture of the two moves the rate and the beat
    /// error); else every beat stays on the sound followed. Returns the
    /// rule (`None`: one sound) and, for two sounds, each side's median
    /// time from the unlocking to the drop.
    fn settle_events(&mut self) -> (Option<EventRule>, [Option<f64>; 2]) {
        let Some(rule) = self.event_rule() else {
            return (None, [None; 2]);
        };
        let mut timed = Vec::with_capacity(self.onsets.len());
        let onsets = std::mem::take(&mut self.onsets);
        let neighbours = std::mem::take(&mut self.neighbours);
        for (&(k, t), &n) in onsets.iter().zip(&neighbours) {
            timed.extend(self.settle_one(&rule, k, t, n));
        }
        self.neighbours = neighbours;
        let d = rule.spacing;
        self.onsets = one_line_a_side(earlier_of_two(timed, d), 0.4 * d);
        (Some(rule), self.side_drops())
    }

    /// The rule of one event a beat from the beats followed so far, `None`
    /// when the beats do not show two sounds at one spacing (see
    /// [`Self::settle_events`]).
    fn event_rule(&self) -> Option<EventRule> {
        let seen: Vec<&Neighbours> = self.neighbours.iter().flatten().collect();
        let delays: Vec<f64> = seen
            .iter()
            .flat_map(|n| [n.earlier, n.later])
            .flatten()
            .map(|(d, _, _)| d)
            .collect();
        // (A clip of a few beats needs fewer.)
        let fewest = PAIR_COUNT.min(seen.len() / 2).max(3);
        if delays.len() < fewest {
            return None;
        }
        // The spacing most beats share: the densest cluster of spacings
        // (a room's reflection after each sound makes another, a few ms
        // away). Spacings within its width, or within 2.5 standard
        // deviations of the spacings near it (within 15%: the onsets of a
        // slow sound on the envelope scatter by half a ms and more, and a
        // clock's two pallets drop a little differently), are it.
        let d = densest(&delays)?;
        let near: Vec<f64> = delays
            .iter()
            .copied()
            .filter(|x| (x / d - 1.0).abs() <= NEAR_SPACING)
            .collect();
        let mad = median(&mut near.iter().map(|x| (x - d).abs()).collect::<Vec<_>>());
        let tolerance = spacing_width(d).max(2.5 * 1.4826 * mad);
        let mut rule = EventRule {
            spacing: d,
            tolerance,
            steady: [false; 2],
        };
        let pairs = seen
            .iter()
            .filter(|n| rule.matches(n.earlier).is_some() || rule.matches(n.later).is_some())
            .count();
        if pairs < fewest || (pairs as f64) < PAIR_SHARE * seen.len() as f64 {
            return None;
        }
        // Each side followed at its unlocking (its beats showing both
        // sounds had the drop after the sound followed) in all but a few.
        let mut followed = [[0usize; 2]; 2];
        for (&(k, _), n) in self.onsets.iter().zip(&self.neighbours) {
            if let Some(n) = n {
                let side = (k % 2) as usize;
                if rule.matches(n.earlier).is_some() {
                    followed[side][1] += 1;
                } else if rule.matches(n.later).is_some() {
                    followed[side][0] += 1;
                }
            }
        }
        rule.steady = followed.map(|[at_unlock, at_drop]| {
            at_unlock >= fewest && (at_drop as f64) <= 0.05 * (at_unlock + at_drop) as f64
        });
        Some(rule)
    }

    /// The other sound of the beat followed at `onset` (index `i` in the
    /// envelope is its sound's peak `peak`): see [`Neighbours`]. `None`
    /// when the envelope around it is not all buffered.
    fn neighbours_of(&self, onset: f64, peak: f64) -> Option<Neighbours> {
        let reach = (PAIR_REACH * self.beat).min(PAIR_REACH_MAX);
        let first = ((onset - reach) * self.rate).floor();
        let last = ((onset + reach) * self.rate).ceil() as usize;
        if first < self.offset as f64 || last >= self.offset + self.values.len() {
            return None;
        }
        let (first, at) = (first as usize, (onset * self.rate).round() as usize);
        let floor = self.floor;
        let rise = peak - floor;
        if rise <= 0.0 {
            return Some(Neighbours::default());
        }
        let level = floor + (PAIR_LEVEL * rise).max(PAIR_NOISE * self.spread);
        let half = ((0.001 * self.rate) as usize).max(1);
        // The followed sound's own peak: the first local maximum (over
        // 1 ms either way) within 6 ms of its onset that reaches a third
        // of the largest there (a louder drop merged into its run is
        // another sound; a bump of noise on its rise is not its peak).
        let own_end = (at + (0.006 * self.rate) as usize).min(last);
        let largest = (at..=own_end).max_by(|&a, &b| self.at(a).total_cmp(&self.at(b)))?;
        let least = floor + (self.at(largest) - floor) / 3.0;
        let own_at = (at..=own_end)
            .find(|&j| {
                self.at(j) >= least
                    && (j.saturating_sub(half)..=(j + half).min(last))
                        .all(|i| self.at(i) <= self.at(j))
            })
            .unwrap_or(largest);
        let is_peak = |j: usize| {
            let v = self.at(j);
            v >= level
                && (j.saturating_sub(half).max(first)..=(j + half).min(last))
                    .all(|i| self.at(i) <= v)
        };
        // A peak apart from the followed sound's: the dip between them
        // at least PAIR_DIP of the quieter's rise.
        let apart = |j: usize| {
            let (a, b) = if j < own_at { (j, own_at) } else { (own_at, j) };
            let dip = (a..=b).map(|i| self.at(i)).fold(f64::INFINITY, f64::min);
            let quieter = self.at(j).min(self.at(own_at));
            quieter - dip >= PAIR_DIP * (quieter - floor)
        };
        // Its onset: back from its peak to 30% of its rise over the dip.
        let onset_of = |j: usize, stop: usize| -> f64 {
            let low = (stop.min(j)..=j)
                .map(|i| self.at(i))
                .fold(f64::INFINITY, f64::min);
            let own = low + SOUND_LEVEL * (self.at(j) - low);
            let mut i = j;
            while i > stop && self.at(i - 1) >= own {
                i -= 1;
            }
            i as f64 / self.rate
        };
        let loudest = |range: std::ops::Range<usize>| {
            range
                .filter(|&j| is_peak(j) && apart(j))
                .max_by(|&a, &b| self.at(a).total_cmp(&self.at(b)))
        };
        let gap = ((0.001 * self.rate) as usize).max(1);
        // Before: the earliest (a drop followed with a reflection of the
        // unlocking between them, or a reflection of the drop followed,
        // has the unlocking first); after: the loudest (the drop).
        let earliest = (first..at.saturating_sub(gap)).find(|&j| is_peak(j) && apart(j));
        let earlier = earliest.map(|j| {
            let o = onset_of(j, first);
            (onset - o, o, self.at(j) - floor)
        });
        let later = loudest(own_at + 2 * gap..last).map(|j| {
            let o = onset_of(j, own_at);
            (o - onset, o, self.at(j) - floor)
        });
        Some(Neighbours {
            earlier: earlier.filter(|(d, _, _)| *d > 0.0),
            later: later.filter(|(d, _, _)| *d > 0.0),
            own: self.at(own_at) - floor,
        })
    }

    fn current_floor(&self) -> f64 {
        let mut s: Vec<f64> = self.floor_sample.iter().map(|&v| f64::from(v)).collect();
        median(&mut s)
    }

    fn refresh_floor(&mut self) {
        let due = self.floors.is_empty() || self.total >= self.floor_updated + self.rate as usize;
        if due && !self.floor_sample.is_empty() {
            self.floor = self.current_floor();
            // (From the values below the median only: the ticks and the
            // room's tail lie above it.)
            let mut deviations: Vec<f64> = self
                .floor_sample
                .iter()
                .map(|&v| self.floor - f64::from(v))
                .filter(|&d| d >= 0.0)
                .collect();
            self.spread = 1.4826 * median(&mut deviations);
            self.floors.push(self.floor);
            self.floor_updated = self.total;
        }
    }

    /// The envelope value at whole-envelope index `i`.
    fn at(&self, i: usize) -> f64 {
        f64::from(self.values[i - self.offset])
    }

    /// Index of time `t` s, clamped to what is buffered.
    fn index(&self, t: f64) -> usize {
        let i = (t * self.rate).round().max(0.0) as usize;
        i.clamp(self.offset, self.offset + self.values.len())
    }

    /// The sounds whose peaks lie in `[from, to)` s, the envelope above
    /// `floor + SOUND_LEVEL (reference - floor)`.
    fn sounds(&self, from: f64, to: f64, reference: f64) -> Vec<Sound> {
        let (a, b) = (self.index(from), self.index(to));
        let floor = self.floor;
        let level = floor + SOUND_LEVEL * (reference - floor);
        let mut out = Vec::new();
        let mut i = a;
        while i < b {
            if self.at(i) < level {
                i += 1;
                continue;
            }
            // A run above the level: its peak.
            let mut peak_at = i;
            while i < b && self.at(i) >= level {
                if self.at(i) > self.at(peak_at) {
                    peak_at = i;
                }
                i += 1;
            }
            let peak = self.at(peak_at);
            // Its onset: back from the peak to 30% of its own rise (at
            // most 25 ms, never before the buffer).
            let own = floor + SOUND_LEVEL * (peak - floor);
            let earliest = peak_at
                .saturating_sub((0.025 * self.rate) as usize)
                .max(self.offset);
            let mut j = peak_at;
            while j > earliest && self.at(j - 1) >= own {
                j -= 1;
            }
            let before = if j > self.offset {
                self.at(j - 1)
            } else {
                floor
            };
            let now = self.at(j);
            let fraction = if now > before && before < own {
                ((own - before) / (now - before)).clamp(0.0, 1.0)
            } else {
                1.0
            };
            out.push(Sound {
                onset: (j as f64 - 1.0 + fraction) / self.rate,
                peak,
            });
        }
        out
    }

    /// The first beat's onset, s, from the envelope folded at the beat
    /// (the mean of up to 16 beats, so that one loud noise or a missing
    /// tick does not decide): its loudest sound, or the earliest sound
    /// before it (within 25 ms, and a third of a beat) that reaches half
    /// its rise: the unlocking before a louder drop. Also sets the typical
    /// tick peak (the median of the beats' maxima near that onset, each
    /// side at its own phase).
    fn lock(&mut self, buffered: f64) -> Option<f64> {
        let width = (self.beat * self.rate).round() as usize;
        let cycles = self.heard_cycles(buffered, LOCK_CYCLES);
        if width < 4 || cycles.is_empty() {
            return None;
        }
        let first = self.index(SETTLE);
        let at = |c: usize, j: usize| -> usize {
            first + (c as f64 * self.beat * self.rate).round() as usize + j
        };
        let last = self.offset + self.values.len();
        let mut profile = vec![0.0_f64; width];
        for (j, p) in profile.iter_mut().enumerate() {
            let cells: Vec<f64> = cycles
                .iter()
                .map(|&c| at(c, j))
                .filter(|&i| i < last)
                .map(|i| self.at(i))
                .collect();
            *p = cells.iter().sum::<f64>() / cells.len().max(1) as f64;
        }
        let (loudest, &max) = profile
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(b.1))?;
        let floor = self.floor;
        if max <= floor {
            return None;
        }
        // The onset of the profile `profile` whose loudest is `loudest`
        // (its peak `max`): back from the loudest, cyclically, for an
        // earlier sound reaching half its rise, then to 30% of the rise.
        let back = ((0.025_f64).min(self.beat / 3.0) * self.rate) as isize;
        let onset_of = |profile: &[f64], loudest: isize, max: f64| -> isize {
            let half = floor + 0.5 * (max - floor);
            let cyclic = |j: isize| profile[j.rem_euclid(width as isize) as usize];
            let mut onset = loudest;
            for j in (loudest - back)..=loudest {
                if cyclic(j) >= half && cyclic(j - 1) < half {
                    onset = j;
                    break;
                }
            }
            let level = floor + SOUND_LEVEL * (max - floor);
            while onset > loudest - back - 5 && cyclic(onset - 1) >= level {
                onset -= 1;
            }
            onset
        };
        let loudest = loudest as isize;
        let onset = onset_of(&profile, loudest, max);
        let phase = onset.rem_euclid(width as isize) as usize;
        // Each side's onset on its own beats' profile, its loudest near the
        // loudest of both: a clock out of beat has its tocks off its
        // ticks' phase (by up to a fifth of the beat), and the profile of
        // both shows two humps, each half as high as the sounds.
        let reach = (0.2 * width as f64) as isize;
        let sides = [0usize, 1].map(|parity| {
            let own: Vec<usize> = cycles.iter().copied().filter(|c| c % 2 == parity).collect();
            if own.is_empty() {
                return phase as isize;
            }
            let side: Vec<f64> = (0..width)
                .map(|j| {
                    let cells: Vec<f64> = own
                        .iter()
                        .map(|&c| at(c, j))
                        .filter(|&i| i < last)
                        .map(|i| self.at(i))
                        .collect();
                    cells.iter().sum::<f64>() / cells.len().max(1) as f64
                })
                .collect();
            let cyclic = |j: isize| side[j.rem_euclid(width as isize) as usize];
            let Some(top) = (loudest - reach..=loudest + reach)
                .max_by(|&a, &b| cyclic(a).total_cmp(&cyclic(b)))
            else {
                return phase as isize;
            };
            let own = onset_of(&side, top, cyclic(top));
            // (On the beat of the onset of both, whichever way it wrapped.)
            phase as isize + (own - onset)
        });
        // The typical tick: the median of each beat's maximum within 3 ms
        // of its side's onset (not the louder drop's peak after it).
        let near = (0.003 * self.rate) as isize;
        let mut maxima: Vec<f64> = cycles
            .iter()
            .filter_map(|&c| {
                let from = at(c, 0) as isize + sides[c % 2];
                let a = (from - near).max(self.offset as isize) as usize;
                let b = ((from + near).max(0) as usize).min(last);
                (a..b).map(|i| self.at(i)).max_by(f64::total_cmp)
            })
            .collect();
        self.typical = [median(&mut maxima); 2];
        Some(SETTLE + phase as f64 / self.rate)
    }

    /// The first `most` whole beats buffered by `buffered` s (counted
    /// from [`SETTLE`]) outside the spans cut ([`Self::cut`]): a beat cut
    /// by the gate (a strike, a knock, handling) would teach the lock a
    /// tick's level and phase that are not the clock's.
    fn heard_cycles(&self, buffered: f64, most: usize) -> Vec<usize> {
        let whole = ((buffered - SETTLE) / self.beat).floor().max(0.0) as usize;
        (0..whole)
            .filter(|&c| {
                let a = SETTLE + c as f64 * self.beat;
                let b = a + self.beat;
                self.cuts.iter().all(|&(from, to)| to <= a || from >= b)
            })
            .take(most)
            .collect()
    }

    /// How long after an onset the drop is looked for, s: up to nearly
    /// half a beat (a seconds pendulum with a small lift crosses it in a
    /// few tenths of a second).
    fn profile_span(&self) -> f64 {
        0.45 * self.beat
    }

    /// Adds the envelope around the pending onset to its side's profile,
    /// once the envelope after it has come (or drops it at the end).
    fn profile_pending(&mut self) {
        let Some((side, onset, index, peak)) = self.pending else {
            return;
        };
        let first = ((onset - PROFILE_BEFORE) * self.rate).round();
        let length = ((PROFILE_BEFORE + self.profile_span()) * self.rate).round() as usize;
        if first < self.offset as f64 {
            self.pending = None;
            return;
        }
        let first = first as usize;
        if first + length > self.offset + self.values.len() {
            return;
        }
        self.neighbours[index] = self.neighbours_of(onset, peak);
        let profile = &mut self.profiles[side];
        profile.resize(length, 0.0);
        for (j, p) in profile.iter_mut().enumerate() {
            *p += f64::from(self.values[first + j - self.offset]);
        }
        self.profile_counts[side] += 1;
        self.pending = None;
    }

    /// The local beat: the least-squares slope of the last onsets.
    fn local_beat(&self) -> f64 {
        let recent = &self.onsets[self.onsets.len().saturating_sub(LOCAL_BEATS)..];
        if recent.len() < 8 {
            return self.beat;
        }
        let n = recent.len() as f64;
        let (mk, mt) = recent
            .iter()
            .fold((0.0, 0.0), |(a, b), &(k, t)| (a + k as f64 / n, b + t / n));
        let (sxy, sxx) = recent.iter().fold((0.0, 0.0), |(a, b), &(k, t)| {
            let dk = k as f64 - mk;
            (a + dk * (t - mt), b + dk * dk)
        });
        let slope = sxy / sxx;
        // A wild slope (a run of wrong onsets) is not trusted.
        if sxx > 0.0 && (slope / self.beat - 1.0).abs() < 0.05 {
            slope
        } else {
            self.beat
        }
    }

    fn advance(&mut self, end: bool) {
        if self.done {
            return;
        }
        let buffered = (self.offset + self.values.len()) as f64 / self.rate;
        if self.locked.is_none() {
            // Eight beats heard, or 2 s of them (16 beats at most); beats
            // cut or silent are not counted.
            let span = (8.0 * self.beat).max(2.0).min(16.0 * self.beat);
            let wanted = (span / self.beat).round() as usize;
            if !end
                && (buffered < span + SETTLE || self.heard_cycles(buffered, wanted).len() < wanted)
            {
                return;
            }
            self.refresh_floor();
            match self.lock(buffered) {
                Some(start) => self.locked = Some(start),
                None => {
                    self.done = true;
                    return;
                }
            }
        }
        let start = self.locked.unwrap_or(0.0);
        loop {
            let beat = self.local_beat();
            let k = self.k;
            let same = self.onsets.iter().rev().find(|(j, _)| (k - j) % 2 == 0);
            let predicted = match (same, self.onsets.last()) {
                (Some(&(j, t)), _) | (None, Some(&(j, t))) => t + (k - j) as f64 * beat,
                (None, None) => start + k as f64 * beat,
            };
            // The window: wide until the beat is known from the onsets
            // themselves, then a few ms (a clock's beat does not wander
            // more), wide again after a run of misses (the clock was
            // stopped or touched, or the recording has a gap).
            let gap = same.map_or(1, |&(j, _)| k - j) as f64;
            let half = if self.onsets.len() < 4 || self.run_of_misses >= 4 {
                0.4 * self.beat
            } else if self.onsets.len() < 8 {
                (0.004 + 0.02 * self.beat).min(0.4 * self.beat)
            } else {
                (0.003 + 5e-4 * gap * self.beat).min(0.4 * self.beat)
            };
            // The window, and 25 ms before it for a sound's rise.
            if predicted + half + 0.03 > buffered {
                if end {
                    if predicted <= buffered - 0.02 {
                        self.decide(predicted, half, buffered, half < 0.3 * self.beat);
                    }
                    self.done = true;
                }
                break;
            }
            self.decide(predicted, half, buffered, half < 0.3 * self.beat);
            // Let go of what no later beat needs (nor the drop profile).
            self.profile_pending();
            let reach = (PAIR_REACH * self.beat).min(PAIR_REACH_MAX) + 0.001;
            let mut keep = ((predicted - 0.05 - reach).max(0.0) * self.rate) as usize;
            if let Some((_, t, _, _)) = self.pending {
                let before = PROFILE_BEFORE.max(reach);
                keep = keep.min(((t - before).max(0.0) * self.rate) as usize);
            }
            if keep > self.offset + 8192 {
                let drop = (keep - self.offset).min(self.values.len());
                self.values.drain(..drop);
                self.offset += drop;
            }
        }
    }

    /// Decides beat `self.k`, predicted at `predicted` s.
    fn decide(&mut self, predicted: f64, half: f64, buffered: f64, narrow: bool) {
        self.refresh_floor();
        let side = (self.k % 2) as usize;
        let typical = self.typical[side];
        let tick = self.floor + TICK_LEVEL[usize::from(narrow)] * (typical - self.floor);
        let best = self
            .sounds(predicted - half, (predicted + half).min(buffered), typical)
            .into_iter()
            .filter(|s| s.peak >= tick && (s.onset - predicted).abs() <= half && s.onset >= SETTLE)
            .min_by(|a, b| {
                (a.onset - predicted)
                    .abs()
                    .total_cmp(&(b.onset - predicted).abs())
            });
        match best {
            Some(s) => {
                self.run_of_misses = 0;
                self.side_misses[side] = 0;
                self.profile_pending();
                self.pending = Some((side, s.onset, self.onsets.len(), s.peak));
                self.onsets.push((self.k, s.onset));
                self.neighbours.push(None);
                self.levels.push((self.k, s.peak, self.floor));
                let peaks = &mut self.peaks[side];
                peaks.push_back(s.peak);
                if peaks.len() > TYPICAL_PEAKS {
                    peaks.pop_front();
                }
                let mut p: Vec<f64> = peaks.iter().copied().collect();
                self.typical[side] = median(&mut p);
            }
            None => {
                if !self.onsets.is_empty() {
                    self.missed += 1;
                    self.run_of_misses += 1;
                }
                // A side missed beat after beat while the other is found
                // may have been given its typical peak by a loud noise
                // (the phone handled at the start): let it sink towards the
                // floor, and forget the peaks that set it, so its ticks can
                // be found again.
                self.side_misses[side] += 1;
                if self.side_misses[side] >= RELEARN_AFTER && self.side_misses[1 - side] == 0 {
                    self.typical[side] = self.floor + RELEARN * (self.typical[side] - self.floor);
                    self.peaks[side].clear();
                }
            }
        }
        self.k += 1;
    }
}

/// The spacings whose scatter sets the rule's tolerance: within this
/// fraction of the spacing.
const NEAR_SPACING: f64 = 0.15;

/// Spacings within this of `d` (s) are `d`.
fn spacing_width(d: f64) -> f64 {
    (PAIR_SPREAD * d).max(PAIR_TOLERANCE)
}

/// The middle of the densest cluster of `delays` (s): a window of twice
/// [`spacing_width`] slid over them sorted, then the median of those
/// within a width of its centre; `None` for none.
fn densest(delays: &[f64]) -> Option<f64> {
    let mut sorted = delays.to_vec();
    sorted.sort_by(f64::total_cmp);
    let (mut best, mut best_count, mut hi) = (None, 0, 0);
    for (lo, &a) in sorted.iter().enumerate() {
        while hi < sorted.len() && sorted[hi] <= a + 2.0 * spacing_width(a) {
            hi += 1;
        }
        if hi - lo > best_count {
            best_count = hi - lo;
            best = Some(0.5 * (a + sorted[hi - 1]));
        }
    }
    let best = best?;
    let mut cluster: Vec<f64> = sorted
        .into_iter()
        .filter(|&b| (b - best).abs() <= spacing_width(best))
        .collect();
    Some(median(&mut cluster))
}

/// The beat of a side that is `spacing` s later on the line than two or
/// more of its side's [`LINE_REACH`] beats either way is timed on the
/// second of its two sounds where they were timed on the first: dropped.
/// Of two sounds a spacing apart the unlocking is the earlier, so a side
/// followed now on one, now on the other (a stretch where the unlocking
/// was not heard apart) keeps its unlockings, whichever is the more.
fn earlier_of_two(onsets: Vec<(u64, f64)>, spacing: f64) -> Vec<(u64, f64)> {
    keep_by_side(onsets, |r, around| {
        around
            .iter()
            .filter(|&&a| ((r - a) - spacing).abs() <= 0.3 * spacing)
            .count()
            < 2
    })
}

/// The onsets `keep` accepts, given each one's residual from the line at
/// the beat of [`beat_of_pairs`] (its time less its number times the beat)
/// and the residuals of its side's [`LINE_REACH`] beats either way (itself
/// among them); all of them when the beat cannot be told.
fn keep_by_side(
    onsets: Vec<(u64, f64)>,
    keep: impl Fn(f64, &mut [f64]) -> bool,
) -> Vec<(u64, f64)> {
    let Some(beat) = beat_of_pairs(&onsets) else {
        return onsets;
    };
    let residual = |&(k, t): &(u64, f64)| t - k as f64 * beat;
    let kept: Vec<bool> = (0..onsets.len())
        .map(|i| {
            let side = onsets[i].0 % 2;
            let lo = i.saturating_sub(2 * LINE_REACH);
            let hi = (i + 2 * LINE_REACH + 1).min(onsets.len());
            let mut around: Vec<f64> = onsets[lo..hi]
                .iter()
                .filter(|o| o.0 % 2 == side)
                .map(residual)
                .collect();
            keep(residual(&onsets[i]), &mut around)
        })
        .collect();
    onsets
        .into_iter()
        .zip(kept)
        .filter_map(|(o, k)| k.then_some(o))
        .collect()
}

/// The beat of `onsets` (beat number, s): the median of half the time
/// between beats of a side two apart; `None` for fewer than four such.
fn beat_of_pairs(onsets: &[(u64, f64)]) -> Option<f64> {
    let mut steps: Vec<f64> = onsets
        .windows(3)
        .flat_map(|w| {
            [(w[0], w[1]), (w[0], w[2])]
                .into_iter()
                .filter(|(a, b)| b.0 == a.0 + 2)
                .map(|(a, b)| 0.5 * (b.1 - a.1))
        })
        .collect();
    (steps.len() >= 4).then(|| median(&mut steps))
}

/// Beats of each side within `off` s of the line their side's beats draw
/// around them: each beat's time less its number times the beat (the
/// median over the pairs of the same side two beats apart), against the
/// median of the same over the [`LINE_REACH`] beats of its side either
/// way. A beat timed on the other sound of its beat (a reflection in the
/// room that made the drop look like an unlocking) lies a spacing off:
/// dropped. A median of single beats keeps to the line with up to half of
/// them off it (a median of midpoints of two beats would not).
fn one_line_a_side(onsets: Vec<(u64, f64)>, off: f64) -> Vec<(u64, f64)> {
    keep_by_side(onsets, |r, around| {
        around.len() < 3 || (r - median(around)).abs() <= off
    })
}

/// Beats of a side either way that the line of [`one_line_a_side`] is
/// drawn through.
const LINE_REACH: usize = 10;

/// The time from the tick's onset to the second sound of the beat (the
/// drop of the escapement onto its next tooth), s, on `profile`: the mean
/// envelope around a side's onsets, `before` values before the onset, at
/// `rate` values per second, over a noise `floor`. The second sound is the
/// most prominent peak after the tick's own (prominence: its height over
/// the lowest envelope between the two, at least a quarter of the tick's
/// rise); each sound's onset is where the envelope crosses 10% of its rise,
/// interpolated. `None` when no second sound stands out.
pub fn second_sound(profile: &[f64], floor: f64, rate: f64, before: usize) -> Option<f64> {
    let n = profile.len();
    let near = (0.006 * rate) as usize;
    let (tick_at, &tick) = profile
        .iter()
        .enumerate()
        .skip(before)
        .take(near)
        .max_by(|a, b| a.1.total_cmp(b.1))?;
    let rise = tick - floor;
    if rise <= 0.0 {
        return None;
    }
    // The crossing of `low + 0.1 (peak - low)` before index `peak` (low
    // on the mean of many beats, where the noise is averaged away; nearer
    // the sound's start than a higher level, whatever the sound's rise).
    let onset = |peak: usize, low: f64, stop: usize| -> f64 {
        let level = low + 0.1 * (profile[peak] - low);
        let mut j = peak;
        while j > stop && profile[j - 1] >= level {
            j -= 1;
        }
        if j == 0 {
            return 0.0;
        }
        let (a, b) = (profile[j - 1], profile[j]);
        let f = if b > a {
            ((level - a) / (b - a)).clamp(0.0, 1.0)
        } else {
            1.0
        };
        j as f64 - 1.0 + f
    };
    // The tick rises from the lowest envelope before it (the tail of the
    // beat before may keep it above the floor).
    let quiet_at = (0..tick_at)
        .min_by(|&a, &b| profile[a].total_cmp(&profile[b]))
        .unwrap_or(0);
    let tick_onset = onset(tick_at, profile[quiet_at].min(tick), quiet_at);
    let reach = ((0.001 * rate) as usize).max(1);
    let gap = ((0.002 * rate) as usize).max(2);
    let mut best: Option<(f64, usize, f64)> = None;
    for j in tick_at + gap..n.saturating_sub(reach) {
        let around = &profile[j.saturating_sub(reach)..=j + reach];
        if around.iter().any(|&v| v > profile[j]) {
            continue;
        }
        let valley = profile[tick_at..j]
            .iter()
            .copied()
            .fold(f64::INFINITY, f64::min);
        let prominence = profile[j] - valley;
        if prominence >= 0.25 * rise && best.is_none_or(|b| prominence > b.0) {
            best = Some((prominence, j, valley));
        }
    }
    let (_, drop_at, valley) = best?;
    let valley_at = (tick_at..drop_at)
        .min_by(|&a, &b| profile[a].total_cmp(&profile[b]))
        .unwrap_or(tick_at);
    let drop_onset = onset(drop_at, valley, valley_at);
    Some((drop_onset - tick_onset) / rate)
}
