//! The wasm module's allocator: talc, given memory that grows geometrically.
//!
//! Every `memory.grow` makes V8 account the new bytes as external memory, and past a
//! few megabytes of such growth it may run a full garbage collection of the page's
//! heap. Rust's default wasm allocator (dlmalloc) and talc's own wasm source grow by
//! what each request needs, rounded up to a 64 KB page: a classification that built up
//! 126 MB grew memory about 2,000 times. Growing by an eighth of the current size (at
//! least 1 MB) reaches the same size in about 40 grows and leaves at most an eighth
//! unused: 50,000 strokes classified in wasm, 3.70 s with dlmalloc -> 3.18 s (medians
//! of 3, Node 20; on a machine under load the collections cost far more: 5.4 s of a
//! 10.9 s run in one profile). talc rather than dlmalloc: as fast here
//! and 33 KB smaller in the module. Memory never shrinks either way: the package drops
//! an instance whose memory grew far past its start (`js/pkg/instance.js`).

use core::alloc::Layout;
use core::arch::wasm32;
use core::ptr::NonNull;
use talc::base::{binning::Binning, Talc};
use talc::cell::TalcSyncCell;
use talc::wasm::WasmBinning;

const PAGE: usize = 64 << 10;
/// The smallest growth, in pages (1 MB).
const MIN_GROWTH: usize = 16;
/// Bytes talc may need beside a request (its chunk header and alignment), generously.
const OVERHEAD: usize = 256;

/// talc's source of memory: `memory.grow` by at least an eighth of the memory, the new
/// pages joined to the heap they follow.
#[derive(Debug)]
struct Geometric {
    /// The end of the heap, where the next grown pages join it.
    end: Option<NonNull<u8>>,
}

// SAFETY: `acquire` allocates nothing; it only grows memory and hands it to talc.
unsafe impl talc::source::Source for Geometric {
    fn acquire<B: Binning>(talc: &mut Talc<Self, B>, layout: Layout) -> Result<(), ()> {
        let needed = (layout.size() + layout.align() + OVERHEAD).div_ceil(PAGE);
        let wanted = needed.max(wasm32::memory_size(0) / 8).max(MIN_GROWTH);
        // Near the 4 GB limit the geometric step may not fit where the request does.
        let (previous, pages) = [wanted, needed]
            .into_iter()
            .map(|pages| (wasm32::memory_grow(0, pages), pages))
            .find(|&(previous, _)| previous != usize::MAX)
            .ok_or(())?;
        let base = (previous * PAGE) as *mut u8;
        let size = pages * PAGE;
        if let Some(end) = talc.source.end.take() {
            if end.as_ptr() == base {
                // SAFETY: the pages just grown follow the heap's end and belong to no one.
                talc.source.end = Some(unsafe { talc.extend(end, base.add(size)) });
                return Ok(());
            }
        }
        // SAFETY: the pages just grown belong to no one.
        talc.source.end = unsafe { talc.claim(base, size) };
        talc.source.end.map(|_| ()).ok_or(())
    }
}

/// The module is built without threads (no `atomics`), which `new_wasm` checks.
#[global_allocator]
static HEAP: TalcSyncCell<Geometric, WasmBinning> = TalcSyncCell::new_wasm(Geometric { end: None });
