//! The random tests' generator: the perturbed chain's splitmix64, with the draws they need. The
//! same seed gives the same cases on every machine.

pub use super::perturbed_chain::SplitMix as Rng;

impl Rng {
    /// Uniform in `0..n`.
    pub fn below(&mut self, n: usize) -> usize {
        (self.next_u64() % n as u64) as usize
    }
    /// True with probability `p`.
    pub fn chance(&mut self, p: f64) -> bool {
        self.uniform(0.0, 1.0) < p
    }
}
