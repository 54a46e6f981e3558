//! What a `no_std` static library brings itself (feature `std` off): the panic handler, which
//! stops the process with a trap instruction, and the unwinding personality routine that the
//! precompiled `core` refers to. Neither is reached: the exported paths are written without
//! panicking operations and nothing unwinds without std. `bcsdf-core/nostd-check` includes
//! this file too (one trap for both no_std builds).

/// Stops the program at once and deterministically: the architecture's trap instruction
/// (an illegal-instruction or breakpoint exception, SIGILL/SIGTRAP on a hosted OS), or the
/// C library's `abort` on an architecture without one here. Never a spin loop: a hang in an
/// engine is worse than a crash.
#[cfg_attr(any(feature = "std", test), allow(dead_code))]
#[inline(always)]
pub(crate) fn trap() -> ! {
    #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
    // SAFETY: `ud2` raises an invalid-opcode exception; it touches no memory or stack and
    // never returns, as `noreturn` says.
    unsafe {
        core::arch::asm!("ud2", options(noreturn, nomem, nostack));
    }
    #[cfg(any(target_arch = "arm", target_arch = "aarch64"))]
    // SAFETY: `udf #0` is permanently undefined (an undefined-instruction exception); it
    // touches no memory or stack and never returns.
    unsafe {
        core::arch::asm!("udf #0", options(noreturn, nomem, nostack));
    }
    #[cfg(any(target_arch = "riscv32", target_arch = "riscv64"))]
    // SAFETY: `unimp` is an illegal instruction; it touches no memory or stack and never
    // returns.
    unsafe {
        core::arch::asm!("unimp", options(noreturn, nomem, nostack));
    }
    #[cfg(target_arch = "wasm32")]
    core::arch::wasm32::unreachable();
    #[cfg(not(any(
        target_arch = "x86",
        target_arch = "x86_64",
        target_arch = "arm",
        target_arch = "aarch64",
        target_arch = "riscv32",
        target_arch = "riscv64",
        target_arch = "wasm32"
    )))]
    {
        extern "C" {
            fn abort() -> !;
        }
        // SAFETY: the C library's abort takes no arguments and ends the process.
        unsafe { abort() };
    }
}

#[cfg(all(not(feature = "std"), not(test)))]
#[panic_handler]
fn panic(_: &core::panic::PanicInfo<'_>) -> ! {
    trap()
}

/// The unwinding personality routine the precompiled `core` refers to (its unwind tables
/// name it), with the Itanium C++ ABI signature (`_Unwind_Personality_Fn`): version,
/// actions, exception class, exception object, context; the reason code is returned.
/// Nothing unwinds without std (the no_std build aborts on panic), so it is never called; if
/// an unwinder ever did, it traps rather than guess.
#[cfg(all(not(feature = "std"), not(test), not(target_arch = "arm")))]
#[no_mangle]
pub extern "C" fn rust_eh_personality(
    _version: core::ffi::c_int,
    _actions: core::ffi::c_int,
    _exception_class: u64,
    _exception: *mut core::ffi::c_void,
    _context: *mut core::ffi::c_void,
) -> core::ffi::c_int {
    trap()
}

/// [`rust_eh_personality`] for 32-bit ARM, whose EHABI personality takes the unwind state,
/// the exception object and the context.
#[cfg(all(not(feature = "std"), not(test), target_arch = "arm"))]
#[no_mangle]
pub extern "C" fn rust_eh_personality(
    _state: core::ffi::c_int,
    _exception: *mut core::ffi::c_void,
    _context: *mut core::ffi::c_void,
) -> core::ffi::c_int {
    trap()
}
