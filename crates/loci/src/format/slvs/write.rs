//! Saving a loaded file: the original text with only the parameter values rewritten.

use super::SlvsFile;
use std::collections::HashMap;

/// What to do at a line of the original text.
enum Edit {
    /// Replace this `Param.val=` line with the new value.
    Replace(f64),
    /// Write a `Param.val=` line after this `Param.h.v.=` line (the value was 0 and omitted).
    InsertAfter(f64),
}

impl SlvsFile {
    /// The file as SolveSpace writes it, with every parameter's current value from
    /// [`SlvsFile::system`]. Every other line is kept byte for byte, in order.
    #[must_use]
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut edits: HashMap<usize, Edit> = HashMap::new();
        for p in &self.param_lines {
            let Some(v) = self.system.value(p.h) else {
                continue;
            };
            match p.val_line {
                Some(l) => {
                    edits.insert(l, Edit::Replace(v));
                }
                // SolveSpace omits zero values; so do we.
                None if v != 0.0 => {
                    edits.insert(p.h_line, Edit::InsertAfter(v));
                }
                None => {}
            }
        }
        let mut out = Vec::with_capacity(self.bytes.len() + 64 * edits.len());
        let mut pos = 0;
        for (i, &(start, end)) in self.spans.iter().enumerate() {
            let line = &self.bytes[start..end];
            let cr = line.ends_with(b"\r");
            // Keep what lies between lines (the newline) exactly.
            out.extend_from_slice(&self.bytes[pos..start]);
            pos = end;
            match edits.get(&i) {
                Some(Edit::Replace(v)) => {
                    out.extend_from_slice(format_val(*v).as_bytes());
                    if cr {
                        out.push(b'\r');
                    }
                }
                Some(Edit::InsertAfter(v)) => {
                    out.extend_from_slice(line);
                    out.push(b'\n');
                    out.extend_from_slice(format_val(*v).as_bytes());
                    if cr {
                        out.push(b'\r');
                    }
                }
                None => out.extend_from_slice(line),
            }
        }
        out.extend_from_slice(&self.bytes[pos..]);
        out
    }
}

/// A `Param.val=` line as SolveSpace writes it (`%.20f`).
fn format_val(v: f64) -> String {
    // Rust prints the exact decimal expansion, as C's printf does.
    format!("Param.val={v:.20}")
}
