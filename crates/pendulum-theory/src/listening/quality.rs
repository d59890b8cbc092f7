//! What a recording's samples say of how it was made: clipping and mains
//! hum, measured in one pass beside the tick refiner, in fixed memory.
//!
//! * Clipping: runs of three or more samples at full scale (|x| ≥
//!   [`FULL_SCALE`]), runs within 10 ms of each other counted once (one
//!   clipped tick).
//! * Hum: the Goertzel algorithm (Goertzel, Am. Math. Monthly 65, 34,
//!   1958; Lyons, Understanding DSP, 3rd ed., §13.17) at 50 and 60 Hz on
//!   blocks of one second (lines 1 Hz wide, so that mains a few tenths of
//!   a hertz off are taken in); the amplitude is the root of the blocks'
//!   mean power at each line (`2|X|/N` for a sine), against the largest
//!   sample. Exact for a steady sine on a whole number of cycles a block;
//!   a sine 0.3 Hz off its line loses at most 13% of its amplitude.

/// A sample this near full scale counts as clipped (16-bit full scale is
/// 32767/32768).
pub const FULL_SCALE: f32 = 0.999;
/// The mains frequencies looked at, Hz.
pub const MAINS_HZ: [f64; 2] = [50.0, 60.0];

/// The running measures.
#[derive(Clone, Debug)]
pub struct Quality {
    rate: f64,
    block: usize,
    filled: usize,
    /// Goertzel state per mains line: coefficient, s1, s2.
    lines: [(f64, f64, f64); 2],
    /// Summed power per line over the blocks, and the blocks.
    power: [f64; 2],
    blocks: usize,
    peak: f32,
    samples: u64,
    run: usize,
    last_clip: Option<u64>,
    /// Each clipped sound's first sample (at most [`MOST_CLIPS`]).
    clips: Vec<u64>,
    /// Clipped sounds past those kept.
    more_clips: usize,
}

/// Clipped sounds whose times are kept (the rest are counted).
pub const MOST_CLIPS: usize = 100_000;

/// What [`Quality`] measured.
#[derive(Clone, Debug, PartialEq)]
pub struct Measured {
    /// Clipped sounds (runs at full scale, 10 ms apart).
    pub clips: usize,
    /// Clipped sounds past [`MOST_CLIPS`], whose times are not kept.
    pub clips_untimed: usize,
    /// The strongest mains line, Hz.
    pub hum_hz: f64,
    /// Its amplitude over the largest sample's (0 to about 1).
    pub hum_fraction: f64,
    /// When each clipped sound began, s.
    pub clip_times_s: Vec<f64>,
}

impl Quality {
    /// For samples at `rate` a second.
    pub fn new(rate: f64) -> Self {
        let block = rate.round().max(1.0) as usize;
        let lines = MAINS_HZ.map(|hz| (2.0 * (std::f64::consts::TAU * hz / rate).cos(), 0.0, 0.0));
        Self {
            rate,
            block,
            filled: 0,
            lines,
            power: [0.0; 2],
            blocks: 0,
            peak: 0.0,
            samples: 0,
            run: 0,
            last_clip: None,
            clips: Vec::new(),
            more_clips: 0,
        }
    }

    /// Takes the next samples.
    pub fn push(&mut self, samples: &[f32]) {
        let apart = (0.01 * self.rate) as u64;
        for &x in samples {
            let a = x.abs();
            self.peak = self.peak.max(a);
            if a >= FULL_SCALE {
                self.run += 1;
                if self.run == 3 {
                    if self.last_clip.is_none_or(|l| self.samples > l + apart) {
                        if self.clips.len() < MOST_CLIPS {
                            self.clips.push(self.samples);
                        } else {
                            self.more_clips += 1;
                        }
                    }
                    self.last_clip = Some(self.samples);
                } else if self.run > 3 {
                    self.last_clip = Some(self.samples);
                }
            } else {
                self.run = 0;
            }
            self.samples += 1;
            let x = f64::from(x);
            for line in &mut self.lines {
                let s0 = x + line.0 * line.1 - line.2;
                line.2 = line.1;
                line.1 = s0;
            }
            self.filled += 1;
            if self.filled == self.block {
                self.end_block();
            }
        }
    }

    /// The block's power at each line, and the state reset.
    fn end_block(&mut self) {
        let n = self.filled as f64;
        for (line, power) in self.lines.iter_mut().zip(&mut self.power) {
            let (c, s1, s2) = *line;
            let squared = s1 * s1 + s2 * s2 - c * s1 * s2;
            // A sine of amplitude a gives |X|² = (a N / 2)².
            *power += squared * 4.0 / (n * n);
            line.1 = 0.0;
            line.2 = 0.0;
        }
        self.blocks += 1;
        self.filled = 0;
    }

    /// What was measured (a last part block of under a second is left
    /// out of the hum).
    pub fn finish(&self) -> Measured {
        let (which, power) = if self.power[1] > self.power[0] {
            (1, self.power[1])
        } else {
            (0, self.power[0])
        };
        let amplitude = if self.blocks > 0 {
            (power / self.blocks as f64).sqrt()
        } else {
            0.0
        };
        Measured {
            clips: self.clips.len() + self.more_clips,
            clips_untimed: self.more_clips,
            clip_times_s: self.clips.iter().map(|&i| i as f64 / self.rate).collect(),
            hum_hz: MAINS_HZ[which],
            hum_fraction: if self.peak > 0.0 {
                amplitude / f64::from(self.peak)
            } else {
                0.0
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hum_and_clipping_are_measured() {
        let rate = 8000.0;
        let mut q = Quality::new(rate);
        // 3 s of 0.2 at 50.2 Hz, with three clipped bursts of 5 samples.
        let samples: Vec<f32> = (0..24_000)
            .map(|i| {
                let t = i as f64 / rate;
                let clip = [4000, 12_000, 20_000]
                    .iter()
                    .any(|&c| (c..c + 5).contains(&i));
                if clip {
                    1.0
                } else {
                    (0.2 * (std::f64::consts::TAU * 50.2 * t).sin()) as f32
                }
            })
            .collect();
        for chunk in samples.chunks(1000) {
            q.push(chunk);
        }
        let m = q.finish();
        assert_eq!(m.clips, 3);
        assert_eq!(m.hum_hz, 50.0);
        // 0.2 of a peak of 1, less the 0.2 Hz offset's loss (sinc: 6%).
        assert!((m.hum_fraction - 0.2).abs() < 0.02, "{m:?}");
    }
}
