//! The polysweep playground: draw two polygon sets and watch intersection, union, both differences and xor update
//! live, on egui over wgpu (WebGPU in the browser where available, WebGL2 otherwise; Vulkan/Metal/DX12/GL natively).
//!
//! The editing model ([`scene`]), camera ([`view`]), operations ([`operation`]) and fill ([`fill`]) hold no UI
//! state and are tested natively; [`app`] is the egui front end, which draws the fills through its own wgpu
//! pipeline ([`gpu`], with the WGSL of `fill.wgsl`); [`io`] is the only part that differs between the browser and a
//! native window.

pub mod app;
pub mod fill;
pub mod gpu;
pub mod io;
pub mod operation;
pub mod presets;
pub mod scene;
pub mod view;

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

        pub async fn start(&self, canvas: web_sys::HtmlCanvasElement) -> Result<(), JsValue> {
            let options = eframe::WebOptions::default();
            self.runner
                .start(
                    canvas,
                    options,
                    Box::new(|cc| Ok(Box::new(crate::Playground::new(cc)))),
                )
                .await
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
