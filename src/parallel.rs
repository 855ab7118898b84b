//! A parallel map over a slice on the machine's cores, with `std` threads only (the light core
//! takes no thread-pool dependency): items are handed out one at a time from a shared counter,
//! so uneven items balance, and the results come back in the items' order — the same on any
//! number of cores.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// `items.iter().map(f).collect()`, on up to `std::thread::available_parallelism()` threads.
pub(crate) fn map<T: Sync, R: Send>(items: &[T], f: impl Fn(&T) -> R + Sync) -> Vec<R> {
    let threads = cores().min(items.len());
    if threads <= 1 {
        return items.iter().map(f).collect();
    }
    let next = AtomicUsize::new(0);
    let results: Mutex<Vec<Option<R>>> = Mutex::new((0..items.len()).map(|_| None).collect());
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(item) = items.get(i) else { break };
                let r = f(item);
                // a poisoned lock means another worker panicked; its panic is re-raised by
                // the scope, so this value is not needed
                if let Ok(mut all) = results.lock() {
                    all[i] = Some(r);
                }
            });
        }
    });
    results
        .into_inner()
        .unwrap_or_else(|e| e.into_inner())
        .into_iter()
        .map(|r| r.expect("every item is mapped once the scope has joined"))
        .collect()
}

/// The machine's cores (`std::thread::available_parallelism`, 1 if unknown), asked once:
/// the question reads cgroup files, tens of microseconds each time.
pub(crate) fn cores() -> usize {
    static CORES: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    *CORES.get_or_init(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
}

/// Resizes `out` to `inputs.len()` (new slots `zero`, the rest overwritten) and fills it by
/// `fill(part, out_part)` on the two halves of `inputs`, on two threads when `parallel` is
/// set: the batch shape of the curve and spline evaluators, whose values depend on each input
/// alone, so the result does not depend on the split.
pub(crate) fn fill_halves<T: Copy + Send>(
    inputs: &[f64],
    out: &mut Vec<T>,
    zero: T,
    parallel: bool,
    fill: impl Fn(&[f64], &mut [T]) + Sync,
) {
    out.truncate(inputs.len());
    out.resize(inputs.len(), zero);
    let half = inputs.len() / 2;
    let (first, second) = inputs.split_at(half);
    let (out_first, out_second) = out.split_at_mut(half);
    join(
        parallel,
        || fill(first, out_first),
        || fill(second, out_second),
    );
}

/// `(a(), b())`, with `b` on a second thread when `parallel` is set (and the machine lets a
/// thread be made: otherwise, or if `parallel` is not set, both run here, `a` first). A panic
/// of `b` is re-raised here.
pub(crate) fn join<A: Send, B: Send>(
    parallel: bool,
    a: impl FnOnce() -> A + Send,
    b: impl FnOnce() -> B + Send,
) -> (A, B) {
    if !(parallel && cores() > 1) {
        let ra = a();
        return (ra, b());
    }
    // b waits in a cell, so that it can still run here if no thread can be made
    let cell = Mutex::new(Some(b));
    std::thread::scope(|scope| {
        let spawned = std::thread::Builder::new().spawn_scoped(scope, || {
            let b = cell.lock().ok().and_then(|mut b| b.take());
            b.map(|b| b())
        });
        let ra = a();
        let rb = match spawned {
            Ok(handle) => match handle.join() {
                Ok(rb) => rb,
                Err(panic) => std::panic::resume_unwind(panic),
            },
            Err(_) => None,
        };
        let rb = rb.unwrap_or_else(|| {
            let b = cell
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .take()
                .expect("b runs once: on the thread, or here when the thread was not made");
            b()
        });
        (ra, rb)
    })
}

#[cfg(test)]
mod tests {
    #[test]
    fn keeps_order() {
        let items: Vec<usize> = (0..1000).collect();
        assert_eq!(
            super::map(&items, |&i| i * i),
            items.iter().map(|&i| i * i).collect::<Vec<_>>()
        );
        assert!(super::map(&[] as &[usize], |&i| i).is_empty());
    }
}
