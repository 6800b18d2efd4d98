//! A small reader that turns fuzzer bytes into choices. Once the bytes run out every read
//! returns zero (the first choice), so any input decodes to some case.

/// Fuzzer bytes, read front to back.
pub struct Bytes<'a> {
    data: &'a [u8],
    pos: usize,
}

impl<'a> Bytes<'a> {
    /// A reader over `data`.
    pub fn new(data: &'a [u8]) -> Self {
        Self { data, pos: 0 }
    }

    /// The next byte, or 0 at the end.
    pub fn u8(&mut self) -> u8 {
        let b = self.data.get(self.pos).copied().unwrap_or(0);
        self.pos += 1;
        b
    }

    /// Two bytes, little-endian.
    pub fn u16(&mut self) -> u16 {
        u16::from(self.u8()) | (u16::from(self.u8()) << 8)
    }

    /// A number in `0..n` (`n > 0`).
    pub fn below(&mut self, n: usize) -> usize {
        debug_assert!(n > 0);
        if n <= 256 {
            usize::from(self.u8()) % n
        } else {
            usize::from(self.u16()) % n
        }
    }

    /// A coin.
    pub fn bool(&mut self) -> bool {
        self.u8() & 1 == 1
    }

    /// True one time in `n`.
    pub fn one_in(&mut self, n: usize) -> bool {
        self.below(n) == 0
    }

    /// One of `items` (non-empty).
    pub fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.below(items.len())]
    }

    /// A number in `[lo, hi]` on a grid of 65536 steps.
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * f64::from(self.u16()) / 65535.0
    }

    /// A coordinate: mostly small round numbers (which make exact coincidences, zero-length
    /// lines and right angles likely), sometimes anything in `[-100, 100]`.
    pub fn coord(&mut self) -> f64 {
        match self.below(4) {
            0 => f64::from(self.u8() as i8) / 4.0,
            1 => f64::from(self.u8() as i8 % 16),
            _ => self.range(-100.0, 100.0),
        }
    }

    /// Whether the input is used up.
    pub fn is_empty(&self) -> bool {
        self.pos >= self.data.len()
    }
}
