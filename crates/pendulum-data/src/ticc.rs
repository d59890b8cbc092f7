//! The logs of the TAPR TICC, a two-channel time-interval counter and
//! timestamper that clock people log over its USB serial port (picocom,
//! minicom, its own `ticc_logger`): `#` lines of banner and settings, then
//! one reading a line, a number of seconds to the picosecond and a label.
//! In its timestamp mode, `12.345678901234 chA`, the time of each pulse on
//! channel A or B (a pendulum's photogate on one, a GPS receiver's pulse
//! per second on the other); in its time-interval mode, `0.000000012345
//! TI(A->B)`, from each pulse on A to the next on B; in its period mode,
//! `2.000123456789 chA`, the time since the channel's last pulse. The
//! firmware's output (TAPR's TICC sources, `TICC.ino`) is the reference.
//!
//! Timestamps become `time_s` with a `gate` column of the channel (the
//! beat commands read one channel, `--gate chB` the other); time
//! intervals become `offset_s` (phase, for `stability` and `log`, with
//! `--tau0` the interval between pulses); periods become `period_s` with
//! their channel. A period log and a timestamp log are told apart by
//! their values: timestamps rise line after line, periods do not.

use crate::formats::{Converted, FileFormat};

/// The TICC log's entry in [`crate::formats::FORMATS`]: told by its
/// lines, not its name (loggers write `.txt`, `.log`, `.dat`).
pub const FORMAT: FileFormat = FileFormat {
    name: "TICC log",
    extensions: &[],
    recognise: Some(recognise),
    read,
};

/// One reading: its value (s) and its label.
fn reading(line: &str) -> Option<(f64, &str)> {
    let mut words = line.split_whitespace();
    let (value, label) = (words.next()?, words.next()?);
    if words.next().is_some() || !matches!(label, "chA" | "chB" | "TI(A->B)") {
        return None;
    }
    // The firmware writes digits, a sign and a point only.
    if !value
        .bytes()
        .all(|b| b.is_ascii_digit() || b == b'.' || b == b'-')
    {
        return None;
    }
    Some((value.parse().ok().filter(|v: &f64| v.is_finite())?, label))
}

/// A TICC log: its banner, or its first lines of data (three readings,
/// nothing else but `#` lines and blank ones before them).
fn recognise(head: &[u8]) -> bool {
    let text = String::from_utf8_lossy(head);
    if text.contains("TAPR TICC") {
        return true;
    }
    // The last line of the head may be cut short.
    let lines: Vec<&str> = text.lines().collect();
    let whole = &lines[..lines.len().saturating_sub(1)];
    let data: Vec<&str> = whole
        .iter()
        .map(|l| l.trim())
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .take(3)
        .collect();
    data.len() == 3 && data.iter().all(|l| reading(l).is_some())
}

/// The readings of a TICC log as table text.
fn read(bytes: Vec<u8>) -> Result<Converted, String> {
    let text = String::from_utf8_lossy(&bytes);
    let mut readings: Vec<(f64, &str, usize)> = Vec::new();
    let mut other = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let t = line.trim();
        if t.is_empty() || t.starts_with('#') {
            continue;
        }
        match reading(t) {
            Some((v, label)) => readings.push((v, label, i + 1)),
            None => other.push(i + 1),
        }
    }
    if readings.is_empty() {
        return Err("a TICC log with no readings (lines like `12.345678901234 chA`)".into());
    }
    let intervals = readings.iter().filter(|r| r.1 == "TI(A->B)").count();
    let mut notes = Vec::new();
    if !other.is_empty() {
        notes.push(format!(
            "{} lines that are not readings left out (the first: line {})",
            other.len(),
            other[0]
        ));
    }
    // The file's line of each line of the table text (its header's: the
    // line before the first reading, the banner's last).
    let mut lines = Vec::with_capacity(readings.len() + 1);
    let header_line = (readings[0].2 as u64 - 1).max(1);
    let text = if intervals * 2 >= readings.len() {
        if intervals < readings.len() {
            notes.push(format!(
                "{} channel readings left out: read as a time-interval log (TI(A->B))",
                readings.len() - intervals
            ));
        }
        let mut out = String::from("offset_s\n");
        lines.push(header_line);
        for (v, _, line) in readings.iter().filter(|r| r.1 == "TI(A->B)") {
            out.push_str(&format!("{v}\n"));
            lines.push(*line as u64);
        }
        out
    } else {
        if intervals > 0 {
            notes.push(format!(
                "{intervals} time-interval readings left out: read as channel readings"
            ));
        }
        let channels: Vec<(f64, &str, usize)> = readings
            .iter()
            .copied()
            .filter(|r| r.1 != "TI(A->B)")
            .collect();
        let column = if rising(&channels) {
            "time_s"
        } else {
            notes.push(
                "read as a period log (the values do not rise line after line as \
                 timestamps do)"
                    .into(),
            );
            "period_s"
        };
        let mut out = format!("{column},gate\n");
        lines.push(header_line);
        for (v, label, line) in &channels {
            out.push_str(&format!("{v},{label}\n"));
            lines.push(*line as u64);
        }
        out
    };
    Ok(Converted {
        text,
        lines,
        notes,
        ..Converted::default()
    })
}

/// Whether each channel's values rise from reading to reading (nine in
/// ten steps or more): timestamps, not periods.
fn rising(readings: &[(f64, &str, usize)]) -> bool {
    let (mut up, mut steps) = (0usize, 0usize);
    for channel in ["chA", "chB"] {
        let values: Vec<f64> = readings
            .iter()
            .filter(|r| r.1 == channel)
            .map(|r| r.0)
            .collect();
        for w in values.windows(2) {
            steps += 1;
            up += usize::from(w[1] > w[0]);
        }
    }
    steps == 0 || up * 10 >= steps * 9
}

#[cfg(test)]
mod tests {
    use crate::{read_table, ReadOptions, Role, Source};

    /// Reads `text` as the file `name`, the columns of `roles`.
    fn table(name: &str, text: &str, roles: &[Role]) -> crate::Table {
        let roles = roles.to_vec();
        read_table(
            Source::bytes(name, text.as_bytes()),
            &ReadOptions::default(),
            &move |_| Ok(roles.clone()),
        )
        .unwrap()
    }

    /// The firmware's banner, then timestamps of two channels as they
    /// come (a pendulum on A, a pulse per second on B): each channel's
    /// times, to the picosecond the text holds, under its label.
    #[test]
    fn a_timestamp_log_gives_times_and_their_channels() {
        let log = "\
# TAPR TICC Timestamping Counter
# Copyright 2016-2025 N8UR, K9TRV, NH6Z, WA8YWQ
#####################
# timestamp (seconds)
  17.123456789012 chA
  17.300000000125 chB
  18.123479937150 chA
  18.300000000117 chB
  19.123503085288 chA
";
        let t = table("run.log", log, &[Role::Time, Role::Gate]);
        assert_eq!(t.format.reader, "TICC log");
        assert_eq!(t.format.gate_labels, vec!["chA", "chB"]);
        let times = t.column(Role::Time).unwrap();
        let origin = t.format.time_origin_s.unwrap_or(0.0);
        let written = [
            17.123456789012,
            17.300000000125,
            18.12347993715,
            18.300000000117,
            19.123503085288,
        ];
        for (got, want) in times.iter().zip(written) {
            assert!(
                (got + origin - want).abs() < 1e-12,
                "{got} + {origin} against {want}"
            );
        }
        assert_eq!(t.lines, vec![5, 6, 7, 8, 9]);
    }

    /// Time-interval readings (no banner: a logger started late) are the
    /// phase of B against A, s; a line the counter garbled is named.
    #[test]
    fn a_time_interval_log_gives_offsets() {
        let log = "\
   0.000000012345 TI(A->B)
   0.000000012391 TI(A->B)
  -0.000000000412 TI(A->B)
   0.0000000 TI(A->
   0.000000012288 TI(A->B)
";
        let t = table("ti.txt", log, &[Role::Offset]);
        assert_eq!(t.format.reader, "TICC log");
        assert_eq!(
            t.column(Role::Offset).unwrap(),
            &[12.345e-9, 12.391e-9, -0.412e-9, 12.288e-9]
        );
        assert!(
            t.format.notes.iter().any(|n| n.contains("line 4")),
            "{:?}",
            t.format.notes
        );
    }

    /// A period log (values that do not rise) is read as periods, and
    /// says so.
    #[test]
    fn a_period_log_is_told_from_timestamps() {
        let log =
            "2.000123456789 chA\n2.000120001234 chA\n2.000125550000 chA\n2.000119990000 chA\n";
        let t = table("p.dat", log, &[Role::Period]);
        assert_eq!(t.column(Role::Period).unwrap()[1], 2.000120001234);
        assert!(t.format.notes.iter().any(|n| n.contains("period log")));
    }

    /// Files that are not TICC logs are left to the table reader: a
    /// space-separated table, one with a channel word in a header, and a
    /// banner line alone is enough to be taken (the first 8 KiB may be
    /// all settings).
    #[test]
    fn only_ticc_logs_are_taken() {
        assert!(!super::recognise(b"0.0 1.0\n1.0 2.0\n2.0 3.0\n3.0 4.0\n"));
        assert!(!super::recognise(b"time chA\n1.0 2.0\n2.0 3.0\n3.0 4.0\n"));
        assert!(!super::recognise(b"1.5 chA\n2.5 chC\n3.5 chA\n4.5 chA\n"));
        assert!(super::recognise(
            b"# TAPR TICC Timestamping Counter\n# settings"
        ));
        // Three readings whole; a fourth cut by the end of the head.
        assert!(super::recognise(b"1.5 chA\n2.5 chA\n3.5 chA\n4.5 c"));
        assert!(!super::recognise(b"1.5 chA\n2.5 chA\n3.5 c"));
        let plain = table("plain.txt", "t x\n0 1\n1 2\n2 3\n", &[Role::Time, Role::X]);
        assert_eq!(plain.format.reader, "text table");
    }
}
