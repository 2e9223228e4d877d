//! The process's peak resident set, as Linux reports it, for the peak bytes-per-disk columns
//! of `exact2d-bench minimal`.
//!
//! The allocator's count (`counting_alloc`) says what the code asks for; the resident set is
//! what the machine pays: the allocator's own overhead, pages kept after a free, the binary.
//! Each measurement runs in a child process of its own (`exact2d-bench peak`), so that no
//! memory an earlier case freed but kept resident is counted or reused.

use std::fs;

/// Resets the peak resident set to the current one (`/proc/self/clear_refs`, value 5:
/// Linux 4.0 and later). Returns whether it could.
pub fn reset_peak() -> bool {
    fs::write("/proc/self/clear_refs", "5").is_ok()
}

/// The peak resident set in bytes (`VmHWM` of `/proc/self/status`), if the system says.
#[must_use]
pub fn peak_bytes() -> Option<u64> {
    let status = fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kilobytes: u64 = line
        .trim_start_matches("VmHWM:")
        .trim()
        .trim_end_matches("kB")
        .trim()
        .parse()
        .ok()?;
    Some(kilobytes * 1024)
}
