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
    /// Seed of every random choice.
    pub seed: u64,
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
        Ok(())
    }
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
    /// The time from each tick's onset to its drop's, s.
    pub drop_delay: f64,
}

/// splitmix64 with Box-Muller: small, seeded, reproducible everywhere.
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
    fn gaussian(&mut self) -> f64 {
        let (u, v) = (self.uniform(), self.uniform());
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }
}

/// A sound: decaying resonances `(amplitude, frequency Hz, decay s)`.
#[derive(Clone, Debug)]
struct Sound(Vec<(f64, f64, f64)>);

impl Sound {
    fn random(random: &mut Random, sample_rate: f64, modes: usize) -> Self {
        let top = 8000.0_f64.min(0.45 * sample_rate);
        let mut parts: Vec<(f64, f64, f64)> = (0..modes)
            .map(|_| {
                (
                    random.between(0.4, 1.0),
                    random.between(1000.0, top),
                    random.between(3e-4, 2e-3),
                )
            })
            .collect();
        // Scale so that the peak of the sum is 1.
        let peak = (0..2000)
            .map(|i| Sound(parts.clone()).value(i as f64 * 5e-6).abs())
            .fold(0.0, f64::max);
        for p in &mut parts {
            p.0 /= peak;
        }
        Sound(parts)
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
    /// The time from each tick's onset to its drop's, s.
    pub drop_delay: f64,
    drop_gain: f64,
    /// Room echoes: delay s, gain.
    echoes: Vec<(f64, f64)>,
    /// Every tick present: onset s, gain.
    events: Vec<(f64, f64)>,
    /// The first event that can still sound.
    first_live: usize,
    /// How long after its onset an event's sounds last, s.
    span: f64,
    noise_level: f64,
    hum_level: f64,
    hum_phase: f64,
    noise: Random,
    /// The true onset of every tick present, s.
    pub ticks: Vec<f64>,
    /// The times of the ticks left out, s.
    pub missing: Vec<f64>,
}

impl Synthesizer {
    /// A synthesiser of `spec`; the tick times are drawn at once.
    pub fn new(spec: &TickRecording) -> Self {
        let mut random = Random(spec.seed);
        let rate = f64::from(spec.sample_rate);
        let length = (spec.duration * rate).max(0.0) as usize;
        let tick = Sound::random(&mut random, rate, 3);
        let drop = Sound::random(&mut random, rate, 3);
        let drop_delay = random.between(8e-3, 20e-3);
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
        // The time of beat k from the first: the beats counted, k, are the
        // integral of (1 + rate(t) / 86,400) / nominal over t, a quadratic
        // in t with a linearly changing rate, solved in the form that does
        // not cancel when the change is small.
        let quadratic = spec.rate_change_s_per_day_per_hour / (2.0 * 3600.0 * 86_400.0 * nominal);
        let elapsed =
            |k: f64| 2.0 * k / (1.0 / beat + (1.0 / (beat * beat) + 4.0 * quadratic * k).sqrt());
        // The first tick a little after the start, as a recording begins.
        let start = random.between(0.05, 0.05 + beat);
        let (mut ticks, mut missing, mut events) = (Vec::new(), Vec::new(), Vec::new());
        let mut k = 0_u64;
        loop {
            let shift = if k % 2 == 1 {
                spec.beat_error_ms * 1e-3
            } else {
                0.0
            };
            let t = start + elapsed(k as f64) + shift;
            if t + drop_delay + drop.length() >= spec.duration {
                break;
            }
            k += 1;
            if random.uniform() < spec.missing {
                missing.push(t);
                continue;
            }
            ticks.push(t);
            events.push((t, random.between(0.9, 1.1)));
        }
        let longest_echo = echoes.iter().map(|e| e.0).fold(0.0, f64::max);
        let span = drop_delay + tick.length().max(drop.length()) + longest_echo;
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
            noise: Random(spec.seed ^ 0x5DEE_CE66_D1CE_4E5B),
            ticks,
            missing,
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
        for &(t, gain) in self.events[self.first_live..]
            .iter()
            .take_while(|e| e.0 <= end_time)
        {
            let mut sounds: Vec<(f64, f64, &Sound)> = vec![
                (t, gain, &self.tick),
                (t + self.drop_delay, gain * self.drop_gain, &self.drop),
            ];
            for &(delay, g) in &self.echoes {
                sounds.push((t + delay, gain * g, &self.tick));
                sounds.push((
                    t + self.drop_delay + delay,
                    gain * self.drop_gain * g,
                    &self.drop,
                ));
            }
            for (onset, g, sound) in sounds {
                let from = ((onset * self.rate).ceil().max(0.0) as usize).max(first);
                let to = (((onset + sound.length()) * self.rate) as usize).min(last);
                for i in from..to {
                    block[i - first] += g * sound.value(i as f64 / self.rate - onset);
                }
            }
        }
        for (j, (slot, value)) in out.iter_mut().zip(&block).enumerate() {
            let t = (first + j) as f64 / self.rate;
            let phase = std::f64::consts::TAU * 50.0 * t + self.hum_phase;
            let mains = phase.sin() + 0.3 * (3.0 * phase).sin();
            let v = value + self.hum_level * mains + self.noise_level * self.noise.gaussian();
            // Leave head room: the tick's peak at half of full scale.
            *slot = (0.5 * v).clamp(-1.0, 1.0) as f32;
        }
        self.position = last;
        count
    }
}

/// Synthesises the whole recording of `spec` in memory.
pub fn synthesize(spec: &TickRecording) -> Synthesized {
    let mut synth = Synthesizer::new(spec);
    let mut samples = vec![0.0_f32; synth.len()];
    synth.fill(&mut samples);
    Synthesized {
        samples,
        ticks: synth.ticks,
        missing: synth.missing,
        drop_delay: synth.drop_delay,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
