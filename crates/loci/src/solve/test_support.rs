//! What the solver's own tests share: drawings jittered reproducibly, solving a copy of a
//! drawing and measuring how far the answer moved from it.

use super::{solve, Config, Report};
use crate::model::System;

/// A deterministic generator of numbers in `[-0.5, 0.5)`.
pub(super) struct Rng(pub u64);

impl Rng {
    pub(super) fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    }
}

/// Solves group `group` of a copy of `start` with `cfg`: the report and the values of the
/// group's parameters.
pub(super) fn run(start: &System, group: u32, cfg: &Config) -> (Report, Vec<f64>) {
    let mut sys = start.clone();
    let report = solve(&mut sys, group.into(), &[], cfg).unwrap();
    (report, group_values(&sys, group))
}

/// The values of group `group`'s parameters, in order.
pub(super) fn group_values(sys: &System, group: u32) -> Vec<f64> {
    sys.params()
        .iter()
        .filter(|p| p.group.0 == group)
        .map(|p| p.val)
        .collect()
}

/// The distance from the drawing `start` to `values` of group `group`'s parameters.
pub(super) fn moved(start: &System, group: u32, values: &[f64]) -> f64 {
    group_values(start, group)
        .iter()
        .zip(values)
        .map(|(a, b)| (a - b) * (a - b))
        .sum::<f64>()
        .sqrt()
}
