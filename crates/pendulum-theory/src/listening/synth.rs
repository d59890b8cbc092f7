//! A synthetic recording of a ticking clock, with the true time of every
//! tick: for users to check their setup, and for the tests.
//!
//! Each beat makes two sounds, as a pendulum escapement does: the unlocking
//! (the tick proper, whose onset is the beat's time) and, 8 to 20 ms later,
//! the drop. Each sound is a few exponentially decaying resonances of the
//! clock case, `Σ a_i e^{-t/τ_i} sin(2π f_i t)` with `f_i` between 1 and
//! 8 kHz (below 0.45 of the sample rate) and `τ_i` of 0.3 to 2 ms, drawn
//! once per recording from the seed, so that different seeds give
//! differently shaped ticks. The sounds are evaluated at the exact event
//! time (no rounding to a sample). The room adds 40 echoes between 3 ms and
//! the reverberation time, falling by 60 dB over it; the mains adds a
//! 50 Hz hum with its third harmonic; the microphone adds white Gaussian
//! noise. The signal-to-noise ratio is the direct tick's peak over the
//! noise's RMS, in dB.

/// What to synthesise.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TickRecording {
    /// Samples per second.
    pub sample_rate: u32,
    /// Length, s.
    pub duration: f64,
    /// Nominal beats per hour.
    pub beats_per_hour: f64,
    /// The clock's rate against the nominal at the start, s/day
    /// (positive: gaining).
    pub rate_s_per_day: f64,
    /// How fast the rate changes, s/day an hour (a clock warming up, or
    /// its mainspring running down): the rate at time t is
    /// `rate_s_per_day + rate_change t / 3600`.
    pub rate_change_s_per_day_per_hour: f64,
    /// Half the difference of the tick and tock intervals, ms.
    pub beat_error_ms: f64,
    /// Peak of a tick over the noise RMS, dB.
    pub snr_db: f64,
    /// Reverberation time (−60 dB), s; 0 for none.
    pub reverb_s: f64,
    /// Mains hum amplitude against the tick's peak, dB (e.g. −30).
    pub hum_db: f64,
    /// Probability that a tick is missing (the clock skipped, or a knock
    /// covered it), 0 to 1.
    pub missing: f64,
    /// The time from the unlocking to the drop at the start, ms: a
    /// pendulum clock's crossing of its lift is a large share of its beat
    /// ([`typical_drop_ms`]); none: the sound's own, 8 to 20 ms from the
    /// seed (a watch's).
    pub drop_ms: Option<f64>,
    /// How fast the swing changes, % an hour (negative: the arc falls, as
    /// a clock's running down or drying out): the swing at time t is
    /// `1 + arc_change t / 100 h` times the first, and the drop's time the
    /// crossing of the same lift at that swing
    /// (`sin(π Δ / 2b) = h / A`, `b` the beat).
    pub arc_change_percent_per_hour: f64,
    /// The tock's level against the tick's, dB (a watch's or a clock's
    /// two pallets often sound unlike: −10 dB is a tock a third of the
    /// tick).
    pub tock_db: f64,
    /// A wheel's periodic error: each tick early or late by this much at
    /// most, ms (the time warp `t + e sin(2π t / P)`).
    pub periodic_error_ms: f64,
    /// Its period `P`, s (a seconds clock's escape wheel: 60 s).
    pub periodic_error_period_s: f64,
    /// Seed of every random choice.
    pub seed: u64,
}

/// The drop's time after the unlocking in a pendulum clock of beat `beat`
/// s, ms: the time to cross a lift of 1.5° whole at a swing of 2.5°
/// either side (`2 asin(h/A) b / π`, a Graham escapement's usual figures):
/// 194 ms in a seconds clock, 97 ms at 7,200 beats an hour. (A watch's
/// balance crosses its lift in a few ms.)
pub fn typical_drop_ms(beat: f64) -> f64 {
    2.0 * (0.75_f64 / 2.5).asin() * beat / std::f64::consts::PI * 1e3
}

impl TickRecording {
    /// A minute of a seconds clock keeping time, in beat, at 44.1 kHz, 30
    /// dB over the noise, in a room of 0.3 s with hum 30 dB down, no tick
    /// missing: every input of `synth ticks` not given.
    pub const DEFAULT: Self = Self {
        sample_rate: 44_100,
        duration: 60.0,
        beats_per_hour: 3600.0,
        rate_s_per_day: 0.0,
        rate_change_s_per_day_per_hour: 0.0,
        beat_error_ms: 0.0,
        snr_db: 30.0,
        reverb_s: 0.3,
        hum_db: -30.0,
        missing: 0.0,
        drop_ms: None,
        tock_db: 0.0,
        arc_change_percent_per_hour: 0.0,
        periodic_error_ms: 0.0,
        periodic_error_period_s: 60.0,
        seed: 1,
    };
    /// The longest recording, s (a WAV file holds at most 4 GiB).
    pub const MAX_DURATION_S: f64 = 4.0 * 3600.0;

    /// Checks the recording asked for: the beats listening reads (1800 to
    /// 72,000 an hour), up to four hours at 8 to 192 kHz, a rate within
    /// ±3600 s/day, a beat error under a fifth of the beat, a room of at
    /// most 3 s, at most half the ticks missing.
    pub fn check(&self) -> Result<(), crate::analysis::Refusal> {
        use crate::analysis::Refusal;
        use crate::error::format_significant as n;
        let bph = self.beats_per_hour;
        if !(1800.0..=72_000.0).contains(&bph) {
            return Err(Refusal::field(
                "bph",
                format!(
                    "must be between 1800 and 72000 beats/hour, got {}",
                    n(bph, 6)
                ),
            ));
        }
        if !(self.duration > 0.0 && self.duration <= Self::MAX_DURATION_S) {
            return Err(Refusal::field(
                "duration",
                format!(
                    "must be between 0 and 4 hours, got {} s",
                    n(self.duration, 6)
                ),
            ));
        }
        if !(8000..=192_000).contains(&self.sample_rate) {
            return Err(Refusal::field(
                "sample_rate",
                format!(
                    "must be between 8000 and 192000 Hz, got {}",
                    self.sample_rate
                ),
            ));
        }
        if !(0.0..=3.0).contains(&self.reverb_s) {
            return Err(Refusal::field("reverb", "must be between 0 and 3 s"));
        }
        if !(0.0..=0.5).contains(&self.missing) {
            return Err(Refusal::field("missing", "must be between 0 and 0.5"));
        }
        let rate = crate::analysis::require_finite("rate", self.rate_s_per_day)?;
        if rate.abs() > 3600.0 {
            return Err(Refusal::field("rate", "must be within ±3600 s/day"));
        }
        let change =
            crate::analysis::require_finite("rate_change", self.rate_change_s_per_day_per_hour)?;
        if (rate + change * self.duration / 3600.0).abs() > 3600.0 {
            return Err(Refusal::field(
                "rate_change",
                "must keep the rate within ±3600 s/day to the end of the recording",
            ));
        }
        let beat_error = crate::analysis::require_finite("beat_error", self.beat_error_ms)?;
        if beat_error.abs() > 0.2 * 1800.0 / bph * 1e3 {
            return Err(Refusal::field(
                "beat_error",
                "must be less than a fifth of the beat",
            ));
        }
        crate::analysis::require_finite("snr_db", self.snr_db)?;
        crate::analysis::require_finite("hum_db", self.hum_db)?;
        let tock = crate::analysis::require_finite("tock_db", self.tock_db)?;
        if !(-40.0..=40.0).contains(&tock) {
            return Err(Refusal::field(
                "tock_db",
                format!("must be within ±40 dB of the tick, got {} dB", n(tock, 6)),
            ));
        }
        let beat_ms = 3.6e6 / bph;
        if let Some(drop) = self.drop_ms {
            let drop = crate::analysis::require_finite("drop", drop)?;
            within(
                drop > 0.0 && drop < 0.45 * beat_ms,
                "drop",
                format!(
                    "between 0 and 45% of the beat ({} ms)",
                    n(0.45 * beat_ms, 3)
                ),
                drop,
                "ms",
            )?;
        }
        let arc = crate::analysis::require_finite("arc_change", self.arc_change_percent_per_hour)?;
        let end = 1.0 + arc * self.duration / 3600.0 / 100.0;
        if !(0.5..=2.0).contains(&end) {
            return Err(Refusal::field(
                "arc_change",
                "must keep the swing between half and twice the first to the end of the recording",
            ));
        }
        let error = crate::analysis::require_finite("periodic_error", self.periodic_error_ms)?;
        within(
            error.abs() <= 0.1 * beat_ms,
            "periodic_error",
            format!("within a tenth of the beat ({} ms)", n(0.1 * beat_ms, 3)),
            error,
            "ms",
        )?;
        let period =
            crate::analysis::require_finite("periodic_error_period", self.periodic_error_period_s)?;
        within(
            period >= 4.0 * beat_ms * 1e-3,
            "periodic_error_period",
            format!("at least four beats ({} s)", n(4.0 * beat_ms * 1e-3, 3)),
            period,
            "s",
        )
    }
}

/// A refusal of `field`, "must be `limits`, got `value` `unit`", unless
/// it is `inside` them.
fn within(
    inside: bool,
    field: &'static str,
    limits: String,
    value: f64,
    unit: &str,
) -> Result<(), crate::analysis::Refusal> {
    if inside {
        return Ok(());
    }
    Err(crate::analysis::Refusal::field(
        field,
        format!(
            "must be {limits}, got {} {unit}",
            crate::error::format_significant(value, 6)
        ),
    ))
}

/// A synthesised recording.
#[derive(Clone, Debug, PartialEq)]
pub struct Synthesized {
    /// Mono samples in [-1, 1].
    pub samples: Vec<f32>,
    /// The true onset of every tick present, s.
    pub ticks: Vec<f64>,
    /// The times of the ticks left out, s.
    pub missing: Vec<f64>,
    /// The time from each tick's onset to its drop's at the start, s.
    pub drop_delay: f64,
    /// The same for each tick present (it changes with the swing), s.
    pub drops: Vec<f64>,
    /// Where the interference is loud: its RMS over half a tick's over
    /// the tick's first ms (from s, to s).
    pub loud: Vec<(f64, f64)>,
}

/// A sound that is not a tick laid over the recording: what a clock's own
/// strike and chime, or the hands holding the recorder, add to it.
///
/// A blow of a bell is five partials, a minor-third bell's hum, prime,
/// tierce, quint and nominal (0.5, 1, 1.19, 1.5 and 2 times its strike
/// note, each detuned by up to 1%), decaying over 1 to 5 s, the note
/// drawn between 500 and 1,000 Hz from the seed (a chime's between 600
/// and 1,100); blows come 2 to 2.6 s
/// apart. A chime is notes 0.65 to 0.8 s apart, each on one of four bells
/// a fifth apart at most (a tune's notes drawn from the seed), 4 dB below
/// the strike. Handling is rubbing (noise low-passed at 2 kHz, its level
/// changing every 20 ms) with a knock a second (a low, short resonance).
/// `level_db` of [`Synthesizer::interfere`] is a blow's peak, and the
/// rubbing's peak, over a tick's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Interference {
    /// A clock striking.
    Strike {
        /// The first blow, s from the start.
        at_s: f64,
        /// Blows (the hour).
        blows: u32,
    },
    /// A chime.
    Chime {
        /// The first note, s from the start.
        at_s: f64,
        /// Notes.
        notes: u32,
    },
    /// The recorder handled.
    Handling {
        /// From, s from the start.
        at_s: f64,
        /// For, s.
        for_s: f64,
    },
}

/// The level of [`Interference`] over a tick's peak that `synth ticks`
/// takes when none is given, dB: a strike near the clock.
pub const DEFAULT_INTERFERENCE_DB: f64 = 18.0;

/// Checks `interference` for a recording of `duration` s at `level_db`:
/// each within the recording, 1 to 100 blows or notes, handling of a
/// positive time, the level within ±60 dB of a tick's. The error names the
/// field (`strike`, `chime`, `handling`, `interference_db`).
pub fn check_interference(
    interference: &[Interference],
    duration: f64,
    level_db: f64,
) -> Result<(), crate::analysis::Refusal> {
    use crate::analysis::{require_finite, Refusal};
    use crate::error::format_significant as n;
    let level = require_finite("interference_db", level_db)?;
    if level.abs() > 60.0 {
        return Err(Refusal::field(
            "interference_db",
            format!(
                "must be within ±60 dB of a tick's peak, got {} dB",
                n(level, 6)
            ),
        ));
    }
    for item in interference {
        let (field, at, count) = match *item {
            Interference::Strike { at_s, blows } => ("strike", at_s, Some(blows)),
            Interference::Chime { at_s, notes } => ("chime", at_s, Some(notes)),
            Interference::Handling { at_s, for_s } => {
                if !(for_s > 0.0 && for_s.is_finite()) {
                    return Err(Refusal::field(
                        "handling",
                        format!("must last longer than 0 s, got {} s", n(for_s, 6)),
                    ));
                }
                ("handling", at_s, None)
            }
        };
        if !(at >= 0.0 && at < duration) {
            return Err(Refusal::field(
                field,
                format!(
                    "must start within the recording (0 to {} s), got {} s",
                    n(duration, 6),
                    n(at, 6)
                ),
            ));
        }
        if let Some(c) = count.filter(|c| !(1..=100).contains(c)) {
            return Err(Refusal::field(
                field,
                format!("must have 1 to 100 blows or notes, got {c}"),
            ));
        }
    }
    Ok(())
}

/// Handling noise: its spans, its own random stream and its low-pass
/// state (carried across blocks).
#[derive(Clone, Debug)]
struct Handling {
    spans: Vec<(f64, f64)>,
    level: f64,
    random: Random,
    seed: u64,
    low: f64,
}

impl Handling {
    /// The rubbing's level in the 20 ms segment `segment` (0.1 to 1, from
    /// a hash of the segment: the same whatever the blocks).
    fn level_at(&self, segment: u64) -> f64 {
        let mut r = Random(self.seed ^ segment.wrapping_mul(0x9E37_79B9_7F4A_7C15));
        r.between(0.1, 1.0)
    }
}

/// splitmix64: small, seeded, reproducible everywhere.
#[derive(Clone, Debug)]
struct Random(u64);

impl Random {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn uniform(&mut self) -> f64 {
        ((self.next() >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }
    fn between(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.uniform()
    }
}

/// Gaussian noise from both halves of each Box-Muller pair (one logarithm,
/// square root and sine-cosine pair for two samples); the spare half is
/// kept across blocks.
#[derive(Clone, Debug)]
struct Noise {
    random: Random,
    spare: Option<f64>,
}

impl Noise {
    fn next(&mut self) -> f64 {
        if let Some(v) = self.spare.take() {
            return v;
        }
        let (u, v) = (self.random.uniform(), self.random.uniform());
        let r = (-2.0 * u.ln()).sqrt();
        let (sin, cos) = (std::f64::consts::TAU * v).sin_cos();
        self.spare = Some(r * sin);
        r * cos
    }
}

/// Samples between two fresh computations of a phasor that is otherwise
/// advanced by one complex product a sample: any sample's value is the same
/// whatever block it falls in.
const CHECKPOINT: usize = 64;

/// Adds `gain` times sin(`phase` + `step` i) to `out[i − first]` for the
/// samples `from..to` of a recording whose phase starts counting at
/// sample `begins`, damped by `decay` a sample (1 for none): a damped
/// phasor advanced by one complex product a sample, computed afresh at
/// every [`CHECKPOINT`]-th sample.
fn add_phasor(
    out: &mut [f64],
    first: usize,
    (begins, from, to): (usize, usize, usize),
    gain: f64,
    (phase, step): (f64, f64),
    decay: f64,
) {
    let (c, s) = (decay * step.cos(), decay * step.sin());
    let advance = |(re, im): (f64, f64)| (re * c - im * s, re * s + im * c);
    let mut k = from;
    while k < to {
        let anchor = (k / CHECKPOINT * CHECKPOINT).max(begins);
        let end = ((k / CHECKPOINT + 1) * CHECKPOINT).min(to);
        let n = (anchor - begins) as f64;
        let m = gain * decay.powf(n);
        let (sin, cos) = (phase + step * n).sin_cos();
        let mut z = (m * cos, m * sin);
        for _ in anchor..k {
            z = advance(z);
        }
        for slot in &mut out[k - first..end - first] {
            *slot += z.1;
            z = advance(z);
        }
        k = end;
    }
}

/// A sound: decaying resonances `(amplitude, frequency Hz, decay s)`.
#[derive(Clone, Debug)]
struct Sound(Vec<(f64, f64, f64)>);

impl Sound {
    fn random(random: &mut Random, sample_rate: f64, modes: usize) -> Self {
        let top = 8000.0_f64.min(0.45 * sample_rate);
        let parts: Vec<(f64, f64, f64)> = (0..modes)
            .map(|_| {
                (
                    random.between(0.4, 1.0),
                    random.between(1000.0, top),
                    random.between(3e-4, 2e-3),
                )
            })
            .collect();
        Self::normalized(parts, 5e-6)
    }

    /// The resonances `parts` scaled so that the peak of their sum over
    /// its first 2,000 steps of `step` s is 1.
    fn normalized(mut parts: Vec<(f64, f64, f64)>, step: f64) -> Self {
        let peak = (0..2000)
            .map(|i| Sound(parts.clone()).value(i as f64 * step).abs())
            .fold(0.0, f64::max);
        for p in &mut parts {
            p.0 /= peak;
        }
        Sound(parts)
    }

    /// A bell struck at `note` Hz (see [`Interference`]).
    fn bell(random: &mut Random, note: f64) -> Self {
        let partials = [
            (0.4, 0.5, 4.0),
            (1.0, 1.0, 3.0),
            (0.5, 1.19, 2.0),
            (0.3, 1.5, 1.5),
            (0.6, 2.0, 1.2),
        ];
        let parts = partials
            .iter()
            .map(|&(a, ratio, tau)| {
                let f = note * ratio * random.between(0.99, 1.01);
                (a, f, tau * random.between(0.8, 1.2))
            })
            .collect();
        // (The peak within the first 20 ms: the partials beat slowly.)
        Self::normalized(parts, 1e-5)
    }

    /// The sound `t` seconds after its onset.
    fn value(&self, t: f64) -> f64 {
        if t < 0.0 {
            return 0.0;
        }
        self.0
            .iter()
            .map(|&(a, f, tau)| a * (-t / tau).exp() * (std::f64::consts::TAU * f * t).sin())
            .sum()
    }

    /// Adds `gain` times the sound with its onset at `onset` s, sampled at
    /// `rate`, to `out`, whose first slot is sample `first`. Each
    /// resonance is a damped phasor ([`add_phasor`]), not an exponential
    /// and a sine a sample: some twenty times faster, and within 1e-12 of
    /// [`Sound::value`] (test `the_recurrence_follows_the_sound`).
    fn add_to(&self, out: &mut [f64], first: usize, gain: f64, onset: f64, rate: f64) {
        let begins = (onset * rate).ceil().max(0.0) as usize;
        let from = begins.max(first);
        let to = (((onset + self.length()) * rate) as usize).min(first + out.len());
        if from >= to {
            return;
        }
        // Time of the first sample after the onset.
        let t = begins as f64 / rate - onset;
        for &(a, f, tau) in &self.0 {
            let w = std::f64::consts::TAU * f;
            let m = gain * a * (-t / tau).exp();
            let decay = (-1.0 / (rate * tau)).exp();
            add_phasor(out, first, (begins, from, to), m, (w * t, w / rate), decay);
        }
    }

    /// How long it lasts (until e^{-12} of its slowest resonance), s.
    fn length(&self) -> f64 {
        12.0 * self.0.iter().map(|p| p.2).fold(0.0, f64::max)
    }
}

/// A recording being synthesised block by block, in fixed memory (but for
/// the list of tick times): for recordings of hours.
#[derive(Clone, Debug)]
pub struct Synthesizer {
    rate: f64,
    length: usize,
    position: usize,
    tick: Sound,
    drop: Sound,
    /// The time from each tick's onset to its drop's at the start, s.
    pub drop_delay: f64,
    drop_gain: f64,
    /// Room echoes: delay s, gain.
    echoes: Vec<(f64, f64)>,
    /// Every tick present: onset s, gain, the drop's delay s.
    events: Vec<(f64, f64, f64)>,
    /// The first event that can still sound.
    first_live: usize,
    /// How long after its onset an event's sounds last, s.
    span: f64,
    noise_level: f64,
    hum_level: f64,
    hum_phase: f64,
    noise: Noise,
    /// The true onset of every tick present, s.
    pub ticks: Vec<f64>,
    /// The times of the ticks left out, s.
    pub missing: Vec<f64>,
    /// Bells struck: onset s, gain, the bell.
    blows: Vec<(f64, f64, Sound)>,
    handling: Option<Handling>,
    /// Where the interference is loud: its RMS over half a tick's over
    /// the tick's first ms (from s, to s).
    pub loud: Vec<(f64, f64)>,
}

impl Synthesizer {
    /// Lays `interference` over the recording, `level_db` over a tick's
    /// peak (see [`Interference`]); the spans where it is louder than a
    /// tick are in [`Self::loud`].
    pub fn interfere(mut self, interference: &[Interference], level_db: f64) -> Self {
        let mut random = Random(self.noise.random.0 ^ 0xB311_5EED);
        let gain = 10f64.powf(level_db / 20.0);
        let note = random.between(500.0, 1000.0);
        let spacing = random.between(2.0, 2.6);
        let chime_note = random.between(600.0, 1100.0);
        let chime: Vec<Sound> = [1.0, 9.0 / 8.0, 5.0 / 4.0, 3.0 / 2.0]
            .iter()
            .map(|r| Sound::bell(&mut random, chime_note * r))
            .collect();
        let strike = Sound::bell(&mut random, note);
        // A tick's loudness as a listener's envelope has it: its RMS over
        // its first millisecond.
        let tick_rms = ((0..1000)
            .map(|i| self.tick.value(i as f64 * 1e-6).powi(2))
            .sum::<f64>()
            / 1000.0)
            .sqrt();
        // Until a bell's ring (the RMS of its partials) falls under half
        // that, s (by bisection: the RMS only falls).
        let ring = |g: f64, bell: &Sound| {
            let rms = |t: f64| {
                let power: f64 = bell
                    .0
                    .iter()
                    .map(|&(a, _, tau)| (g * a * (-t / tau).exp()).powi(2) / 2.0)
                    .sum();
                power.sqrt()
            };
            let (mut lo, mut hi) = (0.0, bell.length());
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if rms(mid) > 0.5 * tick_rms {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            hi
        };
        for item in interference {
            match *item {
                Interference::Strike { at_s, blows } => {
                    for i in 0..blows {
                        let at = at_s + f64::from(i) * spacing;
                        self.blows.push((at, gain, strike.clone()));
                    }
                    let last = at_s + f64::from(blows.max(1) - 1) * spacing;
                    self.loud.push((at_s, last + ring(gain, &strike)));
                }
                Interference::Chime { at_s, notes } => {
                    let g = gain * 10f64.powf(-4.0 / 20.0);
                    let mut at = at_s;
                    let mut end = at_s;
                    for _ in 0..notes {
                        let bell = &chime[(random.uniform() * 4.0) as usize % 4];
                        self.blows.push((at, g, bell.clone()));
                        end = end.max(at + ring(g, bell));
                        at += random.between(0.65, 0.8);
                    }
                    self.loud.push((at_s, end));
                }
                Interference::Handling { at_s, for_s } => {
                    let h = self.handling.get_or_insert_with(|| Handling {
                        spans: Vec::new(),
                        level: gain,
                        random: Random(random.next()),
                        seed: random.next(),
                        low: 0.0,
                    });
                    h.spans.push((at_s, at_s + for_s));
                    self.loud.push((at_s, at_s + for_s));
                }
            }
        }
        self.blows.sort_by(|a, b| a.0.total_cmp(&b.0));
        self.loud.sort_by(|a, b| a.0.total_cmp(&b.0));
        self
    }

    /// Adds the bells and the handling to `block`, whose first sample is
    /// `first`.
    fn add_interference(&mut self, block: &mut [f64], first: usize) {
        let (start, end) = (
            first as f64 / self.rate,
            (first + block.len()) as f64 / self.rate,
        );
        for (at, gain, bell) in &self.blows {
            if *at <= end && at + bell.length() >= start {
                bell.add_to(block, first, *gain, *at, self.rate);
            }
        }
        let Some(h) = &mut self.handling else {
            return;
        };
        // Rubbing: noise through a one-pole low-pass at 2 kHz; a knock a
        // second: a 150 Hz resonance of 30 ms.
        let pole = (-std::f64::consts::TAU * 2000.0 / self.rate).exp();
        let knock = Sound(vec![(1.0, 150.0, 0.03)]);
        for (j, slot) in block.iter_mut().enumerate() {
            let t = (first + j) as f64 / self.rate;
            let white = h.random.uniform() - 0.5;
            h.low = pole * h.low + (1.0 - pole) * white;
            if h.spans.iter().any(|&(a, b)| t >= a && t < b) {
                let level = h.level_at((t / 0.02) as u64);
                // (The low-pass keeps about a tenth of uniform noise's
                // range: scaled back to a peak near `level`.)
                *slot += h.level * level * 6.0 * h.low;
            }
        }
        let knocks: Vec<f64> = h
            .spans
            .iter()
            .flat_map(|&(a, b)| {
                (0..)
                    .map(move |i| a + 0.3 + f64::from(i))
                    .take_while(move |&k| k < b)
            })
            .filter(|&k| k <= end && k + knock.length() >= start)
            .collect();
        let level = h.level;
        for k in knocks {
            knock.add_to(block, first, level, k, self.rate);
        }
    }

    /// A synthesiser of `spec`; the tick times are drawn at once.
    pub fn new(spec: &TickRecording) -> Self {
        let mut random = Random(spec.seed);
        let rate = f64::from(spec.sample_rate);
        let length = (spec.duration * rate).max(0.0) as usize;
        let tick = Sound::random(&mut random, rate, 3);
        let drop = Sound::random(&mut random, rate, 3);
        let drawn = random.between(8e-3, 20e-3);
        let drop_delay = spec.drop_ms.map_or(drawn, |d| d * 1e-3);
        let drop_gain = random.between(0.4, 0.8);
        let echoes: Vec<(f64, f64)> = if spec.reverb_s > 0.0 {
            (0..40)
                .map(|_| {
                    let delay = random.between(3e-3, spec.reverb_s);
                    let gain = 0.3 * 10f64.powf(-3.0 * delay / spec.reverb_s);
                    (delay, if random.uniform() < 0.5 { -gain } else { gain })
                })
                .collect()
        } else {
            Vec::new()
        };
        let nominal = 3600.0 / spec.beats_per_hour;
        let beat = nominal / (1.0 + spec.rate_s_per_day / 86_400.0);
        // The drop at time t: the same lift crossed at the swing then
        // (sin(π Δ / 2b) = h / A, A scaled by the arc's change).
        let arc = spec.arc_change_percent_per_hour / 100.0 / 3600.0;
        let drop_at = |first: f64, t: f64| -> f64 {
            if arc == 0.0 {
                return first;
            }
            let w = std::f64::consts::PI / nominal;
            let edge = (0.5 * w * first).sin() / (1.0 + arc * t);
            2.0 * edge.min(1.0).asin() / w
        };
        // The time of beat k from the first: the beats counted, k, are the
        // integral of (1 + rate(t) / 86,400) / nominal over t, a quadratic
        // in t with a linearly changing rate, solved in the form that does
        // not cancel when the change is small.
        let quadratic = spec.rate_change_s_per_day_per_hour / (2.0 * 3600.0 * 86_400.0 * nominal);
        let elapsed =
            |k: f64| 2.0 * k / (1.0 / beat + (1.0 / (beat * beat) + 4.0 * quadratic * k).sqrt());
        // The first tick a little after the start, as a recording begins.
        let start = random.between(0.05, 0.05 + beat);
        let tock_gain = 10f64.powf(spec.tock_db / 20.0);
        let (mut ticks, mut missing, mut events) = (Vec::new(), Vec::new(), Vec::new());
        let mut k = 0_u64;
        loop {
            let shift = if k % 2 == 1 {
                spec.beat_error_ms * 1e-3
            } else {
                0.0
            };
            let clean = start + elapsed(k as f64);
            let wheel = spec.periodic_error_ms
                * 1e-3
                * (std::f64::consts::TAU * clean / spec.periodic_error_period_s).sin();
            let t = clean + shift + wheel;
            let delay = drop_at(drop_delay, t);
            if t + delay + drop.length() >= spec.duration {
                break;
            }
            k += 1;
            if random.uniform() < spec.missing {
                missing.push(t);
                continue;
            }
            ticks.push(t);
            let side = if k % 2 == 0 { tock_gain } else { 1.0 };
            events.push((t, side * random.between(0.9, 1.1), delay));
        }
        let longest_echo = echoes.iter().map(|e| e.0).fold(0.0, f64::max);
        let latest_drop = events.iter().map(|e| e.2).fold(drop_delay, f64::max);
        let span = latest_drop + tick.length().max(drop.length()) + longest_echo;
        let hum_phase = random.between(0.0, std::f64::consts::TAU);
        Self {
            rate,
            length,
            position: 0,
            tick,
            drop,
            drop_delay,
            drop_gain,
            echoes,
            events,
            first_live: 0,
            span,
            noise_level: 10f64.powf(-spec.snr_db / 20.0),
            hum_level: 10f64.powf(spec.hum_db / 20.0),
            hum_phase,
            // The noise from its own stream, so that blocks of any size
            // give the same recording.
            noise: Noise {
                random: Random(spec.seed ^ 0x5DEE_CE66_D1CE_4E5B),
                spare: None,
            },
            ticks,
            missing,
            blows: Vec::new(),
            handling: None,
            loud: Vec::new(),
        }
    }

    /// Samples in the whole recording.
    pub fn len(&self) -> usize {
        self.length
    }

    /// Whether the recording has no samples.
    pub fn is_empty(&self) -> bool {
        self.length == 0
    }

    /// Writes the next samples (in [-1, 1], the tick's peak at half of full
    /// scale) into `out`; returns how many (fewer than `out.len()` only at
    /// the end, 0 after it).
    pub fn fill(&mut self, out: &mut [f32]) -> usize {
        let count = out.len().min(self.length - self.position);
        let (first, last) = (self.position, self.position + count);
        let mut block = vec![0.0_f64; count];
        let end_time = last as f64 / self.rate;
        while self.first_live < self.events.len()
            && self.events[self.first_live].0 + self.span < first as f64 / self.rate
        {
            self.first_live += 1;
        }
        for &(t, gain, drop_delay) in self.events[self.first_live..]
            .iter()
            .take_while(|e| e.0 <= end_time)
        {
            let mut sounds: Vec<(f64, f64, &Sound)> = vec![
                (t, gain, &self.tick),
                (t + drop_delay, gain * self.drop_gain, &self.drop),
            ];
            for &(delay, g) in &self.echoes {
                sounds.push((t + delay, gain * g, &self.tick));
                sounds.push((
                    t + drop_delay + delay,
                    gain * self.drop_gain * g,
                    &self.drop,
                ));
            }
            for (onset, g, sound) in sounds {
                sound.add_to(&mut block, first, g, onset, self.rate);
            }
        }
        self.add_interference(&mut block, first);
        // Mains hum: 50 Hz and its third harmonic.
        let step = std::f64::consts::TAU * 50.0 / self.rate;
        for (harmonic, gain) in [(1.0, self.hum_level), (3.0, 0.3 * self.hum_level)] {
            let phasor = (harmonic * self.hum_phase, harmonic * step);
            add_phasor(&mut block, first, (0, first, last), gain, phasor, 1.0);
        }
        for (slot, value) in out.iter_mut().zip(&block) {
            let v = value + self.noise_level * self.noise.next();
            // Leave head room: the tick's peak at half of full scale.
            *slot = (0.5 * v).clamp(-1.0, 1.0) as f32;
        }
        self.position = last;
        count
    }
}

/// Synthesises the whole recording of `spec` in memory.
pub fn synthesize(spec: &TickRecording) -> Synthesized {
    synthesize_with(spec, &[], 0.0)
}

/// Synthesises the whole recording of `spec` in memory, with
/// `interference` laid over it `level_db` over a tick's peak.
pub fn synthesize_with(
    spec: &TickRecording,
    interference: &[Interference],
    level_db: f64,
) -> Synthesized {
    let mut synth = Synthesizer::new(spec).interfere(interference, level_db);
    let mut samples = vec![0.0_f32; synth.len()];
    synth.fill(&mut samples);
    Synthesized {
        samples,
        ticks: synth.ticks,
        missing: synth.missing,
        drop_delay: synth.drop_delay,
        drops: synth.events.iter().map(|e| e.2).collect(),
        loud: synth.loud,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_recurrence_follows_the_sound() {
        let mut random = Random(5);
        for rate in [8000.0, 44_100.0, 96_000.0] {
            let sound = Sound::random(&mut random, rate, 3);
            let onset = 10.63 / rate;
            // To the sound's end, where add_to stops.
            let n = ((sound.length() + onset) * rate) as usize;
            let mut out = vec![0.0; n];
            sound.add_to(&mut out, 0, 0.8, onset, rate);
            for (i, v) in out.iter().enumerate() {
                let direct = 0.8 * sound.value(i as f64 / rate - onset);
                assert!(
                    (v - direct).abs() < 1e-12,
                    "{rate} Hz, sample {i}: {v} {direct}"
                );
            }
        }
    }

    #[test]
    fn blocks_of_any_size_give_the_same_recording() {
        let spec = TickRecording {
            sample_rate: 8000,
            duration: 3.0,
            beats_per_hour: 18_000.0,
            rate_s_per_day: 0.0,
            rate_change_s_per_day_per_hour: 0.0,
            beat_error_ms: 1.0,
            snr_db: 20.0,
            reverb_s: 0.3,
            hum_db: -30.0,
            missing: 0.1,
            seed: 7,
            ..TickRecording::DEFAULT
        };
        let whole = synthesize(&spec).samples;
        let mut synth = Synthesizer::new(&spec);
        let mut pieces = Vec::new();
        let mut block = vec![0.0_f32; 777];
        loop {
            let n = synth.fill(&mut block);
            if n == 0 {
                break;
            }
            pieces.extend_from_slice(&block[..n]);
        }
        assert_eq!(pieces, whole);
    }

    #[test]
    fn ticks_follow_rate_and_beat_error() {
        let spec = TickRecording {
            sample_rate: 8000,
            duration: 20.0,
            beats_per_hour: 3600.0,
            rate_s_per_day: 86.4,
            rate_change_s_per_day_per_hour: 0.0,
            beat_error_ms: 2.0,
            snr_db: 30.0,
            reverb_s: 0.0,
            hum_db: -40.0,
            missing: 0.0,
            seed: 1,
            ..TickRecording::DEFAULT
        };
        let s = synthesize(&spec);
        assert_eq!(s.samples.len(), 160_000);
        assert!(s.ticks.len() >= 18);
        let beat = 1.0 / 1.001;
        for w in s.ticks.windows(3) {
            // Two intervals sum to two beats; they differ by twice the beat error.
            assert!((w[2] - w[0] - 2.0 * beat).abs() < 1e-12);
            assert!(((w[1] - w[0]) - (w[2] - w[1])).abs() - 4e-3 < 1e-12);
        }
    }
}
