//! The polygons on the GPU. egui draws the UI; the polygons — the operands (filled as their fill rule reads them),
//! the result and its pieces, fills and outlines — go through these two pipelines, in an egui_wgpu paint callback:
//! each fill's triangles and each outline's edges (fill.rs) are uploaded once, when they are made, and every frame
//! only a small uniform per layer moves them with the view. A frame therefore costs the same whatever the vertex
//! count, where egui's meshes would transform and upload every vertex every frame.
//!
//! Fills are triangulated once on the CPU rather than drawn from the rings with the stencil method: eframe's render
//! pass has no stencil buffer (the stencil method would need a texture of its own and a pass to copy it back), and
//! earcut runs once per change, in a few milliseconds for the 59,212-vertex land.
//!
//! The shaders are in fill.wgsl; `tests::shaders_pass_naga` validates them with naga, as wgpu does before it
//! compiles them, so that a broken shader fails the native tests (CI has no GPU).
//!
//! Precision: positions are stored as f32 relative to an origin, the view's centre when they were uploaded, and the
//! view's offset from it is worked out in f64. f32 keeps an eighth of a pixel within two million pixels of the
//! origin, so a layer is uploaded again about the view's new centre when the view has moved further than that
//! (only at deep zoom: the whole world is a few thousand pixels wide at the usual zooms).
//!
//! Anti-aliasing: natively the pass is multisampled ([`MSAA_SAMPLES`], main.rs asks eframe for it); eframe's web
//! painter offers no MSAA, so there outlines fade out across their outermost pixel (fill.wgsl) as egui feathers.

use crate::fill::{Fill, Outline};
use crate::view::View;
use eframe::egui::{self, Color32, Rect, Stroke};
use eframe::egui_wgpu::{
    self, wgpu, CallbackResources, CallbackTrait, RenderState, ScreenDescriptor,
};
use polysweep::Point;
use std::collections::hash_map::{Entry, HashMap};
use wgpu::util::DeviceExt;

/// The WGSL of both pipelines.
pub const SHADER: &str = include_str!("fill.wgsl");

/// Samples per pixel of eframe's render pass, which the pipelines must match: 4 natively, where main.rs asks
/// eframe for them; 1 in the browser, where eframe has no multisampling.
pub const MSAA_SAMPLES: u32 = if cfg!(target_arch = "wasm32") { 1 } else { 4 };

/// How far, in pixels, the view may move from a layer's origin before the layer is uploaded again about the view's
/// centre: f32's 24 bits then still place every point within an eighth of a pixel.
const REBASE_PIXELS: f64 = (1u32 << 21) as f64;

/// The GPU side: the pipelines, the uploaded layers by id, and a uniform per layer drawn in the frame.
pub struct FillPipeline {
    fill: wgpu::RenderPipeline,
    outline: wgpu::RenderPipeline,
    placement_layout: wgpu::BindGroupLayout,
    uploaded: HashMap<u64, Uploaded>,
    placements: Vec<Placement>,
}

/// A layer's buffers: a fill's vertices and triangles' indices, or an outline's edges (two points each).
struct Uploaded {
    vertices: wgpu::Buffer,
    indices: Option<wgpu::Buffer>,
    count: u32,
    origin: Point,
}

struct Placement {
    uniform: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
}

/// Bytes of the `Placement` uniform of fill.wgsl: scale, offset, colour, pixel and width, padded to 16 bytes.
const PLACEMENT_SIZE: u64 = 12 * 4;

impl FillPipeline {
    /// Creates the pipeline for egui's render target and leaves it in egui's callback resources.
    pub fn install(render_state: &RenderState) {
        let device = &render_state.device;
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("polysweep fill"),
            source: wgpu::ShaderSource::Wgsl(SHADER.into()),
        });
        let placement_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("polysweep fill placement"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: wgpu::BufferSize::new(PLACEMENT_SIZE),
                },
                count: None,
            }],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("polysweep fill"),
            bind_group_layouts: &[Some(&placement_layout)],
            immediate_size: 0,
        });
        // egui writes gamma-space colours to a gamma target and converts them for an sRGB one: so do the fills.
        let fragment = if render_state.target_format.is_srgb() {
            "fs_linear"
        } else {
            "fs_gamma"
        };
        let pipeline = |vertex: &str, step_mode, attributes: &[wgpu::VertexAttribute]| {
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some("polysweep polygons"),
                layout: Some(&layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some(vertex),
                    compilation_options: Default::default(),
                    buffers: &[Some(wgpu::VertexBufferLayout {
                        array_stride: attributes.len() as u64 * 2 * 4,
                        step_mode,
                        attributes,
                    })],
                },
                primitive: wgpu::PrimitiveState::default(),
                // egui's render pass has no depth or stencil buffer (eframe's defaults).
                depth_stencil: None,
                multisample: wgpu::MultisampleState {
                    count: MSAA_SAMPLES,
                    ..Default::default()
                },
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some(fragment),
                    compilation_options: Default::default(),
                    targets: &[Some(wgpu::ColorTargetState {
                        format: render_state.target_format,
                        blend: Some(wgpu::BlendState::PREMULTIPLIED_ALPHA_BLENDING),
                        write_mask: wgpu::ColorWrites::ALL,
                    })],
                }),
                multiview_mask: None,
                cache: None,
            })
        };
        let fill = pipeline(
            "vs_fill",
            wgpu::VertexStepMode::Vertex,
            &wgpu::vertex_attr_array![0 => Float32x2],
        );
        // One instance per edge: its two ends.
        let outline = pipeline(
            "vs_outline",
            wgpu::VertexStepMode::Instance,
            &wgpu::vertex_attr_array![0 => Float32x2, 1 => Float32x2],
        );
        render_state
            .renderer
            .write()
            .callback_resources
            .insert(FillPipeline {
                fill,
                outline,
                placement_layout,
                uploaded: HashMap::new(),
                placements: Vec::new(),
            });
    }

    /// Uploads the layers not on the GPU yet (and those the view has moved too far from, see [`REBASE_PIXELS`]),
    /// forgets those no longer drawn, and writes each layer's placement.
    fn prepare(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, polygons: &Polygons) {
        let (layers, view) = (&polygons.layers, &polygons.view);
        self.uploaded
            .retain(|id, _| layers.iter().any(|layer| layer.id() == *id));
        for layer in layers {
            match self.uploaded.entry(layer.id()) {
                Entry::Occupied(entry) if !too_far(view, entry.get().origin) => {}
                entry => {
                    if let Some(uploaded) = upload(device, layer, view.center) {
                        entry.insert_entry(uploaded);
                    }
                }
            }
        }
        while self.placements.len() < layers.len() {
            let uniform = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("polysweep fill placement"),
                size: PLACEMENT_SIZE,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("polysweep fill placement"),
                layout: &self.placement_layout,
                entries: &[wgpu::BindGroupEntry {
                    binding: 0,
                    resource: uniform.as_entire_binding(),
                }],
            });
            self.placements.push(Placement {
                uniform,
                bind_group,
            });
        }
        let (canvas, view) = (polygons.canvas, &polygons.view);
        let pixel = [2.0 / canvas.width(), 2.0 / canvas.height()];
        for (layer, placement) in layers.iter().zip(&self.placements) {
            if let Some(uploaded) = self.uploaded.get(&layer.id()) {
                let [scale, offset] = clip_transform(view, canvas, uploaded.origin);
                let (color, width) = match layer {
                    Layer::Fill(_, color) => (color, 0.0),
                    Layer::Outline(_, stroke) => (&stroke.color, stroke.width),
                };
                let [r, g, b, a] = color.to_array().map(|c| f32::from(c) / 255.0);
                let floats = [
                    scale[0], scale[1], offset[0], offset[1], r, g, b, a, pixel[0], pixel[1],
                    width, 0.0,
                ];
                queue.write_buffer(&placement.uniform, 0, &f32_bytes(&floats));
            }
        }
    }
}

/// Whether the view has moved so far from `origin` that positions relative to it lose precision on screen.
fn too_far(view: &View, origin: Point) -> bool {
    let apart = (view.center.x - origin.x)
        .abs()
        .max((view.center.y - origin.y).abs());
    apart * view.scale > REBASE_PIXELS
}

/// A layer's points on the GPU, as f32 positions relative to `origin`: a fill's vertices and triangles, or an
/// outline's edges. `None` for an empty layer (wgpu has no empty buffers).
fn upload(device: &wgpu::Device, layer: &Layer, origin: Point) -> Option<Uploaded> {
    let points: &[Point] = match layer {
        Layer::Fill(fill, _) => fill.points(),
        Layer::Outline(outline, _) => outline.segments().as_flattened(),
    };
    if points.is_empty() || matches!(layer, Layer::Fill(fill, _) if fill.triangle_count() == 0) {
        return None;
    }
    let positions: Vec<f32> = (points.iter())
        .flat_map(|p| [(p.x - origin.x) as f32, (p.y - origin.y) as f32])
        .collect();
    let buffer = |contents: &[u8], usage| {
        device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("polysweep polygons"),
            contents,
            usage,
        })
    };
    let vertices = buffer(&f32_bytes(&positions), wgpu::BufferUsages::VERTEX);
    Some(match layer {
        Layer::Fill(fill, _) => {
            let indices: Vec<u8> = (fill.triangles().iter())
                .flat_map(|i| i.to_le_bytes())
                .collect();
            Uploaded {
                vertices,
                indices: Some(buffer(&indices, wgpu::BufferUsages::INDEX)),
                count: fill.triangles().len() as u32,
                origin,
            }
        }
        Layer::Outline(outline, _) => Uploaded {
            vertices,
            indices: None,
            count: outline.segments().len() as u32,
            origin,
        },
    })
}

fn f32_bytes(values: &[f32]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_le_bytes()).collect()
}

/// `[scale, offset]` such that `(p - origin) * scale + offset` is world point `p` in the clip space of `canvas`
/// (x right and y up, -1 to 1 across the canvas), as `view` places it.
pub fn clip_transform(view: &View, canvas: Rect, origin: Point) -> [[f32; 2]; 2] {
    let [sx, sy] = [
        view.scale / (f64::from(canvas.width()) / 2.0),
        view.scale / (f64::from(canvas.height()) / 2.0),
    ];
    [
        [sx as f32, sy as f32],
        [
            ((origin.x - view.center.x) * sx) as f32,
            ((origin.y - view.center.y) * sy) as f32,
        ],
    ]
}

/// One layer of the picture: a fill in a colour, or an outline in a stroke (its width in points).
pub enum Layer {
    Fill(Fill, Color32),
    Outline(Outline, Stroke),
}

impl Layer {
    fn id(&self) -> u64 {
        match self {
            Layer::Fill(fill, _) => fill.id(),
            Layer::Outline(outline, _) => outline.id(),
        }
    }
}

/// The polygons of one frame, layers in drawing order, over `canvas` as `view` shows it: an egui paint callback.
/// (One per frame: the placements are the pipeline's, one per layer.)
pub struct Polygons {
    pub layers: Vec<Layer>,
    pub view: View,
    pub canvas: Rect,
}

impl Polygons {
    pub fn paint(self, painter: &egui::Painter) {
        let canvas = self.canvas;
        painter.add(egui_wgpu::Callback::new_paint_callback(canvas, self));
    }
}

impl CallbackTrait for Polygons {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        _screen: &ScreenDescriptor,
        _encoder: &mut wgpu::CommandEncoder,
        resources: &mut CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        if let Some(pipeline) = resources.get_mut::<FillPipeline>() {
            pipeline.prepare(device, queue, self);
        }
        Vec::new()
    }

    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        render_pass: &mut wgpu::RenderPass<'static>,
        resources: &CallbackResources,
    ) {
        let Some(pipeline) = resources.get::<FillPipeline>() else {
            return;
        };
        for (layer, placement) in self.layers.iter().zip(&pipeline.placements) {
            let Some(uploaded) = pipeline.uploaded.get(&layer.id()) else {
                continue;
            };
            render_pass.set_bind_group(0, &placement.bind_group, &[]);
            render_pass.set_vertex_buffer(0, uploaded.vertices.slice(..));
            match &uploaded.indices {
                Some(indices) => {
                    render_pass.set_pipeline(&pipeline.fill);
                    render_pass.set_index_buffer(indices.slice(..), wgpu::IndexFormat::Uint32);
                    render_pass.draw_indexed(0..uploaded.count, 0, 0..1);
                }
                None => {
                    render_pass.set_pipeline(&pipeline.outline);
                    render_pass.draw(0..6, 0..uploaded.count);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use eframe::egui::{pos2, Pos2};

    #[test]
    fn shaders_pass_naga() {
        let module = naga::front::wgsl::parse_str(SHADER)
            .unwrap_or_else(|e| panic!("{}", e.emit_to_string(SHADER)));
        // No optional capability: the shaders must run on WebGL2 as on WebGPU.
        naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::empty(),
        )
        .validate(&module)
        .unwrap_or_else(|e| panic!("{}", e.emit_to_string(SHADER)));
        let entry_points: Vec<_> = module
            .entry_points
            .iter()
            .map(|e| e.name.as_str())
            .collect();
        assert_eq!(
            entry_points,
            ["vs_fill", "vs_outline", "fs_gamma", "fs_linear"]
        );
    }

    /// Where the shaders put world point `p`, uploaded relative to `origin`, in the canvas's pixels (f32 as on the
    /// GPU).
    fn placed(view: &View, canvas: Rect, origin: Point, p: Point) -> Pos2 {
        let [scale, offset] = clip_transform(view, canvas, origin);
        let clip = [
            (p.x - origin.x) as f32 * scale[0] + offset[0],
            (p.y - origin.y) as f32 * scale[1] + offset[1],
        ];
        // Clip space to the canvas's pixels: x from the left edge, y down from the top.
        Pos2::new(
            canvas.left() + (clip[0] + 1.0) / 2.0 * canvas.width(),
            canvas.top() + (1.0 - clip[1]) / 2.0 * canvas.height(),
        )
    }

    #[test]
    fn deep_zoom_far_from_the_first_origin_uploads_again_and_stays_exact() {
        // A billion pixels a degree, at a coastline near the antimeridian; the layer was first uploaded about
        // (0, 0), where the view was when the whole world showed.
        let view = View {
            center: Point::new(179.123_456_789, 60.987_654_321),
            scale: 1e9,
        };
        let canvas = Rect::from_min_max(pos2(0.0, 0.0), pos2(1200.0, 800.0));
        let first = Point::new(0.0, 0.0);
        assert!(
            !too_far(&View { scale: 3.0, ..view }, first),
            "the world view keeps it"
        );
        assert!(too_far(&view, first));
        let p = Point::new(view.center.x + 2.5e-7, view.center.y - 1.25e-7);
        let expected = view.to_screen(canvas, p);
        let error = |origin| (placed(&view, canvas, origin, p) - expected).length();
        assert!(
            error(first) > 100.0,
            "f32 about (0, 0) misplaces it: {}",
            error(first)
        );
        assert!(error(view.center) < 0.125, "{}", error(view.center));
        // Panning up to the limit from the new origin keeps the error within an eighth of a pixel.
        let step = (REBASE_PIXELS - 600.0) / view.scale;
        let panned = View {
            center: Point::new(view.center.x + step, view.center.y - step),
            ..view
        };
        assert!(!too_far(&panned, view.center));
        let q = Point::new(panned.center.x - 3e-7, panned.center.y + 2e-7);
        let error =
            (placed(&panned, canvas, view.center, q) - panned.to_screen(canvas, q)).length();
        assert!(error < 0.125, "{error}");
    }

    #[test]
    fn the_clip_transform_places_points_where_the_view_does() {
        let view = View {
            center: Point::new(1000.25, -40.5),
            scale: 37.0,
        };
        let canvas = Rect::from_min_max(pos2(100.0, 50.0), pos2(900.0, 650.0));
        let origin = Point::new(1003.0, -42.0);
        for p in [
            Point::new(1000.25, -40.5),
            Point::new(1010.0, -30.0),
            Point::new(990.5, -45.25),
        ] {
            let screen = placed(&view, canvas, origin, p);
            let expected = view.to_screen(canvas, p);
            assert!(
                (screen - expected).length() < 1e-3,
                "{p:?}: {screen:?}, not {expected:?}"
            );
        }
    }
}
