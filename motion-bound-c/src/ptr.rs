//! Every raw pointer the C caller hands over is read or written here, in
//! these few functions: the registry of live handles, handle borrowing and
//! freeing, array reading and `out` writing. Each `unsafe` block says why it
//! is sound.
//!
//! The registry is what makes a freed (dangling), foreign or mistyped handle
//! an error instead of a read of freed memory: a handle is dereferenced only
//! if its address is registered with its type, and it is unregistered before
//! its memory is released.

use std::collections::BTreeMap;
use std::sync::{RwLock, RwLockReadGuard, RwLockWriteGuard};

use crate::error::{Failure, MbStatus, Res};

/// The type of a registered handle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
    Shape,
    Motion,
    Scene,
    SceneResult,
    Chain,
    ChainScene,
}

/// A type given out to C as an opaque handle (`Box::into_raw`).
pub(crate) trait Handle: Sized {
    /// Its registry tag.
    const KIND: Kind;
    /// Its C name, for messages.
    const NAME: &'static str;
}

/// A type every bit pattern of which is a valid value (plain numbers and raw
/// pointers, and `repr(C)` structs of them), so that reading one from C
/// memory cannot make an invalid value.
///
/// # Safety
/// Only for such types.
pub(crate) unsafe trait Plain: Copy {}

// SAFETY: every bit pattern is an `f64`, a `u32`, a `usize`.
unsafe impl Plain for f64 {}
// SAFETY: as above.
unsafe impl Plain for u32 {}
// SAFETY: any address is a valid raw pointer value (it is checked before use).
unsafe impl<T> Plain for *const T {}
// SAFETY: as above.
unsafe impl<T> Plain for *mut T {}

/// The addresses of the live handles (as [`key`]s), with their types.
static LIVE: RwLock<BTreeMap<usize, Kind>> = RwLock::new(BTreeMap::new());

/// The registry, for reading. A panic while it was held cannot leave it
/// inconsistent (each insert or remove is one call), so a poisoned lock is
/// used as it is.
fn live() -> RwLockReadGuard<'static, BTreeMap<usize, Kind>> {
    LIVE.read()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

fn live_mut() -> RwLockWriteGuard<'static, BTreeMap<usize, Kind>> {
    LIVE.write()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// The registry's key of a handle: its address with every bit flipped, so
/// that the registry does not hold the handle's address itself: a leak
/// checker scanning memory for pointers (LeakSanitizer) would otherwise find
/// every handle reachable from the registry, and a handle the C caller never
/// freed would not be reported as leaked.
fn key<T>(ptr: *const T) -> usize {
    !(ptr as usize)
}

fn null(what: &str) -> Failure {
    Failure::new(MbStatus::NullPointer, format!("{what} is NULL"))
}

/// Why `found` (the registry's entry for a handle of type `T`, if any) is not
/// a live `T`, or `Ok`.
/// The messages name the argument `what` (`shape_a`, `parts[2]`).
fn verdict<T: Handle>(found: Option<Kind>, what: &str) -> Res<()> {
    match found {
        Some(k) if k == T::KIND => Ok(()),
        Some(_) => Err(Failure::new(
            MbStatus::InvalidHandle,
            format!(
                "{what} is a handle of another type (not {})",
                T::NAME.replacen("the ", "a ", 1)
            ),
        )),
        None => Err(Failure::new(
            MbStatus::InvalidHandle,
            format!(
                "{what} is not a live {}: never made by this library, or freed",
                T::NAME.trim_start_matches("the ")
            ),
        )),
    }
}

/// Checks that `ptr` is a live handle of type `T`.
fn check_live<T: Handle>(ptr: *const T, what: &str) -> Res<()> {
    if ptr.is_null() {
        return Err(null(what));
    }
    let found = live().get(&key(ptr)).copied();
    verdict::<T>(found, what)
}

/// The value behind the handle `ptr`, the argument `what`.
///
/// # Safety
/// No other thread frees `ptr` or borrows it mutably while the reference
/// lives (the C caller's contract: a handle is not freed while in use).
pub(crate) unsafe fn handle_ref<'a, T: Handle>(ptr: *const T, what: &str) -> Res<&'a T> {
    check_live(ptr, what)?;
    // SAFETY: a registered address of kind `T` came from `Box::into_raw` of a
    // `T` (`write_handle`) and is unregistered before that box is dropped
    // (`free_handle`), so it points to a live, aligned `T`; the caller
    // guarantees it stays so, unaliased by a `&mut`, while `'a` lasts.
    Ok(unsafe { &*ptr })
}

/// The value behind the handle `ptr`, to change.
///
/// # Safety
/// No other thread uses `ptr` while the reference lives.
pub(crate) unsafe fn handle_mut<'a, T: Handle>(ptr: *mut T, what: &str) -> Res<&'a mut T> {
    check_live(ptr, what)?;
    // SAFETY: as in `handle_ref`, `ptr` points to a live `T`; the caller
    // guarantees no other reference to it exists while `'a` lasts.
    Ok(unsafe { &mut *ptr })
}

/// Frees the handle `ptr` (nothing for `NULL`).
///
/// # Safety
/// No other thread uses `ptr` during or after the call.
pub(crate) unsafe fn free_handle<T: Handle>(ptr: *mut T, what: &str) -> Res<()> {
    if ptr.is_null() {
        return Ok(());
    }
    {
        // Checked and removed under one write lock: no other call can free
        // or re-register this address in between.
        let mut live = live_mut();
        verdict::<T>(live.get(&key(ptr)).copied(), what)?;
        live.remove(&key(ptr));
    }
    // SAFETY: the address was registered as a `T`, so it came from
    // `Box::into_raw` of a `T`; it was unregistered above under the write
    // lock, so no other call frees it again or reads it from now on; the
    // caller guarantees no other thread holds a reference to it.
    drop(unsafe { Box::from_raw(ptr) });
    Ok(())
}

/// Checks that `out` can take a `T`: not `NULL`, aligned.
fn check_out<T>(out: *mut T, what: &str) -> Res<()> {
    if out.is_null() {
        return Err(null(what));
    }
    if !out.is_aligned() {
        return Err(Failure::new(
            MbStatus::InvalidSize,
            format!("{what} is misaligned"),
        ));
    }
    Ok(())
}

/// Writes `value` to `out`.
///
/// # Safety
/// `out` is `NULL` or valid for writing a `T` (the C caller's contract).
pub(crate) unsafe fn write_out<T>(out: *mut T, value: T, what: &str) -> Res<()> {
    check_out(out, what)?;
    // SAFETY: `out` is not null and is aligned (checked), and the caller
    // guarantees it is valid for writes of a `T`; `write` does not read or
    // drop the old contents (C memory, possibly uninitialised).
    unsafe { out.write(value) };
    Ok(())
}

/// Writes `values` to the array `out` (nothing for no value).
///
/// # Safety
/// `out` is `NULL` or valid for writing `values.len()` consecutive `T`s.
pub(crate) unsafe fn write_slice<T: Copy>(out: *mut T, values: &[T], what: &str) -> Res<()> {
    if values.is_empty() {
        return Ok(());
    }
    check_out(out, what)?;
    // SAFETY: `out` is not null and aligned (checked) and valid for
    // `values.len()` writes by the caller's contract; a fresh `Vec`'s
    // buffer (`values`) cannot overlap C's array.
    unsafe { std::ptr::copy_nonoverlapping(values.as_ptr(), out, values.len()) };
    Ok(())
}

/// Makes `value` a handle and writes it to `out`. Nothing is allocated when
/// `out` is unusable.
///
/// # Safety
/// As [`write_out`].
pub(crate) unsafe fn write_handle<T: Handle>(out: *mut *mut T, value: T) -> Res<()> {
    check_out(out, "out")?;
    let ptr = Box::into_raw(Box::new(value));
    live_mut().insert(key(ptr), T::KIND);
    // SAFETY: as in `write_out`: `out` is checked not null and aligned, and
    // valid for writes by the caller's contract.
    unsafe { out.write(ptr) };
    Ok(())
}

/// The value at `ptr`, or `None` for `NULL`.
///
/// # Safety
/// `ptr` is `NULL` or valid for reading a `T`.
pub(crate) unsafe fn read_in<T: Plain>(ptr: *const T, what: &str) -> Res<Option<T>> {
    if ptr.is_null() {
        return Ok(None);
    }
    if !ptr.is_aligned() {
        return Err(Failure::new(
            MbStatus::InvalidSize,
            format!("{what} is misaligned"),
        ));
    }
    // SAFETY: not null, aligned (checked), valid for reads by the caller's
    // contract; any bit pattern is a `T` (`Plain`).
    Ok(Some(unsafe { ptr.read() }))
}

/// The array of `len` values at `ptr` (empty for `len == 0`, whatever
/// `ptr`).
///
/// # Safety
/// For `len > 0`, `ptr` is `NULL` or valid for reading `len` consecutive
/// `T`s, not written by anyone while the slice lives.
pub(crate) unsafe fn slice_from<'a, T: Plain>(
    ptr: *const T,
    len: usize,
    what: &str,
) -> Res<&'a [T]> {
    if len == 0 {
        return Ok(&[]);
    }
    if ptr.is_null() {
        return Err(null(what));
    }
    if !ptr.is_aligned() {
        return Err(Failure::new(
            MbStatus::InvalidSize,
            format!("{what} is misaligned"),
        ));
    }
    let bytes = len.checked_mul(std::mem::size_of::<T>());
    if bytes.is_none_or(|b| b > isize::MAX as usize) {
        return Err(Failure::new(
            MbStatus::InvalidSize,
            format!("{what}: {len} items overflow the address space"),
        ));
    }
    // SAFETY: not null, aligned, `len * size_of::<T>()` fits in `isize`
    // (checked); the caller guarantees `len` readable `T`s, unchanged while
    // the slice lives; every bit pattern is a `T` (`Plain`).
    Ok(unsafe { std::slice::from_raw_parts(ptr, len) })
}
