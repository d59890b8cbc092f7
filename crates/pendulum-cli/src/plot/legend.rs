//! Where the legend goes: inside the plot where it covers nothing, else in
//! room made above the data, else beside the plot. Worked out in device
//! pixels from the positions of what is drawn, before anything is drawn.

/// A rectangle in device pixels (y grows downwards).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rect {
    /// Left.
    pub x0: f64,
    /// Top.
    pub y0: f64,
    /// Right.
    pub x1: f64,
    /// Bottom.
    pub y1: f64,
}

impl Rect {
    /// Its height.
    pub fn height(&self) -> f64 {
        self.y1 - self.y0
    }

    /// Whether the disc at `(x, y)` of radius `r` touches it.
    pub fn touches(&self, x: f64, y: f64, r: f64) -> bool {
        x + r >= self.x0 && x - r <= self.x1 && y + r >= self.y0 && y - r <= self.y1
    }
}

/// The spots tried inside the plot, in order of preference.
const SPOTS: [(f64, f64); 6] = [
    (1.0, 0.0), // upper right
    (0.0, 0.0), // upper left
    (1.0, 1.0), // lower right
    (0.0, 1.0), // lower left
    (0.5, 0.0), // top centre
    (0.5, 1.0), // bottom centre
];

/// The box of size `size` at `spot` (fractions of the free width and
/// height) inside `plot`, `inset` pixels from its edges.
pub fn box_at(plot: Rect, size: (f64, f64), inset: f64, spot: (f64, f64)) -> Rect {
    let x0 = plot.x0 + inset + spot.0 * (plot.x1 - plot.x0 - 2.0 * inset - size.0);
    let y0 = plot.y0 + inset + spot.1 * (plot.y1 - plot.y0 - 2.0 * inset - size.1);
    Rect {
        x0,
        y0,
        x1: x0 + size.0,
        y1: y0 + size.1,
    }
}

/// What is drawn: data markers `(x, y, radius)` and points along every
/// line, a few pixels apart, in device pixels.
#[derive(Debug, Default)]
pub struct Drawn {
    /// Data markers.
    pub markers: Vec<(f64, f64, f64)>,
    /// Points along the lines.
    pub lines: Vec<(f64, f64)>,
}

impl Drawn {
    /// Whether `area` (with `gap` pixels around it) covers anything.
    pub fn covered_by(&self, area: Rect, gap: f64) -> bool {
        self.markers
            .iter()
            .any(|&(x, y, r)| area.touches(x, y, r + gap))
            || self.lines.iter().any(|&(x, y)| area.touches(x, y, gap))
    }

    /// Adds the points along the segment `a`–`b`, at most `step` apart.
    pub fn trace(&mut self, a: (f64, f64), b: (f64, f64), step: f64) {
        let length = (b.0 - a.0).hypot(b.1 - a.1);
        let n = (length / step).ceil().clamp(1.0, 10_000.0) as usize;
        for i in 0..=n {
            let t = i as f64 / n as f64;
            self.lines
                .push((a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)));
        }
    }
}

/// Where the legend goes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Place {
    /// Inside the plot at a spot (fractions of the free width and height).
    Inside((f64, f64)),
    /// In a band made for it at the top of the plot (the data range grown
    /// upwards), at the upper right.
    Above,
    /// Beside the plot, to its right.
    Beside,
}

/// The legend's place: the first spot inside `plot` where a box of `size`
/// covers nothing drawn; else a band on top when it takes at most a
/// third of the plot's height; else beside.
pub fn place(plot: Rect, size: (f64, f64), inset: f64, gap: f64, drawn: &Drawn) -> Place {
    let fits = size.0 + 2.0 * inset <= plot.x1 - plot.x0 && size.1 + 2.0 * inset <= plot.height();
    if fits {
        for spot in SPOTS {
            if !drawn.covered_by(box_at(plot, size, inset, spot), gap) {
                return Place::Inside(spot);
            }
        }
    }
    if size.1 + 2.0 * inset <= plot.height() / 3.0 {
        Place::Above
    } else {
        Place::Beside
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const PLOT: Rect = Rect {
        x0: 0.0,
        y0: 0.0,
        x1: 800.0,
        y1: 400.0,
    };

    #[test]
    fn the_legend_moves_away_from_the_data() {
        let mut drawn = Drawn::default();
        // A marker in the upper right corner.
        drawn.markers.push((790.0, 10.0, 3.0));
        assert_eq!(
            place(PLOT, (150.0, 60.0), 8.0, 4.0, &drawn),
            Place::Inside((0.0, 0.0))
        );
        // A line across the top half: the lower right is free.
        drawn.trace((0.0, 100.0), (800.0, 100.0), 3.0);
        drawn.trace((0.0, 20.0), (800.0, 20.0), 3.0);
        assert_eq!(
            place(PLOT, (150.0, 60.0), 8.0, 4.0, &drawn),
            Place::Inside((1.0, 1.0))
        );
    }

    #[test]
    fn a_full_plot_makes_room_above_or_beside() {
        let mut drawn = Drawn::default();
        for i in 0..40 {
            let y = 10.0 * f64::from(i);
            drawn.trace((0.0, y), (800.0, y), 3.0);
        }
        assert_eq!(place(PLOT, (150.0, 60.0), 8.0, 4.0, &drawn), Place::Above);
        assert_eq!(place(PLOT, (150.0, 200.0), 8.0, 4.0, &drawn), Place::Beside);
    }
}
