//! The book's committed figures (book/src/images/*.png, listed in
//! tools/figures/figures.txt): drawn again by the binary and compared with
//! the committed files, by size and by the share of pixels that differ,
//! not byte for byte (a PNG encoder may pack the same picture
//! differently). The gallery's figures are not committed: the book's
//! build draws them.

use crate::util::{decode_png, docs_text, pendulum, repo_root};

/// A pixel differs when a channel moves by more than this (of 255).
const CHANNEL_TOLERANCE: u8 = 32;
/// The share of differing pixels a regenerated figure may show.
const PIXEL_SHARE: f64 = 0.002;

/// Where the committed figures are, from the repository's top.
const IMAGES: &str = "book/src/images";

/// The share of pixels that differ between two pictures of one size.
fn differing_share(a: &[u8], b: &[u8]) -> f64 {
    let differ = a
        .chunks(3)
        .zip(b.chunks(3))
        .filter(|(p, q)| {
            p.iter()
                .zip(*q)
                .any(|(x, y)| x.abs_diff(*y) > CHANNEL_TOLERANCE)
        })
        .count();
    differ as f64 / (a.len() / 3) as f64
}

/// The figures: (file name, arguments).
fn figures() -> Vec<(String, Vec<String>)> {
    let list = std::fs::read_to_string(repo_root().join("tools/figures/figures.txt")).unwrap();
    list.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .map(|l| {
            let mut words = l.split_whitespace().map(String::from);
            let name = words.next().unwrap();
            (name, words.collect())
        })
        .collect()
}

#[test]
fn the_books_figures_are_what_the_binary_draws() {
    let docs = docs_text();
    let figures = figures();
    assert!(figures.len() >= 2, "the book shows at least two figures");
    let dir = tempfile::tempdir().unwrap();
    let mut drawn = Vec::new();
    for (name, args) in &figures {
        assert!(
            docs.contains(&format!("](images/{name})")),
            "no page of the book shows images/{name}"
        );
        let fresh = dir.path().join(name);
        pendulum()
            .args(args)
            .arg("--plot")
            .arg(&fresh)
            .assert()
            .success();
        let (w, h, new) = decode_png(std::fs::read(&fresh).unwrap());
        let committed = repo_root().join(IMAGES).join(name);
        let (cw, ch, old) = decode_png(
            std::fs::read(&committed).unwrap_or_else(|e| panic!("{IMAGES}/{name}: {e}")),
        );
        assert_eq!(
            (w, h),
            (cw, ch),
            "{IMAGES}/{name}: size changed; run bash tools/figures/make_figures.sh"
        );
        let share = differing_share(&new, &old);
        assert!(
            share <= PIXEL_SHARE,
            "{IMAGES}/{name}: {:.3}% of the pixels differ from the figure drawn now; \
             run bash tools/figures/make_figures.sh and commit {IMAGES}/",
            100.0 * share
        );
        drawn.push(new);
    }
    // The measure can fail: two different figures differ far beyond it.
    let between = differing_share(&drawn[0], &drawn[1]);
    assert!(between > 10.0 * PIXEL_SHARE, "{between}");
}

/// The sentences under the isochronism figures quote the figures' own
/// numbers, as the binary computes them now: the arc and the rate at half
/// and twice the drive for each escapement, and the spread of the rate
/// with half the recoil.
#[test]
fn the_isochronism_sentences_are_what_the_binary_says() {
    let docs = docs_text();
    let docs = docs.split_whitespace().collect::<Vec<_>>().join(" ");
    let curve = |args: &[String]| -> Vec<(f64, f64)> {
        let out = pendulum().args(args).arg("--json").output().unwrap();
        assert!(out.status.success());
        let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        json["isochronism"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| {
                (
                    p["amplitude_deg"].as_f64().unwrap(),
                    p["rate_s_per_day"].as_f64().unwrap(),
                )
            })
            .collect()
    };
    let says = |text: String| {
        assert!(
            docs.contains(&text),
            "the book (clock.md) should say '{text}' under the isochronism figures"
        );
    };
    let figures = figures();
    let args = |name: &str| {
        figures
            .iter()
            .find(|(n, _)| n == name)
            .unwrap_or_else(|| panic!("{name} is not in figures.txt"))
            .1
            .clone()
    };
    let deadbeat = curve(&args("isochronism-deadbeat.png"));
    let recoil = curve(&args("isochronism-recoil.png"));
    let (d0, d1) = (deadbeat[0], *deadbeat.last().unwrap());
    let (r0, r1) = (recoil[0], *recoil.last().unwrap());
    says(format!(
        "({:.2}° to {:.2}° from half to twice the drive)",
        d0.0, d1.0
    ));
    says(format!("({:.2} to {:.1} s/day;", d0.1, d1.1));
    says(format!("much less ({:.2}° to {:.2}°)", r0.0, r1.0));
    says(format!("(+{:.2} to +{:.1} s/day)", r0.1, r1.1));
    assert!(recoil.windows(2).all(|w| w[1].1 > w[0].1), "{recoil:?}");
    assert!(deadbeat.windows(2).all(|w| w[1].1 < w[0].1), "{deadbeat:?}");
    let mut half = args("isochronism-recoil.png");
    half.extend(["--recoil".into(), "0.5".into()]);
    let rates: Vec<f64> = curve(&half).iter().map(|p| p.1).collect();
    let spread = rates.iter().copied().fold(f64::MIN, f64::max)
        - rates.iter().copied().fold(f64::MAX, f64::min);
    assert!(
        spread < 0.3,
        "half the recoil: the rate spreads {spread} s/day"
    );
    says("keeps time within 0.3 s/day".into());
}
