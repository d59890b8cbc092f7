//! Which channel of a recording to listen to: the one whose ticks stand
//! out clearest ([`crate::listening::detect::gate::prominence`] of the
//! detector's envelope), not the loudest. A stereo recording from a phone
//! or a pair of microphones often has one channel near the movement and
//! one picking up the room, a fan or a bad cable, louder and useless.

use super::detect::gate::prominence;
use super::detect::{envelope_rate, Envelope};

/// Channels whose ticks stand out within this factor (3 dB) of the
/// clearest's are as clear: the louder of them is taken (the quieter is
/// the same sound with fewer bits).
pub const AS_CLEAR: f64 = std::f64::consts::SQRT_2;

/// The channel (0-based) of `channels` (each the same stretch of the
/// recording, a few tens of seconds, at `sample_rate` Hz) whose ticks
/// stand out clearest, the louder among those as clear ([`AS_CLEAR`]);
/// 0 when none can be measured (under two seconds).
pub fn clearest_channel(channels: &[Vec<f32>], sample_rate: f64) -> usize {
    let scored: Vec<(f64, f64)> = channels
        .iter()
        .map(|samples| {
            let mut env = Envelope::new(sample_rate);
            env.push(samples);
            let rate = envelope_rate(&env, sample_rate);
            let energy: f64 = samples.iter().map(|&x| f64::from(x).powi(2)).sum();
            (prominence(&env.values, rate).unwrap_or(0.0), energy)
        })
        .collect();
    let clearest = scored.iter().map(|s| s.0).fold(0.0, f64::max);
    if clearest <= 0.0 {
        return 0;
    }
    scored
        .iter()
        .enumerate()
        .filter(|(_, s)| s.0 * AS_CLEAR >= clearest)
        .fold((0, f64::NEG_INFINITY), |best, (i, s)| {
            if s.1 > best.1 {
                (i, s.1)
            } else {
                best
            }
        })
        .0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::listening::synth::{synthesize, TickRecording};

    #[test]
    fn the_clear_channel_is_taken_over_a_louder_noisy_one() {
        let clock = synthesize(&TickRecording {
            duration: 20.0,
            sample_rate: 8000,
            ..TickRecording::DEFAULT
        })
        .samples;
        // The other channel: the clock 30 dB down under uniform noise
        // whose RMS passes the ticks' peak (a fan by the microphone).
        let mut state = 7_u64;
        let noisy: Vec<f32> = clock
            .iter()
            .map(|&x| {
                state = state
                    .wrapping_mul(6_364_136_223_846_793_005)
                    .wrapping_add(1_442_695_040_888_963_407);
                let u = (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
                (0.03 * f64::from(x) + 2.0 * u) as f32
            })
            .collect();
        assert_eq!(clearest_channel(&[noisy.clone(), clock.clone()], 8000.0), 1);
        assert_eq!(clearest_channel(&[clock, noisy], 8000.0), 0);
        assert_eq!(clearest_channel(&[vec![0.0; 100]], 8000.0), 0);
    }
}
