//! The renderer on the shipped examples and on small systems built here: well-formed,
//! deterministic SVG whose elements match the entities, with the colours and dashes the
//! diagnosis and the options call for.

use super::style::Ink;
use super::{render_svg, RenderOptions};
use loci::format::json::Problem;
use loci::{
    Config, Constraint, ConstraintKind as K, Entity, EntityId, GroupId, Member, Param, System,
};
use std::collections::BTreeSet;
use std::path::Path;

fn example(name: &str) -> (System, GroupId) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name);
    let text = std::fs::read_to_string(&path).unwrap();
    let p = Problem::from_json(&text).unwrap();
    let g = p.request().group;
    (p.system, g)
}

/// Solves and diagnoses `group`, then draws it.
fn draw(sys: &mut System, group: GroupId, opts: &RenderOptions) -> (String, loci::Diagnosis) {
    let _ = loci::solve(sys, group, &[], &Config::default()).unwrap();
    let d = loci::diagnose(sys, group, &Config::default()).unwrap();
    (render_svg(sys, group, Some(&d), opts), d)
}

/// The elements drawn for entities: (handle, tag, class, attributes by name).
fn entity_elements<'a, 'i>(
    doc: &'a roxmltree::Document<'i>,
) -> Vec<(u32, String, String, roxmltree::Node<'a, 'i>)> {
    doc.descendants()
        .filter_map(|n| {
            let h = n.attribute("data-entity")?.parse().ok()?;
            Some((
                h,
                n.tag_name().name().to_string(),
                n.attribute("class").unwrap_or("").to_string(),
                n,
            ))
        })
        .collect()
}

fn colour(n: &roxmltree::Node<'_, '_>) -> String {
    match n.attribute("stroke") {
        Some(s) if s != "none" => s.to_string(),
        _ => n.attribute("fill").unwrap_or("").to_string(),
    }
}

#[test]
fn the_triangle_is_well_formed_deterministic_and_fully_constrained() {
    let (mut sys, g) = example("triangle.json");
    let (svg, d) = draw(&mut sys, g, &RenderOptions::default());
    assert_eq!(d.dof, 0);
    let again = render_svg(&sys, g, Some(&d), &RenderOptions::default());
    assert_eq!(svg, again, "the same input draws the same bytes");
    assert!(!svg.contains("NaN") && !svg.contains("inf"));
    let doc = roxmltree::Document::parse(&svg).expect("well-formed XML");
    assert_eq!(doc.root_element().tag_name().name(), "svg");

    let els = entity_elements(&doc);
    // Three points and three lines of group 2, and the workplane's origin of group 1.
    let lines: Vec<_> = els.iter().filter(|e| e.1 == "line").collect();
    let points: Vec<_> = els.iter().filter(|e| e.2.contains("point")).collect();
    assert_eq!(lines.len(), 3);
    assert_eq!(points.len(), 4);
    for (h, _, class, n) in &els {
        if *h == 101 {
            assert!(class.contains("earlier"), "{class}");
            assert_eq!(colour(n), Ink::Earlier.colour());
        } else {
            assert!(class.contains("fixed"), "entity {h}: {class}");
            assert_eq!(colour(n), Ink::Fixed.colour(), "entity {h}");
        }
    }
    // One glyph per constraint: dragged, horizontal and three distances with their values.
    let glyphs: Vec<_> = doc
        .descendants()
        .filter(|n| n.attribute("data-constraint").is_some())
        .collect();
    assert_eq!(glyphs.len(), 5);
    let texts: BTreeSet<String> = doc
        .descendants()
        .filter(|n| n.tag_name().name() == "text")
        .filter_map(|n| n.text().map(str::to_string))
        .collect();
    for v in ["30", "40", "50", "H"] {
        assert!(texts.contains(v), "{v} missing from {texts:?}");
    }
}

#[test]
fn geometry_that_can_still_move_has_the_other_colour() {
    let (mut sys, g) = example("triangle.json");
    // Without the 50 between 301 and 303, point 303 and the lines to it can move.
    let c = sys
        .constraints()
        .iter()
        .find(|c| c.kind == K::PtPtDistance && c.val == 50.0)
        .unwrap()
        .h;
    sys.remove_constraint(c).unwrap();
    let (svg, d) = draw(&mut sys, g, &RenderOptions::default());
    assert_eq!(d.dof, 1);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let mut free = BTreeSet::new();
    for (h, _, class, n) in entity_elements(&doc) {
        let moves = d.freedom(EntityId(h)).is_some_and(|f| f.dof > 0);
        let want = if h == 101 {
            Ink::Earlier
        } else if moves {
            Ink::Free
        } else {
            Ink::Fixed
        };
        assert_eq!(colour(&n), want.colour(), "entity {h} ({class})");
        if moves {
            free.insert(h);
        }
    }
    // The end 303 swings about 302; the fixed base 304 stays.
    assert!(free.contains(&303), "{free:?}");
    assert!(!free.contains(&304) && !free.contains(&301) && !free.contains(&302));
}

#[test]
fn conflicting_constraints_are_red_and_the_others_are_not() {
    let (mut sys, g) = example("inconsistent.json");
    let (svg, d) = draw(&mut sys, g, &RenderOptions::default());
    let conflict: BTreeSet<u32> = d
        .conflicting
        .iter()
        .flat_map(|s| &s.members)
        .filter_map(|m| match m {
            Member::Constraint(c) => Some(c.0),
            Member::Entity(_) => None,
        })
        .collect();
    assert!(!conflict.is_empty(), "the example conflicts");
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let mut seen = BTreeSet::new();
    for n in doc.descendants() {
        let Some(h) = n.attribute("data-constraint") else {
            continue;
        };
        let h: u32 = h.parse().unwrap();
        let class = n.attribute("class").unwrap();
        let inks: BTreeSet<String> = n
            .descendants()
            .filter(|c| c.is_element() && *c != n)
            .map(|c| colour(&c))
            .collect();
        if conflict.contains(&h) {
            seen.insert(h);
            assert!(class.contains("conflict"), "{h}: {class}");
            assert_eq!(
                inks,
                BTreeSet::from([Ink::Conflict.colour().to_string()]),
                "{h}"
            );
        } else {
            assert!(!class.contains("conflict"), "{h}: {class}");
            assert!(!inks.contains(Ink::Conflict.colour()), "{h}: {inks:?}");
        }
    }
    assert_eq!(seen, conflict, "every conflicting constraint is drawn");
}

#[test]
fn construction_entities_are_dashed_and_no_others() {
    let (mut sys, g) = example("slot_mechanism.json");
    let opts = RenderOptions {
        construction: BTreeSet::from([EntityId(313), EntityId(312)]),
        ..RenderOptions::default()
    };
    let (svg, _) = draw(&mut sys, g, &opts);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let mut dashed = BTreeSet::new();
    for (h, tag, class, n) in entity_elements(&doc) {
        let is = class.contains("construction");
        assert_eq!(is, h == 313 || h == 312, "{h} {tag} {class}");
        if tag != "circle" || !class.contains("point") {
            assert_eq!(n.attribute("stroke-dasharray").is_some(), is, "{h}");
        }
        if is {
            dashed.insert(h);
        }
    }
    assert_eq!(dashed, BTreeSet::from([312, 313]));
}

#[test]
fn every_drawable_entity_is_drawn_once_with_its_shape() {
    let (mut sys, g) = example("slot_mechanism.json");
    let (svg, _) = draw(&mut sys, g, &RenderOptions::default());
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let els = entity_elements(&doc);
    for e in sys.entities() {
        let drawn: Vec<_> = els.iter().filter(|x| x.0 == e.h.0).collect();
        let t = e.entity_type();
        let want = if t.is_point() {
            Some("circle")
        } else {
            match t {
                loci::EntityType::LineSegment => Some("line"),
                loci::EntityType::ArcOfCircle => Some("path"),
                _ => None,
            }
        };
        match want {
            Some(tag) => {
                assert_eq!(drawn.len(), 1, "entity {} drawn once", e.h.0);
                assert_eq!(drawn[0].1, tag, "entity {}", e.h.0);
            }
            None => assert!(drawn.is_empty(), "entity {} is not geometry", e.h.0),
        }
    }
    // The radius of the arcs and the angle are written with their values.
    assert!(svg.contains(">R10<"), "radius label");
    assert!(svg.contains(">10°<"), "angle label");
    assert!(svg.contains(">40<"), "distance label");
}

#[test]
fn the_view_box_holds_everything_drawn() {
    for name in [
        "triangle.json",
        "slot_mechanism.json",
        "tetrahedron_3d.json",
    ] {
        let (mut sys, g) = example(name);
        let (svg, _) = draw(&mut sys, g, &RenderOptions::default());
        let doc = roxmltree::Document::parse(&svg).unwrap();
        let vb: Vec<f64> = doc
            .root_element()
            .attribute("viewBox")
            .unwrap()
            .split(' ')
            .map(|v| v.parse().unwrap())
            .collect();
        let inside = |x: f64, y: f64| {
            x >= vb[0] - 0.01
                && x <= vb[0] + vb[2] + 0.01
                && y >= vb[1] - 0.01
                && y <= vb[1] + vb[3] + 0.01
        };
        for n in doc.descendants().filter(|n| n.tag_name().name() == "line") {
            let a = |k: &str| n.attribute(k).unwrap().parse::<f64>().unwrap();
            assert!(
                inside(a("x1"), a("y1")) && inside(a("x2"), a("y2")),
                "{name}: {n:?}"
            );
        }
        for n in doc.descendants().filter(|n| n.tag_name().name() == "text") {
            let a = |k: &str| n.attribute(k).unwrap().parse::<f64>().unwrap();
            assert!(inside(a("x"), a("y")), "{name}: {n:?}");
        }
    }
}

/// A system with no workplane: 3D points and lines off the xy plane, drawn isometric.
fn tripod() -> System {
    let mut sys = System::new();
    let coords = [
        [0.0, 0.0, 0.0],
        [10.0, 0.0, 0.0],
        [0.0, 10.0, 0.0],
        [0.0, 0.0, 10.0],
    ];
    for (i, c) in coords.iter().enumerate() {
        let base = 10 * i as u32 + 1;
        for (k, v) in c.iter().enumerate() {
            sys.add_param(Param::new(base + k as u32, 2, *v)).unwrap();
        }
        sys.add_entity(Entity::point_3d(
            100 + i as u32,
            2,
            [base, base + 1, base + 2],
        ))
        .unwrap();
    }
    for i in 1..4 {
        sys.add_entity(Entity::line(200 + i, 2, None, 100, 100 + i))
            .unwrap();
    }
    sys.add_constraint(
        Constraint::new(1, 2, K::PtPtDistance)
            .with_points(100, 101)
            .with_val(10.0),
    )
    .unwrap();
    sys
}

#[test]
fn a_sketch_in_3d_is_drawn_isometric_with_finite_numbers() {
    let mut sys = tripod();
    let (svg, _) = draw(&mut sys, GroupId(2), &RenderOptions::default());
    let doc = roxmltree::Document::parse(&svg).unwrap();
    assert!(!svg.contains("NaN"));
    // Three distinct directions on paper: the axes do not collapse onto each other.
    let ends: Vec<(f64, f64)> = doc
        .descendants()
        .filter(|n| n.tag_name().name() == "line" && n.attribute("data-entity").is_some())
        .map(|n| {
            let a = |k: &str| n.attribute(k).unwrap().parse::<f64>().unwrap();
            (a("x2") - a("x1"), a("y2") - a("y1"))
        })
        .collect();
    assert_eq!(ends.len(), 3);
    for i in 0..3 {
        for j in i + 1..3 {
            let cross = ends[i].0 * ends[j].1 - ends[i].1 * ends[j].0;
            assert!(cross.abs() > 1.0, "{ends:?}");
        }
    }
}

#[test]
fn degenerate_sketches_draw_without_panics_or_nan() {
    // Everything at one point, a zero radius, a group with nothing in it.
    let mut sys = System::new();
    sys.add_xy_workplane(1, 1, [101, 102, 200]).unwrap();
    for h in 11..=17 {
        sys.add_param(Param::new(h, 2, 0.0)).unwrap();
    }
    sys.add_entity(Entity::point_2d(301, 2, 200, [11, 12]))
        .unwrap();
    sys.add_entity(Entity::point_2d(302, 2, 200, [13, 14]))
        .unwrap();
    sys.add_entity(Entity::point_2d(303, 2, 200, [15, 16]))
        .unwrap();
    sys.add_entity(Entity::line(304, 2, Some(200), 301, 302))
        .unwrap();
    sys.add_entity(Entity::normal_2d(305, 2, 200)).unwrap();
    sys.add_entity(Entity::distance(306, 2, Some(200), 17))
        .unwrap();
    sys.add_entity(Entity::circle(307, 2, Some(200), 303, 305, 306))
        .unwrap();
    sys.add_entity(Entity::arc(308, 2, 200, 305, 301, 302, 303))
        .unwrap();
    sys.add_constraint(
        Constraint::new(1, 2, K::PtPtDistance)
            .in_workplane(Some(200))
            .with_points(301, 302),
    )
    .unwrap();
    sys.add_constraint(Constraint::new(2, 2, K::Diameter).with_entities([307, 0, 0, 0]))
        .unwrap();
    sys.add_constraint(
        Constraint::new(3, 2, K::Angle)
            .in_workplane(Some(200))
            .with_entities([304, 304, 0, 0])
            .with_val(0.0),
    )
    .unwrap();
    sys.add_constraint(
        Constraint::new(4, 2, K::PtLineDistance)
            .in_workplane(Some(200))
            .with_points(303, 0)
            .with_entities([304, 0, 0, 0]),
    )
    .unwrap();
    for group in [GroupId(2), GroupId(1), GroupId(9)] {
        for d in [
            None,
            loci::diagnose(&sys, GroupId(2), &Config::default()).ok(),
        ] {
            let svg = render_svg(&sys, group, d.as_ref(), &RenderOptions::default());
            assert!(!svg.contains("NaN") && !svg.contains("inf"), "{svg}");
            roxmltree::Document::parse(&svg).unwrap();
        }
    }
}

/// Two lines from the origin at 0° and 60°, with an angle dimension of `degrees`
/// (supplementary with `other`).
fn vee(degrees: f64, other: bool) -> System {
    let mut sys = System::new();
    sys.add_xy_workplane(1, 1, [101, 102, 200]).unwrap();
    let (c, s) = (60f64.to_radians().cos(), 60f64.to_radians().sin());
    for (h, v) in [
        (11, 0.0),
        (12, 0.0),
        (13, 50.0),
        (14, 0.0),
        (15, 50.0 * c),
        (16, 50.0 * s),
    ] {
        sys.add_param(Param::new(h, 2, v)).unwrap();
    }
    sys.add_entity(Entity::point_2d(301, 2, 200, [11, 12]))
        .unwrap();
    sys.add_entity(Entity::point_2d(302, 2, 200, [13, 14]))
        .unwrap();
    sys.add_entity(Entity::point_2d(303, 2, 200, [15, 16]))
        .unwrap();
    sys.add_entity(Entity::line(304, 2, Some(200), 301, 302))
        .unwrap();
    sys.add_entity(Entity::line(305, 2, Some(200), 301, 303))
        .unwrap();
    sys.add_constraint(
        Constraint::new(1, 2, K::Angle)
            .in_workplane(Some(200))
            .with_entities([304, 305, 0, 0])
            .with_val(degrees)
            .with_flags(other, false),
    )
    .unwrap();
    sys
}

#[test]
fn an_angle_arc_spans_the_angle_its_label_states() {
    for (degrees, other) in [(60.0, false), (120.0, false), (60.0, true), (120.0, true)] {
        let sys = vee(degrees, other);
        let svg = render_svg(&sys, GroupId(2), None, &RenderOptions::default());
        let doc = roxmltree::Document::parse(&svg).unwrap();
        let at = |h: &str, k: &str| -> f64 {
            doc.descendants()
                .find(|n| n.attribute("data-entity") == Some(h))
                .and_then(|n| n.attribute(k))
                .unwrap()
                .parse()
                .unwrap()
        };
        let vertex = (at("301", "cx"), at("301", "cy"));
        let glyph = doc
            .descendants()
            .find(|n| n.attribute("data-constraint") == Some("1"))
            .unwrap();
        let d = glyph
            .descendants()
            .find(|n| n.tag_name().name() == "path")
            .and_then(|n| n.attribute("d"))
            .unwrap();
        // "Mx0 y0 AR R 0 0 s x1 y1"
        let nums: Vec<f64> = d
            .replace(['M', 'A'], " ")
            .split_whitespace()
            .map(|v| v.parse().unwrap())
            .collect();
        let (p0, p1) = ((nums[0], nums[1]), (nums[7], nums[8]));
        let a0 = (p0.1 - vertex.1).atan2(p0.0 - vertex.0);
        let a1 = (p1.1 - vertex.1).atan2(p1.0 - vertex.0);
        let mut between = (a1 - a0).abs().to_degrees();
        if between > 180.0 {
            between = 360.0 - between;
        }
        assert!(
            (between - degrees).abs() < 0.5,
            "{degrees}: {between} ({d})"
        );
        let label = format!(">{degrees}°<");
        assert!(svg.contains(&label), "{label}");
    }
}

#[test]
fn a_reference_dimension_shows_what_it_measures_in_parentheses() {
    let (mut sys, g) = example("triangle.json");
    // A driven dimension across the hypotenuse: it measures 50 and constrains nothing.
    sys.add_constraint(
        Constraint::new(90, 2, K::PtPtDistance)
            .in_workplane(Some(200))
            .with_points(303, 301)
            .with_val(7.0)
            .as_reference(),
    )
    .unwrap();
    let (svg, d) = draw(&mut sys, g, &RenderOptions::default());
    assert_eq!(d.dof, 0);
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let glyph = doc
        .descendants()
        .find(|n| n.attribute("data-constraint") == Some("90"))
        .unwrap();
    assert!(glyph.attribute("class").unwrap().contains("reference"));
    let text: Vec<&str> = glyph.descendants().filter_map(|n| n.text()).collect();
    assert!(text.contains(&"(50)"), "{text:?}");
}
