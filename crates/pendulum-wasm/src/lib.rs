//! The library in a browser page: plain WebAssembly exports over linear
//! memory, JSON in and JSON out, with a few lines of JavaScript
//! (`web/pendulum.js`) as the glue; no generated bindings.
//!
//! The protocol: JavaScript asks for memory with [`pendulum_alloc`], writes
//! a request (UTF-8 JSON, or samples as 32-bit floats) there and calls an
//! export; every export that answers returns a pointer to a reply: its
//! length as a little-endian `u32`, then that many bytes of JSON, either
//! `{"ok": …}` with the same keys as the command line's `--json` prints,
//! or `{"error": {"field": …, "flag": …, "message": …}}` with the command
//! line's sentence. JavaScript reads the reply and gives it back with
//! [`pendulum_free`].
//!
//! The requests and their answers are [`requests`]; a live listener is
//! held here by a handle between calls.

use pendulum_data::lab;
pub mod requests;

use pendulum_theory::listening::live::LiveListener;
use std::cell::RefCell;

thread_local! {
    /// The live listeners, by handle (index + 1).
    static LISTENERS: RefCell<Vec<Option<LiveListener>>> = const { RefCell::new(Vec::new()) };
}

/// `len` bytes of memory for JavaScript to write into (aligned for
/// 32-bit floats).
#[no_mangle]
pub extern "C" fn pendulum_alloc(len: usize) -> *mut u8 {
    let words = len.div_ceil(4).max(1);
    let mut buffer = vec![0u32; words];
    let ptr = buffer.as_mut_ptr().cast::<u8>();
    std::mem::forget(buffer);
    ptr
}

/// Gives back memory from [`pendulum_alloc`] or a reply (`len` bytes).
///
/// # Safety
/// `ptr` must come from [`pendulum_alloc`] with this `len`, or be a
/// reply whose length prefix plus four is `len`; and be freed once.
#[no_mangle]
pub unsafe extern "C" fn pendulum_free(ptr: *mut u8, len: usize) {
    let words = len.div_ceil(4).max(1);
    drop(Vec::from_raw_parts(ptr.cast::<u32>(), words, words));
}

/// The reply to a request of `len` bytes of JSON at `ptr`
/// ([`requests::answer`]).
///
/// # Safety
/// `ptr` and `len` must describe memory from [`pendulum_alloc`].
#[no_mangle]
pub unsafe extern "C" fn pendulum_call(ptr: *const u8, len: usize) -> *mut u8 {
    let request = std::slice::from_raw_parts(ptr, len);
    reply(&requests::answer(request))
}

/// Fits the measurement file of `file_len` bytes at `file` with the
/// options of the JSON at `request` ([`lab::fit`]).
///
/// # Safety
/// The pointers and lengths must describe memory from [`pendulum_alloc`].
#[no_mangle]
pub unsafe extern "C" fn pendulum_fit(
    request: *const u8,
    request_len: usize,
    file: *const u8,
    file_len: usize,
) -> *mut u8 {
    let request = std::slice::from_raw_parts(request, request_len);
    let file = std::slice::from_raw_parts(file, file_len);
    reply(&lab::fit(request, file))
}

/// Listens to `n` samples at `ptr` (32-bit floats), at `sample_rate` Hz,
/// with the options of the JSON at `options` (`options_len` bytes):
/// [`requests::listen`].
///
/// # Safety
/// The pointers and lengths must describe memory from [`pendulum_alloc`].
#[no_mangle]
pub unsafe extern "C" fn pendulum_listen(
    options: *const u8,
    options_len: usize,
    samples: *const f32,
    n: usize,
    sample_rate: u32,
) -> *mut u8 {
    let options = std::slice::from_raw_parts(options, options_len);
    let samples = std::slice::from_raw_parts(samples, n);
    reply(&requests::listen(options, samples, sample_rate))
}

/// The channel (from 0) whose ticks stand out clearest, of `channels`
/// channels of `frames` samples each at `samples`, one channel after
/// another (the first 30 s of a recording, as the command line takes):
/// the reply's `ok` is `{"channel": n}`.
///
/// # Safety
/// The pointer and lengths must describe memory from [`pendulum_alloc`].
#[no_mangle]
pub unsafe extern "C" fn pendulum_clearest(
    samples: *const f32,
    frames: usize,
    channels: usize,
    sample_rate: u32,
) -> *mut u8 {
    let all = std::slice::from_raw_parts(samples, frames * channels);
    reply(&requests::clearest(all, frames, sample_rate))
}

/// A live listener at `sample_rate` Hz with the options of the JSON at
/// `options`: the reply's `ok` is `{"handle": n}`.
///
/// # Safety
/// The pointer and length must describe memory from [`pendulum_alloc`].
#[no_mangle]
pub unsafe extern "C" fn pendulum_live_new(
    options: *const u8,
    options_len: usize,
    sample_rate: u32,
) -> *mut u8 {
    let options = std::slice::from_raw_parts(options, options_len);
    let made = requests::live_new(options, sample_rate).map(|listener| {
        LISTENERS.with(|all| {
            let mut all = all.borrow_mut();
            all.push(Some(listener));
            serde_json::json!({ "handle": all.len() })
        })
    });
    reply(&requests::reply_of(made))
}

/// The next `n` samples at `ptr` for the listener `handle`: the reply's
/// `ok` is `{"windows": […], "provisional": … or null}`.
///
/// # Safety
/// The pointer and length must describe memory from [`pendulum_alloc`].
#[no_mangle]
pub unsafe extern "C" fn pendulum_live_push(
    handle: usize,
    samples: *const f32,
    n: usize,
) -> *mut u8 {
    let samples = std::slice::from_raw_parts(samples, n);
    let pushed = LISTENERS.with(|all| {
        let mut all = all.borrow_mut();
        match all.get_mut(handle.wrapping_sub(1)).and_then(Option::as_mut) {
            Some(listener) => requests::live_push(listener, samples),
            None => Err(requests::no_listener(handle)),
        }
    });
    reply(&requests::reply_of(pushed))
}

/// Ends the listener `handle`: the reply's `ok` is the whole recording's
/// analysis, as `listen` gives it.
#[no_mangle]
pub extern "C" fn pendulum_live_finish(handle: usize) -> *mut u8 {
    let listener = LISTENERS.with(|all| {
        all.borrow_mut()
            .get_mut(handle.wrapping_sub(1))
            .and_then(Option::take)
    });
    let finished = match listener {
        Some(listener) => requests::live_finish(listener),
        None => Err(requests::no_listener(handle)),
    };
    reply(&requests::heard_reply(finished))
}

/// A reply in memory: its length (`u32`, little-endian), then its bytes.
fn reply(text: &str) -> *mut u8 {
    let bytes = text.as_bytes();
    let ptr = pendulum_alloc(4 + bytes.len());
    // Safety: pendulum_alloc gave at least 4 + len bytes.
    unsafe {
        std::ptr::copy_nonoverlapping((bytes.len() as u32).to_le_bytes().as_ptr(), ptr, 4);
        std::ptr::copy_nonoverlapping(bytes.as_ptr(), ptr.add(4), bytes.len());
    }
    ptr
}
