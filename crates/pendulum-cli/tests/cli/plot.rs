//! Every plot kind, drawn to SVG and PNG and checked as a file a viewer can
//! open; the report, looked at by a real browser.

use crate::util::{decode_png, pendulum, refuses};
use std::path::{Path, PathBuf};

/// Decodes a PNG: its size and how many pixels differ from the first.
fn png_summary(bytes: Vec<u8>) -> (u32, u32, usize) {
    let (width, height, rgb) = decode_png(bytes);
    let first = rgb[..3].to_vec();
    let distinct = rgb.chunks(3).filter(|p| *p != first.as_slice()).count();
    (width, height, distinct)
}

/// A rectangle in SVG pixels.
#[derive(Clone, Copy, Debug)]
struct Rect {
    x0: f64,
    y0: f64,
    x1: f64,
    y1: f64,
}

impl Rect {
    fn contains(&self, x: f64, y: f64, slack: f64) -> bool {
        x >= self.x0 - slack && x <= self.x1 + slack && y >= self.y0 - slack && y <= self.y1 + slack
    }
}

/// What an SVG figure draws, read back from its elements: the plot frames
/// (from the grid lines: vertical ones span a frame's height, horizontal
/// ones its width), the legend boxes (the grey-bordered rectangles), the
/// data markers (circles) and the points of the series' lines (polylines
/// in the palette's colours).
struct Drawing {
    frames: Vec<Rect>,
    legends: Vec<Rect>,
    markers: Vec<(f64, f64, f64)>,
    line_points: Vec<(f64, f64)>,
}

const SERIES_COLOURS: [&str; 7] = [
    "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#56B4E9", "#E69F00", "#F0E442",
];

fn drawing(doc: &roxmltree::Document) -> Drawing {
    let num = |n: &roxmltree::Node, a: &str| -> f64 {
        n.attribute(a)
            .unwrap_or_else(|| panic!("{a} missing"))
            .parse()
            .unwrap()
    };
    let grid: Vec<(f64, f64, f64, f64)> = doc
        .descendants()
        .filter(|n| n.has_tag_name("line") && n.attribute("stroke") == Some("#EBEBEB"))
        .map(|n| (num(&n, "x1"), num(&n, "y1"), num(&n, "x2"), num(&n, "y2")))
        .collect();
    let mut frames: Vec<Rect> = Vec::new();
    for &(x1, y1, x2, y2) in grid.iter().filter(|g| g.0 == g.2) {
        let _ = (x1, x2);
        let (top, bottom) = (y1.min(y2), y1.max(y2));
        if frames.iter().any(|f| f.y0 == top && f.y1 == bottom) {
            continue;
        }
        // The horizontal grid lines inside this height give the width.
        let (left, right) = grid
            .iter()
            .filter(|h| h.1 == h.3 && h.1 >= top && h.1 <= bottom)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, r), h| {
                (l.min(h.0.min(h.2)), r.max(h.0.max(h.2)))
            });
        frames.push(Rect {
            x0: left,
            y0: top,
            x1: right,
            y1: bottom,
        });
    }
    let legends = doc
        .descendants()
        .filter(|n| n.has_tag_name("rect") && n.attribute("stroke") == Some("#969696"))
        .map(|n| {
            let (x, y) = (num(&n, "x"), num(&n, "y"));
            Rect {
                x0: x,
                y0: y,
                x1: x + num(&n, "width"),
                y1: y + num(&n, "height"),
            }
        })
        .collect();
    let markers = doc
        .descendants()
        .filter(|n| n.has_tag_name("circle"))
        .map(|n| (num(&n, "cx"), num(&n, "cy"), num(&n, "r")))
        .collect();
    let line_points = doc
        .descendants()
        .filter(|n| {
            n.has_tag_name("polyline")
                && SERIES_COLOURS.contains(&n.attribute("stroke").unwrap_or(""))
        })
        .flat_map(|n| {
            n.attribute("points")
                .unwrap_or("")
                .split_whitespace()
                .filter_map(|p| {
                    let (x, y) = p.split_once(',')?;
                    Some((x.parse::<f64>().ok()?, y.parse::<f64>().ok()?))
                })
                .collect::<Vec<_>>()
        })
        .collect();
    Drawing {
        frames,
        legends,
        markers,
        line_points,
    }
}

/// The layout rules every figure keeps: no legend box covers a data
/// marker; every marker and every point of a line lies inside a frame
/// (nothing is drawn outside the axes; the legend's own swatches aside).
fn check_layout(path: &Path, d: &Drawing) {
    let name = path.display();
    assert!(!d.frames.is_empty(), "{name}: no plot frame found");
    for box_ in &d.legends {
        for &(x, y, r) in &d.markers {
            assert!(
                !box_.contains(x, y, r),
                "{name}: the legend box {box_:?} covers the marker at ({x}, {y})"
            );
        }
    }
    for &(x, y, _) in &d.markers {
        assert!(
            d.frames.iter().any(|f| f.contains(x, y, 1.0)),
            "{name}: a marker at ({x}, {y}) outside every frame {:?}",
            d.frames
        );
    }
    for &(x, y) in &d.line_points {
        let in_legend = d.legends.iter().any(|b| b.contains(x, y, 1.0));
        assert!(
            in_legend || d.frames.iter().any(|f| f.contains(x, y, 1.5)),
            "{name}: a line point at ({x}, {y}) outside every frame {:?}",
            d.frames
        );
    }
}

/// A tick label's value: a plain number, or a log axis's `10⁻⁴` or
/// `2×10³`.
fn label_value(text: &str) -> Option<f64> {
    let text = text.trim().replace('−', "-");
    let text = text.as_str();
    if let Ok(v) = text.parse::<f64>() {
        return Some(v);
    }
    let (mantissa, power) = match text.split_once("×10") {
        Some((m, p)) => (m.parse::<f64>().ok()?, p),
        None => match text.strip_prefix('-') {
            Some(rest) => (-1.0, rest.strip_prefix("10")?),
            None => (1.0, text.strip_prefix("10")?),
        },
    };
    let digits: String = power
        .chars()
        .map(|c| match c {
            '⁻' => Some('-'),
            '⁰' => Some('0'),
            '¹' => Some('1'),
            '²' => Some('2'),
            '³' => Some('3'),
            '⁴' => Some('4'),
            '⁵' => Some('5'),
            '⁶' => Some('6'),
            '⁷' => Some('7'),
            '⁸' => Some('8'),
            '⁹' => Some('9'),
            _ => None,
        })
        .collect::<Option<String>>()?;
    Some(mantissa * 10_f64.powi(digits.parse().ok()?))
}

/// Checks that `path` is a well-formed SVG or a PNG of the plot size that
/// is not one flat colour.
fn check_picture(path: &Path) {
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert!(
        bytes.len() > 1000,
        "{}: only {} bytes",
        path.display(),
        bytes.len()
    );
    match path.extension().and_then(|e| e.to_str()) {
        Some("svg") => {
            let text = String::from_utf8(bytes).unwrap();
            let doc = roxmltree::Document::parse(&text)
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            assert_eq!(doc.root_element().tag_name().name(), "svg");
            assert!(
                doc.descendants()
                    .filter(|n| n.has_tag_name("polyline")
                        || n.has_tag_name("path")
                        || n.has_tag_name("circle"))
                    .count()
                    > 3
            );
            assert!(
                doc.descendants().any(|n| n.has_tag_name("text")),
                "{}: no text",
                path.display()
            );
            // Tick labels (the texts that are numbers) carry the digits
            // they need: never `1400.0`, never `-0`.
            let ticks: Vec<&str> = doc
                .descendants()
                .filter(|n| n.has_tag_name("text"))
                .filter_map(|n| n.text())
                .map(str::trim)
                .filter(|t| !t.is_empty() && label_value(t).is_some())
                .collect();
            assert!(ticks.len() >= 4, "{}: {ticks:?}", path.display());
            check_layout(path, &drawing(&doc));
            for t in &ticks {
                assert!(
                    !t.ends_with(".0") && !t.contains(".0e") && *t != "-0",
                    "{}: tick label {t}",
                    path.display()
                );
                // Short enough for the label area: an axis whose values
                // differ far down their digits is labelled from an offset.
                // (A superscript is half a digit wide.)
                let width: f64 = t
                    .chars()
                    .map(|c| {
                        if "⁰¹²³⁴⁵⁶⁷⁸⁹⁻".contains(c) {
                            0.5
                        } else {
                            1.0
                        }
                    })
                    .sum();
                assert!(width <= 8.0, "{}: tick label {t}", path.display());
                let negative_zero = (t.starts_with('-') || t.starts_with('−'))
                    && t.trim_start_matches(['-', '−'])
                        .chars()
                        .all(|c| c == '0' || c == '.');
                assert!(!negative_zero, "{}: tick label {t}", path.display());
            }
        }
        Some("png") => {
            // Twice the pixel density of the SVG's 960 × 640 (or taller
            // for three panels and more).
            let (width, height, distinct) = png_summary(bytes);
            assert_eq!(width, 1920, "{}", path.display());
            assert!(height >= 1280 && height % 2 == 0, "{}", path.display());
            assert!(distinct > 1000, "{}: a flat picture", path.display());
        }
        other => panic!("unexpected extension {other:?}"),
    }
}

fn fit_files(dir: &Path) -> (PathBuf, PathBuf, PathBuf) {
    let mut decay = String::from("time_s,amplitude_deg\n");
    let mut video = String::from("time_s,angle_deg\n");
    let mut beats = String::from("time_s\n");
    for i in 0..200 {
        let x = f64::from(i);
        decay.push_str(&format!(
            "{},{}\n",
            10.0 * x,
            3.0 * (-0.002 * x).exp() + 0.01 * (x * 1.3).sin()
        ));
        video.push_str(&format!(
            "{},{}\n",
            0.02 * x,
            5.0 * (4.43 * 0.02 * x).cos() + 0.1 * (x * 2.1).sin()
        ));
        beats.push_str(&format!(
            "{}\n",
            x + if i % 2 == 1 { 0.0005 } else { 0.0 } + 1e-4 * (x * 0.7).sin()
        ));
    }
    let write = |name: &str, text: &str| {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p
    };
    (
        write("decay.csv", &decay),
        write("video.csv", &video),
        write("beats.csv", &beats),
    )
}

#[test]
fn every_plot_kind_in_both_formats() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (decay, video, beats) = fit_files(d);
    let spike = d.join("spike.csv");
    let mut text = String::from("time_s,angle_deg\n");
    for i in 0..300 {
        let x = f64::from(i);
        let a = if i == 150 {
            80.0
        } else {
            5.0 * (4.43 * 0.02 * x).cos() + 0.1 * (x * 2.1).sin()
        };
        text.push_str(&format!("{},{a}\n", 0.02 * x));
    }
    std::fs::write(&spike, text).unwrap();
    for ext in ["svg", "png"] {
        let out = |name: &str| d.join(format!("{name}.{ext}"));
        let s = |p: &Path| p.to_str().unwrap().to_string();
        let runs: Vec<(Vec<String>, Vec<PathBuf>)> = vec![
            (
                vec![
                    "period".into(),
                    "--length".into(),
                    "1".into(),
                    "--amplitude".into(),
                    "1deg..40deg".into(),
                    "--plot".into(),
                    s(&out("period")),
                ],
                vec![out("period")],
            ),
            (
                vec![
                    "damped".into(),
                    "--length".into(),
                    "1".into(),
                    "--amplitude".into(),
                    "10deg".into(),
                    "--q".into(),
                    "20".into(),
                    "--plot".into(),
                    s(&out("damped")),
                ],
                vec![out("damped")],
            ),
            (
                vec![
                    "simulate".into(),
                    "--length".into(),
                    "1".into(),
                    "--amplitude".into(),
                    "20deg".into(),
                    "--q".into(),
                    "100".into(),
                    "--duration".into(),
                    "200s".into(),
                    "--plot".into(),
                    s(&out("simulate")),
                    "--phase-plot".into(),
                    s(&out("phase")),
                ],
                vec![out("simulate"), out("phase")],
            ),
            (
                vec![
                    "fit".into(),
                    "decay".into(),
                    s(&decay),
                    "--plot".into(),
                    s(&out("decay")),
                ],
                vec![out("decay")],
            ),
            (
                vec![
                    "fit".into(),
                    "trajectory".into(),
                    s(&video),
                    "--plot".into(),
                    s(&out("trajectory")),
                ],
                vec![out("trajectory")],
            ),
            (
                vec![
                    "fit".into(),
                    "beats".into(),
                    s(&beats),
                    "--plot".into(),
                    s(&out("beats")),
                ],
                vec![out("beats")],
            ),
        ];
        let words =
            |line: &str| -> Vec<String> { line.split_whitespace().map(String::from).collect() };
        let more: Vec<(&str, Vec<String>)> = vec![
            // One amplitude: the working amplitude marked, the series'
            // error on a log axis.
            ("period-one", words("period --length 1 --amplitude 15deg")),
            // Dry friction: the envelope through the turning points.
            (
                "friction",
                words("damped --length 1 --amplitude 10deg --q 200 --friction-angle 0.2deg"),
            ),
            (
                "isochronism",
                words(
                    "clock --length 0.99362m --q 10000 --escapement recoil --lift-angle 2 \
                     --drive 20uJ --drive-range 0.5x..2x --steps 5",
                ),
            ),
            (
                "clock-run",
                words(
                    "clock --length 0.99362m --q 10000 --escapement deadbeat --lift-angle 2 \
                     --drive 20uJ --duration 3day --every 1h",
                ),
            ),
            // A loss constant to its eighth digit: labelled from an offset.
            (
                "offset",
                words("simulate --length 1 --amplitude 0.0001deg --q 10 --duration 100s"),
            ),
            // A tracked angle with one bad value: clipped, counted.
            ("spike", vec!["fit".into(), "trajectory".into(), s(&spike)]),
            // Deviations with their intervals as bars, and a second axis
            // in s/day on the right.
            (
                "stability",
                vec![
                    "stability".into(),
                    concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/offsets.csv").into(),
                ],
            ),
        ];
        // A timegrapher's strip from a synthetic recording.
        let wav = d.join("clock.wav");
        if !wav.exists() {
            pendulum()
                .args(["synth", "ticks", wav.to_str().unwrap(), "--bph", "3600"])
                .args(["--rate", "12", "--beat-error", "1.5", "--duration", "1min"])
                .args(["--snr-db", "20", "--seed", "7"])
                .assert()
                .success();
        }
        let mut more = more;
        more.push(("listen", vec!["listen".into(), s(&wav)]));
        let mut runs = runs;
        for (name, mut args) in more {
            args.push("--plot".into());
            args.push(s(&out(name)));
            runs.push((args, vec![out(name)]));
        }
        for (args, files) in runs {
            pendulum().args(&args).assert().success();
            for f in files {
                check_picture(&f);
            }
        }
    }
    // Quantities that span decades on log axes: the Allan deviation
    // (log-log, under two decades: ticks at 1, 2, 5, 10, ... which no
    // linear axis has) and the power series' error (log y over 13
    // decades: five powers of ten or more).
    for name in ["beats", "period-one"] {
        let svg = std::fs::read_to_string(d.join(format!("{name}.svg"))).unwrap();
        let doc = roxmltree::Document::parse(&svg).unwrap();
        let labels: Vec<f64> = doc
            .descendants()
            .filter(|n| n.has_tag_name("text"))
            .filter_map(|n| n.text())
            .filter_map(label_value)
            .filter(|v| *v > 0.0)
            .collect();
        let has = |v: f64| labels.iter().any(|l| (l / v - 1.0).abs() < 1e-9);
        let one_two_five = labels
            .iter()
            .any(|&x| has(2.0 * x) && has(5.0 * x) && has(10.0 * x));
        let decades = labels
            .iter()
            .filter(|v| (v.log10() - v.log10().round()).abs() < 1e-9)
            .count();
        assert!(
            one_two_five || decades >= 5,
            "{name}: no log axis in the labels {labels:?}"
        );
    }
    let offset = std::fs::read_to_string(d.join("offset.svg")).unwrap();
    assert!(
        offset.contains("loss (s/day) − 108.0675"),
        "no offset in the title"
    );
    // The deviations' second axis, in s/day.
    let stability = std::fs::read_to_string(d.join("stability.svg")).unwrap();
    assert!(stability.contains("the same in s/day"), "no s/day axis");
    // The working amplitude is marked and named.
    let period = std::fs::read_to_string(d.join("period-one.svg")).unwrap();
    assert!(period.contains("working amplitude, 15°"));
    // The bad value is left off the axes and said to be.
    let spike = std::fs::read_to_string(d.join("spike.svg")).unwrap();
    assert!(
        spike.contains("measured (1 off-scale)"),
        "no off-scale count"
    );
    // Dry friction: turning points over the whole curve (20 s at a
    // 2 s period: 21), and the envelope named.
    let friction = std::fs::read_to_string(d.join("friction.svg")).unwrap();
    assert!(friction.contains("envelope through the turning points"));
    let doc = roxmltree::Document::parse(&friction).unwrap();
    let turns = doc
        .descendants()
        .filter(|n| n.has_tag_name("circle"))
        .count();
    assert!(turns >= 20, "{turns} turning points drawn");
}

#[test]
fn bad_plot_names_and_folders_are_refused_cleanly() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let pdf = d.join("period.pdf");
    refuses(
        &[
            "period",
            "--length",
            "1",
            "--amplitude",
            "3",
            "--plot",
            pdf.to_str().unwrap(),
        ],
        "--plot",
    );
    let none = d.join("period");
    refuses(
        &[
            "period",
            "--length",
            "1",
            "--amplitude",
            "3",
            "--plot",
            none.to_str().unwrap(),
        ],
        "--plot",
    );
    let missing = d.join("no/such/folder/p.svg");
    refuses(
        &[
            "period",
            "--length",
            "1",
            "--amplitude",
            "3",
            "--plot",
            missing.to_str().unwrap(),
        ],
        "--plot",
    );
    let phase = d.join("phase.jpg");
    refuses(
        &[
            "simulate",
            "--length",
            "1",
            "--amplitude",
            "3",
            "--duration",
            "10s",
            "--phase-plot",
            phase.to_str().unwrap(),
        ],
        "--phase-plot",
    );
    assert_eq!(std::fs::read_dir(d).unwrap().count(), 0, "nothing written");
    // A report into a folder that cannot be made: under a regular file.
    let file = d.join("a-file");
    std::fs::write(&file, "x").unwrap();
    let under = file.join("report");
    refuses(&["report", "--output", under.to_str().unwrap()], "--output");
    assert_eq!(std::fs::read_dir(d).unwrap().count(), 1);
}

#[test]
fn the_report_opens_in_a_browser_with_every_picture() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("report");
    let assert = pendulum()
        .args(["report", "--output", out.to_str().unwrap()])
        .assert()
        .success();
    let printed = String::from_utf8(assert.get_output().stdout.clone()).unwrap();
    assert!(printed.trim_end().ends_with("index.html"), "{printed}");
    for name in ["period.svg", "decay.svg", "rundown.svg"] {
        check_picture(&out.join(name));
    }
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert!(html.contains("s/day") && html.contains("Q") && html.contains("kg m²/s"));
    let Some(browser) = crate::util::system_program(
        &["chromium", "chromium-browser", "google-chrome"],
        "chromium",
        "the report's browser test",
    ) else {
        return;
    };
    let profile = tempfile::tempdir().unwrap();
    let url = format!("file://{}", out.join("index.html").display());
    let common = [
        "--headless".to_string(),
        "--no-sandbox".into(),
        "--disable-gpu".into(),
        "--disable-background-networking".into(),
        "--disable-component-update".into(),
        "--disable-sync".into(),
        "--no-first-run".into(),
        format!("--user-data-dir={}", profile.path().display()),
        "--virtual-time-budget=5000".into(),
    ];
    let shot = dir.path().join("shot.png");
    let status = std::process::Command::new(&browser)
        .args(&common)
        .arg("--window-size=960,640")
        .arg(format!("--screenshot={}", shot.display()))
        .arg(&url)
        .output()
        .unwrap();
    assert!(
        status.status.success(),
        "{}",
        String::from_utf8_lossy(&status.stderr)
    );
    let (_, _, distinct) = png_summary(std::fs::read(&shot).unwrap());
    assert!(distinct > 1000, "the screenshot is blank");
    let dom = std::process::Command::new(&browser)
        .args(&common)
        .arg("--dump-dom")
        .arg(&url)
        .output()
        .unwrap();
    let dom = String::from_utf8_lossy(&dom.stdout);
    assert!(
        dom.contains("data-broken-images=\"0\""),
        "pictures failed to load: {dom}"
    );
}
