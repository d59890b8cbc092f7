//! The one look every figure shares: colours, marker and line sizes, fonts,
//! margins, all in CSS pixels and scaled by the picture's pixel density
//! (1 for SVG, 2 for PNG, so a PNG's lines and letters are as smooth as a
//! print's).

use plotters::style::RGBColor;

/// Colours for successive series: the colour-blind-safe palette of Okabe
/// & Ito (2008, "Color universal design"), yellow late (faint on white)
/// and black last, as a dark grey.
pub const PALETTE: [RGBColor; 8] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(86, 180, 233),
    RGBColor(230, 159, 0),
    RGBColor(240, 228, 66),
    // Okabe & Ito's black, lightened to tell it from the axes: an eighth
    // series (a fit of seven laws with its data) wraps no colour.
    RGBColor(90, 90, 90),
];

/// The colour of marks that are not data (a working point's line).
pub const MARK: RGBColor = RGBColor(80, 80, 80);

/// The legend box's border (also how the tests find the box in an SVG).
pub const LEGEND_BORDER: RGBColor = RGBColor(150, 150, 150);

/// The grid's colour.
pub const GRID: RGBColor = RGBColor(235, 235, 235);

/// Sizes in device pixels at a pixel density.
#[derive(Clone, Copy, Debug)]
pub struct Look {
    /// Device pixels per CSS pixel.
    pub density: u32,
}

impl Look {
    /// `n` CSS pixels in device pixels.
    pub fn px(self, n: u32) -> u32 {
        n * self.density
    }

    /// Title font size.
    pub fn title_font(self) -> u32 {
        self.px(20)
    }

    /// Tick label and legend font size.
    pub fn label_font(self) -> u32 {
        self.px(14)
    }

    /// Axis title font size.
    pub fn axis_font(self) -> u32 {
        self.px(16)
    }

    /// A line's width at a weight.
    pub fn weighted_width(self, weight: super::Weight) -> u32 {
        match weight {
            super::Weight::Normal => self.px(2),
            super::Weight::Strong => self.px(4),
            super::Weight::Light => self.px(1),
        }
    }

    /// A data marker's radius: smaller when there are many.
    pub fn marker_radius(self, count: usize) -> u32 {
        if count > 400 {
            self.px(2)
        } else {
            self.px(3)
        }
    }

    /// Margin around a panel.
    pub fn margin(self) -> u32 {
        self.px(12)
    }

    /// Height of the area under the plot for tick labels and axis title.
    pub fn x_label_area(self) -> u32 {
        self.px(44)
    }

    /// Width of the area left of the plot for tick labels and axis title.
    pub fn y_label_area(self) -> u32 {
        self.px(80)
    }
}
