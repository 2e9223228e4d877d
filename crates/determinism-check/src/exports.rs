//! The cases as C functions, for the wasm32 module (`web/hashes.mjs` calls them from
//! Node.js): no imports, no bindings generator; a name is read from the module's memory.
//!
//! Indices follow [`cases`]. Names and hashes of an index past the count are
//! empty and zero: ask the count first.
//!
//! `#[unsafe(no_mangle)]` is what exports a function from a wasm module under its own name;
//! the `unsafe_code` lint flags it because two such symbols could collide at link time. The
//! names here carry the crate's prefix, and nothing else in the crate is unsafe.
#![allow(unsafe_code)]

use crate::{Case, cases};

fn case(index: u32) -> Option<&'static Case> {
    cases().nth(usize::try_from(index).ok()?)
}

/// How many cases there are.
#[unsafe(no_mangle)]
pub extern "C" fn determinism_case_count() -> u32 {
    u32::try_from(cases().count()).expect("a few cases")
}

/// Where case `index`'s name (UTF-8) starts in memory; null past the count.
#[unsafe(no_mangle)]
pub extern "C" fn determinism_case_name_ptr(index: u32) -> *const u8 {
    case(index).map_or(std::ptr::null(), |c| c.name.as_ptr())
}

/// The length in bytes of case `index`'s name; 0 past the count.
#[unsafe(no_mangle)]
pub extern "C" fn determinism_case_name_len(index: u32) -> u32 {
    case(index).map_or(0, |c| u32::try_from(c.name.len()).expect("a short name"))
}

/// Runs case `index` and returns its hash; 0 past the count.
#[unsafe(no_mangle)]
pub extern "C" fn determinism_case_hash(index: u32) -> u64 {
    case(index).map_or(0, |c| (c.hash)())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_exports_name_every_case_in_order() {
        let count = determinism_case_count();
        assert_eq!(count as usize, cases().count());
        for (index, case) in (0..count).zip(cases()) {
            assert_eq!(determinism_case_name_ptr(index), case.name.as_ptr());
            assert_eq!(determinism_case_name_len(index) as usize, case.name.len());
        }
        assert!(determinism_case_name_ptr(count).is_null());
        assert_eq!(determinism_case_name_len(count), 0);
        assert_eq!(determinism_case_hash(count), 0);
    }
}
