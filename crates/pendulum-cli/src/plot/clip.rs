//! Clipping to the frame: a curve that leaves the axes is cut where it
//! crosses the frame and picks up where it comes back, so nothing is drawn
//! outside the axes.

use super::axis::Span;

/// A point in axis units.
pub type Point = (f64, f64);

/// The part of the segment `a`–`b` inside the rectangle `x` × `y`, by the
/// Liang–Barsky parametric test (Liang & Barsky 1984, "A new concept and
/// method for line clipping"); `None` when it misses.
pub fn segment(a: Point, b: Point, x: Span, y: Span) -> Option<(Point, Point)> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    for (p, q) in [
        (-dx, a.0 - x.lo),
        (dx, x.hi - a.0),
        (-dy, a.1 - y.lo),
        (dy, y.hi - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    (t0 <= t1).then_some((
        (a.0 + t0 * dx, a.1 + t0 * dy),
        (a.0 + t1 * dx, a.1 + t1 * dy),
    ))
}

/// The polyline `points` (axis units; `None` breaks it) cut to the
/// rectangle: the pieces that lie inside, each drawn as one line.
pub fn polyline(points: &[Option<Point>], x: Span, y: Span) -> Vec<Vec<Point>> {
    let mut pieces: Vec<Vec<Point>> = Vec::new();
    let mut current: Vec<Point> = Vec::new();
    let mut finish = |current: &mut Vec<Point>| {
        if current.len() > 1 {
            pieces.push(std::mem::take(current));
        } else {
            current.clear();
        }
    };
    // A lone valid point between breaks is a piece of one point: drawn
    // as nothing (a line needs two).
    for pair in points.windows(2) {
        match (pair[0], pair[1]) {
            (Some(a), Some(b)) => match segment(a, b, x, y) {
                Some((p, q)) => {
                    if current.last() != Some(&p) {
                        finish(&mut current);
                        current.push(p);
                    }
                    current.push(q);
                }
                None => finish(&mut current),
            },
            _ => finish(&mut current),
        }
    }
    finish(&mut current);
    pieces
}

#[cfg(test)]
mod tests {
    use super::*;

    const UNIT: Span = Span { lo: 0.0, hi: 1.0 };

    #[test]
    fn a_spike_is_cut_at_the_frame_and_the_line_goes_on() {
        let line = [
            Some((0.0, 0.5)),
            Some((0.4, 0.5)),
            Some((0.5, 100.0)),
            Some((0.6, 0.5)),
            Some((1.0, 0.5)),
        ];
        let pieces = polyline(&line, UNIT, UNIT);
        assert_eq!(pieces.len(), 2, "{pieces:?}");
        for p in pieces.iter().flatten() {
            assert!(UNIT.contains(p.0) && UNIT.contains(p.1), "{p:?}");
        }
        // The cut lies on the frame's top.
        assert!((pieces[0].last().unwrap().1 - 1.0).abs() < 1e-12);
        assert!((pieces[1][0].1 - 1.0).abs() < 1e-12);
    }

    #[test]
    fn a_segment_outside_is_dropped_and_one_inside_kept_whole() {
        assert_eq!(segment((2.0, 2.0), (3.0, 3.0), UNIT, UNIT), None);
        assert_eq!(
            segment((0.1, 0.2), (0.3, 0.4), UNIT, UNIT),
            Some(((0.1, 0.2), (0.3, 0.4)))
        );
        let broken = [Some((0.1, 0.1)), None, Some((0.2, 0.2)), Some((0.3, 0.3))];
        assert_eq!(polyline(&broken, UNIT, UNIT).len(), 1);
    }
}
