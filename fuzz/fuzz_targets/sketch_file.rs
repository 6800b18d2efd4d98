#![no_main]
//! See `fuzz/src/cases/files.rs`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| loci_fuzz::cases::files::sketch(data));
