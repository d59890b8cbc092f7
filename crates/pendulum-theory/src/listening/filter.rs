//! Second-order IIR sections (biquads) after R. Bristow-Johnson's "Audio
//! EQ cookbook" (Butterworth Q = 1/√2), in direct form I, and the band-pass
//! the tick detector uses: high-pass at 500 Hz (mains hum, handling noise,
//! room rumble), low-pass at 10 kHz or 0.45 of the sample rate.

use std::f64::consts::{FRAC_1_SQRT_2, PI};

/// One biquad section.
#[derive(Clone, Copy, Debug)]
pub struct Biquad {
    b: [f64; 3],
    a: [f64; 2],
    x: [f64; 2],
    y: [f64; 2],
}

impl Biquad {
    fn new(b: [f64; 3], a0: f64, a: [f64; 2]) -> Self {
        Self {
            b: b.map(|v| v / a0),
            a: a.map(|v| v / a0),
            x: [0.0; 2],
            y: [0.0; 2],
        }
    }

    /// A Butterworth high-pass at `cutoff` Hz for `rate` samples per second.
    pub fn high_pass(cutoff: f64, rate: f64) -> Self {
        let w = 2.0 * PI * cutoff / rate;
        let (cos, alpha) = (w.cos(), w.sin() / (2.0 * FRAC_1_SQRT_2));
        Self::new(
            [(1.0 + cos) / 2.0, -(1.0 + cos), (1.0 + cos) / 2.0],
            1.0 + alpha,
            [-2.0 * cos, 1.0 - alpha],
        )
    }

    /// A Butterworth low-pass at `cutoff` Hz for `rate` samples per second.
    pub fn low_pass(cutoff: f64, rate: f64) -> Self {
        let w = 2.0 * PI * cutoff / rate;
        let (cos, alpha) = (w.cos(), w.sin() / (2.0 * FRAC_1_SQRT_2));
        Self::new(
            [(1.0 - cos) / 2.0, 1.0 - cos, (1.0 - cos) / 2.0],
            1.0 + alpha,
            [-2.0 * cos, 1.0 - alpha],
        )
    }

    /// Filters one sample.
    #[inline]
    pub fn process(&mut self, x: f64) -> f64 {
        let y = self.b[0] * x + self.b[1] * self.x[0] + self.b[2] * self.x[1]
            - self.a[0] * self.y[0]
            - self.a[1] * self.y[1];
        self.x = [x, self.x[0]];
        self.y = [y, self.y[0]];
        y
    }
}

/// The detector's high-pass, Hz.
pub const DETECTOR_HIGH_PASS_HZ: f64 = 500.0;
/// The wide band's high-pass, Hz (above mains hum and its second harmonic,
/// and room rumble), for the check of a sound between the ticks.
pub const WIDE_HIGH_PASS_HZ: f64 = 150.0;

/// The detector's band-pass: two high-pass and one low-pass sections.
#[derive(Clone, Copy, Debug)]
pub struct BandPass {
    sections: [Biquad; 3],
}

impl BandPass {
    /// The band-pass for `rate` samples per second.
    pub fn new(rate: f64) -> Self {
        Self::from(DETECTOR_HIGH_PASS_HZ, rate)
    }

    /// The same from `high_pass` Hz (a low tock whose sound is mostly
    /// under the detector's 500 Hz is heard from 100 Hz).
    pub fn from(high_pass: f64, rate: f64) -> Self {
        let low = 10_000.0_f64.min(0.45 * rate);
        Self {
            sections: [
                Biquad::high_pass(high_pass, rate),
                Biquad::high_pass(high_pass, rate),
                Biquad::low_pass(low, rate),
            ],
        }
    }

    /// Filters one sample.
    #[inline]
    pub fn process(&mut self, x: f64) -> f64 {
        self.sections.iter_mut().fold(x, |v, s| s.process(v))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The steady-state gain of a sine of `f` Hz through `filter`.
    fn gain(mut filter: impl FnMut(f64) -> f64, f: f64, rate: f64) -> f64 {
        let n = (rate * 0.5) as usize;
        let mut peak: f64 = 0.0;
        for i in 0..n {
            let y = filter((2.0 * PI * f * i as f64 / rate).sin());
            if i > n / 2 {
                peak = peak.max(y.abs());
            }
        }
        peak
    }

    #[test]
    fn butterworth_half_power_at_the_cutoff() {
        let rate = 44_100.0;
        let mut hp = Biquad::high_pass(1000.0, rate);
        assert!((gain(|x| hp.process(x), 1000.0, rate) - FRAC_1_SQRT_2).abs() < 0.01);
        let mut lp = Biquad::low_pass(1000.0, rate);
        assert!((gain(|x| lp.process(x), 1000.0, rate) - FRAC_1_SQRT_2).abs() < 0.01);
        let mut band = BandPass::new(rate);
        assert!(gain(|x| band.process(x), 50.0, rate) < 1e-3);
        assert!((gain(|x| band.process(x), 3000.0, rate) - 1.0).abs() < 0.05);
    }
}
