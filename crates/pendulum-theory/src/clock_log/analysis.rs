//! One call for a clock's log, in named stages: read ([`super::input`]),
//! jumps and outliers ([`super::jumps`]), bins ([`super::series`]), the
//! design from the table of terms ([`super::terms`]), the lag and the
//! choice of terms ([`super::choice`]), the fit and the noise
//! ([`super::model`]), its checks ([`super::checks`]), the periodic
//! errors of what the model leaves ([`super::periodic`]), and stability.

use super::checks::{check, Checked};
use super::choice::{centred, choose, fit_choice, search_lag, Choice, Design, Extent, LagFound};
use super::daily::daily_cycle;
use super::input::{mean, prepare, Prepared};
use super::jumps::{clean_offsets, rate_outliers, Wrap};
use super::model::{mean_level, smoothed_walk, Fit};
use super::periodic::{periodic, running_mean, whole_cycle, Periodic, PeriodicFound};
use super::result::{
    Coefficients, DesignComparison, LogInput, LogKind, LogResult, LogWarning, Partial,
    ReferenceWeather, Term,
};
use super::series::{
    interval_means, lagged_interval_means, offsets_to_bins, rates_to_bins, Bins, Coarse,
};
use super::swing::{swing, Swing};
use super::terms::{ModelTerm, Source, TERMS};
use crate::analysis::Refusal;
use crate::fitting::beats::standard_rate_near;
use crate::stability::{
    stability, Accident, AccidentKind, DataKind, Outliers, StabilityInput, StabilityRow, Taus,
};
use crate::tide::{gravity_change, rate_s_per_day};

const DAY: f64 = 86_400.0;

/// The most knots the lag search lags (a log's weather shortened to
/// this: [`Coarse`]).
const SEARCH_KNOTS: usize = 200_000;

/// Analyses a clock's log.
///
/// # Examples
///
/// ```
/// use pendulum_theory::clock_log::{analyse, LogColumn, LogInput, LogKind};
///
/// // Nine days of hourly offsets (s) of a clock gaining 2 s a day at 20 °C and
/// // losing 0.5 s a day per °C, its room swinging ±3 °C every three days.
/// let w = std::f64::consts::TAU / (3.0 * 86_400.0);
/// let time: Vec<f64> = (0..216).map(|h| 3600.0 * h as f64).collect();
/// let temperature = time.iter().map(|t| 20.0 + 3.0 * (w * t).sin()).collect();
/// let offset = time.iter().map(|t| (2.0 * t + 1.5 * ((w * t).cos() - 1.0) / w) / 86_400.0);
/// let log = analyse(&LogInput {
///     time_s: time.clone(),
///     values: offset.collect(),
///     kind: Some(LogKind::Offset),
///     columns: vec![LogColumn::new("temperature", temperature)],
///     ..Default::default()
/// })?;
/// assert!((log.coefficients.get("temperature").unwrap() + 0.5).abs() < 1e-3);
/// assert!((log.rate_s_per_day - 2.0).abs() < 1e-3);
/// # Ok::<(), pendulum_theory::analysis::Refusal>(())
/// ```
pub fn analyse(input: &LogInput) -> Result<LogResult, Refusal> {
    let mut prepared = prepare(input)?;
    let beat_s = match prepared.kind {
        LogKind::HalfPeriods => Some(mean(&prepared.values)),
        _ => input.beat_s,
    };
    let mut warnings = std::mem::take(&mut prepared.warnings);
    let series = binned(&mut prepared, &mut warnings)?;
    let bins = &series.bins;
    let m = bins.rate.len();
    let mut design = regressors(input, &prepared, bins, &mut warnings)?;

    // The lag with every term in, then the terms, then the lag again on
    // the model chosen.
    // A short log gives its mean rate alone.
    let enough = m >= super::input::FOR_TERMS;
    if !enough {
        warnings.retain(|w| !matches!(w, LogWarning::Short { .. }));
        for &e in &input.events_s {
            if e.is_finite()
                && !warnings
                    .iter()
                    .any(|w| matches!(w, LogWarning::EventIgnored { time_s, .. } if *time_s == e))
            {
                warnings.push(LogWarning::EventIgnored {
                    time_s: e,
                    reason: "the log is too short for steps",
                });
            }
        }
        warnings.push(LogWarning::Short {
            what: "weather, drift and wander (ten bins needed; the mean rate alone is given)",
        });
        design.columns.iter_mut().for_each(|c| *c = None);
        design.steps.clear();
    }
    let available = Choice {
        terms: design.columns.iter().map(Option::is_some).collect(),
        walk: enough,
    };
    let lagged: Vec<usize> = (0..TERMS.len())
        .filter(|&i| TERMS[i].source == Source::LaggedColumn && design.columns[i].is_some())
        .collect();
    let coarse: Vec<(usize, Coarse)> = lagged
        .iter()
        .map(|&i| {
            let values = scaled(term_column(&prepared, i), i);
            let cycle = daily_cycle(&prepared.times, &values, prepared.dt);
            (
                i,
                Coarse::new(bins, &prepared.times, &values, cycle, SEARCH_KNOTS),
            )
        })
        .collect();
    let t0 = prepared.times[0];
    let extent = Extent {
        t0,
        span: prepared.span,
        bin: prepared.bin,
    };
    let mut lags: Vec<(usize, LagFound)> = Vec::new();
    for (i, c) in &coarse {
        if let Some(found) = search_lag(&mut design, &available, *i, c, bins, extent) {
            design.set_lagged(*i, c.lagged_means(found.tau), found.tau, bins, t0);
        }
    }
    let (choice, _, mut judged) = choose(&design, available, bins).ok_or_else(not_independent)?;
    for (i, c) in &coarse {
        if !choice.terms[*i] {
            continue;
        }
        if let Some(found) = search_lag(&mut design, &choice, *i, c, bins, extent) {
            // The lag found applied to every sample.
            let values = scaled(term_column(&prepared, *i), *i);
            let exact = bins.average(&lagged_interval_means(
                &prepared.times,
                &values,
                found.tau,
                c.cycle.as_ref(),
            ));
            design.set_lagged(*i, exact, found.tau, bins, t0);
            lags.push((*i, found));
        }
    }
    let mut fitted = fit_choice(&design, &choice, bins).ok_or_else(not_independent)?;
    let x = design.matrix(&choice, m);
    lag_uncertainty(
        &mut fitted,
        &mut design,
        &choice,
        &lags,
        &coarse,
        (&prepared, bins, t0),
    );
    // A term left out: what the final model with it put back allows,
    // the lag's uncertainty carried as for the kept ones.
    for (i, kept, j) in judged.iter_mut() {
        if *kept || *i >= TERMS.len() {
            continue;
        }
        let mut back = choice.clone();
        back.terms[*i] = true;
        let Some(mut f) = fit_choice(&design, &back, bins) else {
            continue;
        };
        lag_uncertainty(
            &mut f,
            &mut design,
            &back,
            &lags,
            &coarse,
            (&prepared, bins, t0),
        );
        if let Some(k) = design.names(&back).iter().position(|n| n == TERMS[*i].name) {
            j.estimate = Some((f.beta[k], f.cov[(k, k)].sqrt()));
        }
    }

    // Checks against the residuals and against what pendulums do.
    let walk = smoothed_walk(&fitted.residuals, &bins.weight, fitted.lambda);
    let Checked {
        widen,
        warnings: checked,
    } = check(&fitted, &walk, bins, &design, &choice);
    warnings.extend(checked);
    let (rate, rate_var) = mean_level(&fitted, &bins.rate, &x, &bins.weight);
    let names = design.names(&choice);
    for w in &mut warnings {
        w.date(input.epoch_unix_s);
    }
    let mut result = assemble(Assembly {
        input,
        prepared: &prepared,
        series: &series,
        design: &design,
        choice: &choice,
        fitted: &fitted,
        names,
        judged,
        lags,
        walk,
        rate: (rate, rate_var.sqrt() * widen),
        widen,
        warnings,
    })?;
    result.beat_s = beat_s;
    result.advise(&crate::advice::Known::default())?;
    Ok(result)
}

fn not_independent() -> Refusal {
    Refusal::data("the rate model cannot be fitted: its terms are not independent (a weather column that never changes?)")
}

/// Term `i`'s column as read (empty when the log lacks it).
fn term_column(p: &Prepared, i: usize) -> &[f64] {
    TERMS[i]
        .column
        .and_then(|c| p.column(c.name))
        .unwrap_or(&[])
}

/// A column in its term's variable unit (Pa to hPa, rad to degrees).
fn scaled(values: &[f64], term: usize) -> Vec<f64> {
    let s = 1.0 / TERMS[term].variable_si;
    values.iter().map(|v| v * s).collect()
}

/// The log as bins, and what the periodic analyses read.
struct Series {
    bins: Bins,
    /// Offsets (s) or fractional rates a sample, cleaned: the stability's
    /// and the spectrum's series.
    raw: Vec<f64>,
    raw_kind: DataKind,
    /// The nominal half period the rates are against.
    half: Option<f64>,
    swing: Option<Swing>,
    wraps: Vec<Wrap>,
    accidents: Vec<Accident>,
}

/// Jumps and outliers out, then the bins.
fn binned(p: &mut Prepared, warnings: &mut Vec<LogWarning>) -> Result<Series, Refusal> {
    let bin = p.bin;
    let (mut wraps, mut accidents) = (Vec::new(), Vec::new());
    let mut half = p.nominal_half;
    let mut early_swing = None;
    let (bins, raw_kind, raw) = match p.kind {
        LogKind::Offset => {
            let mut x = p.values.clone();
            let cleaned = clean_offsets(&p.times, &mut x, None);
            wraps = cleaned.wraps;
            accidents = cleaned.accidents;
            if !wraps.is_empty() {
                warnings.push(LogWarning::WrapsUndone { count: wraps.len() });
            }
            accident_warnings(&accidents, warnings);
            p.values = x;
            drop_samples(p, &cleaned.drop);
            (
                offsets_to_bins(&p.times, &p.values, bin),
                DataKind::Phase,
                p.values.clone(),
            )
        }
        LogKind::Rate => {
            let out = rate_outliers(&p.values);
            if let Some(&(first, _)) = out.first() {
                let largest =
                    out.iter().map(|o| o.1).fold(
                        0.0,
                        |a: f64, b| {
                            if b.abs() > a.abs() {
                                b
                            } else {
                                a
                            }
                        },
                    );
                warnings.push(LogWarning::RatesLeftOut {
                    count: out.len(),
                    first_time_s: p.times[first],
                    largest_s_per_day: largest,
                    epoch_unix_s: None,
                });
                let mut drop = vec![false; p.times.len()];
                for (i, _) in &out {
                    drop[*i] = true;
                }
                drop_samples(p, &drop);
            }
            (
                rates_to_bins(&p.times, &p.values, None, bin),
                DataKind::Frequency,
                p.values.iter().map(|r| r / DAY).collect(),
            )
        }
        LogKind::HalfPeriods => {
            let nominal = match p.nominal_half {
                Some(h) => h,
                None => match standard_rate_near(3600.0 / mean(&p.values)) {
                    Some(s) => 3600.0 / s.beats_per_hour,
                    None => {
                        warnings.push(LogWarning::RateAgainstMean);
                        mean(&p.values)
                    }
                },
            };
            half = Some(nominal);
            let rates: Vec<f64> = p.values.iter().map(|h| (nominal / h - 1.0) * DAY).collect();
            let times = &p.times;
            if let Some(a) = p.column("amplitude") {
                let degrees: Vec<f64> = a.iter().map(|r| r.to_degrees()).collect();
                early_swing = swing(&degrees, &|i| times[i] - times[i - 1] > 1.5 * nominal);
            }
            // A bin that ends part way through a cycle the swing repeats
            // (an impulse every few swings, the escape wheel's turn) takes
            // part of the cycle's pattern into its rate and its mean
            // amplitude alike, which the model would read as an effect of
            // the amplitude: both are averaged over whole cycles first.
            let cycle = whole_cycle(
                early_swing.as_ref(),
                p.arbors.last().map(|a| a.period_s / nominal),
                bin / nominal,
            );
            let b = match cycle {
                Some(w) => {
                    if let Some(k) = p.columns.iter().position(|(c, _)| c.name == "amplitude") {
                        p.columns[k].1 = running_mean(&p.columns[k].1, w);
                    }
                    // Weighted by the half periods, as the bins are.
                    let timed: Vec<f64> = rates.iter().zip(&p.values).map(|(r, h)| r * h).collect();
                    let smooth: Vec<f64> = running_mean(&timed, w)
                        .iter()
                        .zip(running_mean(&p.values, w))
                        .map(|(rh, h)| rh / h)
                        .collect();
                    rates_to_bins(&p.times, &smooth, Some(&p.values), bin)
                }
                None => rates_to_bins(&p.times, &rates, Some(&p.values), bin),
            };
            let fractional = rates.iter().map(|r| r / DAY).collect();
            (b, DataKind::Frequency, fractional)
        }
    };
    let m = bins.rate.len();
    if m < super::input::LEAST {
        return Err(Refusal::data(format!(
            "only {m} bins hold a rate; a mean rate needs {}",
            super::input::LEAST
        )));
    }
    Ok(Series {
        bins,
        raw,
        raw_kind,
        half,
        swing: early_swing,
        wraps,
        accidents,
    })
}

/// Leaves out the samples `drop` marks, from every column.
fn drop_samples(p: &mut Prepared, drop: &[bool]) {
    if !drop.iter().any(|&d| d) {
        return;
    }
    let pick = |v: &mut Vec<f64>| {
        let mut i = 0;
        v.retain(|_| {
            let keep = !drop[i];
            i += 1;
            keep
        });
    };
    pick(&mut p.times);
    pick(&mut p.values);
    for (_, c) in &mut p.columns {
        pick(c);
    }
}

/// The warnings for jumps and glitches, each naming the first's time and
/// the largest.
fn accident_warnings(accidents: &[Accident], warnings: &mut Vec<LogWarning>) {
    let of = |kind: AccidentKind| accidents.iter().filter(move |a| a.kind == kind);
    let largest = |it: &mut dyn Iterator<Item = &Accident>| {
        it.map(|a| a.size_s)
            .fold(0.0, |a: f64, b| if b.abs() > a.abs() { b } else { a })
    };
    if let Some(first) = of(AccidentKind::Jump).next() {
        warnings.push(LogWarning::JumpsUndone {
            count: of(AccidentKind::Jump).count(),
            first_time_s: first.time_s,
            largest_s: largest(&mut of(AccidentKind::Jump)),
            epoch_unix_s: None,
        });
    }
    if let Some(first) = of(AccidentKind::Glitch).next() {
        warnings.push(LogWarning::GlitchesLeftOut {
            count: of(AccidentKind::Glitch).count(),
            samples: of(AccidentKind::Glitch).map(|a| a.samples).sum(),
            first_time_s: first.time_s,
            largest_s: largest(&mut of(AccidentKind::Glitch)),
            epoch_unix_s: None,
        });
    }
}

/// The design from the table: each term's column a bin (a lagged term's
/// without lag until its lag is found), the steps at the events.
fn regressors(
    input: &LogInput,
    p: &Prepared,
    bins: &Bins,
    warnings: &mut Vec<LogWarning>,
) -> Result<Design, Refusal> {
    let m = bins.rate.len();
    let w = &bins.weight;
    let total: f64 = w.iter().sum();
    let t_ref = bins.centre.iter().zip(w).map(|(t, w)| t * w).sum::<f64>() / total;
    let mut design = Design {
        columns: vec![None; TERMS.len()],
        means: vec![None; TERMS.len()],
        steps: Vec::new(),
        transients: vec![None; TERMS.len()],
        lags: vec![0.0; TERMS.len()],
        t_ref,
    };
    for (i, term) in TERMS.iter().enumerate() {
        let binned: Option<Vec<f64>> = match term.source {
            Source::Time => {
                if p.span >= 2.0 * DAY {
                    Some(bins.centre.iter().map(|t| (t - t_ref) / DAY).collect())
                } else {
                    warnings.push(LogWarning::Short { what: "drift" });
                    None
                }
            }
            Source::Column | Source::LaggedColumn => {
                let name = term.column.map_or("", |c| c.name);
                p.column(name)
                    .filter(|c| c.iter().any(|v| v.is_finite()))
                    .map(|c| {
                        let v = scaled(c, i);
                        let cycle = daily_cycle(&p.times, &v, p.dt);
                        bins.average(&interval_means(&p.times, &v, cycle.as_ref()))
                    })
            }
            Source::Tide => tide(input, p, bins, warnings)?,
        };
        if let Some(b) = binned {
            let (c, mu) = centred(&b, w);
            design.columns[i] = Some(c);
            design.means[i] = Some(mu);
        }
    }
    // A step needs bins on both sides of it: at least two whole ones, or
    // it cannot be told from the rate (at the log's start) or from one
    // bin's noise (at its end).
    let (first, last) = (bins.centre[0], bins.centre[m - 1]);
    let (start, end) = (p.times[0], p.times[p.times.len() - 1]);
    for &e in &input.events_s {
        let reason = if !e.is_finite() || e < start || e > end {
            Some("outside the log")
        } else if e < first + 1.5 * p.bin || e > last - 1.5 * p.bin {
            Some("within two bins of the log's start or end: a step there cannot be told from the rate or from one bin's noise")
        } else {
            None
        };
        match reason {
            Some(reason) => warnings.push(LogWarning::EventIgnored {
                time_s: if e.is_finite() { e } else { 0.0 },
                reason,
            }),
            // The share of each bin's rate after the event.
            None => design.steps.push(
                bins.ranges
                    .iter()
                    .map(|&(a, b)| {
                        bins.parts[a..b]
                            .iter()
                            .map(|&(j, u)| {
                                let (lo, hi) = interval(&p.times, j);
                                if hi <= lo {
                                    u * f64::from(u8::from(lo >= e))
                                } else {
                                    u * ((hi - e) / (hi - lo)).clamp(0.0, 1.0)
                                }
                            })
                            .sum::<f64>()
                    })
                    .collect(),
            ),
        }
    }
    Ok(design)
}

/// Interval `j`'s ends, s (interval 0 is the first instant).
fn interval(times: &[f64], j: usize) -> (f64, f64) {
    if j == 0 {
        (times[0], times[0])
    } else {
        (times[j - 1], times[j])
    }
}

/// The tide's pendulum rate averaged over each bin's intervals: the
/// two-point Gauss rule on panels of at most 3 hours.
fn tide(
    input: &LogInput,
    p: &Prepared,
    bins: &Bins,
    warnings: &mut Vec<LogWarning>,
) -> Result<Option<Vec<f64>>, Refusal> {
    if !input.tides {
        return Ok(None);
    }
    let station = input.station.ok_or_else(|| {
        Refusal::field(
            "latitude",
            "the tides need the clock's latitude and longitude",
        )
    })?;
    let epoch = input.epoch_unix_s.ok_or_else(|| {
        Refusal::field(
            "time",
            "the tides need the log's times as dates (ISO 8601 or Unix time), or its start",
        )
    })?;
    if p.span < 3.0 * DAY {
        warnings.push(LogWarning::Short { what: "tide" });
    }
    let g = crate::gravity::normal_gravity(station.latitude_deg, station.height_m)
        .map_err(|e| Refusal::input("height", &e))?;
    // Each bin's span, its panels and their Gauss points.
    let node = 0.5 / 3f64.sqrt();
    let mut at = Vec::new();
    let mut panels = Vec::with_capacity(bins.ranges.len());
    for &(a, b) in &bins.ranges {
        let lo = interval(&p.times, bins.parts[a].0).0;
        let hi = interval(&p.times, bins.parts[b - 1].0).1;
        let count = ((hi - lo) / 10_800.0).ceil().max(1.0) as usize;
        let h = (hi - lo) / count as f64;
        for k in 0..count {
            let c = lo + (k as f64 + 0.5) * h;
            at.push(epoch + c - node * h);
            at.push(epoch + c + node * h);
        }
        panels.push(count);
    }
    let dg = gravity_change(station, &at)?;
    let mut k = 0;
    Ok(Some(
        panels
            .iter()
            .map(|&count| {
                let s: f64 = dg[k..k + 2 * count].iter().sum();
                k += 2 * count;
                rate_s_per_day(s / (2 * count) as f64, g)
            })
            .collect(),
    ))
}

/// The lag's own uncertainty carried into every coefficient: refits at
/// the ends of its 95% range (3.92 standard deviations apart) give each
/// coefficient's change over one standard deviation of the lag, added to
/// its covariance (the delta method, written for a range that may start
/// at 0).
fn lag_uncertainty(
    fitted: &mut Fit,
    design: &mut Design,
    choice: &Choice,
    lags: &[(usize, LagFound)],
    coarse: &[(usize, Coarse)],
    (p, bins, t0): (&Prepared, &Bins, f64),
) {
    for (i, found) in lags {
        let values = scaled(term_column(p, *i), *i);
        let cycle = coarse
            .iter()
            .find(|c| c.0 == *i)
            .and_then(|c| c.1.cycle.as_ref());
        let refit = |tau: f64, design: &mut Design| -> Option<Vec<f64>> {
            let exact = bins.average(&lagged_interval_means(&p.times, &values, tau, cycle));
            design.set_lagged(*i, exact, tau, bins, t0);
            let m = bins.rate.len();
            super::model::fit(
                &bins.rate,
                &design.matrix(choice, m),
                &bins.weight,
                super::model::Walk::Fixed(fitted.lambda),
            )
            .map(|f| f.beta)
        };
        let lo = refit(found.range[0], design);
        let hi = refit(found.range[1], design);
        // Back to the lag found.
        let exact = bins.average(&lagged_interval_means(&p.times, &values, found.tau, cycle));
        design.set_lagged(*i, exact, found.tau, bins, t0);
        if let (Some(lo), Some(hi)) = (lo, hi) {
            // The two ends' models hold a start column or not alike only
            // when both lags are positive; otherwise compare the shared
            // columns (all but the start, which is last).
            let k = fitted.beta.len().min(lo.len()).min(hi.len());
            let g: Vec<f64> = (0..k).map(|a| (hi[a] - lo[a]) / 3.92).collect();
            for a in 0..k {
                for b in 0..k {
                    fitted.cov[(a, b)] += g[a] * g[b];
                }
            }
        }
    }
}

/// What the result is made of.
struct Assembly<'a> {
    input: &'a LogInput,
    prepared: &'a Prepared,
    series: &'a Series,
    design: &'a Design,
    choice: &'a Choice,
    fitted: &'a Fit,
    names: Vec<String>,
    judged: Vec<(usize, bool, super::choice::Judged)>,
    lags: Vec<(usize, LagFound)>,
    walk: Vec<f64>,
    rate: (f64, f64),
    widen: f64,
    warnings: Vec<LogWarning>,
}

/// The final model's coefficients by term, with their standard errors
/// (widened for the noise's correlation) and correlations.
struct Estimates {
    /// Each term's value, in [`TERMS`]' order (`None`: not in the model).
    values: Vec<Option<f64>>,
    /// Each term's standard error, likewise.
    errors: Vec<Option<f64>>,
    coefficients: Coefficients,
    standard_errors: Coefficients,
    correlations: Vec<Vec<f64>>,
}

/// Each weather term's variable a bin, in its unit.
type WeatherPerBin = Vec<(&'static ModelTerm, Vec<f64>)>;

/// The model a bin (the walk included), the residuals with it out, and
/// their weighted rms (s/day).
struct Modelled {
    model: Vec<f64>,
    residuals: Vec<f64>,
    residual_rms: f64,
}

/// Builds the result from the fit: the figures, their checks against what
/// pendulums can do and against the design, the stability of the log and
/// of its residuals, the periodic errors the model leaves, and the
/// series the plots draw.
fn assemble(mut a: Assembly) -> Result<LogResult, Refusal> {
    let mut warnings = std::mem::take(&mut a.warnings);
    let estimates = a.estimates();
    let terms = a.judged_terms(&estimates);
    // The lag, reported with its range.
    let temperature = TERMS.iter().position(|t| t.name == "temperature");
    let lag = a
        .lags
        .iter()
        .find(|(i, _)| Some(*i) == temperature)
        .map(|l| l.1.clone());
    if let Some(l) = &lag {
        if l.at_limit {
            warnings.push(LogWarning::LagAtLimit { lag_s: l.tau });
        }
    }
    let reference_weather = ReferenceWeather {
        means: TERMS
            .iter()
            .enumerate()
            .filter(|(i, t)| {
                t.column.is_some() && a.choice.terms[*i] && a.design.columns[*i].is_some()
            })
            .filter_map(|(i, t)| Some((t, a.design.means[i]?)))
            .collect(),
    };
    a.plausibility(&estimates, &mut warnings);
    let design_comparison = a.against_design(&estimates)?;
    let modelled = a.modelled();
    let (stability, residual_stability) = a.stabilities()?;
    let m = a.series.bins.rate.len();
    let x = a.design.matrix(a.choice, m);
    let found = a.periodic_errors(&x, &mut warnings)?;
    let (weather_per_bin, partials) = a.partials(&estimates.values, &modelled.residuals);
    let bins = &a.series.bins;
    let per_bin = (0..m)
        .map(|i| {
            let (model, residual) = (modelled.model[i], modelled.residuals[i]);
            [bins.centre[i], bins.rate[i], model, residual]
        })
        .collect();
    let (p, input, fitted) = (a.prepared, a.input, a.fitted);
    let drift = TERMS.iter().position(|t| t.source == Source::Time);
    Ok(LogResult {
        kind: p.kind,
        epoch_unix_s: input.epoch_unix_s,
        samples: input.time_s.len(),
        span_s: p.span,
        bin_s: p.bin,
        bins: m,
        rate_s_per_day: a.rate.0,
        rate_standard_error_s_per_day: a.rate.1,
        reference_time_s: a.design.t_ref,
        rate_at_end_s_per_day: a.end_rate(&x, modelled.model[m - 1]),
        drift_s_per_day_per_day: drift.and_then(|i| estimates.values[i]),
        drift_standard_error_s_per_day_per_day: drift.and_then(|i| estimates.errors[i]),
        coefficients: estimates.coefficients,
        standard_errors: estimates.standard_errors,
        parameters: std::mem::take(&mut a.names),
        correlations: estimates.correlations,
        temperature_lag_s: lag.as_ref().map(|l| l.tau),
        temperature_lag_range_s: lag.as_ref().map(|l| l.range),
        reference_weather,
        terms,
        white_noise_s_per_day: fitted.sigma2.sqrt(),
        random_walk_s_per_day_per_day: (fitted.lambda * fitted.sigma2 * DAY / p.bin).sqrt(),
        residual_rms_s_per_day: modelled.residual_rms,
        stability,
        residual_stability,
        design: design_comparison,
        wraps: a.series.wraps.clone(),
        accidents: a.series.accidents.clone(),
        warnings,
        spectrum: found.spectrum,
        arbors: p.arbors.clone(),
        folds: found.folds,
        swing: found.swing,
        beat_error_s: found.beat_error_s,
        beat_s: None,
        advice: Vec::new(),
        per_bin,
        partials,
        weather_per_bin,
    })
}

impl Assembly<'_> {
    /// The coefficients by term and the rate steps, their standard errors
    /// widened by `widen`, and the parameters' correlations.
    fn estimates(&self) -> Estimates {
        let (fitted, names, widen) = (self.fitted, &self.names, self.widen);
        let se: Vec<f64> = (0..names.len())
            .map(|i| fitted.cov[(i, i)].sqrt() * widen)
            .collect();
        let index = |name: &str| names.iter().position(|n| n == name);
        let (mut values, mut errors) = (vec![None; TERMS.len()], vec![None; TERMS.len()]);
        for (i, t) in TERMS.iter().enumerate() {
            if let Some(k) = index(t.name) {
                values[i] = Some(fitted.beta[k]);
                errors[i] = Some(se[k]);
            }
        }
        let first_step = 1
            + (0..TERMS.len())
                .filter(|&i| self.choice.terms[i] && self.design.columns[i].is_some())
                .count();
        let steps = self.design.steps.len();
        let coefficients = Coefficients {
            values: values.clone(),
            steps_s_per_day: (0..steps).map(|k| fitted.beta[first_step + k]).collect(),
        };
        let standard_errors = Coefficients {
            values: errors.clone(),
            steps_s_per_day: (0..steps).map(|k| se[first_step + k]).collect(),
        };
        let correlations: Vec<Vec<f64>> = (0..names.len())
            .map(|i| {
                (0..names.len())
                    .map(|j| fitted.cov[(i, j)] * widen * widen / (se[i] * se[j]))
                    .collect()
            })
            .collect();
        Estimates {
            values,
            errors,
            coefficients,
            standard_errors,
            correlations,
        }
    }

    /// Each judged term: a kept term's figures are the final model's (its
    /// lag searched again and its uncertainty carried); a term left out
    /// gives what the model with it put back allows.
    fn judged_terms(&mut self, e: &Estimates) -> Vec<Term> {
        let widen = self.widen;
        std::mem::take(&mut self.judged)
            .into_iter()
            .map(|(i, kept, j)| {
                let (estimate, standard_error) = match (kept, e.values.get(i).copied().flatten()) {
                    (true, Some(v)) => (Some(v), e.errors[i]),
                    _ => (j.estimate.map(|e| e.0), j.estimate.map(|e| e.1 * widen)),
                };
                Term {
                    name: TERMS.get(i).map_or("random_walk", |t| t.name),
                    kept,
                    delta_bic: j.delta_bic,
                    estimate,
                    standard_error,
                }
            })
            .collect()
    }

    /// Warns of a coefficient no pendulum could have (each term's own
    /// test), and of a tidal admittance more than 4 standard errors from 1.
    fn plausibility(&self, e: &Estimates, warnings: &mut Vec<LogWarning>) {
        for (i, t) in TERMS.iter().enumerate() {
            if let Some(v) = e.values[i] {
                if let Some(reason) = (t.implausible)(v, self.design.means[i].unwrap_or(0.0)) {
                    warnings.push(LogWarning::Implausible {
                        term: t.name,
                        reason,
                    });
                }
            }
        }
        if let (Some(k), Some(s)) = (e.coefficients.get("tide"), e.standard_errors.get("tide")) {
            let from_one = (k - 1.0) / s;
            if from_one.abs() > 4.0 && s < 0.5 {
                warnings.push(LogWarning::TideAdmittance {
                    admittance: k,
                    from_one_se: from_one,
                });
            }
        }
    }

    /// The coefficients against the pendulum's design, when one is given.
    fn against_design(&self, e: &Estimates) -> Result<Option<DesignComparison>, Refusal> {
        let Some(d) = &self.input.design else {
            return Ok(None);
        };
        let means: Vec<(usize, f64)> = (0..TERMS.len())
            .filter_map(|i| Some((i, self.design.means[i]?)))
            .collect();
        super::checks::against_design(d, &means, &e.coefficients, &e.standard_errors).map(Some)
    }

    /// The model a bin, the walk included; the residuals with it out and
    /// their rms weighted as the bins are.
    fn modelled(&self) -> Modelled {
        let bins = &self.series.bins;
        let m = bins.rate.len();
        let model: Vec<f64> = (0..m)
            .map(|i| bins.rate[i] - self.fitted.residuals[i] + self.walk[i])
            .collect();
        let residuals: Vec<f64> = (0..m).map(|i| bins.rate[i] - model[i]).collect();
        let total_weight: f64 = bins.weight.iter().sum();
        let residual_rms = (residuals
            .iter()
            .zip(&bins.weight)
            .map(|(r, w)| w * r * r)
            .sum::<f64>()
            / total_weight)
            .sqrt();
        Modelled {
            model,
            residuals,
            residual_rms,
        }
    }

    /// Stability: the cleaned series at its own spacing, and the residuals
    /// (the walk left in: it is the clock's) a bin; none when the input
    /// skips it.
    fn stabilities(&self) -> Result<(Vec<StabilityRow>, Vec<StabilityRow>), Refusal> {
        if self.input.skip_stability {
            return Ok((Vec::new(), Vec::new()));
        }
        let (p, series) = (self.prepared, self.series);
        let mut raw_series = series.raw.clone();
        let mut raw_times = p.times.clone();
        if series.raw.len() != raw_times.len() {
            raw_times.truncate(raw_series.len());
            raw_series.truncate(raw_times.len());
        }
        let raw = crate::stability::grid(&raw_times, &raw_series, Some(p.dt))?;
        let raw_stability = stability(&StabilityInput {
            data: raw.data,
            kind: series.raw_kind,
            tau0_s: raw.tau0_s,
            taus: Taus::Octave,
            force: true,
            // The log's own jumps and glitches are out already.
            outliers: Outliers::Keep,
        })?
        .rows;
        let fraction: Vec<f64> = self.fitted.residuals.iter().map(|r| r / DAY).collect();
        let residual = crate::stability::grid(&series.bins.centre, &fraction, Some(p.bin))?;
        let residual_stability = stability(&StabilityInput {
            data: residual.data,
            kind: DataKind::Frequency,
            tau0_s: p.bin,
            taus: Taus::Octave,
            force: true,
            outliers: Outliers::Keep,
        })
        .map(|s| s.rows)
        .unwrap_or_default();
        Ok((raw_stability, residual_stability))
    }

    /// Periodic errors of what the weather, drift and steps leave (every
    /// column of the design `x` but the constant and the tide), with a
    /// warning when the train's beat and the log's differ by over 1%.
    fn periodic_errors(
        &self,
        x: &[Vec<f64>],
        warnings: &mut Vec<LogWarning>,
    ) -> Result<PeriodicFound, Refusal> {
        let (p, series) = (self.prepared, self.series);
        if let (Some(train), Some(h)) = (&self.input.train, series.half) {
            if let Some(train_bph) = train.beats_per_hour() {
                let log_bph = 3600.0 / h;
                if (train_bph / log_bph - 1.0).abs() > 0.01 {
                    warnings.push(LogWarning::TrainBeat { train_bph, log_bph });
                }
            }
        }
        let tide_slot = TERMS.iter().position(|t| t.source == Source::Tide);
        let not_tidal: Vec<f64> = (0..series.bins.rate.len())
            .map(|i| {
                x.iter()
                    .zip(&self.fitted.beta)
                    .enumerate()
                    .filter(|(k, _)| {
                        *k > 0 && Some(self.names[*k].as_str()) != tide_slot.map(|s| TERMS[s].name)
                    })
                    .map(|(_, (c, b))| c[i] * b)
                    .sum()
            })
            .collect();
        periodic(&Periodic {
            times: &p.times,
            raw: &series.raw,
            kind: series.raw_kind,
            half: (p.kind == LogKind::HalfPeriods)
                .then_some(series.half)
                .flatten(),
            dt: p.dt,
            arbors: &p.arbors,
            swing: series.swing.clone(),
            model: (&series.bins.centre, &not_tidal),
        })
    }

    /// The weather a bin and each weather term's partial residuals (the
    /// residuals with the term's own part put back, against its variable),
    /// for plots.
    fn partials(&self, values: &[Option<f64>], residuals: &[f64]) -> (WeatherPerBin, Vec<Partial>) {
        let (p, design, bins) = (self.prepared, self.design, &self.series.bins);
        let m = bins.rate.len();
        let mut weather_per_bin = Vec::new();
        for (i, t) in TERMS.iter().enumerate() {
            if let (Some(c), true) = (t.column, design.columns[i].is_some()) {
                if let Some(v) = p.column(c.name) {
                    weather_per_bin.push((
                        t,
                        bins.average(&interval_means(&p.times, &scaled(v, i), None)),
                    ));
                }
            }
        }
        let partials = TERMS
            .iter()
            .enumerate()
            .filter(|(_, t)| t.source != Source::Time)
            .filter_map(|(i, t)| {
                let beta = values[i]?;
                let column = design.columns[i].as_ref()?;
                let offset = design.means[i].unwrap_or(0.0);
                let raw_weather = weather_per_bin
                    .iter()
                    .find(|(w, _)| w.name == t.name)
                    .map(|w| &w.1);
                let present = |k: usize| raw_weather.is_none_or(|w| w[k].is_finite());
                let (mut xs, mut ys) = (Vec::new(), Vec::new());
                for k in (0..m).filter(|&k| present(k)) {
                    xs.push(column[k] + offset);
                    ys.push(residuals[k] + beta * column[k] + self.rate.0);
                }
                let mean_x = mean(&xs);
                Some(Partial {
                    term: t,
                    slope: beta,
                    at_mean: self.rate.0 + beta * (mean_x - offset),
                    mean: mean_x,
                    x: xs,
                    y: ys,
                })
            })
            .collect();
        (weather_per_bin, partials)
    }

    /// The model at the last bin (`last_model`) less every weather term
    /// (and the lags' starts): the rate now, at the mean weather, s/day.
    fn end_rate(&self, x: &[Vec<f64>], last_model: f64) -> f64 {
        let m = self.series.bins.rate.len();
        let drift = TERMS.iter().position(|t| t.source == Source::Time);
        last_model
            - x.iter()
                .zip(&self.fitted.beta)
                .zip(&self.names)
                .filter(|(_, n)| {
                    n.as_str() != "rate"
                        && Some(n.as_str()) != drift.map(|d| TERMS[d].name)
                        && !n.starts_with("step_")
                })
                .map(|((c, b), _)| c[m - 1] * b)
                .sum::<f64>()
    }
}
