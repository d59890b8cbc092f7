//! One step of Verner's 9(8) pair ([`super::vern9_tableau`]): sixteen
//! evaluations of `f`, the 9th-order solution and an 8th-order error
//! estimate, `err = sqrt(Σ (e_i / scale_i)² / n)` (the usual RMS norm; 1 at
//! the tolerance). For tight tolerances, where its higher order pays.
//!
//! The pair has no dense output of its own here: the driver locates events
//! and samples by stepping again from the step's start to the time wanted,
//! which is exact to the method's order (one step is 9th-order accurate at
//! any length).

use super::control::Tolerance;
use super::vern9_tableau::{A, B, C, E, STAGES};
use super::State2;

/// The outcome of one attempted step.
#[derive(Clone, Copy, Debug)]
pub struct Step {
    /// State at the end.
    pub y1: State2,
    /// The error norm: 1 at the tolerance.
    pub error: f64,
}

/// Attempts a step of length `h` from `(t, y0)`, where `f0 = f(t, y0)`.
#[inline]
pub fn attempt(
    f: &impl Fn(f64, State2) -> State2,
    t: f64,
    y0: State2,
    f0: State2,
    h: f64,
    tolerance: &Tolerance,
) -> Step {
    let mut k = [[0.0_f64; 2]; STAGES];
    k[0] = f0;
    for i in 1..STAGES {
        let mut dy = [0.0_f64; 2];
        for j in 0..i {
            let a = A[i][j];
            if a != 0.0 {
                dy[0] += a * k[j][0];
                dy[1] += a * k[j][1];
            }
        }
        k[i] = f(t + C[i] * h, [y0[0] + h * dy[0], y0[1] + h * dy[1]]);
    }
    let (mut sum, mut err) = ([0.0_f64; 2], [0.0_f64; 2]);
    for j in 0..STAGES {
        for c in 0..2 {
            sum[c] += B[j] * k[j][c];
            err[c] += E[j] * k[j][c];
        }
    }
    let y1 = [y0[0] + h * sum[0], y0[1] + h * sum[1]];
    let norm = (0..2)
        .map(|c| (h * err[c] / tolerance.scale(y0[c], y1[c])).powi(2))
        .sum::<f64>()
        / 2.0;
    Step {
        y1,
        error: norm.sqrt(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pendulum(_t: f64, y: State2) -> State2 {
        [y[1], -y[0].sin()]
    }

    #[test]
    fn global_error_is_ninth_order() {
        let tol = Tolerance::both(1e-12);
        let start = [1.0, 0.5];
        let run = |n: u32| {
            let h = 4.0 / f64::from(n);
            let mut y = start;
            for i in 0..n {
                let t = h * f64::from(i);
                y = attempt(&pendulum, t, y, pendulum(t, y), h, &tol).y1;
            }
            y
        };
        let reference = run(400);
        let error = |n: u32| (run(n)[0] - reference[0]).abs();
        // Doubling the steps divides the error by about 2^9 = 512.
        let ratio = error(8) / error(16);
        assert!(ratio > 300.0 && ratio < 2000.0, "{ratio}");
    }
}
