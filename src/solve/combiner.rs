//! Requests from several threads served as one batch: the plate's triangular solves on the
//! iterative route, where a solve with m right-hand sides reads the factor from memory once.
//!
//! Measured on `benches/scenes/halfspace-lane.toml`'s plate (57 135 equations, one core): one
//! right-hand side 11–19 ms, eight 25–30 ms — 3.2–3.7 ms a column. Positions of a `critical` or
//! `damage` run solved side by side on more threads than cores therefore share their solves:
//! a thread that asks while a batch is being solved waits for it to end and joins the next one.
//!
//! The scheme is flat combining: every request is queued under one lock; a thread that finds no
//! batch running takes the whole queue, its own request among them, solves it outside the lock
//! and hands the answers back. Nobody waits for a request that has not been made, so a thread
//! alone (or the last one of a run) is never held up: its batch is itself. The answers are
//! those of the single solves up to round-off (the batched kernels sum in another order).

use std::collections::HashMap;
use std::sync::{Condvar, Mutex, MutexGuard, PoisonError};

/// Combines the requests of concurrent callers of [`Combiner::run`] into batches.
pub struct Combiner<T> {
    state: Mutex<State<T>>,
    ready: Condvar,
}

struct State<T> {
    next: u64,
    queue: Vec<(u64, T)>,
    /// Answers by ticket; `None`: the batch it was in panicked.
    done: HashMap<u64, Option<T>>,
    busy: bool,
    /// The largest batch served so far (what the tests look at).
    #[cfg(test)]
    widest: usize,
}

impl<T> Default for Combiner<T> {
    fn default() -> Self {
        Self {
            state: Mutex::new(State {
                next: 0,
                queue: Vec::new(),
                done: HashMap::new(),
                busy: false,
                #[cfg(test)]
                widest: 0,
            }),
            ready: Condvar::new(),
        }
    }
}

impl<T> Combiner<T> {
    /// `work` applied to `item`, possibly in one batch with other threads' items: `work` takes
    /// a batch and returns its answers in the same order.
    pub fn run(&self, item: T, work: impl Fn(Vec<T>) -> Vec<T>) -> T {
        let mut s = self.lock();
        let ticket = s.next;
        s.next += 1;
        s.queue.push((ticket, item));
        loop {
            if let Some(answer) = s.done.remove(&ticket) {
                match answer {
                    Some(a) => return a,
                    None => {
                        std::panic::panic_any("a batched solve that held this request panicked")
                    }
                }
            }
            if !s.busy {
                s.busy = true;
                let (tickets, items): (Vec<u64>, Vec<T>) =
                    std::mem::take(&mut s.queue).into_iter().unzip();
                #[cfg(test)]
                {
                    s.widest = s.widest.max(items.len());
                }
                drop(s);
                let answers =
                    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| work(items)));
                s = self.lock();
                s.busy = false;
                let failed = match answers {
                    Ok(answers) if answers.len() == tickets.len() => {
                        s.done
                            .extend(tickets.into_iter().zip(answers.into_iter().map(Some)));
                        None
                    }
                    Ok(_) => {
                        s.done.extend(tickets.into_iter().map(|t| (t, None)));
                        Some(None)
                    }
                    Err(payload) => {
                        s.done.extend(tickets.into_iter().map(|t| (t, None)));
                        Some(Some(payload))
                    }
                };
                self.ready.notify_all();
                match failed {
                    None => continue,
                    Some(Some(payload)) => {
                        drop(s);
                        std::panic::resume_unwind(payload)
                    }
                    Some(None) => {
                        drop(s);
                        std::panic::panic_any(
                            "a batched solve returned the wrong number of answers",
                        )
                    }
                }
            }
            s = self.ready.wait(s).unwrap_or_else(PoisonError::into_inner);
        }
    }

    /// The largest batch served so far (1 when every caller was alone).
    #[cfg(test)]
    fn widest(&self) -> usize {
        self.lock().widest
    }

    fn lock(&self) -> MutexGuard<'_, State<T>> {
        // A panic is never raised while the lock is held (`work` runs outside it), so a
        // poisoned lock still holds a consistent state.
        self.state.lock().unwrap_or_else(PoisonError::into_inner)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::Barrier;

    #[test]
    fn a_caller_alone_is_its_own_batch() {
        let c = Combiner::default();
        let batches = AtomicUsize::new(0);
        for i in 0..5 {
            let out = c.run(i, |items: Vec<i32>| {
                batches.fetch_add(1, Ordering::Relaxed);
                items.into_iter().map(|x| 10 * x).collect()
            });
            assert_eq!(out, 10 * i);
        }
        assert_eq!(batches.load(Ordering::Relaxed), 5);
        assert_eq!(c.widest(), 1);
    }

    /// Eight threads ask at once while a slow batch runs: every one gets its own answer (not a
    /// neighbour's), and the requests made during the first batch are served together, so
    /// fewer batches run than requests were made.
    #[test]
    fn concurrent_callers_share_batches_and_keep_their_answers() {
        let c = Combiner::default();
        let start = Barrier::new(8);
        let batches = AtomicUsize::new(0);
        std::thread::scope(|scope| {
            for t in 0..8u64 {
                let (c, start, batches) = (&c, &start, &batches);
                scope.spawn(move || {
                    start.wait();
                    for round in 0..20u64 {
                        let item = 1000 * t + round;
                        let out = c.run(item, |items: Vec<u64>| {
                            batches.fetch_add(1, Ordering::Relaxed);
                            std::thread::sleep(std::time::Duration::from_millis(2));
                            items.into_iter().map(|x| x * 3 + 1).collect()
                        });
                        assert_eq!(out, item * 3 + 1);
                    }
                });
            }
        });
        let made = batches.load(Ordering::Relaxed);
        assert!(made < 160, "{made} batches for 160 requests");
        assert!(c.widest() > 1);
    }

    /// A batch that panics wakes its waiters with a panic instead of leaving them waiting.
    #[test]
    fn a_panicking_batch_does_not_leave_waiters_hanging() {
        let c = Combiner::<u32>::default();
        let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            c.run(1, |_: Vec<u32>| -> Vec<u32> { panic!("boom") })
        }));
        assert!(r.is_err());
        // The combiner still serves the next caller.
        assert_eq!(c.run(2, |v: Vec<u32>| v), 2);
    }
}
