//! The envelope of a recording: band-pass, RMS over 1 ms, 2 kHz.

use crate::listening::filter::BandPass;

/// Envelope samples per second.
pub const ENVELOPE_RATE: f64 = 2000.0;

/// The envelope of a recording, fed in blocks: the band-passed sound's
/// root-mean-square over the last 1 ms (two blocks of 0.5 ms), one value
/// per 0.5 ms.
///
/// An RMS over about a tick's length is the energy detector for a sound
/// of unknown shape: at a 44.1 kHz sampling it averages 44 samples of
/// noise, so a tick whose peak is only twice the noise's RMS (6 dB) still
/// stands several standard deviations above the floor, where the largest
/// sample of a block (a peak follower) is lost among the noise's crests.
#[derive(Clone, Debug)]
pub struct Envelope {
    filter: BandPass,
    per_value: usize,
    count: usize,
    block_sum: f64,
    last_block: f64,
    /// The envelope, at [`ENVELOPE_RATE`] (the first value covers the first
    /// `per_value` samples).
    pub values: Vec<f32>,
    /// Audio samples per envelope value.
    pub samples_per_value: usize,
    /// Samples fed.
    pub samples: u64,
}

impl Envelope {
    /// An envelope for audio at `sample_rate`.
    pub fn new(sample_rate: f64) -> Self {
        Self::with_filter(sample_rate, BandPass::new(sample_rate))
    }

    /// An envelope through `filter` (the wide band, for a sound the
    /// detector's band leaves out).
    pub fn with_filter(sample_rate: f64, filter: BandPass) -> Self {
        let per_value = (sample_rate / ENVELOPE_RATE).round().max(1.0) as usize;
        Self {
            filter,
            per_value,
            count: 0,
            block_sum: 0.0,
            last_block: 0.0,
            values: Vec::new(),
            samples_per_value: per_value,
            samples: 0,
        }
    }

    /// Feeds samples.
    pub fn push(&mut self, samples: &[f32]) {
        for &x in samples {
            let y = self.filter.process(f64::from(x));
            self.block_sum += y * y;
            self.count += 1;
            if self.count == self.per_value {
                let block = self.block_sum / self.per_value as f64;
                self.values
                    .push((0.5 * (block + self.last_block)).sqrt() as f32);
                self.last_block = block;
                self.count = 0;
                self.block_sum = 0.0;
            }
        }
        self.samples += samples.len() as u64;
    }

    /// The time of envelope value `i` (its block's middle), in samples.
    fn rate(&self, sample_rate: f64) -> f64 {
        sample_rate / self.per_value as f64
    }
}

/// Times the envelope's values to seconds for `sample_rate`.
pub fn envelope_rate(envelope: &Envelope, sample_rate: f64) -> f64 {
    envelope.rate(sample_rate)
}
