//! Tracker project files (`.trk`): the XML in which Tracker
//! (physlets.org/tracker) saves a video analysis. The first point-mass
//! track's positions are read, turned from image pixels into the
//! project's world units by its coordinate system (origin, axes' angle
//! and scale, per frame), against the clip's time, and handed to the
//! table reader as the CSV text `t (s),x,y` a data export would hold.

use quick_xml::events::Event;
use quick_xml::Reader;
use std::collections::BTreeMap;

/// A project's track, as table text.
#[derive(Debug)]
pub struct Project {
    /// The track's name (`mass A`).
    pub track: String,
    /// `t (s),x,y` rows, one per marked frame.
    pub csv: String,
}

/// The Tracker project's entry in [`crate::formats::FORMATS`].
pub const FORMAT: crate::formats::FileFormat = crate::formats::FileFormat {
    name: "Tracker project",
    extensions: &["trk"],
    recognise: None,
    read: |bytes| {
        let text = String::from_utf8(bytes)
            .map_err(|_| "cannot read it: stream did not contain valid UTF-8".to_string())?;
        let project = read(&text)?;
        Ok(crate::formats::Converted {
            text: project.csv,
            track: Some(project.track),
            ..Default::default()
        })
    },
};

/// One entry of the stack of open elements.
enum Open {
    /// An `<object class=…>`.
    Object(String),
    /// A `<property name=…>`.
    Property(String),
}

/// The image-to-world transform of a frame.
#[derive(Clone, Copy, Default)]
struct Coords {
    xo: f64,
    yo: f64,
    angle: f64,
    xscale: f64,
    yscale: f64,
}

impl Coords {
    /// World coordinates (y up) of an image point (y down): the inverse of
    /// Tracker's translate · rotate(-angle) · scale(xscale, -yscale).
    fn world(&self, x: f64, y: f64) -> (f64, f64) {
        let (dx, dy) = (x - self.xo, y - self.yo);
        let (s, c) = self.angle.sin_cos();
        (
            (c * dx - s * dy) / self.xscale,
            -(s * dx + c * dy) / self.yscale,
        )
    }
}

/// Reads a Tracker project: the first point mass's track.
pub fn read(text: &str) -> Result<Project, String> {
    let mut reader = Reader::from_str(text);
    let mut stack: Vec<Open> = Vec::new();
    let mut clip: BTreeMap<String, f64> = BTreeMap::new();
    let mut coords: BTreeMap<usize, BTreeMap<String, f64>> = BTreeMap::new();
    let mut points: BTreeMap<usize, (Option<f64>, Option<f64>)> = BTreeMap::new();
    let (mut point_masses, mut name) = (0, None::<String>);
    let attr = |e: &quick_xml::events::BytesStart<'_>, key: &[u8]| {
        e.attributes()
            .flatten()
            .find(|a| a.key.as_ref() == key)
            .map(|a| String::from_utf8_lossy(&a.value).into_owned())
            .unwrap_or_default()
    };
    loop {
        match reader.read_event() {
            Err(e) => {
                return Err(format!(
                    "is not readable XML at byte {}: {e}",
                    reader.buffer_position()
                ))
            }
            Ok(Event::Eof) => break,
            Ok(Event::Start(e)) => match e.name().as_ref() {
                b"object" => {
                    let class = attr(&e, b"class");
                    if class.ends_with("tracker.PointMass") {
                        point_masses += 1;
                    }
                    stack.push(Open::Object(class));
                }
                b"property" => stack.push(Open::Property(attr(&e, b"name"))),
                _ => {}
            },
            Ok(Event::End(e)) => {
                if matches!(e.name().as_ref(), b"object" | b"property") {
                    stack.pop();
                }
            }
            Ok(Event::Text(t)) => {
                let Some(Open::Property(property)) = stack.last() else {
                    continue;
                };
                let value = String::from_utf8_lossy(t.as_ref()).trim().to_string();
                // The object the property belongs to, and the frame
                // (`[k]`) that object is the data of.
                let mut objects = stack.iter().rev().filter_map(|o| match o {
                    Open::Object(c) => Some(c.as_str()),
                    Open::Property(_) => None,
                });
                let class = objects.next().unwrap_or("");
                let frame = stack.iter().rev().skip(1).find_map(|o| match o {
                    Open::Property(p) => p
                        .strip_prefix('[')
                        .and_then(|p| p.strip_suffix(']'))
                        .and_then(|k| k.parse::<usize>().ok()),
                    Open::Object(_) => None,
                });
                let number = value.parse::<f64>().ok();
                let in_first_mass = point_masses == 1
                    && stack
                        .iter()
                        .any(|o| matches!(o, Open::Object(c) if c.ends_with("tracker.PointMass")));
                if class.ends_with("media.core.VideoClip") || class.contains("ClipControl") {
                    if let Some(v) = number {
                        clip.insert(property.clone(), v);
                    }
                } else if class.ends_with("ImageCoordSystem$FrameData") {
                    if let (Some(k), Some(v)) = (frame, number) {
                        coords.entry(k).or_default().insert(property.clone(), v);
                    }
                } else if class.ends_with("tracker.PointMass") && in_first_mass {
                    if property == "name" {
                        name = Some(value);
                    }
                } else if class.ends_with("PointMass$FrameData") && in_first_mass {
                    if let (Some(k), Some(v)) = (frame, number) {
                        let p = points.entry(k).or_default();
                        match property.as_str() {
                            "x" => p.0 = Some(v),
                            "y" => p.1 = Some(v),
                            _ => {}
                        }
                    }
                }
            }
            Ok(_) => {}
        }
    }
    if point_masses == 0 {
        return Err(
            "is a Tracker project with no point-mass track: mark the bob in Tracker and save"
                .to_string(),
        );
    }
    let Some(&dt) = clip.get("delta_t").filter(|v| **v > 0.0) else {
        return Err(
            "is a Tracker project without the clip's frame interval (delta_t): export the \
             track's data table from Tracker and give that file"
                .to_string(),
        );
    };
    let start_frame = clip.get("startframe").copied().unwrap_or(0.0);
    let start_time = clip.get("starttime").copied().unwrap_or(0.0);
    // Each frame's transform: the latest set at or before it (the first
    // for frames before any).
    let transform = |k: usize| -> Coords {
        let entry = coords
            .range(..=k)
            .next_back()
            .or_else(|| coords.iter().next())
            .map(|(_, m)| m);
        let get =
            |key: &str, default: f64| entry.and_then(|m| m.get(key)).copied().unwrap_or(default);
        Coords {
            xo: get("xorigin", 0.0),
            yo: get("yorigin", 0.0),
            angle: get("angle", 0.0),
            xscale: get("xscale", 1.0),
            yscale: get("yscale", 1.0),
        }
    };
    let mut csv = String::from("t (s),x,y\n");
    let mut rows = 0;
    for (&k, &(x, y)) in &points {
        let (Some(x), Some(y)) = (x, y) else { continue };
        let c = transform(k);
        if !(c.xscale.is_finite() && c.xscale != 0.0 && c.yscale.is_finite() && c.yscale != 0.0) {
            return Err(format!(
                "is a Tracker project whose scale at frame {k} is zero"
            ));
        }
        let (wx, wy) = c.world(x, y);
        let t = (start_time + (k as f64 - start_frame) * dt) / 1000.0;
        csv.push_str(&format!("{t:?},{wx:?},{wy:?}\n"));
        rows += 1;
    }
    if rows == 0 {
        return Err("is a Tracker project whose point mass has no marked frames".to_string());
    }
    Ok(Project {
        track: name.unwrap_or_else(|| "mass A".to_string()),
        csv,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A project as Tracker 5 writes it (the layout of a public one,
    /// JLefebvre55/PHY180-Pendulum): a clip at 60 frames a second every
    /// 5th frame, axes at (868, 32.5) px at 0°, 598.75 px a metre, and a
    /// point mass marked on three frames.
    fn project(angle: f64) -> String {
        let frame = |k: usize, x: f64, y: f64| {
            format!(
                "<property name=\"[{k}]\" type=\"object\">\n<object class=\"org.opensourcephysics.cabrillo.tracker.PointMass$FrameData\">\n<property name=\"x\" type=\"double\">{x}</property>\n<property name=\"y\" type=\"double\">{y}</property>\n</object>\n</property>\n"
            )
        };
        format!(
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<object class=\"org.opensourcephysics.cabrillo.tracker.TrackerPanel\">\n<property name=\"videoclip\" type=\"object\">\n<object class=\"org.opensourcephysics.media.core.VideoClip\">\n<property name=\"startframe\" type=\"int\">0</property>\n<property name=\"stepsize\" type=\"int\">5</property>\n<property name=\"starttime\" type=\"double\">0.0</property>\n</object>\n</property>\n<property name=\"clipcontrol\" type=\"object\">\n<object class=\"org.opensourcephysics.media.core.StepperClipControl\">\n<property name=\"delta_t\" type=\"double\">16.66808510638298</property>\n</object>\n</property>\n<property name=\"coords\" type=\"object\">\n<object class=\"org.opensourcephysics.media.core.ImageCoordSystem\">\n<property name=\"framedata\" type=\"array\">\n<property name=\"[0]\" type=\"object\">\n<object class=\"org.opensourcephysics.media.core.ImageCoordSystem$FrameData\">\n<property name=\"xorigin\" type=\"double\">868.0</property>\n<property name=\"yorigin\" type=\"double\">32.5</property>\n<property name=\"angle\" type=\"double\">{angle}</property>\n<property name=\"xscale\" type=\"double\">598.753280839895</property>\n<property name=\"yscale\" type=\"double\">598.753280839895</property>\n</object>\n</property>\n</property>\n</object>\n</property>\n<property name=\"tracks\" type=\"collection\">\n<property name=\"item\" type=\"object\">\n<object class=\"org.opensourcephysics.cabrillo.tracker.PointMass\">\n<property name=\"name\" type=\"string\">mass A</property>\n<property name=\"framedata\" type=\"array\">\n{}{}{}</property>\n</object>\n</property>\n</property>\n</object>\n",
            frame(435, 1146.5, 460.5),
            frame(440, 868.0, 631.2532808),
            frame(445, 868.0 - 598.753280839895 * 0.1, 32.5 + 598.753280839895 * 0.5)
        )
    }

    #[test]
    fn a_projects_track_in_world_units_against_the_clips_time() {
        let p = read(&project(0.0)).unwrap();
        assert_eq!(p.track, "mass A");
        let rows: Vec<Vec<f64>> = p
            .csv
            .lines()
            .skip(1)
            .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
            .collect();
        assert_eq!(rows.len(), 3);
        // Frame 440 at 16.668 ms a frame; 1 m straight below the origin.
        assert!((rows[1][0] - 440.0 * 0.016_668_085_106_382_98).abs() < 1e-12);
        assert!(
            rows[1][1].abs() < 1e-9 && (rows[1][2] + 1.0).abs() < 1e-9,
            "{:?}",
            rows[1]
        );
        assert!((rows[2][1] + 0.1).abs() < 1e-9 && (rows[2][2] + 0.5).abs() < 1e-9);
    }

    #[test]
    fn rotated_axes_turn_every_point_alike() {
        // Axes turned by 0.1 rad: each point's angle about the origin
        // changes by the same 0.1 rad, its distance not at all.
        let a = read(&project(0.0)).unwrap().csv;
        let b = read(&project(0.1)).unwrap().csv;
        let polar = |csv: &str| -> Vec<(f64, f64)> {
            csv.lines()
                .skip(1)
                .map(|l| {
                    let v: Vec<f64> = l.split(',').map(|v| v.parse().unwrap()).collect();
                    (v[1].hypot(v[2]), v[2].atan2(v[1]))
                })
                .collect()
        };
        for ((ra, ta), (rb, tb)) in polar(&a).into_iter().zip(polar(&b)) {
            assert!((ra - rb).abs() < 1e-12);
            let d = (tb - ta).rem_euclid(std::f64::consts::TAU);
            assert!(
                (d - 0.1).abs() < 1e-12 || (d - (std::f64::consts::TAU - 0.1)).abs() < 1e-12,
                "{d}"
            );
        }
    }

    #[test]
    fn projects_without_a_track_or_a_clip_are_named() {
        assert!(read("<object class=\"x.TrackerPanel\"></object>")
            .unwrap_err()
            .contains("no point-mass track"));
        let no_clip = project(0.0).replace("delta_t", "other");
        assert!(read(&no_clip).unwrap_err().contains("delta_t"));
        let broken = "<object class=\"a.tracker.PointMass\"><property name=\"x\">1</object>";
        assert!(read(broken).is_err());
    }
}
