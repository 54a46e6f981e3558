//! Checks of the pointer arguments of the C ABI: NULL, alignment, size limits and overlap,
//! and the reads and writes of small fixed-size arrays through checked pointers.

use crate::fur_status;
use core::mem::align_of;

/// Whether `p` is aligned for `T`.
pub(crate) fn aligned<T>(p: *const T) -> bool {
    p.addr().is_multiple_of(align_of::<T>())
}

/// NULL and alignment of a pointer argument (`FUR_ERR_NULL`, then `FUR_ERR_ALIGNMENT`).
pub(crate) fn check_ptr<T>(p: *const T) -> Result<(), fur_status> {
    if p.is_null() {
        Err(fur_status::FUR_ERR_NULL)
    } else if !aligned(p) {
        Err(fur_status::FUR_ERR_ALIGNMENT)
    } else {
        Ok(())
    }
}

/// The bytes a buffer argument covers: `len` bytes from address `start`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Region {
    start: usize,
    len: usize,
}

impl Region {
    /// `count` values of `T` at `p`.
    pub(crate) fn of<T>(p: *const T, count: usize) -> Region {
        Region {
            start: p.addr(),
            len: count.saturating_mul(size_of::<T>()),
        }
    }

    /// `len` bytes at address `start` (a stored address: no pointer is made from it).
    pub(crate) fn at(start: usize, len: usize) -> Region {
        Region { start, len }
    }

    /// Whether the two regions share a byte (empty regions share none).
    fn overlaps(self, other: Region) -> bool {
        self.len != 0
            && other.len != 0
            && self.start < other.start.saturating_add(other.len)
            && other.start < self.start.saturating_add(self.len)
    }
}

/// `FUR_ERR_OVERLAP` if the output region `out` shares a byte with any of `others` (every
/// other buffer the call reads or keeps a reference into), so that the Rust side never holds
/// a shared and a mutable reference to the same memory.
pub(crate) fn disjoint(out: Region, others: &[Region]) -> Result<(), fur_status> {
    if others.iter().any(|r| out.overlaps(*r)) {
        Err(fur_status::FUR_ERR_OVERLAP)
    } else {
        Ok(())
    }
}

/// The start both `*_open` functions share: `out` non-NULL and aligned (else its status,
/// `*out` untouched) and outside the bytes (`FUR_ERR_OVERLAP`, untouched); then `*out` closed
/// by `close`, so that a failed open never leaves it open; then `bytes` non-NULL
/// (`FUR_ERR_NULL`) and `len` in 1 ..= isize::MAX (`FUR_ERR_LENGTH`); the bytes as a slice.
///
/// # Safety
/// `bytes` is NULL or points to `len` readable bytes that stay alive and unchanged for `'a`;
/// `out` is NULL or points to a writable `T` no other thread is using; `close` may be called
/// with a non-NULL, aligned pointer to a writable `T`.
pub(crate) unsafe fn open_bytes<'a, T>(
    bytes: *const u8,
    len: usize,
    out: *mut T,
    close: unsafe fn(*mut T),
) -> Result<&'a [u8], fur_status> {
    check_ptr(out)?;
    if !bytes.is_null() {
        disjoint(Region::of(out, 1), &[Region::of(bytes, len)])?;
    }
    // SAFETY: `out` is a writable, aligned T (checked, and the caller's contract) outside the
    // bytes (checked).
    unsafe { close(out) };
    if bytes.is_null() {
        return Err(fur_status::FUR_ERR_NULL);
    }
    if len == 0 || len > isize::MAX as usize {
        return Err(fur_status::FUR_ERR_LENGTH);
    }
    // SAFETY: non-NULL, `len` ≤ isize::MAX (checked); the caller guarantees `len` readable
    // bytes for `'a`, and `*out`, the only memory the open functions write while the slice
    // lives, is outside them (checked).
    Ok(unsafe { core::slice::from_raw_parts(bytes, len) })
}

/// Writes `v` to `out` (3 floats).
///
/// # Safety
/// `out` is non-NULL, 4-aligned and points to 3 writable floats.
pub(crate) unsafe fn write3(out: *mut f32, v: [f32; 3]) {
    // SAFETY: the caller guarantees 3 writable, aligned floats at `out`, which is what an
    // aligned write of one `[f32; 3]` (alignment 4) needs.
    unsafe { out.cast::<[f32; 3]>().write(v) };
}

/// Reads 3 floats from `p`, checking NULL and alignment.
///
/// # Safety
/// `p` is NULL or points to 3 readable floats.
pub(crate) unsafe fn read3(p: *const f32) -> Result<[f32; 3], fur_status> {
    check_ptr(p)?;
    // SAFETY: non-NULL and 4-aligned (checked); the caller guarantees 3 readable floats.
    Ok(unsafe { p.cast::<[f32; 3]>().read() })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn regions_overlap_when_they_share_a_byte() {
        let r = |start, len| Region { start, len };
        assert!(r(100, 12).overlaps(r(111, 1)));
        assert!(r(111, 4).overlaps(r(100, 12)));
        assert!(!r(100, 12).overlaps(r(112, 4)));
        assert!(!r(112, 4).overlaps(r(100, 12)));
        assert!(!r(100, 0).overlaps(r(100, 4)));
        assert!(r(usize::MAX - 4, 8).overlaps(r(usize::MAX - 1, 1)));
        assert_eq!(
            disjoint(r(0, 8), &[r(8, 8), r(4, 1)]),
            Err(fur_status::FUR_ERR_OVERLAP)
        );
        assert_eq!(disjoint(r(0, 8), &[r(8, 8), r(16, 1)]), Ok(()));
    }
}
