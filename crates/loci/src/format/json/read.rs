//! Reading a problem object by object, so that every error names the object and the field at
//! fault and the line and column where it is written.
//!
//! The text is first checked as JSON as a whole (a syntax error has its place from the
//! parser). Then each parameter, entity and constraint is taken as raw text, whose place in
//! the file is known, and its fields are read one by one: a missing field is reported at its
//! object, a wrong value at the value. A derived `Deserialize` cannot do this for the model
//! (entities are told apart by a `type` tag beside their other fields, and serde buffers such
//! objects, losing their place).

use super::error::*;
use super::fields::*;
use super::{Options, Problem, SolveRequest};
use crate::error::ModelError;
use crate::model::{
    Constraint, ConstraintKind, Entity, EntityId, EntityKind, EntityType, GroupId, ObjectId, Param,
    ParamId, System,
};
use serde_json::value::RawValue;
use std::borrow::Cow;
use std::collections::HashMap;

/// Every entity type, in the order of [`EntityType`].
const ENTITY_TYPES: [EntityType; 13] = [
    EntityType::PointIn3d,
    EntityType::PointIn2d,
    EntityType::PointNTrans,
    EntityType::PointNRotTrans,
    EntityType::NormalNRot,
    EntityType::NormalIn3d,
    EntityType::NormalIn2d,
    EntityType::Distance,
    EntityType::Workplane,
    EntityType::LineSegment,
    EntityType::Cubic,
    EntityType::Circle,
    EntityType::ArcOfCircle,
];

/// The fields every entity has.
const ENTITY_COMMON: [&str; 4] = ["h", "group", "type", "workplane"];

/// The fields of an entity type besides [`ENTITY_COMMON`].
pub(crate) fn entity_fields(t: EntityType) -> &'static [&'static str] {
    match t {
        EntityType::PointIn3d | EntityType::PointIn2d | EntityType::NormalIn3d => &["params"],
        EntityType::PointNTrans => &["params", "base", "translation", "times"],
        EntityType::PointNRotTrans => &["params", "base", "translation", "rotation"],
        EntityType::NormalNRot => &["params", "base", "rotation"],
        EntityType::NormalIn2d => &[],
        EntityType::Distance => &["param"],
        EntityType::Workplane => &["origin", "normal"],
        EntityType::LineSegment | EntityType::Cubic => &["points"],
        EntityType::Circle => &["center", "normal", "radius"],
        EntityType::ArcOfCircle => &["normal", "center", "start", "end"],
    }
}

/// The fields of a constraint.
pub(crate) const CONSTRAINT_FIELDS: [&str; 15] = [
    "h",
    "group",
    "type",
    "workplane",
    "val",
    "pt_a",
    "pt_b",
    "entity_a",
    "entity_b",
    "entity_c",
    "entity_d",
    "other",
    "other2",
    "reference",
    "signed",
];

const PARAM_FIELDS: [&str; 3] = ["h", "group", "val"];
const TOP_FIELDS: [&str; 4] = ["params", "entities", "constraints", "solve"];
const SOLVE_FIELDS: [&str; 4] = ["group", "dragged", "calculate_failed", "options"];
const OPTION_FIELDS: [&str; 7] = [
    "tolerance",
    "max_iterations",
    "dragged_scale",
    "rank_tolerance",
    "verify_conflicts_up_to",
    "nearest",
    "solvespace_angles",
];

/// Reads `type`: a name `of` knows, or an error naming all of `names`.
fn type_name<T: Copy>(
    o: &mut Obj<'_>,
    kind: &str,
    names: impl Fn() -> Vec<&'static str>,
    of: impl Fn(&str) -> Option<T>,
) -> Result<T, JsonError> {
    let raw = o.need("type", || one_of(&names()).replacen("expected ", "", 1))?;
    let text = raw.get();
    // A name without escapes, as written (the common case), or any JSON string.
    let plain = text
        .strip_prefix('"')
        .and_then(|t| t.strip_suffix('"'))
        .filter(|t| !t.contains('\\'));
    let name = match plain {
        Some(p) => Ok(Cow::Borrowed(p)),
        None => serde_json::from_str::<Cow<'_, str>>(text),
    };
    if let Ok(name) = name {
        if let Some(t) = of(&name) {
            return Ok(t);
        }
        let names = names();
        if text.starts_with('"') {
            let hint = match suggest(&name, names.iter().copied()) {
                Some(s) => format!(" (did you mean \"{s}\"?)"),
                None => String::new(),
            };
            return Err(o.err(
                Some(raw),
                "type",
                format!(
                    "field \"type\": unknown {kind} type {text}{hint}; {}",
                    one_of(&names)
                ),
            ));
        }
    }
    Err(o.err(
        Some(raw),
        "type",
        format!(
            "field \"type\": {}, found {}",
            one_of(&names()),
            found(text)
        ),
    ))
}

/// Handles already seen in one list, with where (a byte offset: lines are counted only for
/// a message).
struct Seen {
    what: &'static str,
    at: HashMap<u32, usize>,
}

impl Seen {
    fn new(what: &'static str) -> Self {
        Seen {
            what,
            at: HashMap::new(),
        }
    }

    /// Records handle `h` of object `o`; an error when it was seen before.
    fn add(&mut self, o: &Obj<'_>, h: u32) -> Result<(), JsonError> {
        let Some(first) = self.at.insert(h, offset(o.text, o.raw.get())) else {
            return Ok(());
        };
        let first = Position::at(o.text, first);
        let what = self.what;
        let object = match what {
            "param" => ObjectId::Param(ParamId(h)),
            "entity" => ObjectId::Entity(EntityId(h)),
            _ => ObjectId::Constraint(crate::ConstraintId(h)),
        };
        let at = o.fields.iter().find(|(k, _)| k == "h").map(|(_, v)| *v);
        let mut e = o.err(
            at,
            "h",
            format!(
                "handle {h} is already used by the {what} at {first} (each {what} needs a \
                 handle of its own)"
            ),
        );
        e.model = Some(Box::new(ModelError::DuplicateHandle { object }));
        Err(e)
    }
}

/// Reads a problem, checking every field of every object.
pub(super) fn problem(text: &str) -> Result<Problem, JsonError> {
    let top: &RawValue = serde_json::from_str(text).map_err(|e| syntax(text, &e))?;
    let mut o = Obj::new(text, top, String::new()).map_err(|mut e| {
        e.message = format!(
            "expected an object with \"params\", \"entities\", \"constraints\" and \"solve\", \
             found {}",
            found(top.get())
        );
        e
    })?;
    let params = list(&mut o, "params", Seen::new("param"), param)?;
    let entities = list(&mut o, "entities", Seen::new("entity"), entity)?;
    let constraints = list(&mut o, "constraints", Seen::new("constraint"), constraint)?;
    let solve = match o.get("solve") {
        Some(raw) if raw.get() == "null" => None,
        Some(raw) => Some(solve_request(text, raw)?),
        None => None,
    };
    o.finish(&[&TOP_FIELDS], || ("a problem".into(), Vec::new()))?;
    // Handles are checked above, so this does not fail; if it did, say where.
    let system = System::from_parts(params, entities, constraints)
        .map_err(|e| JsonError::from_model(text, &System::new(), &e))?;
    Ok(Problem { system, solve })
}

/// The objects of list `key`, each read by `read`, their handles checked for repeats.
fn list<'a, T>(
    top: &mut Obj<'a>,
    key: &str,
    mut seen: Seen,
    read: impl Fn(&mut Obj<'a>) -> Result<(T, u32), JsonError>,
) -> Result<Vec<T>, JsonError> {
    let Some(raw) = top.get(key) else {
        return Ok(Vec::new());
    };
    if !raw.get().starts_with('[') {
        return Err(top.err(
            Some(raw),
            key,
            format!(
                "field \"{key}\": expected an array of {key}, found {}",
                found(raw.get())
            ),
        ));
    }
    let all = items(raw);
    let mut out = Vec::with_capacity(all.len());
    for (i, item) in all.into_iter().enumerate() {
        let mut o = Obj::new(top.text, item, format!("{key}[{i}]"))?;
        let (v, h) = read(&mut o)?;
        seen.add(&o, h)?;
        out.push(v);
    }
    Ok(out)
}

fn param(o: &mut Obj<'_>) -> Result<(Param, u32), JsonError> {
    let h = o.own_handle("param")?;
    o.name = ParamId(h).to_string();
    let group = o.need_group()?;
    o.need("val", || "a number".into())?;
    let val = o.value("val", number_value)?.unwrap_or_default();
    o.finish(&[&PARAM_FIELDS], || ("a param".into(), Vec::new()))?;
    Ok((Param::new(h, group, val), h))
}

fn entity(o: &mut Obj<'_>) -> Result<(Entity, u32), JsonError> {
    let h = o.own_handle("entity")?;
    o.name = EntityId(h).to_string();
    let names = || ENTITY_TYPES.iter().map(|t| t.name()).collect();
    let t = type_name(o, "entity", names, |n| {
        ENTITY_TYPES.iter().copied().find(|t| t.name() == n)
    })?;
    o.name = format!("{} ({t})", EntityId(h));
    let group = o.need_group()?;
    let workplane = o.handle("workplane", "entity")?.map(EntityId);
    let p = ParamId;
    let e = EntityId;
    let kind = match t {
        EntityType::PointIn3d => EntityKind::PointIn3d {
            params: o.handles("params", "param", "[x, y, z]")?.map(p),
        },
        EntityType::PointIn2d => EntityKind::PointIn2d {
            params: o.handles("params", "param", "[u, v]")?.map(p),
        },
        EntityType::PointNTrans => EntityKind::PointNTrans {
            params: o.handles("params", "param", "[x, y, z]")?.map(p),
            base: e(o.need_ref("base", "entity")?),
            translation: o.handles("translation", "param", "[x, y, z]")?.map(p),
            times: {
                o.need("times", || "an integer".into())?;
                o.value("times", i32_value)?.unwrap_or_default()
            },
        },
        EntityType::PointNRotTrans => EntityKind::PointNRotTrans {
            params: o.handles("params", "param", "[x, y, z]")?.map(p),
            base: o.array("base", Expect::Number, "[x, y, z]", number_value)?,
            translation: o.handles("translation", "param", "[x, y, z]")?.map(p),
            rotation: e(o.need_ref("rotation", "entity")?),
        },
        EntityType::NormalNRot => EntityKind::NormalNRot {
            params: o.handles("params", "param", "[w, x, y, z]")?.map(p),
            base: o.array("base", Expect::Number, "[w, x, y, z]", number_value)?,
            rotation: e(o.need_ref("rotation", "entity")?),
        },
        EntityType::NormalIn3d => EntityKind::NormalIn3d {
            params: o.handles("params", "param", "[w, x, y, z]")?.map(p),
        },
        EntityType::NormalIn2d => EntityKind::NormalIn2d,
        EntityType::Distance => EntityKind::Distance {
            param: p(o.need_ref("param", "param")?),
        },
        EntityType::Workplane => EntityKind::Workplane {
            origin: e(o.need_ref("origin", "entity")?),
            normal: e(o.need_ref("normal", "entity")?),
        },
        EntityType::LineSegment => EntityKind::LineSegment {
            points: o.handles("points", "entity", "[start, end]")?.map(e),
        },
        EntityType::Cubic => EntityKind::Cubic {
            points: o.handles("points", "entity", "[p0, p1, p2, p3]")?.map(e),
        },
        EntityType::Circle => EntityKind::Circle {
            center: e(o.need_ref("center", "entity")?),
            normal: e(o.need_ref("normal", "entity")?),
            radius: e(o.need_ref("radius", "entity")?),
        },
        EntityType::ArcOfCircle => EntityKind::ArcOfCircle {
            normal: e(o.need_ref("normal", "entity")?),
            center: e(o.need_ref("center", "entity")?),
            start: e(o.need_ref("start", "entity")?),
            end: e(o.need_ref("end", "entity")?),
        },
    };
    o.finish(&[&ENTITY_COMMON, entity_fields(t)], || {
        let kind = format!("{} {t} entity", article(t.name()));
        let elsewhere = ENTITY_TYPES
            .iter()
            .flat_map(|t| entity_fields(*t).iter().copied())
            .collect();
        (kind, elsewhere)
    })?;

    Ok((
        Entity {
            h: EntityId(h),
            group: GroupId(group),
            workplane,
            kind,
        },
        h,
    ))
}

fn constraint(o: &mut Obj<'_>) -> Result<(Constraint, u32), JsonError> {
    let h = o.own_handle("constraint")?;
    o.name = crate::ConstraintId(h).to_string();
    let names = || ConstraintKind::ALL.iter().map(|k| k.name()).collect();
    let kind = type_name(o, "constraint", names, ConstraintKind::from_name)?;
    o.name = format!("{} ({kind})", crate::ConstraintId(h));
    let group = o.need_group()?;
    let mut c = Constraint::new(h, group, kind);
    c.workplane = o.handle("workplane", "entity")?.map(EntityId);
    c.val = o.value("val", number_value)?.unwrap_or_default();
    c.pt_a = o.handle("pt_a", "entity")?.map(EntityId);
    c.pt_b = o.handle("pt_b", "entity")?.map(EntityId);
    c.entity_a = o.handle("entity_a", "entity")?.map(EntityId);
    c.entity_b = o.handle("entity_b", "entity")?.map(EntityId);
    c.entity_c = o.handle("entity_c", "entity")?.map(EntityId);
    c.entity_d = o.handle("entity_d", "entity")?.map(EntityId);
    c.other = o.value("other", bool_value)?.unwrap_or_default();
    c.other2 = o.value("other2", bool_value)?.unwrap_or_default();
    c.reference = o.value("reference", bool_value)?.unwrap_or_default();
    c.signed = o.value("signed", bool_value)?.unwrap_or_default();
    o.finish(&[&CONSTRAINT_FIELDS], || {
        ("a constraint".into(), Vec::new())
    })?;
    Ok((c, h))
}

fn solve_request(text: &str, raw: &RawValue) -> Result<SolveRequest, JsonError> {
    let mut o = Obj::new(text, raw, "solve".into())?;
    let group = GroupId(o.need_group()?);
    let dragged = match o.get("dragged") {
        None => Vec::new(),
        Some(r) if !r.get().starts_with('[') => {
            return Err(o.err(
                Some(r),
                "dragged",
                format!(
                    "field \"dragged\": expected an array of param handles, found {}",
                    found(r.get())
                ),
            ))
        }
        Some(r) => {
            let mut v = Vec::new();
            for (i, item) in items(r).into_iter().enumerate() {
                let h = handle_value(item.get(), "param").map_err(|m| {
                    o.err(Some(item), "dragged", format!("field \"{{f}}[{i}]\": {m}"))
                })?;
                v.push(ParamId(h));
            }
            v
        }
    };
    let calculate_failed = o.value("calculate_failed", bool_value)?.unwrap_or(true);
    let options = match o.get("options") {
        None => Options::default(),
        Some(r) => {
            let mut p = Obj::new(text, r, "solve".into()).map_err(|mut e| {
                e.field = "options".into();
                e.message = format!("field \"options\": {}", e.message);
                e
            })?;
            p.prefix = "options.";
            let options = Options {
                tolerance: p.value("tolerance", number_value)?,
                max_iterations: p.value("max_iterations", count_value)?,
                dragged_scale: p.value("dragged_scale", number_value)?,
                rank_tolerance: p.value("rank_tolerance", number_value)?,
                verify_conflicts_up_to: p.value("verify_conflicts_up_to", count_value)?,
                nearest: p.value("nearest", bool_value)?,
                solvespace_angles: p.value("solvespace_angles", bool_value)?,
            };
            p.finish(&[&OPTION_FIELDS], || ("\"options\"".into(), Vec::new()))?;
            options
        }
    };
    o.finish(&[&SOLVE_FIELDS], || ("\"solve\"".into(), Vec::new()))?;
    Ok(SolveRequest {
        group,
        dragged,
        calculate_failed,
        options,
    })
}

/// A JSON syntax error, with its place and without serde's position suffix.
fn syntax(text: &str, e: &serde_json::Error) -> JsonError {
    let full = e.to_string();
    let what = match full.rfind(" at line ") {
        Some(i) => &full[..i],
        None => &full,
    };
    if text.trim().is_empty() {
        return JsonError::new(
            None,
            "",
            "",
            "the file is empty; expected a JSON object with \"params\", \"entities\" and \
             \"constraints\"",
        );
    }
    let message = if e.is_eof() {
        match what.strip_prefix("EOF while parsing ") {
            Some("a value") => {
                "the file ends where a value should be (is it cut short?)".to_string()
            }
            Some(thing) => format!("the file ends inside {thing} (is it cut short?)"),
            None => format!("{what} (is the file cut short?)"),
        }
    } else {
        format!("invalid JSON: {what}")
    };
    JsonError::new(
        Some(Position {
            line: e.line().max(1),
            column: e.column().max(1),
        }),
        "",
        "",
        message,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::Value;

    const SCHEMA: &str = include_str!("../../../../../docs/loci.schema.json");

    fn keys(v: &Value) -> Vec<String> {
        let mut k: Vec<String> = v.as_object().unwrap().keys().cloned().collect();
        k.sort();
        k
    }

    fn sorted(v: &[&str]) -> Vec<String> {
        let mut k: Vec<String> = v.iter().map(|s| (*s).to_string()).collect();
        k.sort();
        k
    }

    #[test]
    fn the_field_tables_are_the_schema_s() {
        let schema: Value = serde_json::from_str(SCHEMA).unwrap();
        let defs = &schema["$defs"];
        let variants = defs["entity"]["oneOf"].as_array().unwrap();
        assert_eq!(variants.len(), ENTITY_TYPES.len());
        for t in ENTITY_TYPES {
            let v = variants
                .iter()
                .find(|v| v["title"] == t.name())
                .unwrap_or_else(|| panic!("{t} is not in the schema"));
            let mut mine: Vec<&str> = ENTITY_COMMON.to_vec();
            mine.extend(entity_fields(t));
            assert_eq!(keys(&v["properties"]), sorted(&mine), "{t}");
        }
        assert_eq!(
            keys(&defs["constraint"]["properties"]),
            sorted(&CONSTRAINT_FIELDS)
        );
        assert_eq!(keys(&defs["param"]["properties"]), sorted(&PARAM_FIELDS));
        assert_eq!(keys(&schema["properties"]), sorted(&TOP_FIELDS));
        assert_eq!(keys(&defs["solve"]["properties"]), sorted(&SOLVE_FIELDS));
        assert_eq!(
            keys(&defs["solve"]["properties"]["options"]["properties"]),
            sorted(&OPTION_FIELDS)
        );
    }

    #[test]
    fn the_field_tables_are_what_the_model_writes() {
        // A constraint with every field set writes every field the reader accepts.
        let mut c = Constraint::new(1, 2, ConstraintKind::Angle)
            .in_workplane(Some(3))
            .with_val(4.0)
            .with_points(5, 6)
            .with_entities([7, 8, 9, 10]);
        c.other = true;
        c.other2 = true;
        c.reference = true;
        c.signed = true;
        let v = serde_json::to_value(&c).unwrap();
        assert_eq!(keys(&v), sorted(&CONSTRAINT_FIELDS));
        let v = serde_json::to_value(Param::new(1, 2, 3.0)).unwrap();
        assert_eq!(keys(&v), sorted(&PARAM_FIELDS));
        let samples = [
            Entity::point_3d(1, 1, [1, 2, 3]),
            Entity::point_2d(1, 1, 9, [1, 2]),
            Entity::point_n_trans(1, 1, [1, 2, 3], 4, [5, 6, 7], 2),
            Entity::point_n_rot_trans(1, 1, [1, 2, 3], [0.0; 3], [5, 6, 7], 8),
            Entity::normal_n_rot(1, 1, [1, 2, 3, 4], [1.0, 0.0, 0.0, 0.0], 8),
            Entity::normal_3d(1, 1, [1, 2, 3, 4]),
            Entity::normal_2d(1, 1, 9),
            Entity::distance(1, 1, Some(9), 1),
            Entity::workplane(1, 1, 2, 3),
            Entity::line(1, 1, Some(9), 2, 3),
            Entity::cubic(1, 1, Some(9), [2, 3, 4, 5]),
            Entity::circle(1, 1, Some(9), 2, 3, 4),
            Entity::arc(1, 1, 9, 2, 3, 4, 5),
        ];
        for (t, e) in ENTITY_TYPES.iter().zip(samples) {
            assert_eq!(e.entity_type(), *t);
            let mut e = e;
            e.workplane = Some(EntityId(9));
            let v = serde_json::to_value(&e).unwrap();
            let mut mine: Vec<&str> = ENTITY_COMMON.to_vec();
            mine.extend(entity_fields(*t));
            assert_eq!(keys(&v), sorted(&mine), "{t}");
        }
    }

    #[test]
    fn positions_count_lines_and_characters() {
        let text = "{\n  \"é\": [1,\n   2]}";
        let at = |needle: &str| Position::at(text, text.find(needle).unwrap());
        assert_eq!(at("{"), Position { line: 1, column: 1 });
        assert_eq!(at("[1"), Position { line: 2, column: 8 });
        assert_eq!(at("2]"), Position { line: 3, column: 4 });
    }

    #[test]
    fn suggestions_catch_slips_only() {
        let names = ["pt_a", "pt_b", "entity_a", "horizontal", "vertical"];
        assert_eq!(suggest("ptb", names), Some("pt_b"));
        assert_eq!(suggest("Horizontal", names), Some("horizontal"));
        assert_eq!(suggest("entitya", names), Some("entity_a"));
        assert_eq!(suggest("colour", names), None);
    }
}
