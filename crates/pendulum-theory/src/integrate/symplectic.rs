//! A structure-preserving step for `θ'' = F(θ) + G(θ')` where the velocity
//! part `G` (damping) has an exact flow: Yoshida's 6th-order composition
//! (H. Yoshida, Phys. Lett. A 150 (1990) 262, solution A) of the symmetric
//! second-order map
//! `S(τ) = D(τ/2) ∘ K(τ/2) ∘ X(τ) ∘ K(τ/2) ∘ D(τ/2)`,
//! with `K` the kick `v += τ F(θ)`, `X` the drift `θ += τ v`, and `D` the
//! exact flow of `v' = G(v)` (for viscous damping `v e^{-cτ}`: a conformal
//! symplectic splitting). Without damping the method is symplectic: the
//! energy error stays bounded (no drift) over any number of periods, which
//! is what a week of swings needs. Adjacent half-damping flows are merged
//! and the two kicks around them share one evaluation of `F`, so a step
//! costs 7 evaluations of `F` (one of them reused from the step before).

use super::State2;

/// Yoshida's weights `w3, w2, w1, w0, w1, w2, w3` (solution A, to the 15
/// digits published); `w0 = 1 - 2(w1 + w2 + w3)`.
pub const WEIGHTS: [f64; 7] = {
    const W1: f64 = -1.177_679_984_178_87;
    const W2: f64 = 0.235_573_213_359_357;
    const W3: f64 = 0.784_513_610_477_560;
    const W0: f64 = 1.0 - 2.0 * (W1 + W2 + W3);
    [W3, W2, W1, W0, W1, W2, W3]
};

/// The lengths of the eight merged damping flows of a step of length `h`:
/// `w3 h/2`, `(w3 + w2) h/2`, …, `(w2 + w3) h/2`, `w3 h/2`.
pub fn damping_intervals(h: f64) -> [f64; 8] {
    let mut out = [0.0; 8];
    for (i, slot) in out.iter_mut().enumerate() {
        let before = if i > 0 { WEIGHTS[i - 1] } else { 0.0 };
        let after = if i < WEIGHTS.len() { WEIGHTS[i] } else { 0.0 };
        *slot = 0.5 * (before + after) * h;
    }
    out
}

/// One step of length `h` from `y` with force `force_at_start = F(y[0])`;
/// returns the new state and `F` at its position (for the next step).
/// `damp(v, i)` is the exact flow of the velocity part over the `i`-th of
/// [`damping_intervals`] (precomputed by the caller, who knows `h`).
#[inline]
pub fn step(
    force: &mut impl FnMut(f64) -> f64,
    damp: &mut impl FnMut(f64, usize) -> f64,
    y: State2,
    force_at_start: f64,
    h: f64,
) -> (State2, f64) {
    let [mut theta, mut v] = y;
    let mut f = force_at_start;
    for (i, &w) in WEIGHTS.iter().enumerate() {
        let tau = w * h;
        v = damp(v, i);
        v += 0.5 * tau * f;
        theta += tau * v;
        f = force(theta);
        v += 0.5 * tau * f;
    }
    v = damp(v, WEIGHTS.len());
    ([theta, v], f)
}

/// The quintic Hermite interpolant of a step from `(θ0, v0, a0)` to
/// `(θ1, v1, a1)` (positions, velocities, accelerations): accurate to
/// `O(h^6)` like the step, for locating turning points between steps.
#[derive(Clone, Copy, Debug)]
pub struct Hermite {
    t0: f64,
    h: f64,
    /// Coefficients of θ in `x = (t - t0)/h`, lowest power first.
    c: [f64; 6],
}

impl Hermite {
    /// Builds the interpolant over `[t0, t0 + h]`.
    pub fn new(t0: f64, h: f64, start: [f64; 3], end: [f64; 3]) -> Self {
        let (p0, d0, s0) = (start[0], h * start[1], h * h * start[2]);
        let (p1, d1, s1) = (end[0], h * end[1], h * h * end[2]);
        let c3 = 10.0 * (p1 - p0) - 6.0 * d0 - 4.0 * d1 - 1.5 * s0 + 0.5 * s1;
        let c4 = -15.0 * (p1 - p0) + 8.0 * d0 + 7.0 * d1 + 1.5 * s0 - s1;
        let c5 = 6.0 * (p1 - p0) - 3.0 * (d0 + d1) - 0.5 * s0 + 0.5 * s1;
        Self {
            t0,
            h,
            c: [p0, d0, 0.5 * s0, c3, c4, c5],
        }
    }

    /// θ at `t`.
    pub fn angle(&self, t: f64) -> f64 {
        let x = (t - self.t0) / self.h;
        self.c.iter().rev().fold(0.0, |acc, &c| acc * x + c)
    }

    /// θ' at `t`.
    pub fn velocity(&self, t: f64) -> f64 {
        let x = (t - self.t0) / self.h;
        let c = &self.c;
        let dx = c[1] + x * (2.0 * c[2] + x * (3.0 * c[3] + x * (4.0 * c[4] + x * 5.0 * c[5])));
        dx / self.h
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_sum_to_one() {
        let sum: f64 = WEIGHTS.iter().sum();
        assert!((sum - 1.0).abs() < 1e-15);
        let total: f64 = damping_intervals(0.3).iter().sum();
        assert!((total - 0.3).abs() < 1e-15);
    }

    /// With viscous damping applied exactly, the damped oscillator
    /// x'' + 2ζx' + x = 0 is followed to 6th order too.
    #[test]
    fn damped_oscillator() {
        let zeta = 0.05_f64;
        let wd = (1.0 - zeta * zeta).sqrt();
        let exact = |t: f64| (-zeta * t).exp() * ((wd * t).cos() + zeta / wd * (wd * t).sin());
        let error = |n: u32| {
            let t_end = 10.0;
            let h = t_end / f64::from(n);
            let decay = damping_intervals(h).map(|tau| (-2.0 * zeta * tau).exp());
            let mut force = |theta: f64| -theta;
            let mut damp = |v: f64, i: usize| v * decay[i];
            let (mut y, mut f) = ([1.0, 0.0], -1.0);
            for _ in 0..n {
                (y, f) = step(&mut force, &mut damp, y, f, h);
            }
            (y[0] - exact(t_end)).abs()
        };
        let ratio = error(50) / error(100);
        assert!(ratio > 40.0 && ratio < 90.0, "{ratio}");
    }

    /// The harmonic oscillator: global error O(h^6).
    #[test]
    fn sixth_order_on_the_oscillator() {
        let mut force = |theta: f64| -theta;
        let mut damp = |v: f64, _i: usize| v;
        let mut error = |n: u32| {
            let t_end = 10.0;
            let h = t_end / f64::from(n);
            let (mut y, mut f) = ([1.0, 0.0], -1.0);
            for _ in 0..n {
                (y, f) = step(&mut force, &mut damp, y, f, h);
            }
            (y[0] - t_end.cos()).abs()
        };
        let ratio = error(50) / error(100);
        assert!(ratio > 50.0 && ratio < 80.0, "{ratio}");
    }

    #[test]
    fn hermite_reproduces_a_quintic() {
        let p = |t: f64| 1.0 + t * (0.5 + t * (-0.25 + t * (0.1 + t * (0.3 - t * 0.2))));
        let d = |t: f64| 0.5 + t * (-0.5 + t * (0.3 + t * (1.2 - t * 1.0)));
        let s = |t: f64| -0.5 + t * (0.6 + t * (3.6 - t * 4.0));
        let (t0, h) = (0.3, 0.7);
        let hermite = Hermite::new(
            t0,
            h,
            [p(t0), d(t0), s(t0)],
            [p(t0 + h), d(t0 + h), s(t0 + h)],
        );
        for i in 0..=10 {
            let t = t0 + h * f64::from(i) / 10.0;
            assert!((hermite.angle(t) - p(t)).abs() < 1e-14);
            assert!((hermite.velocity(t) - d(t)).abs() < 1e-13);
        }
    }
}
