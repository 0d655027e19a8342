//! `cargo run -p polysweep-playground`: the playground in a native window. The browser build starts from `lib.rs`.

#[cfg(not(target_arch = "wasm32"))]
fn main() -> eframe::Result {
    let options = eframe::NativeOptions {
        viewport: eframe::egui::ViewportBuilder::default().with_inner_size([1200.0, 800.0]),
        // The polygon pipelines (gpu.rs) are built for this many samples.
        multisampling: polysweep_playground::gpu::MSAA_SAMPLES as u16,
        ..Default::default()
    };
    eframe::run_native(
        "polysweep playground",
        options,
        Box::new(|cc| Ok(Box::new(polysweep_playground::Playground::new(cc)))),
    )
}

#[cfg(target_arch = "wasm32")]
fn main() {}
