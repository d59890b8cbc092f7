//! The command line, declared with clap: every flag, its value name, its
//! help and its type. A quantity's type ([`crate::units::Length`], ...)
//! is parsed by clap with [`crate::units`], so a value refused names its
//! flag in our own words; values with a syntax of their own (a range of
//! amplitudes, a pivot, a drag law) arrive as text.

use crate::paths::{InputPath, OutputPath};
use crate::units::{
    Acceleration, Angle, BeatError, BeatsPerHour, Celsius, Decibels, Drive, Fraction, Hectopascals,
    Hertz, Length, Mass, Milliseconds, Number, Percent, Ppm, RateChange, RatePerDay, SampleRate,
    ThreadsPerInch, Time,
};
use clap::{Args, Parser, Subcommand};
use pendulum_theory::clock::analysis as clock;
use pendulum_theory::clock::escapement::spec::Kind as EscapementKind;
use pendulum_theory::compound::datasheet as sheet;
use pendulum_theory::listening::synth::{Interference, TickRecording};
use pendulum_theory::period::table as period_table;
use pendulum_theory::train::analysis as train_analysis;

/// The theory of the clock pendulum: exact period and circular error, damping,
/// simulation over weeks of swings, fitting to measurements, and reports.
///
/// Start with `pendulum report`: a complete analysis of a seconds pendulum.
///
/// Quantities take units: lengths 994mm, 99.4cm, 0.994m, 39.1in; angles 3deg,
/// 3°, 0.05rad, 30arcmin; times 2s, 1.5ms, 3h, 1day; rates +12s/day, 20ppm;
/// pressures 1000hPa, 29.9inHg; temperatures 25°C, 77F, 298K; humidity 60%;
/// beat rates 3600bph; frequencies 30fps, 48kHz; levels 20dB. A bare number
/// is the unit the flag's help names (SI unless it says otherwise; angles
/// in degrees).
#[derive(Debug, Parser)]
#[command(name = "pendulum", version)]
pub struct Cli {
    /// What to compute.
    #[command(subcommand)]
    pub command: Command,
    /// Print the results alone: no progress bar or spinner, and no summary
    /// on standard error when the data go to standard output (its
    /// warnings and errors still print).
    #[arg(long, short, global = true)]
    pub quiet: bool,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// The exact period at any amplitude, the circular error in s/day, and the power series.
    #[command(after_help = "Examples:
  pendulum period --length 0.99362m --amplitude 2deg
  pendulum period --length 994mm --amplitude 1deg..10deg --steps 10 --csv
  pendulum period --length 0.99362m --amplitude 1deg..30deg --plot period.svg

Method: T = 4 sqrt(l/g) K(sin²(A0/2)) (section 1-6 of the web book 機械式時計の理論,
The theory of mechanical clocks and watches), K by the arithmetic-geometric mean.")]
    Period(PeriodArgs),
    /// The length that gives a period (or a beat rate) at an amplitude.
    #[command(after_help = "Examples:
  pendulum length --bph 3600 --amplitude 3deg
  pendulum length --period 2s --latitude 51.75 --height 70m --json")]
    Length(LengthArgs),
    /// The amplitude a measured period implies for a pendulum of known length.
    #[command(after_help = "Examples:
  pendulum amplitude --period 2.0001s --length 0.99362m
  pendulum amplitude --period 2.0001s --length 0.99362m --period-uncertainty 10us")]
    Amplitude(AmplitudeArgs),
    /// Local gravity from latitude and height (WGS 84 normal gravity).
    #[command(after_help = "Examples:
  pendulum gravity --latitude 51.75 --height 70m
  pendulum gravity --latitude -33.9 --json

Heights from -11 km to +100 km (the free-air formula means nothing inside the Earth).")]
    Gravity(GravityCommandArgs),
    /// The damped pendulum in the small-angle theory: Q, decay, turning points, dry friction, energy.
    #[command(after_help = "Examples:
  pendulum damped --length 0.99362m --amplitude 3deg --q 10000 --mass 5kg
  pendulum damped --length 0.99362m --amplitude 3deg --q 300 --friction-angle 0.02deg --extrema 40
  pendulum damped --length 1m --amplitude 5deg --zeta 0.05 --trajectory - --duration 60s

Theory: the linear viscous pendulum of section 1-4 of the web book 機械式時計の理論
(The theory of mechanical clocks and watches), with dry friction as in its section 2-4.
Above about 10° the small-angle period is off; `pendulum simulate` integrates the full
nonlinear motion.")]
    Damped(Box<DampedArgs>),
    /// The full nonlinear damped pendulum, integrated over days of swings.
    #[command(after_help = "Examples:
  pendulum simulate --length 0.99362m --amplitude 3deg --q 1e6 --duration 7day --method symplectic --swings week.csv
  pendulum simulate --length 1m --amplitude 120deg --duration 60s --method exact --trajectory big.csv
  pendulum simulate --length 0.99362m --amplitude 10deg --q 300 --duration 1h --swings - --quiet

Runs estimated to need more than a few seconds of computing are refused without --force.
Ctrl-C stops a run with its files complete (exit status 130).")]
    Simulate(Box<SimulateArgs>),
    /// Fit the theory to measurements: amplitude decay, tracked angle, beat times.
    #[command(after_help = "Examples:
  pendulum fit decay examples/rundown.csv --length 0.99362m --mass 5kg --plot decay.svg
  pendulum fit trajectory examples/video.csv --length 0.5m --model nonlinear
  pendulum fit beats examples/beats.csv --bph 3600")]
    Fit(FitArgs),
    /// Listen to a clock: rate, beat error and jitter from a sound recording.
    #[command(after_help = "Examples:
  pendulum synth ticks clock.wav --bph 3600 --rate 12s/day --beat-error 1.5ms --duration 10min
  pendulum listen clock.wav
  pendulum listen phone.m4a --bph 3600 --ticks ticks.csv --json

Formats: WAV, FLAC, Ogg Vorbis, MP3, AAC in M4A (symphonia). The channel whose ticks stand
out clearest is used unless --channel says otherwise.")]
    Listen(ListenArgs),
    /// Synthetic data with known truth, to check a setup.
    #[command(after_help = "Examples:
  pendulum synth ticks test.wav --bph 3600 --rate 12 --beat-error 1.5 --duration 10min --snr-db 20 --truth truth.csv
  pendulum listen test.wav")]
    Synth(SynthArgs),
    /// A going train: beats per hour and the pendulum it needs, or the
    /// wheel and pinion counts that give a beat rate.
    #[command(after_help = "Examples:
  pendulum train --wheels 64,60,30 --pinions 8,8
  pendulum train --wheels 64,60,30 --pinions 8,8 --design examples/invar-lens.toml
  pendulum train --bph 4800 --escape-teeth 30")]
    Train(TrainArgs),
    /// How far to move the bob (and how many turns of the nut) to correct a
    /// rate, or what weight to add on a tray.
    #[command(after_help = "Examples:
  pendulum regulate --length 0.994m --rate +12s/day --nut-pitch 0.7mm
  pendulum regulate --design examples/seconds-steel-brass.toml --rate -30 --nut-tpi 36")]
    Regulate(RegulateArgs),
    /// A design's temperature coefficient, and the compensator that makes it
    /// vanish: a tube or collar, a gridiron, or a jar of mercury.
    #[command(after_help = "Examples:
  pendulum compensate --design examples/seconds-steel-brass.toml --compensator zinc
  pendulum compensate --design examples/longcase-wood.toml --compensator collar
  pendulum compensate --design examples/seconds-steel-brass.toml --compensator zinc-steel
  pendulum compensate --design examples/seconds-steel-brass.toml --compensator mercury --write jar.toml")]
    Compensate(CompensateArgs),
    /// A design's datasheet: parts, mass, inertia, equivalent length,
    /// period, temperature and barometric coefficients.
    #[command(after_help = "Example:
  pendulum design examples/seconds-steel-brass.toml --pressure 1000hPa --temperature 25°C --humidity 60%")]
    Design(DesignArgs),
    /// A clock: the pendulum kept going by an escapement. Its steady
    /// amplitude and rate (circular and escapement errors), the isochronism
    /// curve against the drive, or a long run (days to years) with the
    /// drive changing.
    #[command(after_help = "Examples:
  pendulum clock --length 0.994m --q 10000 --escapement deadbeat --lift-angle 2 --drive 20uJ
  pendulum clock --design examples/seconds-steel-brass.toml --escapement recoil --drive 2e-4Nm --drive-range 0.5x..2x --steps 7 --plot iso.svg
  pendulum clock --design examples/seconds-steel-brass.toml --escapement deadbeat --drive 20uJ --duration 8days --every 1h --drive-file examples/spring.csv --swings run.csv")]
    Clock(ClockArgs),
    /// The one-command analysis of a pendulum, as an HTML page with figures
    /// (default: a seconds pendulum at 3° with Q = 10,000).
    #[command(after_help = "Examples:
  pendulum report
  pendulum report --length 0.2485m --amplitude 5deg --q 3000 --output half-seconds
  pendulum report --zeta 0 --output free

The folder is written whole or not at all; the simulated run-down is at most 10^5 periods.")]
    Report(ReportArgs),
    /// The frequency stability of any series: Allan, modified Allan, time,
    /// Hadamard and total deviations and MTIE, with confidence intervals
    /// and the noise at each averaging time (NIST SP 1065).
    #[command(after_help = stability_help())]
    Stability(StabilityArgs),
    /// A clock's log: its rate against the weather, the tides and the days
    /// (coefficients with standard errors), and its stability before and
    /// after the model.
    #[command(after_help = "Examples:
  pendulum log examples/clock-log.csv --events examples/clock-events.csv --latitude 52.2 --longitude 0.12 --tides
  pendulum log examples/clock-log.csv --events examples/clock-events.csv --design examples/seconds-steel-brass.toml --json
  pendulum log examples/clock-log.csv --events examples/clock-events.csv --residuals residuals.csv

Columns by name: time (s or ISO 8601), offset (s; clock minus reference), rate (s/day), half_period
(µs bare) or beat times alone; temperature (°C), pressure (hPa, mbar, inHg), humidity (%),
amplitude (deg, mrad). Each term stays only if the Bayesian information criterion wants it.")]
    Log(LogArgs),
    /// The Earth's body tide: the change of gravity (Sun and Moon on an
    /// elastic Earth) and the rate it gives a pendulum clock.
    #[command(after_help = "Examples:
  pendulum tide --latitude 52.2 --longitude 0.12 --from 2026-01-01 --to 2026-01-03 --every 1h
  pendulum tide --latitude 48.33 --longitude 8.33 --height 589m --from 2026-01-01T00:00Z --to 2026-01-31T00:00Z --every 10min --csv

Times are UTC. Rows: time, gravity_change_nm_s2 (positive: g larger), rate_s_per_day (the
pendulum's: +Δg/2g, gaining while g is larger). No ocean loading, no polar motion.")]
    Tide(TideArgs),
}

/// `stability`'s help after its options: examples, the files it reads,
/// and each deviation of the library's list with what it is.
fn stability_help() -> String {
    let mut help = "Examples:
  pendulum stability examples/offsets.csv
  pendulum stability examples/offsets.csv --json
  pendulum stability examples/frequency.txt --kind frequency --tau0 1h

A file with a header names its column: offset (phase, s; also ms, us, ns) or rate (s/day; a
bare `frequency` is a fraction); a time column sets τ0 and marks gaps. A file without a header
holds one column of values, or a time and a value: give --kind.

Deviations (the JSON's and CSV's keys):"
        .to_string();
    for d in pendulum_theory::stability::DEVIATIONS {
        help.push_str(&format!("\n  {} ({}): {}", d.name, d.key, d.help));
    }
    help
}

/// What a stability series holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum SeriesKind {
    /// Time error: clock minus reference, s.
    Phase,
    /// Fractional frequency (a rate column in s/day is read as one).
    Frequency,
}

/// `pendulum stability`.
#[derive(Debug, Args)]
pub struct StabilityArgs {
    /// The series: offsets or rates, with or without a time column.
    #[arg(value_name = "FILE")]
    pub file: InputPath,
    /// What the values are [default: from the column's name].
    #[arg(long, value_enum)]
    pub kind: Option<SeriesKind>,
    /// The spacing of the samples [default: the median interval of the
    /// time column; needed without one].
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true)]
    pub tau0: Option<Time>,
    /// Every averaging time τ0, 2τ0, 3τ0, … instead of octaves.
    #[arg(long)]
    pub all_taus: bool,
    /// Jumps and glitches found (a missed pulse, the reference slipping):
    /// keep them and be warned of them with how much they raise the
    /// shortest τ's deviation, or remove them (a glitch becomes a gap, a
    /// jump is taken back: Stable32's practice).
    #[arg(long, value_enum, default_value = "keep")]
    pub outliers: OutliersArg,
    /// Names of the columns of a file without a header, in order (e.g. time_s,offset_s).
    #[arg(long, value_name = "NAMES")]
    pub columns: Option<String>,
    /// Run even when the work is long (every τ of a long series).
    #[arg(long)]
    pub force: bool,
    /// Plot the deviations against τ with their intervals (.svg or .png).
    #[arg(long, value_name = "FILE")]
    pub plot: Option<OutputPath>,
    /// Print one JSON object.
    #[arg(long, conflicts_with = "csv")]
    pub json: bool,
    /// Print the rows as CSV.
    #[arg(long)]
    pub csv: bool,
}

/// What `stability --outliers` does.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum OutliersArg {
    /// Keep them, and warn.
    Keep,
    /// Take them out, and say so.
    Remove,
}

/// What a log's values are.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum LogKindArg {
    /// Clock minus reference, s.
    Offset,
    /// The clock's rate, s/day.
    Rate,
    /// A photogate's half periods.
    HalfPeriods,
    /// Beat times alone (their differences are the half periods).
    Beats,
}

/// `pendulum log`.
#[derive(Debug, Args)]
pub struct LogArgs {
    /// The log: a time column and offsets, rates, half periods or beat
    /// times, with any weather beside them.
    #[arg(value_name = "FILE")]
    pub file: InputPath,
    /// What the values are [default: from the column's name].
    #[arg(long, value_enum)]
    pub kind: Option<LogKindArg>,
    /// Names of the columns of a file without a header, in order (e.g.
    /// time_s,offset_s,amplitude_mrad).
    #[arg(long, value_name = "NAMES")]
    pub columns: Option<String>,
    /// The clock's latitude, degrees north (for --tides).
    #[arg(long, value_name = "DEG", allow_hyphen_values = true)]
    pub latitude: Option<Angle>,
    /// The clock's longitude, degrees east.
    #[arg(long, value_name = "DEG", allow_hyphen_values = true)]
    pub longitude: Option<Angle>,
    /// Its height above the ellipsoid [default: 0 m].
    #[arg(long, value_name = "H", allow_hyphen_values = true)]
    pub height: Option<Length>,
    /// Fit the Earth's body tide as a term (needs --latitude, --longitude
    /// and dated times).
    #[arg(long, requires_all = ["latitude", "longitude"])]
    pub tides: bool,
    /// When the log's first time was (ISO 8601, UTC), for a log whose
    /// times are seconds from its start.
    #[arg(long, value_name = "DATETIME")]
    pub start: Option<String>,
    /// The clock's design: its predicted temperature, pressure and
    /// humidity coefficients beside the measured ones, and the pendulum
    /// the advice moves.
    #[arg(long, value_name = "FILE")]
    pub design: Option<InputPath>,
    /// The pendulum's length, for the advice's move of the bob [default:
    /// the simple pendulum of the log's beat (half periods, or --beat),
    /// said; a log of offsets or rates without --beat has no advice
    /// without it].
    #[arg(
        long,
        value_name = "L",
        allow_hyphen_values = true,
        conflicts_with = "design"
    )]
    pub length: Option<Length>,
    #[command(flatten)]
    pub nut: NutArgs,
    /// A file of times (one a line, s or ISO 8601) at which the rate
    /// stepped: a regulation, a weight added, a rewinding.
    #[arg(long, value_name = "FILE")]
    pub events: Option<InputPath>,
    /// The bin the rate is fitted in [default: 1 h; a 24th of a log
    /// shorter than a day].
    #[arg(long, value_name = "DURATION", allow_hyphen_values = true)]
    pub bin: Option<Time>,
    /// For offsets: the beat a reference comparison slips by [default:
    /// found from the jumps].
    #[arg(long, value_name = "DURATION", allow_hyphen_values = true)]
    pub beat: Option<Time>,
    /// For half periods: the nominal beat rate [default: the standard
    /// rate within 2%].
    #[arg(
        long,
        value_name = "B",
        allow_hyphen_values = true,
        conflicts_with = "period"
    )]
    pub bph: Option<BeatsPerHour>,
    /// For half periods: the nominal period (two beats).
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub period: Option<Time>,
    /// For a photogate's pulse widths (a `pulse_width` column): the bob's
    /// flag's width, to turn each pulse into the swing's amplitude.
    #[arg(
        long,
        value_name = "W",
        allow_hyphen_values = true,
        requires = "gate_radius"
    )]
    pub flag_width: Option<Length>,
    /// The gate's distance from the pivot, with --flag-width.
    #[arg(
        long,
        value_name = "R",
        allow_hyphen_values = true,
        requires = "flag_width"
    )]
    pub gate_radius: Option<Length>,
    /// The going train as wheels:pinions, from the first arbor to the
    /// escape wheel (e.g. 96,90,30:8,8, as `pendulum train` takes them):
    /// each arbor's period is marked in the spectrum and the rate folded
    /// over its turn.
    #[arg(long, value_name = "W,…:P,…", value_parser = parse_train)]
    pub train: Option<TrainSpec>,
    #[arg(long, allow_hyphen_values = true, value_name = "N", requires = "train", help = with_default("Turns an hour of the train's first arbor", train_analysis::DEFAULT_ARBOR_TURNS_PER_HOUR))]
    pub arbor_turns_per_hour: Option<Number>,
    /// Write the figures as PREFIX-rate.svg, PREFIX-weather.svg,
    /// PREFIX-stability.svg, PREFIX-spectrum.svg and, with --train,
    /// PREFIX-folds.svg (PNG when PREFIX ends in .png).
    #[arg(long, value_name = "PREFIX")]
    pub plot: Option<crate::paths::OutputPrefix>,
    /// Write each bin's time, rate, model and residual to this CSV file.
    #[arg(long, value_name = "FILE.csv")]
    pub residuals: Option<OutputPath>,
    /// Run even when the work is long.
    #[arg(long)]
    pub force: bool,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// A train as `--train` gives it: wheels and pinions.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TrainSpec {
    /// Teeth, first arbor to escape wheel.
    pub wheels: Vec<u32>,
    /// Leaves, one fewer.
    pub pinions: Vec<u32>,
}

/// Reads `W,W,…:P,P,…` (the counts' sense, one pinion fewer than wheels
/// and none zero, is the library's to judge, as for every caller).
/// `--drop`: a time in ms, or `clock`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DropArg {
    /// Where a pendulum clock of the beat has it.
    Clock,
    /// This many ms.
    Ms(f64),
}

fn parse_drop(text: &str) -> Result<DropArg, String> {
    if text.trim() == "clock" {
        return Ok(DropArg::Clock);
    }
    text.parse::<Milliseconds>()
        .map(|m| DropArg::Ms(m.0))
        .map_err(|e| format!("{e}, or `clock`"))
}

/// `T:X` of `--strike`, `--chime` and `--handling`: a time and a count
/// (or a second time).
fn split_at_time(text: &str, what: &str) -> Result<(f64, String), String> {
    let (at, rest) = text
        .split_once(':')
        .ok_or(format!("expected T:{what}, e.g. 240:6"))?;
    let at = at.parse::<Time>().map_err(|e| e.to_string())?.0;
    Ok((at, rest.trim().to_string()))
}

fn count_of(text: &str, what: &str) -> Result<u32, String> {
    text.parse::<u32>()
        .map_err(|_| format!("{what} must be a whole number, got '{text}'"))
}

fn parse_strike(text: &str) -> Result<Interference, String> {
    let (at_s, n) = split_at_time(text, "N")?;
    Ok(Interference::Strike {
        at_s,
        blows: count_of(&n, "the blows")?,
    })
}

fn parse_chime(text: &str) -> Result<Interference, String> {
    let (at_s, n) = split_at_time(text, "N")?;
    Ok(Interference::Chime {
        at_s,
        notes: count_of(&n, "the notes")?,
    })
}

fn parse_handling(text: &str) -> Result<Interference, String> {
    let (at_s, d) = split_at_time(text, "D")?;
    let for_s = d.parse::<Time>().map_err(|e| e.to_string())?.0;
    Ok(Interference::Handling { at_s, for_s })
}

fn parse_train(text: &str) -> Result<TrainSpec, String> {
    let counts = |part: &str| -> Result<Vec<u32>, String> {
        if part.trim().is_empty() {
            return Ok(Vec::new());
        }
        part.split(',')
            .map(|c| {
                c.trim()
                    .parse::<u32>()
                    .map_err(|_| format!("'{}' is not a count of teeth", c.trim()))
            })
            .collect()
    };
    let (wheels, pinions) = text
        .split_once(':')
        .ok_or("expected wheels:pinions, e.g. 96,90,30:8,8")?;
    Ok(TrainSpec {
        wheels: counts(wheels)?,
        pinions: counts(pinions)?,
    })
}

/// `pendulum tide`.
#[derive(Debug, Args)]
pub struct TideArgs {
    /// Latitude, degrees north.
    #[arg(long, value_name = "DEG", allow_hyphen_values = true)]
    pub latitude: Angle,
    /// Longitude, degrees east.
    #[arg(long, value_name = "DEG", allow_hyphen_values = true)]
    pub longitude: Angle,
    /// Height above the ellipsoid [default: 0 m].
    #[arg(long, value_name = "H", allow_hyphen_values = true)]
    pub height: Option<Length>,
    /// The first time (ISO 8601, UTC unless an offset is given: 2026-01-01, 2026-01-01T06:00Z).
    #[arg(long, value_name = "DATETIME")]
    pub from: String,
    /// The last time (included when the steps reach it).
    #[arg(long, value_name = "DATETIME")]
    pub to: String,
    /// The step between rows.
    #[arg(long, value_name = "DURATION", allow_hyphen_values = true)]
    pub every: Time,
    /// Run even when the table is long (about 3·10⁵ rows, or a row a month
    /// or fewer over decades).
    #[arg(long)]
    pub force: bool,
    /// Print one JSON object ({"rows": [...]}).
    #[arg(long, conflicts_with = "csv")]
    pub json: bool,
    /// Print the rows as CSV.
    #[arg(long)]
    pub csv: bool,
}

/// `pendulum listen`.
#[derive(Debug, Args)]
pub struct ListenArgs {
    /// The recording (WAV, FLAC, Ogg, MP3, M4A), or - to listen live to
    /// standard input (a WAV stream, or raw samples with --raw).
    #[arg(value_name = "FILE")]
    pub file: InputPath,
    /// Standard input is raw samples in this layout: s16le, s24le, s32le
    /// or f32le (with --sample-rate, and --channels if not one).
    #[arg(long, value_name = "FORMAT", requires = "sample_rate")]
    pub raw: Option<String>,
    /// The raw samples' rate, Hz.
    #[arg(long, value_name = "HZ", allow_hyphen_values = true, requires = "raw")]
    pub sample_rate: Option<SampleRate>,
    /// The raw samples' channels, interleaved [default: 1].
    #[arg(long, value_name = "N", allow_hyphen_values = true, requires = "raw")]
    pub channels: Option<usize>,
    /// The nominal beat rate, beats per hour [default: found from the recording].
    #[arg(
        long,
        value_name = "B",
        allow_hyphen_values = true,
        conflicts_with = "period"
    )]
    pub bph: Option<BeatsPerHour>,
    /// The nominal period (two beats).
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub period: Option<Time>,
    /// The channel to listen to, from 1 [default: the one whose ticks
    /// stand out clearest; the first on standard input].
    #[arg(long, allow_hyphen_values = true, value_name = "N")]
    pub channel: Option<usize>,
    /// The sound card's clock error, ppm (positive: its clock runs fast).
    #[arg(long, value_name = "P", allow_hyphen_values = true)]
    pub sample_rate_error_ppm: Option<Ppm>,
    /// Measure the sound card's clock error on a recording, made through
    /// the same card, of a quartz watch or a GPS 1 PPS click (one tick a
    /// second), and apply it.
    #[arg(long, value_name = "FILE", conflicts_with = "sample_rate_error_ppm")]
    pub reference: Option<InputPath>,
    /// Write every tick to this CSV file (time_s,side,sound_level: the
    /// sound's peak, full scale 1; `amplitude` repeats it, its old name).
    #[arg(long, value_name = "FILE.csv")]
    pub ticks: Option<OutputPath>,
    /// The escapement's lift angle (degrees unless a unit is given): the
    /// pendulum's amplitude is found from the time between each beat's
    /// unlocking and drop sounds.
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub lift_angle: Option<Angle>,
    /// What swings, for the amplitude: a pendulum (its exact motion) or a
    /// balance wheel (harmonic) [default: a balance above 10,800 beats an
    /// hour].
    #[arg(long, value_name = "KIND")]
    pub oscillator: Option<String>,
    /// Draw the timegrapher's paper strip and the averaged tick and tock
    /// sounds (SVG or PNG by the extension; - for SVG on standard output).
    #[arg(long, value_name = "FILE.svg|FILE.png")]
    pub plot: Option<OutputPath>,
    /// Follow the clock over time: rate, beat error, amplitude and signal
    /// to noise in windows of this length (e.g. 5min), with their mean.
    #[arg(long, value_name = "DURATION", allow_hyphen_values = true)]
    pub every: Option<Time>,
    /// Write the windows of --every to this CSV file.
    #[arg(long, value_name = "OUT.csv", requires = "every")]
    pub windows: Option<OutputPath>,
    #[command(flatten)]
    pub advice: AdviceArgs,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// `pendulum synth`.
#[derive(Debug, Args)]
pub struct SynthArgs {
    /// What to make.
    #[command(subcommand)]
    pub what: SynthCommand,
}

/// The kinds of synthetic data.
#[derive(Debug, Subcommand)]
pub enum SynthCommand {
    /// A recording of a ticking clock (16-bit mono WAV) with known tick times.
    #[command(after_help = "Examples:
  pendulum synth ticks clock.wav --bph 3600 --rate 12s/day --beat-error 1.5ms --duration 10min
  pendulum synth ticks watch.wav --bph 18000 --rate -4s/day --snr-db 10dB --hum-db -20dB --truth truth.csv")]
    Ticks(SynthTicksArgs),
}

/// `pendulum synth ticks`.
#[derive(Debug, Args)]
pub struct SynthTicksArgs {
    /// The WAV file to write.
    #[arg(value_name = "OUT.wav")]
    pub output: OutputPath,
    #[arg(long, value_name = "B", allow_hyphen_values = true, help = with_default("Beats per hour", TickRecording::DEFAULT.beats_per_hour))]
    pub bph: Option<BeatsPerHour>,
    #[arg(long, value_name = "R", allow_hyphen_values = true, help = with_default("The clock's rate, s/day (positive: gaining)", TickRecording::DEFAULT.rate_s_per_day))]
    pub rate: Option<RatePerDay>,
    #[arg(long, value_name = "C", allow_hyphen_values = true, help = with_default("How fast the rate changes, s/day an hour (the rate at time t is --rate + C t / 1 h)", TickRecording::DEFAULT.rate_change_s_per_day_per_hour))]
    pub rate_change: Option<RateChange>,
    #[arg(long, value_name = "E", allow_hyphen_values = true, help = with_default("Beat error, ms (half the difference of the tick and tock intervals)", TickRecording::DEFAULT.beat_error_ms))]
    pub beat_error: Option<Milliseconds>,
    #[arg(long, value_name = "D", allow_hyphen_values = true, help = with_default("Length of the recording, s", TickRecording::DEFAULT.duration))]
    pub duration: Option<Time>,
    #[arg(long, value_name = "S", allow_hyphen_values = true, help = with_default("A tick's peak over the noise, dB", TickRecording::DEFAULT.snr_db))]
    pub snr_db: Option<Decibels>,
    #[arg(long, allow_hyphen_values = true, value_name = "HZ", help = with_default("Samples per second", TickRecording::DEFAULT.sample_rate))]
    pub sample_rate: Option<SampleRate>,
    #[arg(long, value_name = "T", allow_hyphen_values = true, help = with_default("Room reverberation time, s", TickRecording::DEFAULT.reverb_s))]
    pub reverb: Option<Time>,
    #[arg(long, value_name = "DB", allow_hyphen_values = true, help = with_default("Mains hum against a tick's peak, dB", TickRecording::DEFAULT.hum_db))]
    pub hum_db: Option<Decibels>,
    #[arg(long, value_name = "DB", allow_hyphen_values = true, help = with_default("The tock's level against the tick's, dB (-10: a third)", TickRecording::DEFAULT.tock_db))]
    pub tock_db: Option<Decibels>,
    #[arg(long, value_name = "F", allow_hyphen_values = true, help = with_default("Fraction of ticks left out", TickRecording::DEFAULT.missing))]
    pub missing: Option<Fraction>,
    /// The drop's time after the unlocking, ms, or `clock` for where a
    /// pendulum clock of this beat has it (a 1.5° lift crossed at a 2.5°
    /// swing)
    /// [default: 8-20 ms from the seed, a watch's].
    #[arg(long, value_name = "D", allow_hyphen_values = true, value_parser = parse_drop)]
    pub drop: Option<DropArg>,
    #[arg(long, value_name = "P", allow_hyphen_values = true, help = with_default("How fast the swing changes, % an hour (negative: the arc falls)", TickRecording::DEFAULT.arc_change_percent_per_hour))]
    pub arc_change: Option<Number>,
    #[arg(long, value_name = "E", allow_hyphen_values = true, help = with_default("A wheel's periodic error: ticks early and late by up to E, ms", TickRecording::DEFAULT.periodic_error_ms))]
    pub periodic_error: Option<Milliseconds>,
    #[arg(long, value_name = "T", allow_hyphen_values = true, help = with_default("The periodic error's period, s (a seconds clock's escape wheel: 60 s)", TickRecording::DEFAULT.periodic_error_period_s))]
    pub periodic_error_period: Option<Time>,
    /// The clock strikes N blows from T s (e.g. `240:6`); repeat for more.
    #[arg(long, value_name = "T:N", allow_hyphen_values = true, value_parser = parse_strike)]
    pub strike: Vec<Interference>,
    /// A chime of N notes from T s (e.g. `60:16`); repeat for more.
    #[arg(long, value_name = "T:N", allow_hyphen_values = true, value_parser = parse_chime)]
    pub chime: Vec<Interference>,
    /// The recorder handled from T s for D s (e.g. `0:10`); repeat for
    /// more.
    #[arg(long, value_name = "T:D", allow_hyphen_values = true, value_parser = parse_handling)]
    pub handling: Vec<Interference>,
    #[arg(long, value_name = "DB", allow_hyphen_values = true, help = with_default("The strikes', chimes' and handling's peak over a tick's, dB", pendulum_theory::listening::synth::DEFAULT_INTERFERENCE_DB))]
    pub interference_db: Option<Decibels>,
    #[arg(long, allow_hyphen_values = true, value_name = "N", help = with_default("Seed of every random choice (the tick's sound too)", TickRecording::DEFAULT.seed))]
    pub seed: Option<u64>,
    /// Write the true tick times to this CSV file (time_s).
    #[arg(long, value_name = "FILE.csv")]
    pub truth: Option<OutputPath>,
}

/// `pendulum report`.
#[derive(Debug, Args)]
pub struct ReportArgs {
    #[arg(long, value_name = "L", allow_hyphen_values = true, help = with_default("Pendulum length, m (a seconds pendulum)", pendulum_theory::report::DEFAULT_LENGTH_M))]
    pub length: Option<Length>,
    /// A pendulum designed as parts (TOML; see examples/*.toml): its
    /// equivalent simple length is used.
    #[arg(long, value_name = "FILE.toml", conflicts_with = "length")]
    pub design: Option<InputPath>,
    #[arg(long, value_name = "A", allow_hyphen_values = true, help = with_default("Working amplitude, °", pendulum_theory::report::DEFAULT_AMPLITUDE_DEG))]
    pub amplitude: Option<Angle>,
    /// Damping [default: Q = 10,000].
    #[command(flatten)]
    pub damping: DampingArgs,
    #[arg(long, value_name = "M", allow_hyphen_values = true, help = with_default("Bob mass for the energy budget, kg (a design's: its effective mass)", pendulum_theory::clock::analysis::DEFAULT_MASS_KG))]
    pub mass: Option<Mass>,
    /// A clock's log (as `pendulum log` reads it): its rate model,
    /// stability, spectrum and figures as a section of the page.
    #[arg(long, value_name = "FILE")]
    pub log: Option<InputPath>,
    /// The clock's longitude, degrees east: with --latitude, the log's
    /// tidal term.
    #[arg(long, value_name = "DEG", allow_hyphen_values = true, requires_all = ["log", "latitude"])]
    pub longitude: Option<Angle>,
    /// The log's events (a regulation, a rewinding), as `pendulum log
    /// --events` takes them.
    #[arg(long, value_name = "FILE", requires = "log")]
    pub events: Option<InputPath>,
    /// For the log's pulse widths: the flag's width (as `pendulum log`).
    #[arg(long, value_name = "W", allow_hyphen_values = true, requires_all = ["log", "gate_radius"])]
    pub flag_width: Option<Length>,
    /// For the log's pulse widths: the gate's distance from the pivot.
    #[arg(long, value_name = "R", allow_hyphen_values = true, requires_all = ["log", "flag_width"])]
    pub gate_radius: Option<Length>,
    /// The clock's going train, wheels:pinions (as `pendulum log`).
    #[arg(long, value_name = "W,…:P,…", value_parser = parse_train, requires = "log")]
    pub train: Option<TrainSpec>,
    #[arg(long, allow_hyphen_values = true, value_name = "N", requires = "train", help = with_default("Turns an hour of the train's first arbor", train_analysis::DEFAULT_ARBOR_TURNS_PER_HOUR))]
    pub arbor_turns_per_hour: Option<Number>,
    /// Folder to write index.html and its figures in: new, empty, or an
    /// earlier report's holding nothing else (of which only the files its
    /// .pendulum-report lists are removed).
    #[arg(long, value_name = "DIR", default_value = "pendulum-report")]
    pub output: std::path::PathBuf,
    #[command(flatten)]
    pub gravity: GravityArgs,
    /// Print the report's numbers as one JSON object instead of the page's
    /// path (the folder is written all the same).
    #[arg(long)]
    pub json: bool,
}

/// `pendulum fit`.
#[derive(Debug, Args)]
pub struct FitArgs {
    /// What the file holds.
    #[command(subcommand)]
    pub what: FitCommand,
}

/// The kinds of measurement `fit` reads.
#[derive(Debug, Subcommand)]
pub enum FitCommand {
    /// Amplitude against time or swing count: Q, and whether the damping is
    /// viscous, dry friction or air drag.
    #[command(after_help = "Examples:
  pendulum fit decay examples/rundown.csv --length 0.99362m --mass 5kg --plot decay.svg
  pendulum fit decay examples/rundown-semicolon.csv --length 0.99362m
  pendulum fit decay examples/tracker.txt --turning-points turns.csv --json")]
    Decay(FitDecayArgs),
    /// Angle against time (video tracking): amplitude, frequency, damping, offset, g.
    #[command(after_help = "Examples:
  pendulum fit trajectory examples/video.csv --length 0.5m --model nonlinear
  pendulum fit trajectory examples/tracker.txt --pivot fit --plot track.svg")]
    Trajectory(FitTrajectoryArgs),
    /// One timestamp per beat: rate, beat error, jitter, Allan deviation.
    #[command(after_help = "Examples:
  pendulum fit beats examples/beats.csv --bph 3600
  pendulum fit beats examples/beats.csv --period 2s --plot beats.svg --json")]
    Beats(FitBeatsArgs),
    /// A table of periods against amplitude (the exact law: T0, g, the
    /// circular error's coefficient) or against length (g and the offset
    /// of the lengths).
    #[command(after_help = "Examples:
  pendulum fit period crates/pendulum-cli/tests/data/period/silveira1986.csv --length 2.87m
  pendulum fit period crates/pendulum-cli/tests/data/period/hidayat2023.csv --plot g.svg")]
    Period(FitPeriodArgs),
}

/// How to read a measurement file: shared by the `fit` commands.
#[derive(Debug, Args)]
pub struct MeasurementArgs {
    /// The unit of angle or amplitude columns whose header names none.
    #[arg(long, value_name = "UNIT", value_parser = ["deg", "rad"])]
    pub angle_unit: Option<String>,
    /// Names of the columns of a file without a header, in order
    /// (e.g. time_s,angle_deg).
    #[arg(long, value_name = "NAMES")]
    pub columns: Option<String>,
    /// Rebuild the times as the row number over this frame rate (frames
    /// per second), for times exported rounded; or make them, for a file
    /// with no time column (a logger sampling at a fixed rate:
    /// --sample-rate HZ).
    #[arg(
        long,
        visible_alias = "sample-rate",
        value_name = "FPS",
        allow_hyphen_values = true
    )]
    pub frame_rate: Option<Hertz>,
    /// For x and y positions: the pivot, as X,Y in the file's units
    /// [default: 0,0], or `fit` for the centre of the circle the bob traces.
    #[arg(long, value_name = "X,Y|fit", allow_hyphen_values = true)]
    pub pivot: Option<String>,
    /// For x and y positions in image coordinates (pixels from OpenCV, a
    /// screen): y grows downward, and is turned to point up (a given
    /// --pivot is in the file's coordinates).
    #[arg(long)]
    pub y_down: bool,
    /// For x and y positions: metres per unit of the file (e.g. 0.00125 for
    /// 800 pixels a metre), so that the radius of a fitted pivot is a length.
    #[arg(long, value_name = "M", allow_hyphen_values = true)]
    pub scale: Option<Length>,
    /// Of a file whose times restart (runs one after another), read run N
    /// (from 1).
    #[arg(long, value_name = "N", allow_hyphen_values = true)]
    pub run: Option<u64>,
    /// Fit a file estimated to need more than a few seconds of computing
    /// (never one that would not end in a day).
    #[arg(long)]
    pub force: bool,
}

/// `pendulum fit decay`.
#[derive(Debug, Args)]
pub struct FitDecayArgs {
    /// Amplitudes against time (`time_s`, and `amplitude_deg`, `amplitude
    /// (rad)`, …), or against a count of swings (`swing`: a swing is a
    /// half period, one pass from side to side; a count of full swings,
    /// there and back, read as one would halve Q and double every rate),
    /// or a track (angle, or x and y, against time): CSV, semicolon, tab
    /// or space separated.
    #[arg(value_name = "FILE")]
    pub file: InputPath,
    #[command(flatten)]
    pub read: MeasurementArgs,
    #[arg(long, value_name = "LAW", help = with_default(&format!("Which decay law to fit: {}", pendulum_theory::fitting::rundown::model_names()), pendulum_theory::fitting::rundown::DEFAULT_MODEL))]
    pub model: Option<String>,
    /// Pendulum length: turns rates into ζ, Q, friction angle and drag
    /// (needed for a swing column); with a track, g from its turning
    /// points' times.
    #[arg(long, value_name = "L", allow_hyphen_values = true)]
    pub length: Option<Length>,
    /// The standard uncertainty of --length (or of --design's length):
    /// in g's standard error, listed beside the fit's part. Without it g's
    /// ± is the turning times' alone.
    #[arg(long, value_name = "L", allow_hyphen_values = true)]
    pub length_uncertainty: Option<Length>,
    /// A pendulum designed as parts (TOML; see examples/*.toml), in place
    /// of --length: its equivalent length, and its effective mass M d / l
    /// for the energy budget.
    #[arg(long, value_name = "FILE.toml", conflicts_with = "length")]
    pub design: Option<InputPath>,
    /// Bob mass, for the energy lost per period and the power (with --length).
    #[arg(long, value_name = "M", allow_hyphen_values = true)]
    pub mass: Option<Mass>,
    /// The period (there and back: two swings), to turn rates into ζ, Q,
    /// friction angle and drag, and a swing column (half periods) into
    /// time [default: from the turning points of a track, else from
    /// --length].
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub period: Option<Time>,
    /// With a track (angle or x/y against time): write the turning points
    /// found to this CSV file (time_s,amplitude_rad,side).
    #[arg(long, value_name = "FILE.csv")]
    pub turning_points: Option<OutputPath>,
    #[command(flatten)]
    pub gravity: GravityArgs,
    /// Plot the data, the fitted curves and the residuals to this file (.svg or .png).
    #[arg(long, value_name = "FILE")]
    pub plot: Option<OutputPath>,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// `pendulum fit trajectory`.
#[derive(Debug, Args)]
pub struct FitTrajectoryArgs {
    /// Angle against time (`time_s`, `t`, `Time (s)` and `angle_deg`,
    /// `θ (rad)`, …), tracked positions `x`, `y` (a Tracker export), or a
    /// gyroscope's angular velocity (phyphox's `Gyroscope x (rad/s)`, …,
    /// CSV or its Excel workbook), fitted by the models' derivative.
    #[arg(value_name = "FILE")]
    pub file: InputPath,
    #[command(flatten)]
    pub read: MeasurementArgs,
    /// Fit from this time on (s from the record's first sample, as the plot
    /// shows it): leave out a release by hand.
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub from: Option<Time>,
    /// Fit up to this time (s from the record's first sample): leave out
    /// the bob caught at the end.
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub to: Option<Time>,
    /// Pendulum length, to give g.
    #[arg(long, value_name = "L", allow_hyphen_values = true)]
    pub length: Option<Length>,
    /// The standard uncertainty of --length (or of --design's length):
    /// in g's standard error, listed beside the fit's part. Without it g's
    /// ± is the fit's alone.
    #[arg(long, value_name = "L", allow_hyphen_values = true)]
    pub length_uncertainty: Option<Length>,
    /// A pendulum designed as parts (TOML), in place of --length: g from
    /// its equivalent length.
    #[arg(long, value_name = "FILE.toml", conflicts_with = "length")]
    pub design: Option<InputPath>,
    #[arg(long, value_name = "MODEL", help = with_default("Section 1-4's closed form (linear), the nonlinear equation integrated inside the fit (nonlinear), or auto: nonlinear when the largest swing exceeds 5°", pendulum_theory::fitting::tracked::DEFAULT_MODEL))]
    pub model: Option<String>,
    #[arg(long, value_name = "LAW", help = drag_law_help())]
    pub drag_law: Option<String>,
    /// Write the residuals to this CSV file (time_s,residual_rad).
    #[arg(long, value_name = "FILE.csv")]
    pub residuals: Option<OutputPath>,
    /// Plot the data, the fitted curves and the residuals to this file (.svg or .png).
    #[arg(long, value_name = "FILE")]
    pub plot: Option<OutputPath>,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// `pendulum fit period`.
#[derive(Debug, Args)]
pub struct FitPeriodArgs {
    /// Periods (`period_s`, `T (s)`) against amplitude (`amplitude_deg`,
    /// `release_angle (rad)`) or length (`length_m`, `L (cm)`), with their
    /// uncertainties if measured (`period_err_s`, or an `error` column
    /// right after the periods).
    #[arg(value_name = "FILE")]
    pub file: InputPath,
    /// The unit of amplitude columns whose header names none.
    #[arg(long, value_name = "UNIT", value_parser = ["deg", "rad"])]
    pub angle_unit: Option<String>,
    /// Names of the columns of a file without a header, in order
    /// (e.g. amplitude_deg,period_s,period_err_s).
    #[arg(long, value_name = "NAMES")]
    pub columns: Option<String>,
    /// The pendulum's length, for a table against amplitude: gives g.
    #[arg(long, value_name = "L", allow_hyphen_values = true)]
    pub length: Option<Length>,
    /// The standard uncertainty of --length, carried into g's.
    #[arg(
        long,
        value_name = "L",
        allow_hyphen_values = true,
        requires = "length"
    )]
    pub length_uncertainty: Option<Length>,
    /// The radius of a spherical bob whose centre the lengths reach: each
    /// length becomes the physical pendulum's, L + 2r²/(5L).
    #[arg(long, value_name = "R", allow_hyphen_values = true)]
    pub bob_radius: Option<Length>,
    /// Plot the periods and the fitted law to this file (.svg or .png).
    #[arg(long, value_name = "FILE")]
    pub plot: Option<OutputPath>,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// `pendulum fit beats`.
#[derive(Debug, Args)]
pub struct FitBeatsArgs {
    /// One time per beat (`time_s`, `t`, `Time (s)`, …).
    #[arg(value_name = "FILE")]
    pub file: InputPath,
    /// Names of the columns of a file without a header, in order (e.g. time_s).
    #[arg(long, value_name = "NAMES")]
    pub columns: Option<String>,
    /// Of a file whose times restart (runs one after another), read run N
    /// (from 1).
    #[arg(long, value_name = "N", allow_hyphen_values = true)]
    pub run: Option<u64>,
    /// For a photogate log whose times count a clock's ticks: the clock's
    /// rate, ticks a second.
    #[arg(long, value_name = "HZ", allow_hyphen_values = true)]
    pub tick_rate: Option<Hertz>,
    /// For a log of several light gates (a `gate` column): the gate to
    /// read, by its label [default: the first logged].
    #[arg(long, value_name = "LABEL")]
    pub gate: Option<String>,
    /// For a photogate log of both edges of each shadow: the bob's
    /// diameter, to give its speed at the gate.
    #[arg(long, value_name = "D", allow_hyphen_values = true)]
    pub bob_diameter: Option<Length>,
    /// The nominal beat rate, beats per hour [default: the nearest standard rate].
    #[arg(
        long,
        value_name = "B",
        allow_hyphen_values = true,
        conflicts_with = "period"
    )]
    pub bph: Option<BeatsPerHour>,
    /// The nominal period (two beats).
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub period: Option<Time>,
    /// Plot the data, the fitted curves and the residuals to this file (.svg or .png).
    #[arg(long, value_name = "FILE")]
    pub plot: Option<OutputPath>,
    #[command(flatten)]
    pub advice: AdviceArgs,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// Where g comes from: given, from latitude and height, or standard gravity.
#[derive(Debug, Args)]
pub struct GravityArgs {
    /// Gravitational acceleration [default: 9.80665 m/s²].
    #[arg(
        long = "g",
        value_name = "G",
        allow_hyphen_values = true,
        conflicts_with = "latitude"
    )]
    pub g: Option<Acceleration>,
    /// Latitude in degrees (north positive), to compute g (WGS 84).
    #[arg(long, value_name = "DEG", allow_hyphen_values = true)]
    pub latitude: Option<Angle>,
    /// Height above the ellipsoid, with --latitude [default: 0 m].
    #[arg(
        long,
        value_name = "H",
        allow_hyphen_values = true,
        requires = "latitude"
    )]
    pub height: Option<Length>,
}

/// Output format flags shared by the commands.
#[derive(Debug, Args)]
pub struct FormatArgs {
    /// Print one JSON object (SI units, angles in radians).
    #[arg(long, conflicts_with = "csv")]
    pub json: bool,
    /// Print CSV with a header (same names as the JSON keys).
    #[arg(long)]
    pub csv: bool,
}

/// `pendulum period`.
#[derive(Debug, Args)]
pub struct PeriodArgs {
    #[command(flatten)]
    pub pendulum: PendulumArgs,
    /// Amplitude (e.g. 3deg, 0.05rad), or a range 1deg..10deg for a table.
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub amplitude: String,
    /// Rows in the table when --amplitude is a range (at least 2), evenly
    /// spaced [default: a round step of degrees giving at least 10 rows].
    #[arg(
        long,
        allow_hyphen_values = true,
        value_name = "N",
        conflicts_with = "step"
    )]
    pub steps: Option<u32>,
    /// The spacing of the table's rows when --amplitude is a range (e.g.
    /// 5deg): rows from the first amplitude while within the last.
    #[arg(long, allow_hyphen_values = true, value_name = "A")]
    pub step: Option<Angle>,
    /// The CSV's columns, in order (e.g. amplitude_deg,period_s,circular_error_s_per_day)
    /// [default: all].
    #[arg(long, value_name = "NAMES", requires = "csv")]
    pub columns: Option<String>,
    #[arg(long, allow_hyphen_values = true, value_name = "N", help = with_default("Terms of the power series of K in sin²(A0/2) (section 1-6) to compare with", period_table::DEFAULT_SERIES_TERMS))]
    pub series_terms: Option<u32>,
    /// Plot T/T0 (exact, series of 1 to 5 terms, small-angle) and the
    /// circular error against amplitude to this file (.svg or .png).
    #[arg(long, value_name = "FILE")]
    pub plot: Option<OutputPath>,
    #[command(flatten)]
    pub gravity: GravityArgs,
    #[command(flatten)]
    pub format: FormatArgs,
}

/// `pendulum length`.
#[derive(Debug, Args)]
pub struct LengthArgs {
    /// The period wanted (e.g. 2s).
    #[arg(
        long,
        value_name = "T",
        allow_hyphen_values = true,
        required_unless_present = "bph",
        conflicts_with = "bph"
    )]
    pub period: Option<Time>,
    /// The beat rate wanted, beats per hour (a beat is half a period).
    #[arg(long, value_name = "B", allow_hyphen_values = true)]
    pub bph: Option<BeatsPerHour>,
    /// The amplitude it will swing at [default: 0, the small-angle limit].
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub amplitude: Option<Angle>,
    #[command(flatten)]
    pub gravity: GravityArgs,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// `pendulum amplitude`.
#[derive(Debug, Args)]
pub struct AmplitudeArgs {
    /// The measured period (e.g. 2.0002s).
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub period: Time,
    #[command(flatten)]
    pub pendulum: PendulumArgs,
    /// Uncertainty of the measured period, to report the amplitude's.
    #[arg(long, value_name = "DT", allow_hyphen_values = true)]
    pub period_uncertainty: Option<Time>,
    #[command(flatten)]
    pub gravity: GravityArgs,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// `pendulum gravity`.
#[derive(Debug, Args)]
pub struct GravityCommandArgs {
    /// Latitude in degrees (north positive).
    #[arg(long, value_name = "DEG", allow_hyphen_values = true)]
    pub latitude: Angle,
    /// Height above the ellipsoid [default: 0 m].
    #[arg(long, value_name = "H", allow_hyphen_values = true)]
    pub height: Option<Length>,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// The pendulum, as a length or as a design: shared by the commands that
/// need one.
#[derive(Debug, Args)]
pub struct PendulumArgs {
    /// Pendulum length (e.g. 0.99362m, 994mm, 39.1in).
    #[arg(
        long,
        value_name = "L",
        allow_hyphen_values = true,
        required_unless_present = "design"
    )]
    pub length: Option<Length>,
    /// A pendulum designed as parts (TOML; see examples/*.toml), in place
    /// of --length: its equivalent simple length is used.
    #[arg(long, value_name = "FILE.toml", conflicts_with = "length")]
    pub design: Option<InputPath>,
}

/// The rating nut's thread: shared by `regulate` and the advice.
#[derive(Debug, Default, Args)]
pub struct NutArgs {
    /// The rating nut's thread pitch (e.g. 0.7mm), for its turns.
    #[arg(long, allow_hyphen_values = true, value_name = "P")]
    pub nut_pitch: Option<Length>,
    /// The rating nut's threads per inch, for its turns.
    #[arg(long, allow_hyphen_values = true, value_name = "N")]
    pub nut_tpi: Option<ThreadsPerInch>,
    /// Divisions engraved round the nut.
    #[arg(long, allow_hyphen_values = true, value_name = "N")]
    pub nut_divisions: Option<u32>,
}

impl NutArgs {
    /// The thread as the library takes it.
    pub fn nut(&self) -> pendulum_theory::compound::regulate::Nut {
        pendulum_theory::compound::regulate::Nut {
            pitch: self.nut_pitch.map(|p| p.0),
            tpi: self.nut_tpi.map(|t| t.0),
            divisions: self.nut_divisions,
        }
    }
}

/// What is known of the clock, for the advice that ends `listen` and
/// `fit beats`: every flag optional.
#[derive(Debug, Args)]
#[command(next_help_heading = "Advice (how to move the bob, the nut and the crutch)")]
pub struct AdviceArgs {
    /// The pendulum's length [default: the simple pendulum of the beat, said].
    #[arg(long, value_name = "L", allow_hyphen_values = true)]
    pub length: Option<Length>,
    /// The pendulum designed as parts (TOML), in place of --length.
    #[arg(long, value_name = "FILE.toml", conflicts_with = "length")]
    pub design: Option<InputPath>,
    #[command(flatten)]
    pub nut: NutArgs,
    /// From the pendulum's pivot down to the crutch's pin, for the move there.
    #[arg(long, allow_hyphen_values = true, value_name = "D")]
    pub crutch: Option<Length>,
    /// The swing either side as you see it (degrees unless a unit is given) [default: heard with --lift-angle where a clock can swing so, else 2.5° (a balance: 270°), said].
    #[arg(long, allow_hyphen_values = true, value_name = "A")]
    pub amplitude: Option<Angle>,
}

/// One way to give viscous damping (at most one; `damped` needs one).
#[derive(Debug, Args)]
#[group(required = false, multiple = false)]
pub struct DampingArgs {
    /// Damping ratio ζ (1 = critical damping).
    #[arg(long, value_name = "Z", allow_hyphen_values = true)]
    pub zeta: Option<Number>,
    /// Quality factor Q = 1/(2ζ).
    #[arg(long, value_name = "Q", allow_hyphen_values = true)]
    pub q: Option<Number>,
    /// The viscous damping coefficient c in N s (force on the bob c dθ/dt); needs --mass.
    #[arg(long, value_name = "C", allow_hyphen_values = true)]
    pub damping_coefficient: Option<Number>,
    /// Logarithmic decrement of the amplitude per full period.
    #[arg(long, value_name = "D", allow_hyphen_values = true)]
    pub log_decrement: Option<Number>,
    /// Time for the amplitude to fall by a factor e (e.g. 2h).
    #[arg(long, value_name = "TAU", allow_hyphen_values = true)]
    pub decay_time: Option<Time>,
}

/// A pendulum released from rest and what slows it: shared by `damped`
/// and `simulate`.
#[derive(Debug, Args)]
pub struct SwingArgs {
    #[command(flatten)]
    pub pendulum: PendulumArgs,
    /// Amplitude it is released from, at rest.
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub amplitude: Angle,
    #[command(flatten)]
    pub damping: DampingArgs,
    /// Coulomb friction angle r (friction torque / restoring torque per radian), e.g. 0.01deg.
    #[arg(long, value_name = "R", allow_hyphen_values = true)]
    pub friction_angle: Option<Angle>,
    /// Bob mass, for the energy budget and with --damping-coefficient.
    #[arg(long, value_name = "M", allow_hyphen_values = true)]
    pub mass: Option<Mass>,
    #[command(flatten)]
    pub gravity: GravityArgs,
}

/// `pendulum damped`.
#[derive(Debug, Args)]
pub struct DampedArgs {
    #[command(flatten)]
    pub swing: SwingArgs,
    #[arg(long, allow_hyphen_values = true, value_name = "N", help = with_default("How many turning points to list after the start", pendulum_theory::damped::analysis::DEFAULT_EXTREMA))]
    pub extrema: Option<u64>,
    /// Write the motion to this CSV file (time_s,angle_rad,angular_velocity_rad_s).
    #[arg(long, value_name = "FILE.csv")]
    pub trajectory: Option<OutputPath>,
    /// How long a trajectory to write [default: 10 small-angle periods].
    #[arg(
        long,
        value_name = "D",
        allow_hyphen_values = true,
        requires = "trajectory"
    )]
    pub duration: Option<Time>,
    /// Time between trajectory samples [default: a hundredth of the small-angle period].
    #[arg(
        long,
        value_name = "H",
        allow_hyphen_values = true,
        requires = "trajectory"
    )]
    pub sample_interval: Option<Time>,
    /// Allow more than 10^8 trajectory samples or 10^5 turning points.
    #[arg(long)]
    pub force: bool,
    /// Plot θ(t) with its envelope and turning points to this file (.svg or .png).
    #[arg(long, value_name = "FILE")]
    pub plot: Option<OutputPath>,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// Integration methods for `simulate`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum MethodArg {
    /// Dormand-Prince 8(5,3), adaptive, 7th-order dense output.
    Dop853,
    /// Verner 9(8), adaptive: for tight tolerances (events by re-stepping).
    Vern9,
    /// Yoshida 6th-order symplectic with exact damping: for very long runs.
    Symplectic,
    /// The closed form (no damping).
    Exact,
    /// One step per half swing, closed form (viscous damping only): weeks to years of turning points.
    Averaged,
}

/// `pendulum simulate`.
#[derive(Debug, Args)]
pub struct SimulateArgs {
    #[command(flatten)]
    pub swing: SwingArgs,
    /// Quadratic air drag b in θ'' = … - b θ'|θ'| (per radian).
    #[arg(long, value_name = "B", allow_hyphen_values = true)]
    pub quadratic_drag: Option<Number>,
    #[arg(long, value_name = "NAME=VALUE", allow_hyphen_values = true, help = drag_laws_help())]
    pub drag: Vec<String>,
    /// How long to simulate (e.g. 7day, 600s).
    #[arg(long, value_name = "D", allow_hyphen_values = true)]
    pub duration: Time,
    #[arg(long, value_enum, help = with_default("Integration method", pendulum_theory::simulation::analysis::DEFAULT_METHOD))]
    pub method: Option<MethodArg>,
    /// Local error tolerance of each step, relative to the size of the
    /// swing [default: the library's, 1e-10].
    #[arg(long, value_name = "TOL", allow_hyphen_values = true)]
    pub tolerance: Option<Number>,
    /// Write every turning point to this CSV file.
    #[arg(long, value_name = "FILE.csv")]
    pub swings: Option<OutputPath>,
    /// Write the motion, sampled every --sample-interval, to this CSV file.
    #[arg(long, value_name = "FILE.csv")]
    pub trajectory: Option<OutputPath>,
    /// Time between trajectory samples [default: a hundredth of the small-angle period].
    #[arg(
        long,
        value_name = "H",
        allow_hyphen_values = true,
        requires = "trajectory"
    )]
    pub sample_interval: Option<Time>,
    /// Allow a duration over 10^9 s, more than 10^8 samples, or a run
    /// estimated to take more than a few seconds.
    #[arg(long)]
    pub force: bool,
    /// Plot the amplitude and the rate against time to this file (.svg or .png).
    #[arg(long, value_name = "FILE")]
    pub plot: Option<OutputPath>,
    /// Plot the phase portrait, θ' against θ, to this file (.svg or .png).
    #[arg(long, value_name = "FILE")]
    pub phase_plot: Option<OutputPath>,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn command_definition_is_consistent() {
        Cli::command().debug_assert();
    }
}

/// `pendulum train`.
#[derive(Debug, Args)]
pub struct TrainArgs {
    /// Wheel counts, the first on the arbor of --arbor-turns-per-hour, the
    /// last the escape wheel (e.g. 64,60,30).
    #[arg(
        long,
        value_name = "W,W,…",
        value_delimiter = ',',
        requires = "pinions"
    )]
    pub wheels: Vec<u32>,
    /// Pinion counts, one fewer than the wheels (e.g. 8,8).
    #[arg(long, value_name = "P,P,…", value_delimiter = ',')]
    pub pinions: Vec<u32>,
    #[arg(long, allow_hyphen_values = true, value_name = "N", help = with_default("Turns an hour of the first wheel's arbor", train_analysis::DEFAULT_ARBOR_TURNS_PER_HOUR))]
    pub arbor_turns_per_hour: Option<Number>,
    /// Find trains for this beat rate instead (beats per hour).
    #[arg(
        long,
        allow_hyphen_values = true,
        value_name = "B",
        conflicts_with = "wheels"
    )]
    pub bph: Option<BeatsPerHour>,
    #[arg(long, allow_hyphen_values = true, value_name = "N", help = with_default("The escape wheel's teeth, for --bph", train_analysis::DEFAULT_ESCAPE_TEETH))]
    pub escape_teeth: Option<u32>,
    #[arg(long, allow_hyphen_values = true, value_name = "X", help = with_default("Relative tolerance on --bph", train_analysis::DEFAULT_TOLERANCE))]
    pub tolerance: Option<Number>,
    /// A pendulum design: say where its bob must sit for the train's beat.
    #[arg(long, value_name = "FILE.toml")]
    pub design: Option<InputPath>,
    #[command(flatten)]
    pub gravity: GravityArgs,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// `pendulum regulate`.
#[derive(Debug, Args)]
pub struct RegulateArgs {
    /// The clock's rate now (positive: gaining), e.g. +12s/day or -30.
    #[arg(long, value_name = "R", allow_hyphen_values = true)]
    pub rate: RatePerDay,
    /// Pendulum length (e.g. 0.99362m, 994mm, 39.1in).
    #[arg(
        long,
        value_name = "L",
        allow_hyphen_values = true,
        required_unless_present_any = ["design", "bph"]
    )]
    pub length: Option<Length>,
    /// A pendulum designed as parts (TOML; see examples/*.toml), in place
    /// of --length: its equivalent simple length is used.
    #[arg(long, value_name = "FILE.toml", conflicts_with_all = ["length", "bph"])]
    pub design: Option<InputPath>,
    /// The clock's beat rate, beats an hour, in place of --length: the
    /// simple pendulum of that beat is used (3600: a seconds pendulum).
    #[arg(
        long,
        value_name = "B",
        allow_hyphen_values = true,
        conflicts_with = "length"
    )]
    pub bph: Option<BeatsPerHour>,
    #[arg(long, value_name = "NAME", help = with_default("The part the nut moves (with what rests on it)", format_args!("the design's threaded part, else {}, else the bob", pendulum_theory::compound::regulate::DEFAULT_PART)))]
    pub part: Option<String>,
    #[command(flatten)]
    pub nut: NutArgs,
    /// Where a regulating tray sits below the pivot [default: a third of the length] (with --design).
    #[arg(long, value_name = "D", allow_hyphen_values = true)]
    pub tray: Option<Length>,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// `pendulum compensate`.
#[derive(Debug, Args)]
pub struct CompensateArgs {
    /// The pendulum design (TOML).
    #[arg(long, value_name = "FILE.toml")]
    pub design: InputPath,
    /// What to size: a tube of a material under the bob (zinc, aluminium,
    /// brass, ...; `collar`: a brass collar), a tube inside a tube
    /// (`zinc-steel`: zinc on the nut, steel hanging from its top carrying
    /// the bob), `gridiron` (steel and brass rods in place of the rod), or
    /// `mercury` (a jar of mercury in place of the bob).
    #[arg(long, value_name = "KIND")]
    pub compensator: Option<String>,
    #[arg(long, value_name = "NAME", help = with_default("The part the tube goes under, or the jar replaces (it must rest on the nut)", pendulum_theory::compound::compensate::DEFAULT_PART))]
    pub part: Option<String>,
    /// The mercury jar's material [default: glass].
    #[arg(long, value_name = "MATERIAL")]
    pub jar_material: Option<String>,
    /// The mercury jar's outer diameter [default: the bob's, or 60 mm].
    #[arg(long, value_name = "D", allow_hyphen_values = true)]
    pub jar_diameter: Option<Length>,
    /// The mercury jar's wall (and bottom) thickness [default: 4 mm].
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    pub jar_wall: Option<Length>,
    /// Write the compensated design to this TOML file (`-`: standard output).
    #[arg(long, value_name = "FILE.toml")]
    pub write: Option<OutputPath>,
    /// The tube's outer diameter [default: the bore and 3 mm, a 1.5 mm wall].
    #[arg(long, value_name = "D", allow_hyphen_values = true)]
    pub tube_diameter: Option<Length>,
    /// The tube's bore [default: the rod's diameter and 1 mm].
    #[arg(long, value_name = "D", allow_hyphen_values = true)]
    pub tube_bore: Option<Length>,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// `pendulum clock`.
#[derive(Debug, Args)]
pub struct ClockArgs {
    #[command(flatten)]
    pub pendulum: PendulumArgs,
    #[arg(long, value_name = "M", allow_hyphen_values = true, help = with_default("Bob mass, kg (with --design its effective mass M d / l)", clock::DEFAULT_MASS_KG))]
    pub mass: Option<Mass>,
    #[arg(long, value_name = "Q", allow_hyphen_values = true, help = with_default("Quality factor of the free pendulum", clock::DEFAULT_Q))]
    pub q: Option<Number>,
    #[arg(long, value_name = "NAME=VALUE", allow_hyphen_values = true, help = clock_drag_help())]
    pub drag: Vec<String>,
    /// The escapement [default: deadbeat].
    #[arg(long, value_parser = escapement_parser())]
    pub escapement: Option<EscapementKind>,
    #[arg(long, value_name = "A", allow_hyphen_values = true, help = with_default("The lift angle, the whole angle over which the escapement impulses (a bare number is degrees)", clock::DEFAULT_LIFT_DEG))]
    pub lift_angle: Option<Angle>,
    /// The drive: the torque at the pallets (e.g. 2e-4Nm) or the energy
    /// per beat (e.g. 20uJ; the torque is that over the lift). For
    /// impulse and free: the energy of each impulse; for constant-force,
    /// the impulse, while the train's drive only adds locking friction.
    #[arg(long, value_name = "DRIVE", allow_hyphen_values = true)]
    pub drive: Drive,
    #[arg(long, value_name = "MU", allow_hyphen_values = true, help = with_default("Pallet friction coefficient: on the dead (locking) faces of deadbeat and constant-force, on the recoil faces of recoil", clock::DEFAULT_FRICTION))]
    pub friction: Option<Number>,
    #[arg(long, value_name = "R", allow_hyphen_values = true, help = with_default("Recoil: the torque the wheel gives back through the recoil arc, over the impulse torque (1: one straight face)", clock::DEFAULT_RECOIL))]
    pub recoil: Option<Number>,
    #[arg(long, value_name = "A", allow_hyphen_values = true, help = with_default("Where the impulse falls before the bottom (negative: after): for impulse and free the impulse's angle, for deadbeat the lift's centre (degrees)", clock::DEFAULT_IMPULSE_ANGLE_DEG))]
    pub impulse_angle: Option<Angle>,
    #[arg(long, allow_hyphen_values = true, value_name = "N", help = with_default("Free pendulum: beats between impulses (Shortt's)", clock::DEFAULT_EVERY_BEATS))]
    pub every_beats: Option<u64>,
    /// Out of beat: the beat error the ticks show (e.g. 20ms, half the
    /// difference of the tick and tock intervals, as `listen` measures it)
    /// or the escapement's offset from the pendulum's rest (e.g. 0.3deg)
    /// [default: in beat].
    #[arg(long, value_name = "B", allow_hyphen_values = true)]
    pub beat_error: Option<BeatError>,
    /// The isochronism curve: drive factors from..to (e.g. 0.5x..2x).
    #[arg(long, value_name = "A..B", allow_hyphen_values = true)]
    pub drive_range: Option<String>,
    #[arg(long, allow_hyphen_values = true, value_name = "N", help = with_default("Points on the isochronism curve", clock::DEFAULT_STEPS))]
    pub steps: Option<usize>,
    /// A long run of this length (e.g. 8days, 1year).
    #[arg(long, value_name = "D", allow_hyphen_values = true)]
    pub duration: Option<Time>,
    /// With --duration: a row this often (e.g. 1h, 1day) [default: every turning point].
    #[arg(
        long,
        value_name = "E",
        allow_hyphen_values = true,
        requires = "duration"
    )]
    pub every: Option<Time>,
    /// With --duration: what changes with time (CSV: time_s and any of
    /// drive_factor; rate_change_s_per_day, a change of rate from outside,
    /// positive gaining; or, with --design, moving the rate by its
    /// coefficients, temperature_c, pressure_hpa, humidity_percent,
    /// gradient_k_per_m), linear between rows.
    #[arg(long, value_name = "FILE.csv", requires = "duration")]
    pub drive_file: Option<InputPath>,
    /// The gas the --drive-file's pressure_hpa is of: air, nitrogen or
    /// helium (a tank's pressure schedule) [default: air]. The pressure
    /// moves the rate (buoyancy, carried gas) and the damping, so the arc.
    #[arg(long, value_name = "GAS", requires = "drive_file")]
    pub gas: Option<String>,
    /// With --duration: write the rows (time_s,beats,amplitude_rad,rate_s_per_day,time_error_s,drive_factor).
    #[arg(long, value_name = "FILE.csv", requires = "duration")]
    pub swings: Option<OutputPath>,
    /// With --duration: run a long run estimated at more than a few
    /// seconds (never one that would not end in a day or fit the disk).
    #[arg(long, requires = "duration")]
    pub force: bool,
    #[command(flatten)]
    pub gravity: GravityArgs,
    /// Plot the isochronism curve (with --drive-range) or the long run (.svg or .png).
    #[arg(long, value_name = "FILE")]
    pub plot: Option<OutputPath>,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// The escapements of `pendulum clock`: the library's list, with each
/// one's help.
fn escapement_parser() -> impl clap::builder::TypedValueParser<Value = EscapementKind> {
    use clap::builder::TypedValueParser;
    use pendulum_theory::clock::escapement::spec::ESCAPEMENTS;
    clap::builder::PossibleValuesParser::new(ESCAPEMENTS.iter().map(|e| {
        clap::builder::PossibleValue::new(e.name)
            .help(e.help)
            .aliases(e.aliases.iter().copied())
    }))
    .map(|name| EscapementKind::from_name(&name).expect("a name of the list"))
}

/// `pendulum design`.
#[derive(Debug, Args)]
pub struct DesignArgs {
    /// The pendulum design (TOML).
    #[arg(value_name = "FILE.toml")]
    pub file: InputPath,
    #[arg(long, allow_hyphen_values = true, value_name = "P", help = with_default("Air pressure, hPa", sheet::DEFAULT_PRESSURE_PA / 100.0))]
    pub pressure: Option<Hectopascals>,
    #[arg(long, value_name = "T", allow_hyphen_values = true, help = with_default("Temperature, °C", sheet::DEFAULT_TEMPERATURE_C))]
    pub temperature: Option<Celsius>,
    #[arg(long, value_name = "T", allow_hyphen_values = true, help = with_default("The temperature the clock was regulated at, °C", sheet::DEFAULT_TEMPERATURE_C))]
    pub regulated_at: Option<Celsius>,
    #[arg(long, allow_hyphen_values = true, value_name = "H", help = with_default("Relative humidity, % (air only)", sheet::DEFAULT_HUMIDITY * 100.0))]
    pub humidity: Option<Percent>,
    /// The gas it swings in: air, nitrogen or helium, 1 Pa to 1.2 bar
    /// (a Shortt tank: --gas nitrogen --pressure 27hPa) [default: air].
    #[arg(long, value_name = "GAS")]
    pub gas: Option<String>,
    /// The Q its pivot or suspension and escapement alone would give (in
    /// a vacuum), to add to the gas's damping [default: the gas alone].
    #[arg(long, value_name = "Q", allow_hyphen_values = true)]
    pub pivot_q: Option<f64>,
    /// The semi-arc it swings at this pressure: gives the arc a drive
    /// keeps at other pressures, the circular error's share of the
    /// barometric error, and the arc at which the two cancel.
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    pub amplitude: Option<Angle>,
    #[command(flatten)]
    pub gravity: GravityArgs,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// A flag's help with the library's default at its end, so the default is
/// shown without the command line holding one.
fn with_default(help: &str, default: impl std::fmt::Display) -> String {
    format!("{help} [default: {default}]")
}

/// The help of `fit trajectory --drag-law`: the library's drag laws, the
/// ones it tries unnamed first.
fn drag_law_help() -> String {
    use pendulum_theory::simulation::forces::DRAG_LAWS;
    let names = |searched: bool| -> Vec<&str> {
        DRAG_LAWS
            .iter()
            .filter(|l| l.searched() == searched)
            .map(|l| l.name())
            .collect()
    };
    format!(
        "The drag law the nonlinear fit tries beside viscous damping and dry friction (kept \
         where the information criterion prefers it): {}, or {} [default: {}]",
        names(true).join(", "),
        names(false).join(", "),
        names(true).join(", ")
    )
}

/// The help of `clock --drag`: the simulation's drag laws, beside the Q.
fn clock_drag_help() -> String {
    format!(
        "{}; beside the viscous damping of --q, in the integrated half swings and the long \
         run alike",
        drag_laws_help()
    )
}

/// The help of `--drag`: the library's drag laws, each with its
/// coefficient.
fn drag_laws_help() -> String {
    let laws: Vec<String> = pendulum_theory::simulation::forces::DRAG_LAWS
        .iter()
        .map(|l| format!("{} ({})", l.name(), l.describe()))
        .collect();
    format!(
        "A drag law and its coefficient, NAME=VALUE (repeat for more): {}",
        laws.join(", ")
    )
}
