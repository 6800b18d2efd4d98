#![no_main]
//! See `fuzz/src/cases/json.rs`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| loci_fuzz::cases::json::run(data));
