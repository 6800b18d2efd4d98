//! A component's remaining motions, from the core's null space: every first-order motion
//! of the assembly that keeps the mates, restricted to the component's pose, is a twist
//! (the velocity of its origin and its angular velocity); their span says in words how the
//! component can still move.

use super::build::PoseParams;
use super::math::{self, V3};
use super::report::round;
use crate::Diagnosis;

/// The independent motions of the component posed by `pp` (at translation `t`, rotation
/// `q`), and those motions in words.
pub(crate) fn motions(d: &Diagnosis, pp: &PoseParams, t: V3, q: [f64; 4]) -> (usize, Vec<String>) {
    let mut twists: Vec<[f64; 6]> = Vec::new();
    for e in [pp.origin, pp.normal] {
        let n = d.freedom(e).map_or(0, |f| f.dof);
        for i in 0..n {
            let Some(disp) = d.displacement(e, i) else {
                continue;
            };
            let get = |p: crate::ParamId| disp.iter().find(|(h, _)| *h == p).map_or(0.0, |x| x.1);
            let dt = pp.translation.map(get);
            let dq = pp.rotation.map(get);
            // dq = 1/2 w q  =>  w = 2 dq q*.
            let w = math::qmul(dq, math::qconj(q));
            twists.push([dt[0], dt[1], dt[2], 2.0 * w[1], 2.0 * w[2], 2.0 * w[3]]);
        }
    }
    let basis = orthonormalise(twists);
    let dof = basis.len();
    (dof, describe(&basis, t))
}

/// Gram–Schmidt, dropping vectors that add nothing.
fn orthonormalise(v: Vec<[f64; 6]>) -> Vec<[f64; 6]> {
    let mut out: Vec<[f64; 6]> = Vec::new();
    for mut x in v {
        for b in &out {
            let d: f64 = (0..6).map(|i| x[i] * b[i]).sum();
            for i in 0..6 {
                x[i] -= d * b[i];
            }
        }
        let n = x.iter().map(|a| a * a).sum::<f64>().sqrt();
        if n > 1e-6 {
            out.push(x.map(|a| a / n));
        }
    }
    out
}

fn vec_words(v: V3) -> String {
    let v = v.map(|x| if x.abs() < 5e-5 { 0.0 } else { round(x) });
    format!("({}, {}, {})", v[0], v[1], v[2])
}

/// `v` at unit length with its first clear component positive.
fn canonical(v: V3) -> V3 {
    let u = math::unit(v).unwrap_or(v);
    let first = u.iter().find(|x| x.abs() > 1e-9).copied().unwrap_or(1.0);
    if first < 0.0 {
        math::scale(u, -1.0)
    } else {
        u
    }
}

/// Splits the twists into pure translations and rotations, and says each in words.
fn describe(basis: &[[f64; 6]], t: V3) -> Vec<String> {
    // Row-reduce on the angular parts: rows whose angular part vanishes are translations.
    let mut rows: Vec<[f64; 6]> = basis.to_vec();
    let mut pivot_rows = 0;
    for col in 3..6 {
        let Some(p) = (pivot_rows..rows.len())
            .max_by(|&a, &b| rows[a][col].abs().total_cmp(&rows[b][col].abs()))
        else {
            break;
        };
        if rows[p][col].abs() < 1e-6 {
            continue;
        }
        rows.swap(pivot_rows, p);
        let pr = rows[pivot_rows];
        for (r, row) in rows.iter_mut().enumerate() {
            if r != pivot_rows {
                let f = row[col] / pr[col];
                for i in 0..6 {
                    row[i] -= f * pr[i];
                }
            }
        }
        pivot_rows += 1;
    }
    let rotations: Vec<[f64; 6]> = rows[..pivot_rows].to_vec();
    let mut translations: Vec<V3> = Vec::new();
    for r in &rows[pivot_rows..] {
        let mut v = [r[0], r[1], r[2]];
        for b in &translations {
            v = math::sub(v, math::scale(*b, math::dot(v, *b)));
        }
        if let Some(u) = math::unit(v).filter(|_| math::norm(v) > 1e-6) {
            translations.push(u);
        }
    }
    let mut words = Vec::new();
    match translations.len() {
        0 => {}
        1 => words.push(format!(
            "slides along {}",
            vec_words(canonical(translations[0]))
        )),
        2 => words.push(format!(
            "slides in the plane normal to {}",
            vec_words(canonical(math::cross(translations[0], translations[1])))
        )),
        _ => words.push("moves freely in space".into()),
    }
    // Rotations, with the translations taken out of their velocities.
    let strip = |v: V3| {
        translations
            .iter()
            .fold(v, |v, b| math::sub(v, math::scale(*b, math::dot(v, *b))))
    };
    let rot: Vec<(V3, V3)> = rotations
        .iter()
        .map(|r| (strip([r[0], r[1], r[2]]), [r[3], r[4], r[5]]))
        .collect();
    match rot.len() {
        0 => {}
        1 => {
            let (v, w) = rot[0];
            let w2 = math::dot(w, w);
            let axis = canonical(w);
            // The origin moves as w × (t - p): p = t + w × v / |w|², then the point of the
            // axis nearest the world origin.
            let p = math::add(t, math::scale(math::cross(w, v), 1.0 / w2));
            let p = math::sub(p, math::scale(axis, math::dot(p, axis)));
            let pitch = math::dot(w, v) / w2;
            if pitch.abs() < 1e-6 {
                words.push(format!(
                    "rotates about axis {} through {}",
                    vec_words(axis),
                    vec_words(p)
                ));
            } else {
                words.push(format!(
                    "screws about axis {} through {} (pitch {})",
                    vec_words(axis),
                    vec_words(p),
                    round(pitch * std::f64::consts::TAU)
                ));
            }
        }
        k => match common_centre(&rot, t) {
            Some(p) if k >= 3 => words.push(format!("turns freely about {}", vec_words(p))),
            Some(p) => words.push(format!(
                "turns in 2 independent ways about {}",
                vec_words(p)
            )),
            None => words.push(format!("turns in {k} independent ways")),
        },
    }
    words
}

/// The point every rotation leaves in place, if there is one: `v_i = w_i × (t - p)`.
fn common_centre(rot: &[(V3, V3)], t: V3) -> Option<V3> {
    // Least squares on w_i × p = w_i × t - v_i: (sum |w|² I - w wᵀ) p = sum w × (w × t - v)ᵀ...
    let mut a = [[0.0f64; 3]; 3];
    let mut b = [0.0f64; 3];
    for &(v, w) in rot {
        let rhs = math::sub(math::cross(w, t), v);
        let w2 = math::dot(w, w);
        for i in 0..3 {
            for j in 0..3 {
                a[i][j] += if i == j { w2 } else { 0.0 } - w[i] * w[j];
            }
        }
        // [w]×ᵀ rhs = rhs × w.
        let c = math::cross(rhs, w);
        for i in 0..3 {
            b[i] += c[i];
        }
    }
    let p = solve3(a, b)?;
    let ok = rot.iter().all(|&(v, w)| {
        let r = math::sub(math::cross(w, math::sub(t, p)), v);
        math::norm(r) < 1e-6 * (1.0 + math::norm(t))
    });
    ok.then_some(p)
}

fn solve3(a: [[f64; 3]; 3], b: V3) -> Option<V3> {
    let det = |m: [[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d = det(a);
    if d.abs() < 1e-12 {
        return None;
    }
    let mut x = [0.0; 3];
    for (k, xk) in x.iter_mut().enumerate() {
        let mut m = a;
        for i in 0..3 {
            m[i][k] = b[i];
        }
        *xk = det(m) / d;
    }
    Some(x)
}
