//! Seeded standard normal deviates for the unit tests: xorshift64
//! (Marsaglia 2003, shifts 13, 7, 17) and the Box–Muller transform, so a
//! test's draw does not depend on another crate's stream.

/// A seeded stream of uniform and standard normal deviates (seed not zero).
pub(crate) struct Normals(pub(crate) u64);

impl Normals {
    /// The next uniform deviate in (0, 1).
    pub(crate) fn uniform(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        ((self.0 >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }

    /// The next standard normal deviate (two uniforms, Box–Muller's cosine).
    pub(crate) fn next(&mut self) -> f64 {
        let (a, b) = (self.uniform(), self.uniform());
        (-2.0 * a.ln()).sqrt() * (std::f64::consts::TAU * b).cos()
    }
}

/// `n` standard normal deviates from `seed` (not zero).
pub(crate) fn normals(n: usize, seed: u64) -> Vec<f64> {
    let mut stream = Normals(seed);
    (0..n).map(|_| stream.next()).collect()
}
