//! The polysweep playground: draw two polygon sets and watch intersection, union, both differences and xor update
//! live, on egui over wgpu (WebGPU in the browser where available, WebGL2 otherwise; Vulkan/Metal/DX12/GL natively).
//!
//! The editing model ([`scene`]), camera ([`view`]), operations ([`operation`]) and fill ([`fill`]) hold no UI
//! state and are tested natively; [`app`] is the egui front end, which draws the fills through its own wgpu
//! pipeline ([`gpu`], with the WGSL of `fill.wgsl`) and has what takes time computed as [`job`]s in the
//! [`background`] (a thread natively, a Web Worker in the browser, the jobs crossing to it as numbers); [`io`] and
//! the background are the parts that differ between the browser and a native window.

pub mod app;
pub mod background;
pub mod explorer;
pub mod fill;
pub mod gpu;
pub mod io;
pub mod job;
pub mod operation;
pub mod presets;
pub mod scene;
pub mod view;
#[cfg(any(target_arch = "wasm32", test))]
mod wire;

pub use app::Playground;

/// The browser entry: `index.html` constructs a `WebHandle` and starts it on its canvas.
#[cfg(target_arch = "wasm32")]
mod web {
    use wasm_bindgen::prelude::*;

    #[wasm_bindgen]
    pub struct WebHandle {
        runner: eframe::WebRunner,
    }

    #[wasm_bindgen]
    impl WebHandle {
        #[wasm_bindgen(constructor)]
        #[allow(clippy::new_without_default)]
        pub fn new() -> Self {
            eframe::WebLogger::init(log::LevelFilter::Warn).ok();
            WebHandle {
                runner: eframe::WebRunner::new(),
            }
        }

        /// Starts the playground on `canvas`, computing results in a worker running the script at `worker_url`
        /// (`worker.js`, beside this module), or on the page without one; with the preset of that name loaded
        /// (`?preset=land-8` in the page's address), if one is given.
        pub async fn start(
            &self,
            canvas: web_sys::HtmlCanvasElement,
            worker_url: Option<String>,
            preset: Option<String>,
        ) -> Result<(), JsValue> {
            let options = eframe::WebOptions::default();
            let app = move |cc: &eframe::CreationContext<'_>| {
                let mut playground = crate::Playground::new(cc);
                playground.worker_url = worker_url;
                if let Some(name) = preset {
                    playground.load_preset_named(&name);
                }
                Ok(Box::new(playground) as Box<dyn eframe::App>)
            };
            self.runner.start(canvas, options, Box::new(app)).await
        }

        /// Whether a result is being computed (the canvas shows the previous one meanwhile).
        pub fn pending(&self) -> bool {
            (self.runner.app_mut::<crate::Playground>()).is_some_and(|app| app.pending())
        }

        /// Frames drawn, frames drawn while a result was pending, results of the operation received, 1 if they
        /// are computed in the worker (0 on the page), and the milliseconds the shown result's operation took, for
        /// the browser test.
        pub fn counters(&self) -> Vec<f64> {
            let Some(app) = self.runner.app_mut::<crate::Playground>() else {
                return vec![0.0; 5];
            };
            let (frames, pending) = app.frames();
            let in_worker = f64::from(u8::from(app.computes_off_thread()));
            let shown = app.shown().and_then(|c| c.outcome.as_ref().ok());
            let milliseconds = shown.map_or(f64::NAN, |o| o.milliseconds);
            let results = app.results_received() as f64;
            vec![
                frames as f64,
                pending as f64,
                results,
                in_worker,
                milliseconds,
            ]
        }

        /// The graphics API the playground draws with: "WebGPU" or "WebGL2" (undefined before it has started).
        pub fn renderer(&self) -> Option<String> {
            let app = self.runner.app_mut::<crate::Playground>()?;
            app.renderer.map(str::to_string)
        }

        /// The panic message, if the app has crashed (the page shows it instead of a dead canvas).
        pub fn panic_message(&self) -> Option<String> {
            self.runner.panic_summary().map(|s| s.message())
        }
    }
}
