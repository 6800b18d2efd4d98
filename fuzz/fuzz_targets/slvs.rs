#![no_main]
//! See `fuzz/src/cases/slvs.rs`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| loci_fuzz::cases::slvs::run(data));
