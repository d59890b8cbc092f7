//! From tracked positions to angles: the pendulum's angle about its pivot,
//! and the pivot itself found as the centre of the circle the bob traces.
//!
//! Video tracking (Tracker and the like) gives the bob's position `(x, y)`
//! in the image's units with `y` up. About a pivot `(X, Y)` the angle from
//! the downward vertical is `θ = atan2(x - X, Y - y)`.
//!
//! The circle is fitted in two stages: Kåsa's algebraic fit (I. Kåsa, IEEE
//! Trans. Instrum. Meas. 25 (1976) 8: the linear least squares of
//! `x² + y² + D x + E y + F`), which is biased towards small radii on a
//! short noisy arc, then the geometric fit that minimises the distances
//! `sqrt((x-a)² + (y-b)²) - R` (Levenberg-Marquardt from the algebraic
//! start; Chernov, *Circular and linear regression*, CRC 2010, ch. 4),
//! which is unbiased to first order in the noise.

use super::{fit_curve, FitError};

/// A fitted circle, in the positions' units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Circle {
    /// Centre, horizontal.
    pub centre_x: f64,
    /// Centre, vertical.
    pub centre_y: f64,
    /// Radius.
    pub radius: f64,
    /// Standard error of the radius.
    pub radius_standard_error: f64,
}

/// The angle from the downward vertical about the pivot `(px, py)` of the
/// position `(x, y)` (`y` up): `atan2(x - px, py - y)`, rad.
pub fn angle_about(x: f64, y: f64, px: f64, py: f64) -> f64 {
    (x - px).atan2(py - y)
}

/// The circle through the positions `(x, y)`, by the geometric least
/// squares from Kåsa's algebraic start. Needs at least 4 points spread
/// along an arc.
pub fn fit_circle(x: &[f64], y: &[f64]) -> Result<Circle, FitError> {
    let n = x.len().min(y.len());
    if n < 4 {
        return Err(FitError::TooFewPoints {
            points: n,
            parameters: 3,
        });
    }
    // Centred coordinates keep the normal equations well conditioned.
    let mx = x.iter().take(n).sum::<f64>() / n as f64;
    let my = y.iter().take(n).sum::<f64>() / n as f64;
    let (mut suu, mut svv, mut suv, mut suuu, mut svvv, mut suvv, mut svuu) =
        (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    for i in 0..n {
        let (u, v) = (x[i] - mx, y[i] - my);
        suu += u * u;
        svv += v * v;
        suv += u * v;
        suuu += u * u * u;
        svvv += v * v * v;
        suvv += u * v * v;
        svuu += v * u * u;
    }
    // Kåsa: solve [suu suv; suv svv] [uc; vc] = ½ [suuu + suvv; svvv + svuu].
    let det = suu * svv - suv * suv;
    if det.abs() <= f64::EPSILON * (suu * svv).abs() || !det.is_finite() {
        return Err(FitError::Singular);
    }
    let (bu, bv) = (0.5 * (suuu + suvv), 0.5 * (svvv + svuu));
    let uc = (bu * svv - bv * suv) / det;
    let vc = (bv * suu - bu * suv) / det;
    let r0 = (uc * uc + vc * vc + (suu + svv) / n as f64).sqrt();
    // Geometric refinement: residual i is the distance of point i from the circle.
    let index: Vec<f64> = (0..n).map(|i| i as f64).collect();
    let zeros = vec![0.0; n];
    let distance = |i: f64, p: &[f64]| {
        let k = i as usize;
        ((x[k] - mx - p[0]).hypot(y[k] - my - p[1])) - p[2]
    };
    let fit = fit_curve(&distance, &index, &zeros, None, &[uc, vc, r0])?;
    let p = &fit.parameters;
    Ok(Circle {
        centre_x: p[0] + mx,
        centre_y: p[1] + my,
        radius: p[2].abs(),
        radius_standard_error: fit.standard_errors[2],
    })
}

/// The frame rates taken for a video's frame numbers, frames a second: a
/// camera films at a frame an hour (time-lapse) to a million a second.
pub const FRAME_RATE_RANGE: std::ops::RangeInclusive<f64> = 1.0 / 3600.0..=1e6;

/// A video's frame rate, checked against [`FRAME_RATE_RANGE`] (the
/// refusal names `frame_rate`).
pub fn frame_rate(fps: f64) -> Result<f64, crate::analysis::Refusal> {
    if FRAME_RATE_RANGE.contains(&fps) {
        Ok(fps)
    } else {
        Err(crate::analysis::Refusal::field(
            "frame_rate",
            format!(
                "must lie between 1/3600 and 10^6 frames a second, got {}",
                crate::error::format_significant(fps, 10)
            ),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angle_is_zero_below_the_pivot_and_positive_to_the_right() {
        assert_eq!(angle_about(0.0, -1.0, 0.0, 0.0), 0.0);
        let a = angle_about(1.0, -1.0, 0.0, 0.0);
        assert!((a - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
        assert!(angle_about(-0.5, 2.0, 0.0, 3.0) < 0.0);
    }

    #[test]
    fn a_short_noisy_arc_gives_the_radius_within_its_error() {
        // ±16° of a 1.47 m pendulum about (0.2, 0.1), 600 points, noise 2 mm
        // (deterministic pseudo-noise); the algebraic fit alone is biased.
        let (cx, cy, r) = (0.2, 0.1, 1.47);
        let mut state = 12345_u64;
        let mut noise = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 2.0 * 0.002 * 3f64.sqrt()
        };
        let (mut x, mut y) = (Vec::new(), Vec::new());
        for i in 0..600 {
            let a = 0.28 * (i as f64 * 0.1).cos();
            x.push(cx + r * a.sin() + noise());
            y.push(cy - r * a.cos() + noise());
        }
        let c = fit_circle(&x, &y).unwrap();
        assert!(
            (c.radius - r).abs() < 3.0 * c.radius_standard_error,
            "{c:?}"
        );
        assert!(c.radius_standard_error < 0.05);
        assert!((c.centre_x - cx).abs() < 0.01 && (c.centre_y - cy).abs() < 0.05);
    }

    #[test]
    fn too_few_or_collinear_points_are_refused() {
        assert!(fit_circle(&[0.0, 1.0], &[0.0, 1.0]).is_err());
        assert!(fit_circle(&[0.0, 1.0, 2.0, 3.0], &[0.0, 0.0, 0.0, 0.0]).is_err());
    }
}
