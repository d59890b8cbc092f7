//! Every plot kind, drawn to SVG and PNG and checked as a file a viewer can
//! open; the report, looked at by a real browser.

use crate::util::{pendulum, refuses};
use std::path::{Path, PathBuf};

/// Decodes a PNG: its size and how many pixels differ from the first.
fn png_summary(bytes: Vec<u8>) -> (u32, u32, usize) {
    let mut reader = png::Decoder::new(std::io::Cursor::new(bytes))
        .read_info()
        .unwrap();
    let mut pixels = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut pixels).unwrap();
    let channels = info.color_type.samples();
    let first = pixels[..channels].to_vec();
    let distinct = pixels
        .chunks(channels)
        .filter(|p| *p != first.as_slice())
        .count();
    (info.width, info.height, distinct)
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
                .filter(|t| !t.is_empty() && t.parse::<f64>().is_ok())
                .collect();
            assert!(ticks.len() >= 4, "{}: {ticks:?}", path.display());
            for t in &ticks {
                assert!(
                    !t.ends_with(".0") && !t.contains(".0e") && *t != "-0",
                    "{}: tick label {t}",
                    path.display()
                );
                let negative_zero = t.starts_with('-')
                    && t.trim_start_matches('-')
                        .chars()
                        .all(|c| c == '0' || c == '.');
                assert!(!negative_zero, "{}: tick label {t}", path.display());
            }
        }
        Some("png") => {
            let (width, height, distinct) = png_summary(bytes);
            assert_eq!((width, height), (960, 640));
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
        for (args, files) in runs {
            pendulum().args(&args).assert().success();
            for f in files {
                check_picture(&f);
            }
        }
    }
    // The Allan deviation spans decades: log-log axes, ticks at powers of
    // ten (the SVG's numeric labels include at least three, on two axes).
    let svg = std::fs::read_to_string(d.join("beats.svg")).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let decades = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text())
        .filter_map(|t| t.trim().parse::<f64>().ok())
        .filter(|v| *v > 0.0 && (v.log10() - v.log10().round()).abs() < 1e-9 && *v != 1.0)
        .count();
    assert!(
        decades >= 3,
        "{decades} power-of-ten labels in the beats figure"
    );
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

/// Chromium, if installed.
fn chromium() -> Option<PathBuf> {
    ["chromium", "chromium-browser", "google-chrome"]
        .iter()
        .find_map(|name| {
            std::env::var_os("PATH").and_then(|paths| {
                std::env::split_paths(&paths)
                    .map(|p| p.join(name))
                    .find(|p| p.is_file())
            })
        })
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
    let Some(browser) = chromium() else {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "CI must run the browser test: install Debian's chromium (.ci/run does)"
        );
        eprintln!(
            "SKIPPED the_report_opens_in_a_browser_with_every_picture: no chromium installed"
        );
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
