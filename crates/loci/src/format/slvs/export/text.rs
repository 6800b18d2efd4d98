//! The text of a `.slvs` file: its groups, parameters, requests, entities and constraints as
//! SolveSpace's records.

use super::super::codes::GroupKind;
use super::*;
use crate::model::EntityId;
use std::fmt::Write;

impl<'a> Writer<'a> {
    pub(super) fn text(&mut self) -> String {
        let mut s = String::from("\n\n\n");
        let _ = write!(
            s,
            "Group.h.v=00000001\nGroup.type={}\nGroup.order=0\nGroup.name=#references\n\
             Group.remap={{\n}}\nAddGroup\n\n",
            GroupKind::Drawing3d.code()
        );
        for (i, (loci, g)) in self.groups.iter().enumerate() {
            let _ = write!(
                s,
                "Group.h.v={:08x}\nGroup.type={}\nGroup.order={}\nGroup.name=g{}\n\
                 Group.activeWorkplane.v=00010000\nGroup.remap={{\n}}\nAddGroup\n\n",
                g.0,
                GroupKind::Drawing3d.code(),
                i + 1,
                loci.0
            );
        }
        let mut params = std::mem::take(&mut self.params);
        params.sort_by_key(|p| p.0);
        for (h, v) in params {
            let _ = writeln!(s, "Param.h.v.={h:08x}");
            if v != 0.0 {
                let _ = writeln!(s, "Param.val={v:.20}");
            }
            s.push_str("AddParam\n\n");
        }
        for r in &self.requests {
            let _ = writeln!(s, "Request.h.v={:08x}\nRequest.type={}", r.h, r.kind);
            if r.workplane != 0 {
                let _ = writeln!(s, "Request.workplane.v={:08x}", r.workplane);
            }
            let _ = write!(
                s,
                "Request.group.v={:08x}\nRequest.construction=0\nAddRequest\n\n",
                r.group
            );
        }
        self.entities.sort_by_key(|e| e.h);
        for e in &self.entities {
            let _ = writeln!(
                s,
                "Entity.h.v={:08x}\nEntity.type={}\nEntity.construction=0",
                e.h, e.kind
            );
            for (i, p) in e.points.iter().enumerate() {
                let _ = writeln!(s, "Entity.point[{i}].v={p:08x}");
            }
            if e.normal != 0 {
                let _ = writeln!(s, "Entity.normal.v={:08x}", e.normal);
            }
            if e.distance != 0 {
                let _ = writeln!(s, "Entity.distance.v={:08x}", e.distance);
            }
            if e.workplane != 0 {
                let _ = writeln!(s, "Entity.workplane.v={:08x}", e.workplane);
            }
            s.push_str("Entity.actVisible=1\nAddEntity\n\n");
        }
        let constraints = std::mem::take(&mut self.constraints);
        let mut n = 0;
        for c in &constraints {
            let Some(text) = self.constraint_text(c) else {
                continue;
            };
            n += 1;
            let _ = write!(s, "Constraint.h.v={n:08x}\n{text}AddConstraint\n\n");
        }
        s
    }

    /// A constraint's fields, its loci handles mapped to the file's.
    pub(super) fn constraint_text(&self, q: &Queued) -> Option<String> {
        let (c, tie, both_file) = match q {
            Queued::Loci(c) => (c, false, false),
            Queued::Tie(c) => (c, true, false),
            Queued::File(c) => (c, true, true),
        };
        let map = |h: Option<EntityId>, file: bool| -> Option<u32> {
            match h {
                None => Some(0),
                Some(h) if file => Some(h.0),
                Some(h) => self.file_entity(h).ok(),
            }
        };
        let mut s = String::new();
        let _ = writeln!(
            s,
            "Constraint.type={}\nConstraint.group.v={:08x}",
            constraint_code(written_kind(c.kind)),
            self.groups.get(&c.group)?.0
        );
        let wp = map(c.workplane, false)?;
        if wp != 0 {
            let _ = writeln!(s, "Constraint.workplane.v={wp:08x}");
        }
        if c.val != 0.0 {
            let _ = writeln!(s, "Constraint.valA={:.20}", c.val);
        }
        let fields = [
            ("ptA", c.pt_a, tie),
            ("ptB", c.pt_b, both_file),
            ("entityA", c.entity_a, tie),
            ("entityB", c.entity_b, both_file),
            ("entityC", c.entity_c, false),
            ("entityD", c.entity_d, false),
        ];
        for (name, h, file) in fields {
            let v = map(h, file)?;
            if v != 0 {
                let _ = writeln!(s, "Constraint.{name}.v={v:08x}");
            }
        }
        let (other, other2) = if tie {
            (false, false)
        } else {
            (c.other, c.other2)
        };
        let _ = writeln!(
            s,
            "Constraint.other={}\nConstraint.other2={}\nConstraint.reference={}",
            u8::from(other),
            u8::from(other2),
            u8::from(c.reference)
        );
        Some(s)
    }
}
