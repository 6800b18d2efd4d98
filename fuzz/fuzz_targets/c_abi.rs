#![no_main]
//! See `fuzz/src/c_abi.rs`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|input: loci_fuzz::c_abi::Input| loci_fuzz::c_abi::run(&input));
