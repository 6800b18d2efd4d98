//! The summary of a run: counts per outcome pair, per kind and variant, and every case worth
//! a look, with its seed.

use crate::case::Variant;
use crate::judge::{Grade, Resolve};
use crate::sketch::Dim;
use loci::ConstraintKind;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::time::Duration;

pub struct Row {
    pub seed: u64,
    pub label: String,
    /// The gadgets the system was built with (by name).
    pub gadgets: Vec<String>,
    pub dim: Dim,
    pub variant: Variant,
    pub kinds: Vec<ConstraintKind>,
    pub loci: Grade,
    pub loci_said: String,
    /// SolveSpace's grade and what it said, when it ran.
    pub ss: Option<(Grade, String)>,
    pub resolve: Option<Resolve>,
    pub notes: Vec<String>,
}

impl Row {
    /// loci is wrong, fails where SolveSpace is right, or a reused Solver is wrong.
    pub fn loci_bad(&self) -> bool {
        let ss_right = self.ss.as_ref().is_some_and(|(g, _)| g.is_right());
        matches!(self.loci, Grade::Wrong(_))
            || (matches!(self.loci, Grade::Failed(_)) && ss_right)
            || self.resolve.as_ref().is_some_and(|r| r.wrong)
    }
}

fn letter(g: &Grade) -> char {
    match g {
        Grade::Right => 'R',
        Grade::Wrong(_) => 'W',
        Grade::Failed(_) => 'F',
    }
}

fn why(g: &Grade) -> &str {
    match g {
        Grade::Right => "right",
        Grade::Wrong(w) | Grade::Failed(w) => w,
    }
}

/// The columns: loci's grade, then SolveSpace's ('-' without SolveSpace).
const PAIRS: [&str; 12] = [
    "RR", "RW", "RF", "WR", "FR", "WW", "WF", "FW", "FF", "R-", "W-", "F-",
];

fn group_name(dim: Dim, v: Variant) -> String {
    let d = match dim {
        Dim::Planar => "2D",
        Dim::Spatial => "3D",
    };
    format!("{d} {}", v.name())
}

fn describe(r: &Row) -> String {
    let mut s = format!(
        "  seed {:>6}  {}\n      loci: {} -- {}\n",
        r.seed,
        r.label,
        r.loci_said,
        why(&r.loci)
    );
    if let Some((g, said)) = &r.ss {
        let _ = writeln!(s, "      SolveSpace: {said} -- {}", why(g));
    }
    if let Some(p) = &r.resolve {
        let _ = writeln!(s, "      re-solve: {}", p.what);
    }
    for n in &r.notes {
        let _ = writeln!(s, "      note: {n}");
    }
    s
}

pub fn summary(
    rows: &[Row],
    peer: Option<&str>,
    total: Duration,
    peer_time: Duration,
    verbose: bool,
) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "\nrandom differential: {} systems against {} in {:.1} s (SolveSpace's batch {:.1} s)",
        rows.len(),
        peer.unwrap_or("NOTHING (SolveSpace not available)"),
        total.as_secs_f64(),
        peer_time.as_secs_f64()
    );
    let _ = writeln!(
        s,
        "columns: loci's grade then SolveSpace's; R right, W wrong (a false claim), F failed (no claim: did not converge, crash), - not run"
    );
    let mut table: BTreeMap<String, BTreeMap<&str, usize>> = BTreeMap::new();
    for r in rows {
        let pair = format!(
            "{}{}",
            letter(&r.loci),
            r.ss.as_ref().map_or('-', |(g, _)| letter(g))
        );
        let key = PAIRS.iter().find(|p| **p == pair).copied().unwrap_or("??");
        for g in [group_name(r.dim, r.variant), "all".to_string()] {
            *table.entry(g).or_default().entry(key).or_default() += 1;
        }
    }
    let used: Vec<&str> = PAIRS
        .iter()
        .copied()
        .filter(|p| table.values().any(|m| m.contains_key(p)))
        .collect();
    let _ = write!(s, "{:<16}", "");
    for p in &used {
        let _ = write!(s, "{p:>7}");
    }
    s.push('\n');
    let mut names: Vec<String> = table.keys().filter(|k| *k != "all").cloned().collect();
    names.push("all".into());
    for name in &names {
        let _ = write!(s, "{name:<16}");
        for p in &used {
            let _ = write!(s, "{:>7}", table[name].get(p).copied().unwrap_or(0));
        }
        s.push('\n');
    }

    // Where the disagreements come from: the gadgets of the systems of each pair.
    let _ = writeln!(
        s,
        "by construction (a system counts once for each gadget it has):"
    );
    for p in used.iter().filter(|p| **p != "RR" && **p != "R-") {
        let mut by: BTreeMap<String, usize> = BTreeMap::new();
        let mut n = 0;
        for r in rows {
            let pair = format!(
                "{}{}",
                letter(&r.loci),
                r.ss.as_ref().map_or('-', |(g, _)| letter(g))
            );
            if pair != *p {
                continue;
            }
            n += 1;
            if r.gadgets.is_empty() {
                *by.entry(format!("{} (no gadget)", r.variant.name()))
                    .or_default() += 1;
            }
            for g in &r.gadgets {
                *by.entry(g.clone()).or_default() += 1;
            }
        }
        let mut list: Vec<(String, usize)> = by.into_iter().collect();
        list.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
        let list: Vec<String> = list.iter().map(|(g, k)| format!("{g} {k}")).collect();
        let _ = writeln!(s, "  {p} {n:>5}: {}", list.join(", "));
    }

    let mut kinds: BTreeMap<&str, usize> = BTreeMap::new();
    for r in rows {
        for k in &r.kinds {
            *kinds.entry(k.name()).or_default() += 1;
        }
    }
    let list: Vec<String> = kinds.iter().map(|(k, n)| format!("{k} {n}")).collect();
    let _ = writeln!(s, "constraints generated: {}", list.join(", "));

    // loci's wrong answers by what went wrong (numbers and handle lists elided).
    let mut shapes: BTreeMap<String, usize> = BTreeMap::new();
    for r in rows {
        let dim = match r.dim {
            Dim::Planar => "2D",
            Dim::Spatial => "3D",
        };
        if let Grade::Wrong(w) = &r.loci {
            *shapes.entry(format!("{dim} {}", shape(w))).or_default() += 1;
        }
        if matches!(r.loci, Grade::Failed(_)) && r.ss.as_ref().is_some_and(|(g, _)| g.is_right()) {
            *shapes
                .entry(format!(
                    "{dim} {} where SolveSpace is right",
                    shape(why(&r.loci))
                ))
                .or_default() += 1;
        }
        if let Some(p) = r.resolve.as_ref().filter(|p| p.wrong) {
            *shapes
                .entry(format!("{dim} re-solve, {}", shape(&p.what)))
                .or_default() += 1;
        }
    }
    if !shapes.is_empty() {
        let _ = writeln!(s, "loci's wrong answers by kind:");
        let mut list: Vec<(String, usize)> = shapes.into_iter().collect();
        list.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
        for (k, n) in list {
            let _ = writeln!(s, "  {n:>5}  {k}");
        }
    }

    let section = |s: &mut String, title: &str, pick: &dyn Fn(&Row) -> bool, max: usize| {
        let hits: Vec<&Row> = rows.iter().filter(|r| pick(r)).collect();
        if hits.is_empty() {
            return;
        }
        let _ = writeln!(s, "\n{title}: {}", hits.len());
        for r in hits.iter().take(max) {
            s.push_str(&describe(r));
        }
        if hits.len() > max {
            let more: Vec<String> = hits[max..].iter().map(|r| r.seed.to_string()).collect();
            let _ = writeln!(s, "  ... and seeds {}", more.join(","));
        }
    };
    let ss_right = |r: &Row| r.ss.as_ref().is_some_and(|(g, _)| g.is_right());
    let ss_wrong = |r: &Row| {
        r.ss.as_ref()
            .is_some_and(|(g, _)| matches!(g, Grade::Wrong(_)))
    };
    let ss_failed = |r: &Row| {
        r.ss.as_ref()
            .is_some_and(|(g, _)| matches!(g, Grade::Failed(_)))
    };
    section(
        &mut s,
        "LOCI WRONG (a false claim)",
        &|r| matches!(r.loci, Grade::Wrong(_)),
        usize::MAX,
    );
    section(
        &mut s,
        "LOCI FAILED WHERE SOLVESPACE WAS RIGHT",
        &|r| matches!(r.loci, Grade::Failed(_)) && ss_right(r),
        usize::MAX,
    );
    section(
        &mut s,
        "LOCI WRONG IN A RE-SOLVE (a reused Solver, or a fresh solve of the changed system)",
        &|r| r.resolve.as_ref().is_some_and(|p| p.wrong),
        usize::MAX,
    );
    section(
        &mut s,
        "reused Solver's verdict differs from a fresh solve's (not proven wrong)",
        &|r| r.resolve.as_ref().is_some_and(|p| !p.wrong),
        20,
    );
    section(
        &mut s,
        "both failed",
        &|r| matches!(r.loci, Grade::Failed(_)) && !ss_right(r),
        20,
    );
    section(
        &mut s,
        "SolveSpace wrong where loci was right",
        &|r| r.loci.is_right() && ss_wrong(r),
        10,
    );
    section(
        &mut s,
        "SolveSpace failed where loci was right",
        &|r| r.loci.is_right() && ss_failed(r),
        10,
    );
    // Each kind of note with the seeds it came from, so that a note can be looked at.
    let mut notes: BTreeMap<String, Vec<u64>> = BTreeMap::new();
    for r in rows {
        for n in &r.notes {
            let kind = if n.starts_with("conflict set") {
                "conflict set of the diagnosis not minimal".to_string()
            } else {
                n.clone()
            };
            notes.entry(kind).or_default().push(r.seed);
        }
    }
    if !notes.is_empty() {
        let list: Vec<String> = notes
            .iter()
            .map(|(k, seeds)| {
                let shown: Vec<String> = seeds.iter().take(20).map(u64::to_string).collect();
                let more = if seeds.len() > 20 { ", ..." } else { "" };
                format!("{k}: {} (seeds {}{more})", seeds.len(), shown.join(","))
            })
            .collect();
        let _ = writeln!(s, "\nnotes (not failures): {}", list.join("; "));
    }
    if verbose {
        let _ = writeln!(s, "\nevery system:");
        for r in rows {
            s.push_str(&describe(r));
        }
    }
    s
}

/// A description with its numbers and handle lists elided, to count descriptions alike.
fn shape(text: &str) -> String {
    let mut out = String::new();
    let mut depth = 0;
    let mut prev_num = false;
    for ch in text.chars() {
        match ch {
            '[' => {
                depth += 1;
                if depth == 1 {
                    out.push_str("[..]");
                }
            }
            ']' => depth -= 1,
            _ if depth > 0 => {}
            '(' if out.ends_with(' ') => {
                // A parenthesised verdict (outcome, dof, failed) repeats what is said: drop it.
                depth += 1;
                out.pop();
            }
            c if c.is_ascii_digit() || (prev_num && matches!(c, '.' | 'e' | '-')) => {
                if !prev_num {
                    out.push('N');
                }
                prev_num = true;
                continue;
            }
            c => out.push(c),
        }
        prev_num = false;
    }
    out
}
