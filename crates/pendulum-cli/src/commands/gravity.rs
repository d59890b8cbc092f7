//! `pendulum gravity`: WGS 84 normal gravity at a latitude and height.

use super::common;
use crate::args::GravityCommandArgs;
use crate::error::CliError;
use crate::output::{self, num, Summary};
use serde::Serialize;

#[derive(Serialize)]
struct GravityJson {
    g_m_s2: f64,
    latitude_deg: f64,
    height_m: f64,
    model: &'static str,
}

pub fn run(args: &GravityCommandArgs) -> Result<String, CliError> {
    let latitude_deg = args.latitude.0.to_degrees();
    let height_m = args
        .height
        .map_or(pendulum_theory::gravity::DEFAULT_HEIGHT_M, |h| h.0);
    let g = common::resolve(None, Some(latitude_deg), Some(height_m))?.g_m_s2;
    let result = GravityJson {
        g_m_s2: g,
        latitude_deg,
        height_m,
        model: "WGS 84 normal gravity (Somigliana) with free-air correction",
    };
    if args.json {
        return output::json(&result);
    }
    let mut s = Summary::default();
    s.row("g", format!("{} m/s²", num(g, 10)))
        .row("Latitude", format!("{}°", num(latitude_deg, 10)))
        .row("Height", format!("{} m", num(height_m, 10)))
        .row("Model", result.model)
        .row(
            "Note",
            "local anomalies reach a few 1e-4 m/s²; measure g for better than 30 ppm",
        );
    Ok(s.render())
}
