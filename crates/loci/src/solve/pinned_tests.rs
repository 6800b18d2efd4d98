//! A point held where it is dragged is held where the drawing has it, whatever start a solve
//! begins from: the solves from a solution built another way (the rescues of a solve that
//! stopped, the diagnosis's build-ups) start where that point had moved.

use super::{solve_values, Cache, Config};
use crate::model::{Constraint, ConstraintKind as K, Entity, Param, System};

const G: u32 = 2;
const WP: u32 = 200;

/// `P` held where dragged and `Q` at 5 from it, drawn at `p` and `q`; in the xy workplane
/// (the pin's equations merged into fixed parameters) or in space (an equation of its own).
fn pinned(planar: bool, p: [f64; 3], q: [f64; 3]) -> System {
    let mut sys = System::new();
    sys.add_xy_workplane(1, 1, [101, 102, WP]).unwrap();
    let n = if planar { 2 } else { 3 };
    for (k, at) in [p, q].iter().enumerate() {
        let h = 10 * (k as u32 + 1);
        let params: Vec<u32> = (0..n).map(|i| h + i as u32).collect();
        for (i, &v) in params.iter().zip(at) {
            sys.add_param(Param::new(*i, G, v)).unwrap();
        }
        let e = if planar {
            Entity::point_2d(300 + k as u32, G, WP, [params[0], params[1]])
        } else {
            Entity::point_3d(300 + k as u32, G, [params[0], params[1], params[2]])
        };
        sys.add_entity(e).unwrap();
    }
    let wp = planar.then_some(WP);
    sys.add_constraint(
        Constraint::new(1, G, K::WhereDragged)
            .in_workplane(wp)
            .with_points(300, 0),
    )
    .unwrap();
    sys.add_constraint(
        Constraint::new(2, G, K::PtPtDistance)
            .in_workplane(wp)
            .with_points(300, 301)
            .with_val(5.0),
    )
    .unwrap();
    sys
}

#[test]
fn a_pinned_point_stays_where_drawn_when_the_solve_starts_elsewhere() {
    for planar in [true, false] {
        let sys = pinned(planar, [1.0, 2.0, 0.0], [4.0, 6.0, 0.0]);
        let drawn: Vec<f64> = sys.params().iter().map(|p| p.val).collect();
        let at = |v: &[f64], h: u32| v[sys.param_index(crate::ParamId(h)).unwrap()];
        let mut cache = Cache::default();
        // Started with P moved to (3, 4) and Q to (3, 9), twice: compiled, then from the
        // compiled structure.
        for (px, qy) in [(3.0, 9.0), (-2.0, 7.0)] {
            let mut start = drawn.clone();
            start[sys.param_index(crate::ParamId(10)).unwrap()] = px;
            start[sys.param_index(crate::ParamId(11)).unwrap()] = 4.0;
            start[sys.param_index(crate::ParamId(21)).unwrap()] = qy;
            let (report, v) = solve_values(
                &sys,
                G.into(),
                &[],
                &Config::default(),
                &mut cache,
                Some(&start),
            )
            .unwrap();
            assert!(report.outcome.is_ok(), "{planar}: {:?}", report.outcome);
            assert_eq!((at(&v, 10), at(&v, 11)), (1.0, 2.0), "planar {planar}");
            let d = (at(&v, 20) - 1.0).hypot(at(&v, 21) - 2.0);
            assert!((d - 5.0).abs() < 1e-9, "planar {planar}: {d}");
        }
    }
}
