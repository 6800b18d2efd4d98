//! `loci-bench`: runs the comparison and writes `docs/benchmarks.md` and `docs/benchmarks.svg`.
//!
//! ```text
//! loci-bench [--quick] [--out DIR] [--limit SECONDS] [--solvers loci,ezpz,...]
//!            [--families chain,grid,...] [--max-size N] [--sizes N,N,...]
//! loci-bench worker SOLVER PROBLEM.json REPS BUDGET_S OUT.json
//! loci-bench emit FAMILY VARIANT SIZE DIR
//! loci-bench report DIR
//! loci-bench assembly [--sizes N,N,...] [--reps N] [--chains-only] [--cadquery PYTHON]
//! loci-bench python [--sizes N,N,...] [--python PATH] [--slvs-python PATH] [--limit S]
//! loci-bench drag [SIZES [STEPS]] [--long] [--peers slvs,planegcs,brep|none] [--peer-limit S]
//!                                     (sizes as 100,1000,10000; 600 steps)
//! loci-bench wasm [--chain N,N,...] [--grid N,N,...] [--reps N] [--limit SECONDS]
//!                 (loci-wasm under node against native loci and PlaneGCS; build the package
//!                  first with scripts/build-wasm.sh)
//! ```

use anyhow::{bail, Context, Result};
use loci_bench::compare::{compare, Settings};
use loci_bench::generate::generate;
use loci_bench::problem::{Family, Problem, Variant};
use loci_bench::report;
use loci_bench::run::{run_in_process, ProblemFiles, Solver};
use loci_bench::setup::setup;
use std::path::{Path, PathBuf};
use std::time::Duration;

/// Both solvers timed in this process (loci and ezpz) allocate through mimalloc. With glibc's
/// malloc, the large blocks of a 10,000-segment solve go back to the kernel when freed, and the
/// next repetition pays a page fault for every 4 KiB it touches again: a third of the time,
/// spent measuring the allocator rather than the solver.
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

const USAGE: &str = "usage: loci-bench [--quick] [--out DIR] [--limit SECONDS] \
[--solvers loci,ezpz,slvs_py,slvs_c,planegcs] [--families chain,triangles,grid,fillets,chain_3d,truss,mesh,profiles] \
[--max-size N] [--sizes N,N,...]";

fn main() {
    if let Err(e) = real_main() {
        eprintln!("loci-bench: {e:#}");
        std::process::exit(3);
    }
}

fn real_main() -> Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("worker") => return worker(&args[1..]),
        Some("emit") => return emit(&args[1..]),
        Some("report") => return rerender(&args[1..]),
        Some("assembly") => return assembly(&args[1..]),
        Some("drag") => return drag(&args[1..]),
        Some("python") => return python(&args[1..]),
        Some("wasm") => return wasm(&args[1..]),
        _ => {}
    }
    let mut quick = false;
    let mut out: Option<PathBuf> = None;
    let mut limit: Option<f64> = None;
    let mut solvers: Option<Vec<Solver>> = None;
    let mut families: Option<Vec<Family>> = None;
    let mut max_size: Option<usize> = None;
    let mut sizes: Option<Vec<usize>> = None;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let mut value = || {
            it.next()
                .with_context(|| format!("{a} needs a value\n{USAGE}"))
        };
        match a.as_str() {
            "--quick" => quick = true,
            "--out" => out = Some(PathBuf::from(value()?)),
            "--limit" => limit = Some(value()?.parse().context("--limit takes seconds")?),
            "--max-size" => max_size = Some(value()?.parse().context("--max-size takes a number")?),
            "--sizes" => {
                sizes = Some(
                    value()?
                        .split(',')
                        .map(|s| s.parse().with_context(|| format!("bad size {s}")))
                        .collect::<Result<_>>()?,
                );
            }
            "--solvers" => {
                solvers = Some(
                    value()?
                        .split(',')
                        .map(|s| Solver::from_name(s).with_context(|| format!("no solver {s}")))
                        .collect::<Result<_>>()?,
                );
            }
            "--families" => {
                families = Some(
                    value()?
                        .split(',')
                        .map(|s| {
                            Family::ALL
                                .into_iter()
                                .find(|f| f.name() == s)
                                .with_context(|| format!("no family {s}"))
                        })
                        .collect::<Result<_>>()?,
                );
            }
            "-h" | "--help" => {
                println!("{USAGE}");
                return Ok(());
            }
            other => bail!("unknown argument {other}\n{USAGE}"),
        }
    }
    let mut settings = Settings::new(quick);
    if let Some(s) = solvers {
        settings.solvers = s;
    }
    if let Some(f) = families {
        settings.families = f;
    }
    if let Some(m) = max_size {
        settings.max_size = m;
    }
    settings.sizes = sizes;
    if let Some(l) = limit {
        settings.limit = Duration::from_secs_f64(l);
    }
    let bench = Path::new(env!("CARGO_MANIFEST_DIR"));
    let repo = bench.parent().unwrap_or(bench);
    let out = out.unwrap_or_else(|| {
        if quick {
            std::env::temp_dir().join("loci-bench-quick")
        } else {
            repo.join("docs")
        }
    });
    std::fs::create_dir_all(&out).with_context(|| format!("creating {}", out.display()))?;
    let work = std::env::temp_dir().join(format!("loci-bench-{}", std::process::id()));
    std::fs::create_dir_all(&work)?;

    eprintln!("setting up peers ...");
    let (runners, avail) = setup(bench, &bench.join(".build"), &settings.solvers);
    for (s, a) in &avail {
        match a {
            Ok(v) => eprintln!("  {:<9} {v}", s.name()),
            Err(e) => eprintln!("  {:<9} not available: {e}", s.name()),
        }
    }
    let started = std::time::Instant::now();
    let mut results = compare(&settings, &runners, &avail, &work, |line| {
        eprintln!("{line}")
    });
    let _ = std::fs::remove_dir_all(&work);
    let command = if args.is_empty() {
        "cargo run --release -p loci-bench".to_string()
    } else {
        format!("cargo run --release -p loci-bench -- {}", args.join(" "))
    };
    let m = &mut results.meta;
    m.insert("date".into(), today_utc());
    m.insert("machine".into(), cpu_model());
    m.insert(
        "cores".into(),
        std::thread::available_parallelism().map_or("?".into(), |n| n.to_string()),
    );
    m.insert("memory".into(), memory());
    m.insert(
        "os".into(),
        std::fs::read_to_string("/proc/sys/kernel/osrelease")
            .map_or("?".into(), |s| format!("Linux {}", s.trim())),
    );
    m.insert("rustc".into(), command_line("rustc", &["--version"], repo));
    m.insert(
        "loci commit".into(),
        command_line("git", &["rev-parse", "--short", "HEAD"], repo),
    );
    m.insert("command".into(), command.clone());
    m.insert("reps".into(), settings.reps.to_string());
    m.insert("budget_s".into(), settings.budget_s.to_string());
    m.insert("rounds".into(), settings.rounds.to_string());
    m.insert("limit_s".into(), settings.limit.as_secs_f64().to_string());
    m.insert(
        "wall_s".into(),
        format!("{:.0}", started.elapsed().as_secs_f64()),
    );
    std::fs::write(
        out.join("benchmarks.md"),
        report::markdown(&results, &command),
    )?;
    std::fs::write(out.join("benchmarks.svg"), report::svg(&results))?;
    std::fs::write(
        out.join("benchmarks.json"),
        serde_json::to_string_pretty(&results)?,
    )?;
    eprintln!(
        "wrote {} (benchmarks.md, .svg, .json) in {:.0} s",
        out.display(),
        started.elapsed().as_secs_f64()
    );
    Ok(())
}

/// `worker SOLVER PROBLEM.json REPS BUDGET_S OUT.json`: one in-process solver on one problem.
fn worker(args: &[String]) -> Result<()> {
    let [solver, problem, reps, budget, out] = args else {
        bail!("usage: loci-bench worker SOLVER PROBLEM.json REPS BUDGET_S OUT.json");
    };
    let solver = Solver::from_name(solver).with_context(|| format!("no solver {solver}"))?;
    let text = std::fs::read_to_string(problem).with_context(|| format!("reading {problem}"))?;
    let p: Problem = serde_json::from_str(&text).with_context(|| format!("parsing {problem}"))?;
    let o = run_in_process(solver, &p, reps.parse()?, budget.parse()?)?;
    std::fs::write(out, serde_json::to_string(&o)?)?;
    Ok(())
}

/// `report DIR`: writes `benchmarks.md` and `.svg` again from `DIR/benchmarks.json`, to
/// change the report's layout without measuring again.
fn rerender(args: &[String]) -> Result<()> {
    let [dir] = args else {
        bail!("usage: loci-bench report DIR");
    };
    let dir = Path::new(dir);
    let json = dir.join("benchmarks.json");
    let text =
        std::fs::read_to_string(&json).with_context(|| format!("reading {}", json.display()))?;
    let results: loci_bench::compare::Results = serde_json::from_str(&text)?;
    let command = results
        .meta
        .get("command")
        .cloned()
        .unwrap_or_else(|| "cargo run --release -p loci-bench".into());
    std::fs::write(
        dir.join("benchmarks.md"),
        report::markdown(&results, &command),
    )?;
    std::fs::write(dir.join("benchmarks.svg"), report::svg(&results))?;
    Ok(())
}

/// `emit FAMILY VARIANT SIZE DIR`: writes one problem in every input format, to rerun a
/// single cell by hand with a runner.
fn emit(args: &[String]) -> Result<()> {
    let [family, variant, size, dir] = args else {
        bail!("usage: loci-bench emit FAMILY VARIANT SIZE DIR");
    };
    let family = Family::ALL
        .into_iter()
        .find(|f| f.name() == family)
        .with_context(|| format!("no family {family}"))?;
    let variant = Variant::ALL
        .into_iter()
        .find(|v| v.name() == variant)
        .with_context(|| format!("no variant {variant}"))?;
    let p = generate(
        family,
        variant,
        size.parse().context("SIZE takes a number")?,
    );
    std::fs::create_dir_all(dir)?;
    let files = ProblemFiles::new(&p, Path::new(dir));
    eprintln!("{}", files.neutral()?.display());
    eprintln!("{}", files.records()?.display());
    if p.planar {
        eprintln!("{}", files.planegcs()?.display());
    }
    let wasm = Path::new(dir).join(format!("{}.wasm.json", p.label().replace('/', "_")));
    std::fs::write(&wasm, loci_bench::wasm::wasm_input(&p)?)?;
    eprintln!("{}", wasm.display());
    Ok(())
}

fn command_line(program: &str, args: &[&str], dir: &Path) -> String {
    std::process::Command::new(program)
        .args(args)
        .current_dir(dir)
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map_or("?".into(), |o| {
            String::from_utf8_lossy(&o.stdout).trim().to_string()
        })
}

fn cpu_model() -> String {
    std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| "?".into())
}

fn memory() -> String {
    std::fs::read_to_string("/proc/meminfo")
        .ok()
        .and_then(|s| {
            let kb: f64 = s
                .lines()
                .find(|l| l.starts_with("MemTotal"))?
                .split_whitespace()
                .nth(1)?
                .parse()
                .ok()?;
            Some(format!("{:.0} GiB", kb / 1024.0 / 1024.0))
        })
        .unwrap_or_else(|| "?".into())
}

/// Today's date in UTC as YYYY-MM-DD, from the system clock (civil-from-days).
fn today_utc() -> String {
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let z = (secs / 86_400) as i64 + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!("{y:04}-{m:02}-{d:02}")
}

/// `loci-bench assembly`: the assembly benchmark, printed as a markdown table.
fn assembly(args: &[String]) -> Result<()> {
    let mut sizes = vec![10, 100, 1_000, 10_000];
    let mut reps = 5;
    let mut others = true;
    let mut cadquery: Option<PathBuf> = None;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--sizes" => {
                sizes = it
                    .next()
                    .context("--sizes needs a value")?
                    .split(',')
                    .map(|s| s.parse().with_context(|| format!("bad size {s}")))
                    .collect::<Result<_>>()?;
            }
            "--reps" => reps = it.next().context("--reps needs a value")?.parse()?,
            "--chains-only" => others = false,
            "--cadquery" => {
                cadquery = Some(it.next().context("--cadquery needs a Python path")?.into());
            }
            other => bail!("unknown option {other}; usage: loci-bench assembly [--sizes N,N,...] [--reps N] [--chains-only] [--cadquery PYTHON]"),
        }
    }
    let t = loci_bench::assembly::run_all(
        &sizes,
        reps,
        others,
        Some(Path::new(env!("CARGO_MANIFEST_DIR"))),
        cadquery.as_deref(),
    );
    print!("{}", loci_bench::assembly::table(&t));
    Ok(())
}

/// `loci-bench python`: a chain built and solved through the Python package (`loci.Sketch`,
/// `loci.slvs`), through SolveSpace's `slvs` and in Rust, side by side.
fn python(args: &[String]) -> Result<()> {
    use loci_bench::python::{default_python, run_all, table};
    const USAGE: &str = "usage: loci-bench python [--sizes N,N,...] [--python PATH] \
[--slvs-python PATH] [--limit SECONDS]";
    let bench = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut sizes = vec![1_000, 10_000];
    let mut py = default_python(bench);
    let mut slvs_py: Option<PathBuf> = None;
    let mut limit = 300.0;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let mut value = || {
            it.next()
                .with_context(|| format!("{a} needs a value\n{USAGE}"))
        };
        match a.as_str() {
            "--sizes" => {
                sizes = value()?
                    .split(',')
                    .map(|s| s.parse().with_context(|| format!("bad size {s}")))
                    .collect::<Result<_>>()?;
            }
            "--python" => py = PathBuf::from(value()?),
            "--slvs-python" => slvs_py = Some(PathBuf::from(value()?)),
            "--limit" => limit = value()?.parse().context("--limit takes seconds")?,
            other => bail!("unknown option {other}\n{USAGE}"),
        }
    }
    if !py.exists() {
        bail!(
            "no Python with the loci package at {} (run crates/loci-py/run-tests.sh, or give --python)",
            py.display()
        );
    }
    // SolveSpace's module where loci-bench keeps it, else beside loci.
    let slvs_py = slvs_py.unwrap_or_else(|| {
        let venv = bench.join(".venv/bin/python");
        if venv.exists() {
            venv
        } else {
            py.clone()
        }
    });
    let rows = run_all(&sizes, &py, &slvs_py, bench, Duration::from_secs_f64(limit));
    print!("{}", table(&rows));
    Ok(())
}

/// `loci-bench drag [SIZES [STEPS]] [--long] [--peers slvs,planegcs,brep|none]
/// [--peer-limit SECONDS]`: the drag benchmark, loci and the peers that are installed on the
/// same sketches and path, printed as one markdown table. Peers run at 100 shapes only unless
/// `--long` (at 1,000 shapes and more a peer's run takes minutes); each run stops at the limit
/// (180 s, or 600 s with `--long`).
fn drag(args: &[String]) -> Result<()> {
    use loci_bench::drag_peers::{run_peer, Peer, PeerRun, Row};
    let mut positional = Vec::new();
    let mut long = false;
    let mut peers: Vec<Peer> = Peer::ALL.to_vec();
    let mut limit: Option<f64> = None;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--long" => long = true,
            "--peers" => {
                let v = it.next().context("--peers needs a list")?;
                peers = Vec::new();
                for k in v.split(',').filter(|k| *k != "none" && !k.is_empty()) {
                    let p = Peer::ALL
                        .into_iter()
                        .find(|p| p.key() == k)
                        .with_context(|| format!("unknown peer {k} (slvs, planegcs, brep)"))?;
                    peers.push(p);
                }
            }
            "--peer-limit" => {
                let v = it.next().context("--peer-limit needs seconds")?;
                limit = Some(v.parse().context("--peer-limit is a number of seconds")?);
            }
            _ => positional.push(a.clone()),
        }
    }
    let sizes: Vec<usize> = match positional.first() {
        Some(s) => s
            .split(',')
            .map(|n| n.parse().with_context(|| format!("bad size {n}")))
            .collect::<Result<_>>()?,
        None => vec![100, 1000, 10_000],
    };
    let steps: usize = match positional.get(1) {
        Some(s) => s.parse().context("steps is a number")?,
        None => 600,
    };
    let steps = steps.max(2);
    let limit = Duration::from_secs_f64(limit.unwrap_or(if long { 600.0 } else { 180.0 }));
    let bench = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut rows = Vec::new();
    for &n in &sizes {
        for loci in loci_bench::drag::drag_benchmark(&[n], steps) {
            let peers = peers
                .iter()
                .map(|&p| {
                    let run = if n > 100 && !long {
                        PeerRun::Skipped("above 100 shapes peers run only with --long".into())
                    } else {
                        eprintln!("loci-bench drag: {} on {} ({n})", p.name(), loci.sketch);
                        run_peer(p, bench, loci.sketch, n, steps, limit)
                    };
                    (p, run)
                })
                .collect();
            rows.push(Row { loci, peers });
        }
    }
    print!("{}", loci_bench::drag_peers::table(&rows));
    Ok(())
}

/// `loci-bench wasm [--chain N,...] [--grid N,...] [--reps N] [--limit SECONDS]`: loci as
/// WebAssembly under node, native loci and PlaneGCS on the chain and grid families, in one run.
fn wasm(args: &[String]) -> Result<()> {
    use loci_bench::wasm::{run_family, table, Setup};
    let list = |v: &str| -> Result<Vec<usize>> {
        v.split(',')
            .map(|s| s.parse().with_context(|| format!("bad size {s}")))
            .collect()
    };
    let mut chain = vec![10, 30, 100, 300, 1_000, 3_000, 10_000];
    let mut grid = vec![3, 5, 10, 17, 32, 50, 100];
    // Up to 2 s of builds and solves per size and solver: small problems take a thousand
    // repetitions rather than 11.
    let mut reps = 1001;
    let mut limit = 60.0;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let mut value = || it.next().with_context(|| format!("{a} needs a value"));
        match a.as_str() {
            "--chain" => chain = list(value()?)?,
            "--grid" => grid = list(value()?)?,
            "--reps" => reps = value()?.parse().context("--reps takes a number")?,
            "--limit" => limit = value()?.parse().context("--limit takes seconds")?,
            other => bail!("unknown argument {other}"),
        }
    }
    let bench = Path::new(env!("CARGO_MANIFEST_DIR"));
    let repo = bench.parent().unwrap_or(bench);
    // Both WebAssembly runners solve untimed for a second first, so that node has recompiled
    // the hot functions with its optimising compiler (native loci is compiled ahead of time).
    std::env::set_var("LOCI_BENCH_WARMUP_S", "1");
    eprintln!("setting up PlaneGCS ...");
    let (runners, avail) = setup(bench, &bench.join(".build"), &[Solver::PlaneGcs]);
    for (s, a) in &avail {
        if let Err(e) = a {
            eprintln!("  {} not available: {e}", s.name());
        }
    }
    let work = std::env::temp_dir().join(format!("loci-bench-wasm-{}", std::process::id()));
    std::fs::create_dir_all(&work)?;
    let s = Setup {
        node: PathBuf::from("node"),
        repo,
        runners: &runners,
        reps,
        budget_s: 2.0,
        limit: Duration::from_secs_f64(limit),
        work: &work,
    };
    let mut rows = run_family(&s, Family::Chain, &chain, |l| eprintln!("{l}"));
    rows.extend(run_family(&s, Family::Grid, &grid, |l| eprintln!("{l}")));
    let _ = std::fs::remove_dir_all(&work);
    print!("{}", table(&rows));
    Ok(())
}
