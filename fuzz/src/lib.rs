//! Fuzz targets for loci: see `README.md`.

pub mod c_abi;
pub mod cases;
