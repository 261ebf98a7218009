//! Faults made on purpose, for the tests of the worker boundary: in a
//! debug build, and only where the service was started with
//! `MECHDYN_DEBUG_FAULTS=1`, a request whose text holds `fault:hang`,
//! `fault:panic`, `fault:abort` or `fault:overflow` (in any string of it,
//! which the service reads before the worker does) makes the worker hang
//! without looking at the clock, panic, abort, or overflow its stack.
//! A release build has none of this.

use std::sync::OnceLock;

/// Makes the fault `body` asks for, where faults are enabled.
pub fn inject(body: &[u8]) {
    static ENABLED: OnceLock<bool> = OnceLock::new();
    if !*ENABLED.get_or_init(|| std::env::var("MECHDYN_DEBUG_FAULTS").is_ok_and(|v| v == "1")) {
        return;
    }
    let asks = |fault: &str| body.windows(fault.len()).any(|w| w == fault.as_bytes());
    if asks("fault:hang") {
        loop {
            std::thread::sleep(std::time::Duration::from_secs(3600));
        }
    }
    if asks("fault:panic") {
        panic!("a fault made on purpose (fault:panic)");
    }
    if asks("fault:abort") {
        std::process::abort();
    }
    if asks("fault:overflow") {
        std::hint::black_box(deeper(0));
    }
}

/// Recursion without end: each call keeps a frame of half a kilobyte.
fn deeper(n: u64) -> u64 {
    let frame = std::hint::black_box([n; 64]);
    if std::hint::black_box(true) { deeper(n + 1) + frame[7] } else { frame[0] }
}
