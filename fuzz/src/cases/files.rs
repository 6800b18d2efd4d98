//! `sketch_file` and `assembly_file`: bytes into loci's sketch and assembly file readers, as
//! `loci solve`, `loci render` and `loci assemble` read them. What reads is solved; what
//! solves is written back and must read back.

use loci::format::assembly;
use loci::format::sketch::SketchFile;
use loci::Config;

/// Larger inputs are skipped, so that one input stays fast.
pub const MAX_OBJECTS: usize = 200;

/// Runs one input through the sketch file reader; panics on a finding.
pub fn sketch(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let file = match SketchFile::from_json(text) {
        Ok(f) => f,
        Err(e) => {
            let _ = e.to_string();
            return;
        }
    };
    let mut loaded = match file.load() {
        Ok(l) => l,
        Err(e) => {
            let _ = e.to_string();
            return;
        }
    };
    let s = &mut loaded.sketch;
    if s.shapes().count() + s.constraints().count() > MAX_OBJECTS {
        return;
    }
    s.set_config(Config::default().with_max_iterations(20));
    match s.solve() {
        Ok(rep) => {
            let _ = serde_json::to_string(&rep);
            // What loci writes, loci reads and builds again.
            let names = loaded.shapes.clone();
            let out = SketchFile::from_sketch(&loaded.sketch, |id| {
                names
                    .iter()
                    .find(|(_, v)| **v == id)
                    .map(|(k, _)| k.clone())
            })
            .to_json();
            let again = SketchFile::from_json(&out).unwrap_or_else(|e| {
                panic!("a sketch file loci wrote does not read back: {e}\n{out}")
            });
            if let Err(e) = again.load() {
                panic!("a sketch file loci wrote does not build: {e}\n{out}");
            }
        }
        Err(e) => {
            let _ = e.to_string();
        }
    }
}

/// Runs one input through the assembly file reader; panics on a finding.
pub fn assembly(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let mut asm = match assembly::read(text) {
        Ok(a) => a,
        Err(e) => {
            let _ = e.to_string();
            return;
        }
    };
    if asm.components.len() + asm.mates.len() > MAX_OBJECTS {
        return;
    }
    asm.options.max_iterations = asm.options.max_iterations.min(20);
    let out = assembly::write(&asm);
    if let Err(e) = assembly::read(&out) {
        panic!("an assembly file loci wrote does not read back: {e}\n{out}");
    }
    match asm.solve() {
        Ok(rep) => {
            let _ = rep.to_string();
        }
        Err(e) => {
            let _ = e.to_string();
        }
    }
}
