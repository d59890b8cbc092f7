//! A gyroscope that swings with a pendulum (a phone's, read with phyphox)
//! measures the swing's angular velocity about its pivot axis, whatever
//! the phone's place on the pendulum: a rigid body turns at one rate. The
//! phone's axes are seldom the pivot's, so the rate is shared among them;
//! the swing's own axis is the one that carries most of the rotation.

/// The rotation about a gyroscope's principal axis.
#[derive(Clone, Debug, PartialEq)]
pub struct PrincipalAxis {
    /// The axis, a unit vector in the sensor's axes (its largest
    /// component positive).
    pub direction: Vec<f64>,
    /// The share of the rates' variance (about their means) that turns
    /// about it, 0 to 1: 1 for a pendulum swinging in one plane with the
    /// phone fixed to it.
    pub share: f64,
    /// The angular velocity about it at each sample, rad/s.
    pub rate: Vec<f64>,
}

/// The principal axis of the rotation rates `axes` (one slice per sensor
/// axis, of equal lengths): the eigenvector of the rates' covariance
/// matrix with the largest eigenvalue (principal component analysis; the
/// symmetric eigenproblem solved by nalgebra's Jacobi-free QR iteration to
/// machine precision), and the rates projected on it. One axis is itself.
/// `None` for no axes, axes of unequal lengths, or rates that never change.
pub fn principal_axis(axes: &[&[f64]]) -> Option<PrincipalAxis> {
    let k = axes.len();
    let n = axes.first()?.len();
    if axes.iter().any(|a| a.len() != n) || n == 0 {
        return None;
    }
    if k == 1 {
        return Some(PrincipalAxis {
            direction: vec![1.0],
            share: 1.0,
            rate: axes[0].to_vec(),
        });
    }
    let means: Vec<f64> = axes
        .iter()
        .map(|a| a.iter().sum::<f64>() / n as f64)
        .collect();
    let mut cov = nalgebra::DMatrix::<f64>::zeros(k, k);
    for i in 0..k {
        for j in i..k {
            let c = axes[i]
                .iter()
                .zip(axes[j])
                .map(|(a, b)| (a - means[i]) * (b - means[j]))
                .sum::<f64>()
                / n as f64;
            cov[(i, j)] = c;
            cov[(j, i)] = c;
        }
    }
    let total = cov.trace();
    if total.is_nan() || total <= 0.0 {
        return None;
    }
    let eigen = nalgebra::SymmetricEigen::new(cov);
    let (best, value) = eigen
        .eigenvalues
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(b.1))?;
    let mut direction: Vec<f64> = eigen.eigenvectors.column(best).iter().copied().collect();
    let largest = direction
        .iter()
        .copied()
        .max_by(|a, b| a.abs().total_cmp(&b.abs()))
        .unwrap_or(1.0);
    if largest < 0.0 {
        direction.iter_mut().for_each(|d| *d = -*d);
    }
    let rate = (0..n)
        .map(|s| axes.iter().zip(&direction).map(|(a, d)| a[s] * d).sum())
        .collect();
    Some(PrincipalAxis {
        direction,
        share: (value / total).clamp(0.0, 1.0),
        rate,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A swing about a tilted axis, with a little rotation about the
    /// others, is found whole: the axis to 1e-3 and its share.
    #[test]
    fn the_swing_axis_is_found_in_the_sensor_axes() {
        let n = 2000;
        let axis = [0.6, -0.48, 0.64]; // a unit vector
        let other = [0.8, 0.36, -0.48]; // orthogonal to it, unit
        let rate: Vec<f64> = (0..n).map(|i| 2.0 * (i as f64 * 0.05).sin()).collect();
        let wobble: Vec<f64> = (0..n).map(|i| 0.2 * (i as f64 * 0.31).cos()).collect();
        let cols: Vec<Vec<f64>> = (0..3)
            .map(|c| {
                (0..n)
                    .map(|i| rate[i] * axis[c] + wobble[i] * other[c] + 0.1)
                    .collect()
            })
            .collect();
        let refs: Vec<&[f64]> = cols.iter().map(Vec::as_slice).collect();
        let p = principal_axis(&refs).unwrap();
        for (got, want) in p.direction.iter().zip(axis) {
            assert!((got - want).abs() < 1e-3, "{:?}", p.direction);
        }
        // Variances: 2²/2 and 0.2²/2 (whole periods nearly).
        let expected = 2.0 / (2.0 + 0.02);
        assert!((p.share - expected).abs() < 2e-3, "{}", p.share);
        let back = p.rate[100] - 0.1 * axis.iter().sum::<f64>();
        assert!((back - rate[100]).abs() < 0.01, "{back} {}", rate[100]);
    }

    #[test]
    fn no_axes_or_no_rotation_has_no_axis() {
        assert!(principal_axis(&[]).is_none());
        assert!(principal_axis(&[&[1.0, 1.0], &[2.0, 2.0]]).is_none());
        assert!(principal_axis(&[&[1.0, 2.0], &[2.0]]).is_none());
    }
}
