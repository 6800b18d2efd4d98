//! Assembly benchmark: revolute chains, a spatial four-bar and a grid of plates, solved by
//! `loci::assembly` (all mates at once, and the stepped relaxation for its pass count).
//!
//! Every assembly is generated from a known answer, then each free component is moved off
//! it by up to 0.3 in position and 5 degrees in rotation (seeded, so runs repeat).

use loci::assembly::{Assembly, Component, Mate, MateKind, Pose, Reference, Selection};
use std::fmt::Write as _;
use std::time::Instant;

/// A small deterministic generator (64-bit LCG), so the starts are the same on every run.
pub struct Lcg(u64);

impl Lcg {
    /// Seeded.
    #[must_use]
    pub fn new(seed: u64) -> Self {
        Self(
            seed.wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407),
        )
    }

    /// Uniform in [-1, 1).
    pub fn unit(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    }
}

fn qmul(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

/// `p` moved by up to `dt` in each coordinate and turned by up to `deg` degrees.
pub fn perturb(p: Pose, rng: &mut Lcg, dt: f64, deg: f64) -> Pose {
    let axis = [rng.unit(), rng.unit(), rng.unit() + 1e-3];
    let turn = Pose::from_axis_angle([0.0; 3], axis, deg * rng.unit());
    let t = p.translation;
    Pose::new(
        [
            t[0] + dt * rng.unit(),
            t[1] + dt * rng.unit(),
            t[2] + dt * rng.unit(),
        ],
        qmul(turn.rotation, p.rotation),
    )
}

/// Adds a mate with an id of its own, without [`Assembly::add_mate`]'s search for a free
/// one (quadratic in the number of mates; [`Assembly::solve`] still checks ids are unique).
fn push(asm: &mut Assembly, m: Mate) {
    let id = format!("{}{}", m.kind.id_prefix(), asm.mates.len() + 1);
    asm.mates.push(m.with_id(&id));
}

/// A chain of `n` unit links: link 0 grounded, each joint a revolute written as a coincident
/// pivot and parallel hinge axes, plus a 30-degree angle mate between the links' arms.
#[must_use]
pub fn chain(n: usize, seed: u64) -> Assembly {
    let mut rng = Lcg::new(seed);
    let mut asm = Assembly::new();
    asm.options.diagnose = false;
    let mut at = [0.0f64; 3];
    for i in 0..n {
        let angle = 30.0 * i as f64;
        let answer = Pose::from_axis_angle(at, [0.0, 0.0, 1.0], angle);
        let tip = answer.point([1.0, 0.0, 0.0]);
        let mut c = Component::new(format!("link{i}"), answer)
            .with("pivot", Reference::Vertex { point: [0.0; 3] })
            .with(
                "tip",
                Reference::Vertex {
                    point: [1.0, 0.0, 0.0],
                },
            )
            .with(
                "hinge",
                Reference::Axis {
                    point: [0.0; 3],
                    direction: [0.0, 0.0, 1.0],
                },
            )
            .with(
                "arm",
                Reference::Edge {
                    point: [0.0; 3],
                    direction: [1.0, 0.0, 0.0],
                },
            );
        if i == 0 {
            c.grounded = true;
        } else {
            c.pose = perturb(answer, &mut rng, 0.3, 5.0);
        }
        asm.add_component(c).expect("unique names");
        at = tip;
    }
    for i in 1..n {
        let (a, b) = (format!("link{}", i - 1), format!("link{i}"));
        let s = |c: &str, r: &str| Selection::on(c, r);
        push(
            &mut asm,
            Mate::new(MateKind::Coincident, s(&a, "tip"), s(&b, "pivot")),
        );
        push(
            &mut asm,
            Mate::new(MateKind::Parallel, s(&a, "hinge"), s(&b, "hinge")),
        );
        push(
            &mut asm,
            Mate::new(
                MateKind::Angle { degrees: 30.0 },
                s(&a, "arm"),
                s(&b, "arm"),
            ),
        );
    }
    asm
}

/// A spatial four-bar (revolute, ball, ball, revolute) driven by a 60-degree crank angle.
#[must_use]
pub fn four_bar(seed: u64) -> Assembly {
    let mut rng = Lcg::new(seed);
    let tipc = [0.5, 3f64.sqrt() / 2.0, 0.0];
    let tipr = [2.0, 0.0, 3f64.sqrt()];
    let d: Vec<f64> = (0..3).map(|i| tipr[i] - tipc[i]).collect();
    let len = d.iter().map(|x| x * x).sum::<f64>().sqrt();
    let dir = [d[0] / len, d[1] / len, d[2] / len];
    let q = {
        let (w, x, y, z) = (1.0 + dir[0], 0.0, -dir[2], dir[1]);
        let n = (w * w + x * x + y * y + z * z).sqrt();
        [w / n, x / n, y / n, z / n]
    };
    let mut asm = Assembly::new();
    asm.options.diagnose = false;
    let v = |p| Reference::Vertex { point: p };
    let ax = |p, d| Reference::Axis {
        point: p,
        direction: d,
    };
    asm.add_component(
        Component::new("ground", Pose::IDENTITY)
            .grounded()
            .with("crank_axis", ax([0.0; 3], [0.0, 0.0, 1.0]))
            .with("rocker_axis", ax([3.0, 0.0, 0.0], [0.0, 1.0, 0.0]))
            .with(
                "xref",
                Reference::Edge {
                    point: [0.0; 3],
                    direction: [1.0, 0.0, 0.0],
                },
            ),
    )
    .unwrap();
    let mut add = |c: Component| {
        let answer = c.pose;
        asm.add_component(Component {
            pose: perturb(answer, &mut rng, 0.3, 5.0),
            ..c
        })
        .unwrap();
    };
    add(Component::new(
        "crank",
        Pose::from_axis_angle([0.0; 3], [0.0, 0.0, 1.0], 60.0),
    )
    .with("pivot", ax([0.0; 3], [0.0, 0.0, 1.0]))
    .with("tip", v([1.0, 0.0, 0.0]))
    .with(
        "arm",
        Reference::Edge {
            point: [0.0; 3],
            direction: [1.0, 0.0, 0.0],
        },
    ));
    add(Component::new("coupler", Pose::new(tipc, q))
        .with("end_a", v([0.0; 3]))
        .with("end_b", v([len, 0.0, 0.0])));
    add(Component::new(
        "rocker",
        Pose::from_axis_angle([3.0, 0.0, 0.0], [0.0, 1.0, 0.0], -120.0),
    )
    .with("pivot", ax([0.0; 3], [0.0, 1.0, 0.0]))
    .with("tip", v([2.0, 0.0, 0.0])));
    let s = |c: &str, r: &str| Selection::on(c, r);
    for (k, a, b) in [
        (
            MateKind::Revolute,
            s("ground", "crank_axis"),
            s("crank", "pivot"),
        ),
        (MateKind::Ball, s("crank", "tip"), s("coupler", "end_a")),
        (MateKind::Ball, s("rocker", "tip"), s("coupler", "end_b")),
        (
            MateKind::Revolute,
            s("ground", "rocker_axis"),
            s("rocker", "pivot"),
        ),
        (
            MateKind::Angle { degrees: 60.0 },
            s("ground", "xref"),
            s("crank", "arm"),
        ),
    ] {
        asm.add_mate(Mate::new(k, a, b)).unwrap();
    }
    asm
}

/// An `n` by `n` grid of unit plates on a grounded floor: each plate lies on the floor
/// (touch align of its bottom face with the floor's top, 3 DOF), and is placed by two
/// vertex-on-face mates against its left neighbour (or the floor's left face) and one
/// against its front neighbour (or the floor's front face): fully placed, nothing redundant.
#[must_use]
pub fn plates(n: usize, seed: u64) -> Assembly {
    let mut rng = Lcg::new(seed);
    let mut asm = Assembly::new();
    asm.options.diagnose = false;
    let f = |p, d| Reference::Face {
        point: p,
        normal: d,
    };
    asm.add_component(
        Component::new("floor", Pose::IDENTITY)
            .grounded()
            .with("top", f([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]))
            .with("left", f([0.0, 0.0, 0.0], [-1.0, 0.0, 0.0]))
            .with("front", f([0.0, 0.0, 0.0], [0.0, -1.0, 0.0])),
    )
    .unwrap();
    for i in 0..n {
        for j in 0..n {
            let answer = Pose::new([i as f64, j as f64, 0.0], [1.0, 0.0, 0.0, 0.0]);
            let c = Component::new(format!("p{i}_{j}"), perturb(answer, &mut rng, 0.3, 5.0))
                .with("bottom", f([0.0; 3], [0.0, 0.0, -1.0]))
                .with("right", f([1.0, 0.0, 0.0], [1.0, 0.0, 0.0]))
                .with("back", f([0.0, 1.0, 0.0], [0.0, 1.0, 0.0]))
                .with(
                    "v00",
                    Reference::Vertex {
                        point: [0.0, 0.0, 0.0],
                    },
                )
                .with(
                    "v01",
                    Reference::Vertex {
                        point: [0.0, 1.0, 0.0],
                    },
                );
            asm.add_component(c).unwrap();
        }
    }
    let s = |c: &str, r: &str| Selection::on(c, r);
    for i in 0..n {
        for j in 0..n {
            let me = format!("p{i}_{j}");
            asm.add_mate(Mate::new(
                MateKind::TouchAlign,
                s("floor", "top"),
                s(&me, "bottom"),
            ))
            .unwrap();
            let left = if i == 0 {
                s("floor", "left")
            } else {
                s(&format!("p{}_{j}", i - 1), "right")
            };
            asm.add_mate(Mate::new(MateKind::Coincident, left.clone(), s(&me, "v00")))
                .unwrap();
            asm.add_mate(Mate::new(MateKind::Coincident, left, s(&me, "v01")))
                .unwrap();
            let front = if j == 0 {
                s("floor", "front")
            } else {
                s(&format!("p{i}_{}", j - 1), "back")
            };
            asm.add_mate(Mate::new(MateKind::Coincident, front, s(&me, "v00")))
                .unwrap();
        }
    }
    asm
}

/// One measured solve.
#[derive(Clone, Debug)]
pub struct Timing {
    /// The assembly's name.
    pub name: String,
    /// Components.
    pub components: usize,
    /// Mates.
    pub mates: usize,
    /// Best wall time of the simultaneous solve, milliseconds.
    pub ms: f64,
    /// Newton iterations.
    pub iterations: usize,
    /// Largest residual left.
    pub residual: f64,
    /// Whether every mate holds.
    pub converged: bool,
    /// Stepped passes, when run: (passes, converged, milliseconds).
    pub stepped: Option<(usize, bool, f64)>,
    /// SolveSpace on the same chain, when run: its verdict and solve time in milliseconds.
    pub slvs: Option<(String, f64)>,
    /// BREP.io's own relaxation on the same chain, when it applies: what it did, or why it
    /// was not run.
    pub brep: Option<crate::assembly_brep::BrepResult>,
    /// CadQuery's assembly solver on the same chain, when asked for.
    pub cadquery: Option<crate::assembly_cadquery::CadqueryResult>,
}

/// Every component's starting pose as `[tx, ty, tz, w, x, y, z]`: what the peers' runners
/// read, so that they start where loci does.
#[must_use]
pub fn start_poses(asm: &Assembly) -> Vec<Vec<f64>> {
    asm.components
        .iter()
        .map(|c| {
            c.pose
                .translation
                .iter()
                .chain(&c.pose.rotation)
                .copied()
                .collect()
        })
        .collect()
}

/// Runs the chain of `n` links (from the same start as loci's) through SolveSpace's Python
/// binding in `bench/.venv`, if it is there: its verdict and best solve time of `reps`.
pub fn slvs_chain(n: usize, reps: usize, bench: &std::path::Path) -> Option<(String, f64)> {
    let py = bench.join(".venv/bin/python");
    if !py.exists() {
        return None;
    }
    let poses = start_poses(&chain(n, 1));
    let dir = std::env::temp_dir();
    let start = dir.join(format!("loci-asm-start-{}-{n}.json", std::process::id()));
    let out = dir.join(format!("loci-asm-slvs-{}-{n}.json", std::process::id()));
    std::fs::write(&start, serde_json::to_string(&poses).ok()?).ok()?;
    let status = std::process::Command::new(py)
        .arg(bench.join("runners/slvs_assembly.py"))
        .arg(&start)
        .arg(reps.to_string())
        .arg(&out)
        .status()
        .ok()?;
    let _ = std::fs::remove_file(&start);
    if !status.success() {
        return Some(("runner failed".into(), f64::NAN));
    }
    let v: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&out).ok()?).ok()?;
    let _ = std::fs::remove_file(&out);
    let verdict = match v["result"].as_i64() {
        Some(0) => "okay",
        Some(1) => "inconsistent",
        Some(2) => "did not converge",
        Some(3) => "refused: too many unknowns",
        Some(4) => "redundant okay",
        _ => "unknown",
    };
    Some((verdict.into(), v["solve_ms"].as_f64().unwrap_or(f64::NAN)))
}

/// BREP.io's pass cap at 100 links.
pub const BREP_PASSES_100: usize = 5_000;

/// Times `make()`'s assembly: the best of `reps` simultaneous solves (each on a fresh copy,
/// building the constraint system included), then, when `steps` is set, one stepped run of at
/// most `steps` passes.
pub fn time(name: &str, make: &dyn Fn() -> Assembly, reps: usize, steps: Option<usize>) -> Timing {
    let proto = make();
    let mut best = f64::INFINITY;
    let mut last = None;
    for _ in 0..reps.max(1) {
        let mut asm = proto.clone();
        let t = Instant::now();
        let r = asm.solve().expect("a generated assembly is valid");
        best = best.min(t.elapsed().as_secs_f64() * 1e3);
        last = Some(r);
    }
    let r = last.expect("at least one repetition");
    let stepped = steps.map(|max| {
        let mut asm = proto.clone();
        asm.options.max_steps = max;
        let t = Instant::now();
        let run = asm.solve_stepped().expect("valid");
        (
            run.iterations.len(),
            run.converged,
            t.elapsed().as_secs_f64() * 1e3,
        )
    });
    Timing {
        name: name.into(),
        components: proto.components.len(),
        mates: proto.mates.len(),
        ms: best,
        iterations: r.iterations,
        residual: r.residual,
        converged: r.all_hold(),
        stepped,
        slvs: None,
        brep: None,
        cadquery: None,
    }
}

/// The whole set: chains of `sizes` links and, with `others`, the four-bar and a 10 by 10
/// grid of plates (and the stepped mode's passes); with `cadquery`, CadQuery run by that
/// interpreter on the chains of up to 1,000 links.
pub fn run_all(
    sizes: &[usize],
    reps: usize,
    others: bool,
    bench: Option<&std::path::Path>,
    cadquery: Option<&std::path::Path>,
) -> Vec<Timing> {
    let mut out = Vec::new();
    for &n in sizes {
        let steps = (n <= 100 && others).then_some(20_000);
        let reps = if n >= 10_000 { reps.min(3) } else { reps };
        let mut t = time(
            &format!("revolute chain, {n} links"),
            &|| chain(n, 1),
            reps,
            steps,
        );
        t.slvs = bench.and_then(|b| slvs_chain(n, if n >= 100 { 1 } else { reps }, b));
        // BREP.io relaxes one constraint at a time: thousands of passes at 10 links, so it
        // is run up to 100 links only, capped in passes and time.
        t.brep = bench.filter(|_| n <= 100).map(|b| {
            let (passes, secs) = if n <= 10 {
                (20_000, 120)
            } else {
                (BREP_PASSES_100, 600)
            };
            crate::assembly_brep::brep_chain(n, passes, std::time::Duration::from_secs(secs), b)
        });
        if let (Some(py), Some(b)) = (cadquery, bench) {
            t.cadquery = Some(if n <= 1_000 {
                crate::assembly_cadquery::cadquery_chain(
                    n,
                    if n >= 100 { 1 } else { reps },
                    std::time::Duration::from_secs(600),
                    py,
                    b,
                )
            } else {
                Err("not run (over 1,000 links)".into())
            });
        }
        out.push(t);
    }
    if others {
        out.push(time(
            "3D four-bar (RSSR)",
            &|| four_bar(2),
            reps,
            Some(20_000),
        ));
        out.push(time(
            "grid of plates, 10 x 10",
            &|| plates(10, 3),
            reps,
            Some(20_000),
        ));
    }
    out
}

/// A markdown table of the timings.
#[must_use]
pub fn table(t: &[Timing]) -> String {
    let mut s = String::new();
    s.push_str("| assembly | components | mates | loci (ms) | Newton iterations | residual | all mates hold | stepped passes (seed's relaxation) | BREP.io (the seed's own solver) | SolveSpace (slvs) | CadQuery |\n");
    s.push_str("|---|---:|---:|---:|---:|---:|:---:|---:|---|---|---|\n");
    for x in t {
        let stepped = match x.stepped {
            Some((p, true, ms)) => format!("{p} ({ms:.0} ms)"),
            Some((p, false, ms)) => format!("not converged after {p} ({ms:.0} ms)"),
            None => "not run".into(),
        };
        let slvs = match &x.slvs {
            Some((v, ms)) if ms.is_finite() && v == "okay" => {
                format!("{v}, {ms:.1} ms (×{:.1} loci's time)", ms / x.ms)
            }
            Some((v, ms)) if ms.is_finite() => format!("{v} after {ms:.1} ms"),
            Some((v, _)) => v.clone(),
            None => "not run".into(),
        };
        let brep = match &x.brep {
            Some(r) => crate::assembly_brep::cell(r, x.ms),
            None => "not run".into(),
        };
        let cadquery = match &x.cadquery {
            Some(r) => crate::assembly_cadquery::cell(r, x.ms),
            None => "not run".into(),
        };
        let _ = writeln!(
            s,
            "| {} | {} | {} | {:.2} | {} | {:.1e} | {} | {} | {} | {} | {} |",
            x.name,
            x.components,
            x.mates,
            x.ms,
            x.iterations,
            x.residual,
            if x.converged { "yes" } else { "no" },
            stepped,
            brep,
            slvs,
            cadquery
        );
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_assemblies_solve_back_to_their_answers() {
        for asm in [chain(10, 1), four_bar(2), plates(3, 3)] {
            let mut a = asm.clone();
            let r = a.solve().unwrap();
            assert!(r.all_hold(), "{r}");
            assert!(r.residual < 1e-10);
        }
        // The chain's answer: link i turned 30 i degrees, at the end of link i - 1.
        let mut a = chain(10, 1);
        a.solve().unwrap();
        let p = a.components[3].pose;
        let want = [
            1.0 + 30f64.to_radians().cos() + 60f64.to_radians().cos(),
            30f64.to_radians().sin() + 60f64.to_radians().sin(),
            0.0,
        ];
        for (got, want) in p.translation.iter().zip(want) {
            assert!((got - want).abs() < 1e-9, "{:?}", p.translation);
        }
    }
}
