//! Independent solves spread over the machine's cores, results in input order.
//!
//! Each item is computed by the same code on the same inputs whichever thread
//! takes it, so the results are bit for bit those of a serial loop.

use std::sync::atomic::{AtomicUsize, Ordering};

/// The cores to use for `threads`: `0` means all the machine has
/// (`std::thread::available_parallelism`, 1 when that is unknown).
pub fn thread_count(threads: usize) -> usize {
    match threads {
        0 => std::thread::available_parallelism().map_or(1, |n| n.get()),
        n => n,
    }
}

/// `items.iter().map(f).collect()`, with up to `threads` threads taking the
/// next item as they finish one. A thread the system cannot start leaves its
/// share to the others (the calling thread always works), so this never fails.
pub fn map_in_order<T: Sync, R: Send>(
    items: &[T],
    threads: usize,
    f: impl Fn(&T) -> R + Sync,
) -> Vec<R> {
    let workers = thread_count(threads).min(items.len());
    if workers <= 1 {
        return items.iter().map(f).collect();
    }
    let next = AtomicUsize::new(0);
    let work = || {
        let mut done = Vec::new();
        loop {
            let i = next.fetch_add(1, Ordering::Relaxed);
            let Some(item) = items.get(i) else {
                return done;
            };
            done.push((i, f(item)));
        }
    };
    let mut slots: Vec<Option<R>> = std::iter::repeat_with(|| None).take(items.len()).collect();
    std::thread::scope(|scope| {
        let helpers: Vec<_> = (1..workers)
            .filter_map(|_| std::thread::Builder::new().spawn_scoped(scope, work).ok())
            .collect();
        let mut all = work();
        for h in helpers {
            match h.join() {
                Ok(done) => all.extend(done),
                Err(panic) => std::panic::resume_unwind(panic),
            }
        }
        for (i, r) in all {
            slots[i] = Some(r);
        }
    });
    let results: Vec<R> = slots.into_iter().flatten().collect();
    debug_assert_eq!(results.len(), items.len(), "every index is taken once");
    results
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn results_come_back_in_input_order_for_any_thread_count() {
        let items: Vec<u64> = (0..257).collect();
        let serial: Vec<u64> = items.iter().map(|&x| x * x + 7).collect();
        for threads in [1, 2, 3, 8, 300] {
            assert_eq!(
                map_in_order(&items, threads, |&x| x * x + 7),
                serial,
                "{threads} threads"
            );
        }
        assert!(map_in_order(&[] as &[u64], 4, |&x| x).is_empty());
    }

    #[test]
    fn zero_threads_means_every_core() {
        assert!(thread_count(0) >= 1);
        assert_eq!(thread_count(3), 3);
    }
}
