//! Linker arguments for a Python extension module, whoever builds it (cargo or maturin).

fn main() {
    pyo3_build_config::add_extension_module_link_args();
}
