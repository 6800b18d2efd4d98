//! The written report: `benchmarks.md` (tables of medians and ratios against loci) and
//! `benchmarks.svg` (time against size, log-log, one panel per family), hand-written.

use crate::compare::{Cell, Results};
use crate::problem::{Family, Variant};
use crate::run::{Solver, Verdict};
use std::collections::BTreeSet;
use std::fmt::Write as _;

/// A duration in milliseconds, with sensible digits.
#[must_use]
pub fn fmt_ms(ms: f64) -> String {
    if ms >= 1000.0 {
        format!("{:.2} s", ms / 1000.0)
    } else if ms >= 10.0 {
        format!("{ms:.1} ms")
    } else if ms >= 0.1 {
        format!("{ms:.2} ms")
    } else {
        format!("{ms:.3} ms")
    }
}

/// A verdict without a time, in a few words.
#[must_use]
pub fn verdict_text(v: &Verdict) -> String {
    match v {
        Verdict::Solved => "solved".into(),
        Verdict::Detected { .. } => "detected".into(),
        Verdict::Wrong { residual } => format!("wrong answer (residual {residual:.1e})"),
        Verdict::Failed { detail } => format!("failed ({detail})"),
        Verdict::Refused { detail } => format!("refuses ({detail})"),
        Verdict::Timeout { limit_s } => format!("timeout (> {limit_s:.0} s)"),
        Verdict::Crashed { detail } if detail.starts_with("out of memory") => {
            "out of memory".into()
        }
        // The signal or exit code; the last words are in the table of what each solver said.
        Verdict::Crashed { detail } => {
            format!("crashed ({})", detail.split(':').next().unwrap_or(detail))
        }
        Verdict::NotRun { reason } => short_reason(reason),
    }
}

/// A table-sized form of why a cell was not run (the JSON keeps the full reason).
fn short_reason(reason: &str) -> String {
    if let Some(why) = reason
        .strip_prefix("not run: ")
        .and_then(|r| r.strip_suffix(" at a smaller size"))
    {
        let word = ["refuses", "timeout", "out of memory", "crashed", "failed"]
            .into_iter()
            .find(|w| why.starts_with(w))
            .unwrap_or(why);
        return format!("— ({word} at a smaller size)");
    }
    if reason.contains("extrapolates past") {
        return "— (extrapolates past the limit)".into();
    }
    reason.to_string()
}

/// A table cell: the median time (with the ratio to loci's when given) or what happened.
#[must_use]
pub fn cell_text(c: &Cell, loci_ms: Option<f64>) -> String {
    match (&c.verdict, c.solve_ms) {
        (Verdict::Solved, Some(ms)) => match loci_ms {
            Some(l) if c.solver != Solver::Loci && l > 0.0 => {
                format!("{} (×{})", fmt_ms(ms), fmt_ratio(ms / l))
            }
            _ => fmt_ms(ms),
        },
        (Verdict::Detected { .. }, Some(ms)) => match loci_ms {
            Some(l) if c.solver != Solver::Loci && l > 0.0 => {
                format!("{}, detected (×{})", fmt_ms(ms), fmt_ratio(ms / l))
            }
            _ => format!("{}, detected", fmt_ms(ms)),
        },
        (v, _) => {
            let t = verdict_text(v);
            // Cells of a markdown table cannot hold a bar.
            t.replace('|', "/")
        }
    }
}

fn fmt_ratio(r: f64) -> String {
    if r >= 100.0 {
        format!("{r:.0}")
    } else if r >= 10.0 {
        format!("{r:.1}")
    } else {
        format!("{r:.2}")
    }
}

fn size_label(f: Family, size: usize) -> String {
    if f.takes_side() {
        let side = (size as f64).sqrt().round() as usize;
        format!("{side}x{side} ({size})")
    } else {
        size.to_string()
    }
}

fn sizes_of(r: &Results, f: Family, v: Variant) -> Vec<usize> {
    let s: BTreeSet<usize> = r
        .cells
        .iter()
        .filter(|c| c.family == f && c.variant == v)
        .map(|c| c.size)
        .collect();
    s.into_iter().collect()
}

fn solvers_of(r: &Results) -> Vec<Solver> {
    let s: BTreeSet<Solver> = r.cells.iter().map(|c| c.solver).collect();
    Solver::ALL.into_iter().filter(|x| s.contains(x)).collect()
}

fn table(out: &mut String, r: &Results, f: Family, v: Variant, build: bool) {
    let solvers = solvers_of(r);
    let _ = write!(out, "| size |");
    for s in &solvers {
        let _ = write!(out, " {} |", s.heading());
    }
    let _ = write!(out, "\n| ---: |");
    for _ in &solvers {
        let _ = write!(out, " --- |");
    }
    out.push('\n');
    for size in sizes_of(r, f, v) {
        let loci = r
            .cell(f, v, size, Solver::Loci)
            .filter(|c| c.verdict.has_time())
            .and_then(|c| if build { c.build_ms } else { c.solve_ms });
        let _ = write!(out, "| {} |", size_label(f, size));
        for &s in &solvers {
            let text = match r.cell(f, v, size, s) {
                None => "—".to_string(),
                Some(c) if build => match (c.build_ms, c.runs) {
                    (Some(ms), n) if n > 0 => fmt_ms(ms),
                    _ => "—".to_string(),
                },
                Some(c) => cell_text(c, loci),
            };
            let _ = write!(out, " {text} |");
        }
        out.push('\n');
    }
    out.push('\n');
}

/// The rows users ask about first: interactive sizes and sizes where solvers give up.
const HEADLINE: [(Family, usize); 5] = [
    (Family::Chain, 100),
    (Family::Chain, 1_000),
    (Family::Chain, 10_000),
    (Family::Triangles, 10_000),
    (Family::Grid, 2_500),
];

fn headline(out: &mut String, r: &Results) {
    let rows: Vec<(Family, usize)> = HEADLINE
        .into_iter()
        .filter(|&(f, s)| r.cells.iter().any(|c| c.family == f && c.size == s))
        .collect();
    if rows.is_empty() {
        return;
    }
    let solvers = solvers_of(r);
    let _ = writeln!(out, "## Headline\n");
    let _ = write!(out, "| family | size |");
    for s in &solvers {
        let _ = write!(out, " {} |", s.heading());
    }
    let _ = write!(out, "\n| --- | ---: |");
    for _ in &solvers {
        let _ = write!(out, " --- |");
    }
    out.push('\n');
    for (f, size) in rows {
        let v = Variant::Solvable;
        let loci = r
            .cell(f, v, size, Solver::Loci)
            .filter(|c| c.verdict.has_time())
            .and_then(|c| c.solve_ms);
        let _ = write!(out, "| {} | {} |", f.name(), size_label(f, size));
        for &s in &solvers {
            let text = r
                .cell(f, v, size, s)
                .map_or("—".to_string(), |c| cell_text(c, loci));
            let _ = write!(out, " {text} |");
        }
        out.push('\n');
    }
    out.push('\n');
}

/// The markdown report.
#[must_use]
pub fn markdown(r: &Results, command: &str) -> String {
    let mut o = String::new();
    let meta = |k: &str| r.meta.get(k).cloned().unwrap_or_else(|| "?".into());
    let _ = writeln!(o, "# Benchmarks\n");
    let _ = writeln!(
        o,
        "loci side by side with SolveSpace, PlaneGCS and ezpz on the same generated problems, \
         in the same run. Generated by `{command}` on {} (UTC).\n",
        meta("date")
    );
    let _ = writeln!(o, "![time against size, per family](benchmarks.svg)\n");
    let _ = writeln!(o, "## Machine and versions\n");
    let _ = writeln!(o, "| | |\n| --- | --- |");
    for k in ["machine", "cores", "memory", "os", "rustc", "loci commit"] {
        let _ = writeln!(o, "| {k} | {} |", meta(k));
    }
    for (k, v) in &r.versions {
        let _ = writeln!(o, "| {k} | {} |", v.replace('|', "/"));
    }
    let _ = writeln!(o);
    let _ = writeln!(o, "## How it is measured\n");
    let _ = writeln!(
        o,
        "- Each family is generated once per size from a fixed seed (`bench/src/generate.rs`): \
         an exact solution is built, every dimension is read off it, and every free point starts \
         up to 0.3 away from it along each axis. The neutral problem is then translated to each \
         solver's own API (`bench/src/slvs.rs` for loci and both SolveSpace runners, \
         `bench/src/peers.rs` for ezpz and PlaneGCS).\n\
         - Every solver runs in its own worker process: loci and ezpz called as Rust libraries, \
         SolveSpace through a C program over Debian's libslvs and through PyPI `slvs` in a venv, \
         PlaneGCS through node. The Rust workers allocate through mimalloc: with glibc's malloc \
         the large blocks of a big solve go back to the kernel when freed, and every repetition \
         would pay page faults again for the memory it touches (about a third of a \
         10,000-element solve). Times are the solve call alone (building the problem in the \
         solver's API is timed separately, below), the median of up to {} runs; runs stop early \
         once the solves add up to {} s. Problems a solver solves in under {} ms are timed in {} \
         such rounds, every solver in turn, and the median is taken over all of them, so that a \
         burst of load on the machine does not fall on one solver alone. A worker still running \
         after {} s is killed (timeout).\n\
         - Each returned answer is checked by the harness itself (`bench/src/check.rs`): every \
         constraint, fixed point and arc radius is measured from the returned coordinates, and \
         a largest residual of 1e-6 or more makes the answer *wrong*, whatever the solver said.\n\
         - SolveSpace is asked to name failed constraints (`calculateFaileds`), as loci does by \
         default. After a refusal, timeout or crash, larger sizes are not run for that solver; a \
         size whose linear extrapolation from the last time exceeds the limit is not run either.\n\
         - Ratios are peer time / loci time: above 1, loci is faster.\n",
        meta("reps"),
        meta("budget_s"),
        crate::compare::ROUND_MAX_MS,
        meta("rounds"),
        meta("limit_s")
    );
    headline(&mut o, r);
    let _ = writeln!(o, "## Solve times\n");
    for f in Family::ALL {
        if sizes_of(r, f, Variant::Solvable).is_empty() {
            continue;
        }
        let _ = writeln!(o, "### {}\n\n{}.\n", f.name(), f.describe());
        table(&mut o, r, f, Variant::Solvable, false);
    }
    let _ = writeln!(
        o,
        "## Build times (median, problem construction in each API)\n"
    );
    for f in Family::ALL {
        if sizes_of(r, f, Variant::Solvable).is_empty() {
            continue;
        }
        let _ = writeln!(o, "### {}\n", f.name());
        table(&mut o, r, f, Variant::Solvable, true);
    }
    let _ = writeln!(o, "## Diagnosis: redundant and inconsistent variants\n");
    let _ = writeln!(
        o,
        "Each family with one extra constraint: *redundant* adds one implied by the others \
         (a solver should solve it, and may say it is redundant); *inconsistent* adds the same \
         with its value changed so that it contradicts them (a solver should report failure: \
         *detected*). Times are those of the solve call, diagnosis included.\n"
    );
    for f in Family::ALL {
        for v in [Variant::Redundant, Variant::Inconsistent] {
            if sizes_of(r, f, v).is_empty() {
                continue;
            }
            let _ = writeln!(o, "### {} / {}\n", f.name(), v.name());
            table(&mut o, r, f, v, false);
        }
    }
    let _ = writeln!(o, "## What each solver said\n");
    let _ = writeln!(
        o,
        "The outcome each solver reported for every problem it ran, in its own words, with the \
         largest residual the checker measured.\n"
    );
    let _ = writeln!(
        o,
        "| problem | solver | outcome | residual | runs |\n| --- | --- | --- | ---: | ---: |"
    );
    for c in &r.cells {
        if matches!(c.verdict, Verdict::NotRun { .. }) {
            continue;
        }
        let label = match c.variant {
            Variant::Solvable => format!("{}/{}", c.family.name(), c.size),
            v => format!("{}/{}/{}", c.family.name(), v.name(), c.size),
        };
        let said = match &c.verdict {
            Verdict::Crashed { detail } => format!("crashed: {detail}"),
            v if c.detail.is_empty() => verdict_text(v),
            _ => c.detail.clone(),
        };
        let _ = writeln!(
            o,
            "| {label} | {} | {} | {} | {} |",
            c.solver.name(),
            said.replace('|', "/"),
            c.residual.map_or("—".into(), |x| format!("{x:.1e}")),
            c.runs
        );
    }
    o
}

/// A decade of milliseconds as an axis label: 0.01 ms ... 100 s.
fn axis_label(decade: f64) -> String {
    let ms = 10f64.powf(decade);
    if ms >= 1000.0 {
        format!("{} s", ms / 1000.0)
    } else {
        format!("{ms} ms")
    }
}

fn color(s: Solver) -> &'static str {
    match s {
        Solver::Loci => "#d62728",
        Solver::Ezpz => "#1f77b4",
        Solver::SlvsPy => "#2ca02c",
        Solver::SlvsC => "#9467bd",
        Solver::PlaneGcs => "#ff7f0e",
    }
}

/// The plot: one log-log panel of solve time against size per family (solvable problems),
/// one line per solver; a cross near a panel's top marks where a solver stopped
/// (refused, timed out, crashed, failed or answered wrong).
#[must_use]
pub fn svg(r: &Results) -> String {
    let families: Vec<Family> = Family::ALL
        .into_iter()
        .filter(|&f| !sizes_of(r, f, Variant::Solvable).is_empty())
        .collect();
    let solvers = solvers_of(r);
    let (pw, ph) = (340.0, 250.0);
    let (ml, mr, mt, mb) = (58.0, 14.0, 30.0, 40.0);
    let cols = 3usize;
    let panels = families.len() + 1;
    let rows = panels.div_ceil(cols);
    let (w, h) = (pw * cols as f64, ph * rows as f64);
    let times: Vec<f64> = r
        .cells
        .iter()
        .filter(|c| c.variant == Variant::Solvable && c.verdict.has_time())
        .filter_map(|c| c.solve_ms)
        .filter(|&t| t > 0.0)
        .collect();
    let ylo = times
        .iter()
        .copied()
        .fold(f64::INFINITY, f64::min)
        .max(1e-4)
        .log10()
        .floor();
    let yhi = times
        .iter()
        .copied()
        .fold(0.0f64, f64::max)
        .max(1e-3)
        .log10()
        .ceil()
        .max(ylo + 1.0);
    let mut o = String::new();
    let _ = writeln!(
        o,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif" font-size="11">"#
    );
    let _ = writeln!(o, r#"<rect width="{w}" height="{h}" fill="white"/>"#);
    for (i, &f) in families.iter().enumerate() {
        let (ox, oy) = ((i % cols) as f64 * pw, (i / cols) as f64 * ph);
        let sizes = sizes_of(r, f, Variant::Solvable);
        let xlo = (sizes[0] as f64).log10().floor();
        let xhi = (*sizes.last().unwrap_or(&10) as f64)
            .log10()
            .ceil()
            .max(xlo + 1.0);
        let (x0, x1, y0, y1) = (ox + ml, ox + pw - mr, oy + ph - mb, oy + mt);
        let px = |s: f64| x0 + (s.log10() - xlo) / (xhi - xlo) * (x1 - x0);
        let py = |t: f64| y0 - (t.log10() - ylo) / (yhi - ylo) * (y0 - y1);
        let _ = writeln!(
            o,
            r#"<text x="{}" y="{}" font-size="13" font-weight="bold" text-anchor="middle">{}</text>"#,
            (x0 + x1) / 2.0,
            oy + 18.0,
            f.name()
        );
        let _ = writeln!(
            o,
            r##"<rect x="{x0}" y="{y1}" width="{}" height="{}" fill="none" stroke="#444"/>"##,
            x1 - x0,
            y0 - y1
        );
        let mut d = xlo;
        while d <= xhi + 1e-9 {
            let x = px(10f64.powf(d));
            let _ = writeln!(
                o,
                r##"<line x1="{x}" y1="{y1}" x2="{x}" y2="{y0}" stroke="#ddd"/><text x="{x}" y="{}" text-anchor="middle">1e{d}</text>"##,
                y0 + 14.0
            );
            d += 1.0;
        }
        let mut e = ylo;
        while e <= yhi + 1e-9 {
            let y = py(10f64.powf(e));
            let _ = writeln!(
                o,
                r##"<line x1="{x0}" y1="{y}" x2="{x1}" y2="{y}" stroke="#ddd"/><text x="{}" y="{}" text-anchor="end">{}</text>"##,
                x0 - 4.0,
                y + 4.0,
                axis_label(e)
            );
            e += 1.0;
        }
        let _ = writeln!(
            o,
            r#"<text x="{}" y="{}" text-anchor="middle">size</text>"#,
            (x0 + x1) / 2.0,
            y0 + 30.0
        );
        for (k, &s) in solvers.iter().enumerate() {
            let cells: Vec<&Cell> = sizes
                .iter()
                .filter_map(|&z| r.cell(f, Variant::Solvable, z, s))
                .collect();
            let pts: Vec<(f64, f64)> = cells
                .iter()
                .filter(|c| c.verdict.has_time())
                .filter_map(|c| c.solve_ms.map(|t| (px(c.size as f64), py(t.max(1e-4)))))
                .collect();
            let width = if s == Solver::Loci { 2.5 } else { 1.5 };
            if pts.len() > 1 {
                let path: Vec<String> = pts.iter().map(|(x, y)| format!("{x:.1},{y:.1}")).collect();
                let _ = writeln!(
                    o,
                    r#"<polyline points="{}" fill="none" stroke="{}" stroke-width="{width}"/>"#,
                    path.join(" "),
                    color(s)
                );
            }
            for (x, y) in &pts {
                let _ = writeln!(
                    o,
                    r#"<circle cx="{x:.1}" cy="{y:.1}" r="3" fill="{}"/>"#,
                    color(s)
                );
            }
            for c in &cells {
                if !c.verdict.has_time() && !matches!(c.verdict, Verdict::NotRun { .. }) {
                    // Stacked per solver so crosses at the same size stay visible.
                    let (x, y) = (px(c.size as f64), y1 + 6.0 + 9.0 * k as f64);
                    let _ = writeln!(
                        o,
                        r#"<path d="M{} {} L{} {} M{} {} L{} {}" stroke="{}" stroke-width="2"/>"#,
                        x - 4.0,
                        y - 4.0,
                        x + 4.0,
                        y + 4.0,
                        x - 4.0,
                        y + 4.0,
                        x + 4.0,
                        y - 4.0,
                        color(s)
                    );
                }
            }
        }
    }
    // Legend in the next free panel.
    let i = families.len();
    let (ox, oy) = (
        (i % cols) as f64 * pw + ml,
        (i / cols) as f64 * ph + mt + 10.0,
    );
    let _ = writeln!(
        o,
        r#"<text x="{ox}" y="{oy}" font-size="12" font-weight="bold">median solve time (log) against size (log)</text>"#
    );
    for (k, &s) in solvers.iter().enumerate() {
        let y = oy + 22.0 + 20.0 * k as f64;
        let _ = writeln!(
            o,
            r#"<line x1="{ox}" y1="{y}" x2="{}" y2="{y}" stroke="{}" stroke-width="3"/><text x="{}" y="{}">{}</text>"#,
            ox + 24.0,
            color(s),
            ox + 30.0,
            y + 4.0,
            s.heading()
        );
    }
    let y = oy + 22.0 + 20.0 * solvers.len() as f64 + 6.0;
    let _ = writeln!(
        o,
        r#"<text x="{ox}" y="{y}">× near a panel's top: refused, timed out,</text><text x="{ox}" y="{}">crashed, failed or wrong at that size</text>"#,
        y + 14.0
    );
    o.push_str("</svg>\n");
    o
}
