//! `loci`: solve and check constraint problems from the command line.
//!
//! Exit status: 0 solved (okay or okay with redundant constraints), 1 inconsistent,
//! 2 did not converge, 3 bad input (unreadable, malformed or invalid model).

/// Prints to standard output; a closed pipe (`loci solve f | head`) ends the program quietly
/// with status 0 instead of a panic.
macro_rules! out {
    ($($t:tt)*) => { $crate::emit(&format!($($t)*)) };
}

/// [`out!`] with a newline.
macro_rules! outln {
    ($($t:tt)*) => { $crate::emit(&format!("{}\n", format!($($t)*))) };
}

mod assemble;
mod assembly_svg;
mod check;
mod conformance;
mod drag;
mod render;
mod report;
mod sketch;
mod slvs;

use clap::{Parser, Subcommand};
use loci::format::json::{JsonError, Problem, SolveResult};
use std::path::PathBuf;
use std::process::ExitCode;

/// A geometric constraint solver for CAD.
#[derive(Parser)]
#[command(name = "loci", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Solve a problem file and print a report: a loci JSON problem, or a SolveSpace `.slvs`
    /// file (every group in order, each reported).
    Solve {
        /// A loci JSON problem or a SolveSpace `.slvs` file.
        file: PathBuf,
        /// Print the result as JSON instead of a report.
        #[arg(long)]
        json: bool,
        /// Solve this group instead of the one the file names.
        #[arg(long)]
        group: Option<u32>,
        /// Write the solved problem here (JSON; for a `.slvs` input, `.slvs` or `.json` by
        /// the name's extension).
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
    /// Diagnose a problem file: degrees of freedom entity by entity, redundant and
    /// conflicting constraints, over-constrained blocks, reference measurements.
    Check {
        /// A loci JSON problem.
        file: PathBuf,
        /// Print the diagnosis as JSON instead of a report.
        #[arg(long)]
        json: bool,
        /// Check this group instead of the one the file names.
        #[arg(long)]
        group: Option<u32>,
        /// List fixed entities too, not only those that can move.
        #[arg(long)]
        all: bool,
    },
    /// Convert a SolveSpace `.slvs` file to a loci JSON problem (`--to json`), or a loci JSON
    /// problem to a `.slvs` file SolveSpace opens (`--to slvs`).
    Convert {
        /// The `.slvs` or `.json` file.
        file: PathBuf,
        /// The format to write: `json` (from `.slvs`) or `slvs` (from `.json`).
        #[arg(long, value_parser = ["json", "slvs"])]
        to: String,
        /// Write here instead of standard output.
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
    /// Draw a sketch as SVG: geometry coloured by whether it can still move, construction
    /// geometry dashed, constraints and dimensions, conflicting constraints in red. The exit
    /// status is `loci solve`'s; the picture is written whatever the outcome.
    Render {
        /// A loci JSON problem or a SolveSpace `.slvs` file (its last sketch group unless
        /// `--group` says otherwise).
        file: PathBuf,
        /// Write the SVG here instead of standard output.
        #[arg(short, long)]
        output: Option<PathBuf>,
        /// Draw this group instead of the one the file names.
        #[arg(long)]
        group: Option<u32>,
        /// Draw the file's values as they are, without solving first.
        #[arg(long)]
        no_solve: bool,
    },
    /// Solve an assembly file (components, mates, joints) and print each mate's status, the
    /// assembly's degrees of freedom and every component's remaining motions.
    Assemble {
        /// A loci assembly JSON file (docs/assembly-format.md).
        file: PathBuf,
        /// Print the report as JSON.
        #[arg(long)]
        json: bool,
        /// Run the stepped relaxation instead, printing every pass.
        #[arg(long)]
        steps: bool,
        /// Write the assembly with its solved poses here.
        #[arg(short, long)]
        output: Option<PathBuf>,
        /// Draw the solved assembly here as an SVG (isometric wireframe of frames and
        /// references).
        #[arg(long)]
        svg: Option<PathBuf>,
    },
    /// Drag a shape of a sketch file toward a point in equal steps, printing each step.
    Drag {
        /// A sketch file.
        file: PathBuf,
        /// The name of the point (or other shape) to drag.
        #[arg(long)]
        point: String,
        /// Where to: X,Y.
        #[arg(long, value_parser = drag::parse_xy, allow_hyphen_values = true)]
        to: [f64; 2],
        /// How many steps.
        #[arg(long, default_value_t = 10)]
        steps: usize,
        /// Write the dragged sketch here.
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
    /// Check loci against SolveSpace's regression fixtures and print a Markdown report.
    Conformance {
        /// The folder of `.slvs` files (searched recursively).
        dir: PathBuf,
    },
}

/// Exit codes.
pub(crate) mod code {
    pub const SOLVED: u8 = 0;
    pub const INCONSISTENT: u8 = 1;
    pub const DID_NOT_CONVERGE: u8 = 2;
    pub const BAD_INPUT: u8 = 3;
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(c) => ExitCode::from(c),
        Err(e) => {
            eprintln!("loci: error: {e:#}");
            ExitCode::from(code::BAD_INPUT)
        }
    }
}

fn run(cli: Cli) -> anyhow::Result<u8> {
    match cli.command {
        Command::Solve {
            file, json, output, ..
        } if sketch::is_sketch(&file) => sketch::solve(&file, json, output.as_deref()),
        Command::Check { file, json, .. } if sketch::is_sketch(&file) => sketch::check(&file, json),
        Command::Drag {
            file,
            point,
            to,
            steps,
            output,
        } => drag::run(&file, &point, to, steps, output.as_deref()),
        Command::Solve {
            file,
            json,
            group,
            output,
        } if file.extension().is_some_and(|e| e == "slvs") => {
            slvs::solve(&file, json, group, output.as_deref())
        }
        Command::Solve {
            file,
            json,
            group,
            output,
        } => {
            let text = std::fs::read_to_string(&file)
                .map_err(|e| anyhow::anyhow!("cannot read {}: {e}", file.display()))?;
            let mut problem = Problem::from_json(&text)
                .map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
            let mut req = problem.request();
            if let Some(g) = group {
                req.group = g.into();
            }
            let before = problem.system.clone();
            let rep = loci::solve(&mut problem.system, req.group, &req.dragged, &req.config())
                .map_err(|e| {
                    let e = JsonError::from_solve(&text, &problem.system, &e);
                    anyhow::anyhow!("{}: {e}", file.display())
                })?;
            if json {
                outln!(
                    "{}",
                    SolveResult::new(&problem.system, req.group, &rep).to_json()
                );
            } else {
                out!(
                    "{}",
                    report::render(
                        &file.display().to_string(),
                        req.group,
                        &before,
                        &problem.system,
                        &rep,
                        req.config().max_iterations
                    )
                );
            }
            if let Some(out) = output {
                std::fs::write(&out, problem.to_json())
                    .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", out.display()))?;
            }
            Ok(exit_code(rep.outcome))
        }
        Command::Check { file, .. } if file.extension().is_some_and(|e| e == "slvs") => {
            anyhow::bail!(
                "{}: `loci check` reads loci JSON problems; convert the file first with \
                 `loci convert {} --to json -o FILE.json`, or solve it with `loci solve`",
                file.display(),
                file.display()
            )
        }
        Command::Check {
            file,
            json,
            group,
            all,
        } => {
            let text = std::fs::read_to_string(&file)
                .map_err(|e| anyhow::anyhow!("cannot read {}: {e}", file.display()))?;
            let problem = Problem::from_json(&text)
                .map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
            let mut req = problem.request();
            if let Some(g) = group {
                req.group = g.into();
            }
            let d = loci::diagnose(&problem.system, req.group, &req.config()).map_err(|e| {
                let e = JsonError::from_solve(&text, &problem.system, &e);
                anyhow::anyhow!("{}: {e}", file.display())
            })?;
            if json {
                outln!(
                    "{}",
                    serde_json::to_string_pretty(&d).map_err(|e| anyhow::anyhow!("{e}"))?
                );
            } else {
                out!(
                    "{}",
                    check::render(&file.display().to_string(), &problem.system, &d, all)
                );
            }
            Ok(check::exit_code(&d))
        }
        Command::Assemble {
            file,
            json,
            steps,
            output,
            svg,
        } => assemble::run(&file, json, steps, output.as_deref(), svg.as_deref()),
        Command::Convert { file, to, output } => {
            let ext = file.extension().and_then(|e| e.to_str()).unwrap_or("");
            if ext == to {
                anyhow::bail!(
                    "{}: the file is already .{to}; `--to {to}` converts from .{}",
                    file.display(),
                    if to == "slvs" { "json" } else { "slvs" }
                );
            }
            let bytes = if to == "slvs" {
                slvs::from_json(&file)?
            } else {
                let mut text = slvs::to_json(&file)?;
                text.push('\n');
                text.into_bytes()
            };
            match output {
                Some(out) => std::fs::write(&out, bytes)
                    .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", out.display()))?,
                None => emit_bytes(&bytes),
            }
            Ok(code::SOLVED)
        }
        Command::Render {
            file,
            output,
            group,
            no_solve,
        } => render::command::run(&file, output.as_deref(), group, no_solve),
        Command::Conformance { dir } => {
            let cmd = format!("loci conformance {}", dir.display());
            let (md, _) = conformance::run(&dir, &cmd)?;
            out!("{md}");
            Ok(code::SOLVED)
        }
    }
}

pub(crate) fn exit_code(o: loci::Outcome) -> u8 {
    match o {
        loci::Outcome::Okay | loci::Outcome::RedundantOkay => code::SOLVED,
        loci::Outcome::Inconsistent => code::INCONSISTENT,
        loci::Outcome::DidNotConverge => code::DID_NOT_CONVERGE,
    }
}

/// Writes `s` to standard output, exiting quietly when the reader has gone away.
pub(crate) fn emit(s: &str) {
    emit_bytes(s.as_bytes());
}

/// Writes `b` to standard output (a `.slvs` file starts with bytes that are not UTF-8),
/// exiting quietly when the reader has gone away.
pub(crate) fn emit_bytes(b: &[u8]) {
    use std::io::Write;
    let mut o = std::io::stdout().lock();
    if let Err(e) = o.write_all(b).and_then(|()| o.flush()) {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            std::process::exit(0);
        }
        eprintln!("loci: error: cannot write the output: {e}");
        std::process::exit(3);
    }
}
