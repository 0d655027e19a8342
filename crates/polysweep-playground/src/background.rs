//! Jobs (job.rs) run away from the UI thread, so that the canvas keeps drawing at the display's rate while a
//! result is computed: natively on a thread, in the browser in a Web Worker that loads this same wasm module
//! (`worker.js`, the jobs crossing as numbers, wire.rs).
//!
//! One job runs at a time. The newest request of each slot wins: a request replaces the slot's request that has not
//! started yet, so that a drag, which asks for a result on every move, gets the result of where the pointer is when
//! the worker is free, not a backlog of every position it passed. A running job is not interrupted (the core has
//! no cancellation point), but its result is kept only if nothing newer of its slot has been shown since.
//!
//! Without a worker (none given, or it failed to load or to run a job), jobs run on the calling thread: slower, but
//! the same results.

use crate::job::{Derivation, Job, SLOTS};

/// A job and its place in the order of requests.
pub struct Request {
    pub sequence: u64,
    pub job: Job,
}

/// What a job computed, for the slot and request it was made for.
pub struct Delivery {
    pub slot: usize,
    pub sequence: u64,
    pub derivation: Derivation,
}

impl Request {
    fn run(self) -> Delivery {
        Delivery {
            slot: self.job.slot(),
            sequence: self.sequence,
            derivation: self.job.run(),
        }
    }
}

/// The requests not yet started: at most one per slot, the newest; the result's slot is served first.
#[derive(Default)]
struct Waiting([Option<Request>; SLOTS]);

impl Waiting {
    fn put(&mut self, request: Request) {
        let slot = request.job.slot();
        self.0[slot] = Some(request);
    }

    #[cfg(not(target_arch = "wasm32"))]
    fn is_empty(&self) -> bool {
        self.0.iter().all(Option::is_none)
    }

    fn next(&mut self) -> Option<Request> {
        self.0.iter_mut().rev().find_map(Option::take)
    }
}

pub use imp::Background;

#[cfg(not(target_arch = "wasm32"))]
mod imp {
    use super::{Delivery, Request, Waiting};
    use std::sync::mpsc::{channel, Receiver, Sender};

    /// A thread that runs the jobs, and the channels to it and back.
    pub struct Background {
        requests: Sender<Request>,
        deliveries: Receiver<Delivery>,
    }

    impl Background {
        /// Starts the thread; `wake` is called after each delivery (to repaint).
        pub fn new(wake: impl Fn() + Send + 'static) -> Background {
            let (requests, incoming) = channel::<Request>();
            let (outgoing, deliveries) = channel();
            std::thread::Builder::new()
                .name("polysweep jobs".into())
                .spawn(move || {
                    let mut waiting = Waiting::default();
                    loop {
                        if waiting.is_empty() {
                            // Nothing to do: wait for a request, or end when the app has gone.
                            match incoming.recv() {
                                Ok(request) => waiting.put(request),
                                Err(_) => return,
                            }
                        }
                        for request in incoming.try_iter() {
                            waiting.put(request);
                        }
                        let Some(next) = waiting.next() else { continue };
                        if outgoing.send(next.run()).is_err() {
                            return;
                        }
                        wake();
                    }
                })
                .expect("a thread can be started");
            Background {
                requests,
                deliveries,
            }
        }

        pub fn submit(&mut self, request: Request) {
            // The thread ends only when this side is dropped, so sending cannot fail while `self` exists.
            self.requests.send(request).ok();
        }

        pub fn take_deliveries(&mut self) -> Vec<Delivery> {
            self.deliveries.try_iter().collect()
        }

        /// Whether jobs run away from the UI thread: always, natively.
        pub fn off_thread(&self) -> bool {
            true
        }
    }
}

#[cfg(target_arch = "wasm32")]
mod imp {
    use super::{Delivery, Request, Waiting};
    use crate::wire;
    use std::cell::RefCell;
    use std::rc::Rc;
    use wasm_bindgen::prelude::*;
    use web_sys::{MessageEvent, Worker, WorkerOptions, WorkerType};

    /// The worker, what waits for it, and what it delivered.
    pub struct Background {
        shared: Rc<RefCell<Shared>>,
        // Kept for as long as the worker may call them.
        _on_message: Option<Closure<dyn FnMut(MessageEvent)>>,
        _on_error: Option<Closure<dyn FnMut(web_sys::Event)>>,
    }

    struct Shared {
        worker: Option<Worker>,
        running: Option<Request>,
        waiting: Waiting,
        delivered: Vec<Delivery>,
        wake: Box<dyn Fn()>,
    }

    impl Background {
        /// Starts the worker script at `worker_url` (a module that imports this wasm and answers jobs), or, without
        /// one, runs jobs on this thread. `wake` is called after each delivery (to repaint).
        pub fn new(worker_url: Option<&str>, wake: impl Fn() + 'static) -> Background {
            let worker = worker_url.and_then(|url| {
                let options = WorkerOptions::new();
                options.set_type(WorkerType::Module);
                Worker::new_with_options(url, &options)
                    .map_err(|e| log::warn!("no worker, results are computed on the page: {e:?}"))
                    .ok()
            });
            let shared = Rc::new(RefCell::new(Shared {
                worker: worker.clone(),
                running: None,
                waiting: Waiting::default(),
                delivered: Vec::new(),
                wake: Box::new(wake),
            }));
            let Some(worker) = worker else {
                return Background {
                    shared,
                    _on_message: None,
                    _on_error: None,
                };
            };
            let on_message = {
                let shared = shared.clone();
                Closure::<dyn FnMut(MessageEvent)>::new(move |event: MessageEvent| {
                    shared.borrow_mut().receive(answer_of(&event));
                })
            };
            let on_error = {
                let shared = shared.clone();
                Closure::<dyn FnMut(web_sys::Event)>::new(move |_event: web_sys::Event| {
                    shared.borrow_mut().fail("it failed to load or to run");
                })
            };
            worker.set_onmessage(Some(on_message.as_ref().unchecked_ref()));
            worker.set_onerror(Some(on_error.as_ref().unchecked_ref()));
            Background {
                shared,
                _on_message: Some(on_message),
                _on_error: Some(on_error),
            }
        }

        pub fn submit(&mut self, request: Request) {
            let mut shared = self.shared.borrow_mut();
            shared.waiting.put(request);
            shared.start_next();
        }

        pub fn take_deliveries(&mut self) -> Vec<Delivery> {
            std::mem::take(&mut self.shared.borrow_mut().delivered)
        }

        /// Whether jobs run in the worker: not if none was given, or once it has failed.
        pub fn off_thread(&self) -> bool {
            self.shared.borrow().worker.is_some()
        }
    }

    /// The worker's answer: the numbers of a derivation, or the message of what went wrong.
    fn answer_of(event: &MessageEvent) -> Result<Vec<f64>, String> {
        match event.data().dyn_into::<js_sys::Float64Array>() {
            Ok(numbers) => Ok(numbers.to_vec()),
            Err(other) => Err(other.as_string().unwrap_or_else(|| format!("{other:?}"))),
        }
    }

    impl Shared {
        /// Sends the next waiting job to the worker if it is free, or, without a worker, runs every waiting job.
        fn start_next(&mut self) {
            if self.running.is_some() {
                return;
            }
            while let Some(request) = self.waiting.next() {
                let Some(worker) = &self.worker else {
                    self.delivered.push(request.run());
                    (self.wake)();
                    continue;
                };
                let numbers = js_sys::Float64Array::from(&wire::write_job(&request.job)[..]);
                let transfer = js_sys::Array::of1(&numbers.buffer());
                match worker.post_message_with_transfer(&numbers, &transfer) {
                    Ok(()) => {
                        self.running = Some(request);
                        return;
                    }
                    Err(e) => {
                        log::warn!(
                            "the worker refused a job ({e:?}); results are computed on the page"
                        );
                        self.stop_worker();
                        self.waiting.put(request);
                    }
                }
            }
        }

        /// Takes the worker's answer to the running job.
        fn receive(&mut self, answer: Result<Vec<f64>, String>) {
            let derivation = answer.and_then(|numbers| {
                wire::read_derivation(&numbers).map_err(|_| "a malformed answer".to_string())
            });
            let derivation = match derivation {
                Ok(derivation) => derivation,
                Err(message) => return self.fail(&message),
            };
            let Some(request) = self.running.take() else {
                return;
            };
            self.deliver(Delivery {
                slot: request.job.slot(),
                sequence: request.sequence,
                derivation,
            });
        }

        /// Stops using the worker (a panic may have left its instance unusable) and runs here what it was running.
        fn fail(&mut self, message: &str) {
            log::warn!(
                "the worker could not run a job ({message}); results are computed on the page"
            );
            self.stop_worker();
            if let Some(request) = self.running.take() {
                self.deliver(request.run());
            } else {
                self.start_next();
            }
        }

        fn deliver(&mut self, delivery: Delivery) {
            self.delivered.push(delivery);
            (self.wake)();
            self.start_next();
        }

        fn stop_worker(&mut self) {
            if let Some(worker) = self.worker.take() {
                worker.terminate();
            }
        }
    }

    /// The worker's side: runs one job given as numbers and answers with the numbers of what it computed, or
    /// with an error message if the answer holds an error the wire format does not know.
    #[wasm_bindgen]
    pub fn run_job(numbers: &[f64]) -> Result<Vec<f64>, JsError> {
        let job = wire::read_job(numbers).map_err(|_| JsError::new("a malformed job"))?;
        wire::write_derivation(&job.run())
            .ok_or_else(|| JsError::new("an error the page must compute"))
    }
}
