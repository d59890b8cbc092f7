//! A generator of tracked-swing records that varies what real records
//! vary (issue 23): the release (5-120°), Q (20-2,000), the frame rate
//! (30-1,000 a second), the length of the record (10 s to 15 min, less
//! where dry friction stops the swing first), the tracking noise (0.02° to
//! 0.5°), a zero offset, a camera started some way into the swing or a bob
//! held for a few frames before its release, and dry friction and
//! quadratic drag beside the viscous damping. Every record is the full
//! equation integrated (DOP853 at 1e-12) from its release, so it is an
//! independent truth for the fits, which only see samples.
#![allow(dead_code)]

use pendulum_theory::damped::State;
use pendulum_theory::damping::Damping;
use pendulum_theory::simulation::{
    simulate, Action, Method, Model, Observer, Options, TurningPoint,
};
use pendulum_theory::{Amplitude, Pendulum};

/// A seeded source of uniform and Gaussian numbers (SplitMix64).
pub struct Rng(pub u64);

impl Rng {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    pub fn uniform(&mut self) -> f64 {
        ((self.next_u64() >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }
    /// Uniform on a logarithmic scale between `lo` and `hi`.
    pub fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo * (hi / lo).powf(self.uniform())
    }
    pub fn gaussian(&mut self) -> f64 {
        let (u, v) = (self.uniform(), self.uniform());
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }
}

/// What made a record.
#[derive(Clone, Debug)]
pub struct Truth {
    pub length_m: f64,
    pub g: f64,
    pub release_rad: f64,
    pub q: f64,
    /// Dry friction angle, rad (0: none).
    pub friction_rad: f64,
    /// Quadratic drag, per radian (0: none).
    pub quadratic: f64,
    pub frame_rate: f64,
    pub noise_rad: f64,
    pub offset_rad: f64,
    /// Frames the bob is held at the release before the record's motion.
    pub held_frames: usize,
    /// The first crest in the record, rad from the centre.
    pub first_crest_rad: f64,
}

impl Truth {
    /// Viscous damping alone: Q is the record's.
    pub fn viscous_only(&self) -> bool {
        self.friction_rad == 0.0 && self.quadratic == 0.0
    }
}

/// A record: times (s from the first frame), angles (rad), and its truth.
pub struct Record {
    pub time: Vec<f64>,
    pub angle: Vec<f64>,
    pub truth: Truth,
}

struct Collect {
    samples: Vec<(f64, f64)>,
    crests: Vec<(f64, f64)>,
}

impl Observer for Collect {
    fn sample(&mut self, time: f64, state: &State) -> bool {
        self.samples.push((time, state.angle));
        true
    }
    fn turning_point(&mut self, tp: &TurningPoint) -> Action {
        self.crests.push((tp.time, tp.angle));
        Action::Continue
    }
}

/// The most samples a record of the `small` kind has (for the CI subset).
pub const SMALL_SAMPLES: f64 = 12_000.0;

/// Record `seed`; `small` keeps it under [`SMALL_SAMPLES`] samples.
pub fn record(seed: u64, small: bool) -> Record {
    let mut r = Rng(seed.wrapping_mul(0x2545_F491_4F6C_DD1D) ^ 0x5EED);
    let length_m = r.log_uniform(0.15, 2.5);
    let g = 9.80665;
    let release_deg = 5.0 + 115.0 * r.uniform();
    let release_rad = release_deg.to_radians();
    let q = r.log_uniform(20.0, 2000.0);
    // A third of the records have dry friction, a third quadratic drag
    // (some both): each about as strong as the viscous damping at most.
    let kind = r.uniform();
    let friction_rad = if kind < 0.33 {
        release_rad * r.log_uniform(1e-4, 0.25 / q)
    } else {
        0.0
    };
    let quadratic = if (0.25..0.6).contains(&kind) {
        r.log_uniform(1e-3, 1.0 / q.sqrt())
    } else {
        0.0
    };
    let frame_rate = r.log_uniform(30.0, 1000.0);
    let period = std::f64::consts::TAU * (length_m / g).sqrt();
    let mut duration = r.log_uniform(10.0, 900.0).max(6.0 * period);
    if small {
        duration = duration.min(SMALL_SAMPLES / frame_rate).max(6.0 * period);
    }
    let noise_rad = r.log_uniform(0.02, 0.5).to_radians();
    let offset_rad = (r.uniform() - 0.5) * 4f64.to_radians();
    // A third of the records start with the bob held a few frames; the
    // rest start some way into the swing.
    let held_frames = if r.uniform() < 0.33 {
        1 + (r.uniform() * 10.0) as usize
    } else {
        0
    };
    let start = if held_frames > 0 {
        0.0
    } else {
        r.uniform() * 2.0 * period
    };
    let pendulum = Pendulum::new(length_m, g).unwrap();
    let model = Model::new(
        pendulum,
        Damping::from_q(q).unwrap(),
        quadratic,
        friction_rad,
    )
    .unwrap();
    let dt = 1.0 / frame_rate;
    let mut collect = Collect {
        samples: Vec::new(),
        crests: Vec::new(),
    };
    let options = Options {
        duration: start + duration,
        tolerance: 1e-12,
        method: Method::Dop853,
        sample_interval: Some(dt),
    };
    simulate(
        &model,
        Amplitude::from_radians(release_rad).unwrap(),
        &options,
        &mut collect,
    )
    .unwrap();
    // Dry friction stops the swing: keep the part with a swing of at
    // least a fifth of the release.
    let stop = collect
        .crests
        .iter()
        .find(|(_, a)| a.abs() < 0.2 * release_rad)
        .map_or(f64::INFINITY, |(t, _)| *t);
    let first = (start / dt).round() as usize;
    let mut time = Vec::new();
    let mut angle = Vec::new();
    for k in 0..held_frames {
        time.push(k as f64 * dt);
        angle.push(release_rad);
    }
    let shift = held_frames as f64 * dt - first as f64 * dt;
    for &(t, a) in collect.samples.iter().skip(first) {
        if t > stop {
            break;
        }
        time.push(t + shift);
        angle.push(a);
    }
    for a in &mut angle {
        *a += offset_rad + noise_rad * r.gaussian();
    }
    let record_start = first as f64 * dt;
    let first_crest_rad = if held_frames > 0 || record_start < 0.5 * dt {
        release_rad
    } else {
        collect
            .crests
            .iter()
            .find(|(t, _)| *t >= record_start - 0.5 * dt)
            .map_or(release_rad, |(_, a)| a.abs())
    };
    Record {
        time,
        angle,
        truth: Truth {
            length_m,
            g,
            release_rad,
            q,
            friction_rad,
            quadratic,
            frame_rate,
            noise_rad,
            offset_rad,
            held_frames,
            first_crest_rad,
        },
    }
}
