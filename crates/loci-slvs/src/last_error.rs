//! The message behind the last `LOCI_SLVS_RESULT_*` code, per thread, for `Loci_Slvs_LastError`.

use std::cell::RefCell;
use std::os::raw::{c_char, c_int};

thread_local! {
    static LAST: RefCell<String> = const { RefCell::new(String::new()) };
}

/// Forgets the last message.
pub fn clear() {
    LAST.with(|l| l.borrow_mut().clear());
}

/// Records a message.
pub fn set(msg: String) {
    LAST.with(|l| *l.borrow_mut() = msg);
}

/// The last message (empty when none).
#[must_use]
pub fn get() -> String {
    LAST.with(|l| l.borrow().clone())
}

/// Copies the last failure message of this thread into `buf` (at most `len` bytes including the
/// terminating NUL) and returns the full message length in bytes (0 when there is none).
///
/// # Safety
/// `buf` is null or valid for writing `len` bytes.
#[no_mangle]
pub unsafe extern "C" fn Loci_Slvs_LastError(buf: *mut c_char, len: c_int) -> c_int {
    let msg = get();
    let room = usize::try_from(len).unwrap_or(0);
    if !buf.is_null() && room > 0 {
        let n = msg.len().min(room - 1);
        // SAFETY: `buf` is valid for `len >= n + 1` bytes (contract) and cannot overlap our
        // own string.
        unsafe {
            std::ptr::copy_nonoverlapping(msg.as_ptr().cast::<c_char>(), buf, n);
            *buf.add(n) = 0;
        }
    }
    c_int::try_from(msg.len()).unwrap_or(c_int::MAX)
}
