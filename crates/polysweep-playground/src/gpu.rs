//! The polygons' fills on the GPU. egui draws the UI and the outlines; the fills — the operands as their fill rule
//! reads them, the result and its pieces — go through this pipeline, an egui_wgpu paint callback: each fill's
//! triangles (fill.rs) are uploaded once, when the fill is made, and every frame only a small uniform per fill
//! moves them with the view. A frame therefore costs the same whatever the vertex count, where egui's meshes would
//! transform and upload every vertex every frame.
//!
//! The shaders are in fill.wgsl; `tests::shaders_pass_naga` validates them with naga, as wgpu does before it
//! compiles them, so that a broken shader fails the native tests (CI has no GPU).
//!
//! Precision: positions are stored as f32 relative to their fill's centre, and the view's offset is worked out in
//! f64; deep zooms far from a fill's centre lose the f32 positions' last bits (about 1e-7 of the fill's extent).

use crate::fill::Fill;
use crate::view::View;
use eframe::egui::{self, Color32, Rect};
use eframe::egui_wgpu::{
    self, wgpu, CallbackResources, CallbackTrait, RenderState, ScreenDescriptor,
};
use polysweep::Point;
use std::collections::HashMap;
use wgpu::util::DeviceExt;

/// The WGSL of the fill pipeline.
pub const SHADER: &str = include_str!("fill.wgsl");

/// The GPU side: the pipeline, the uploaded fills by id, and a uniform per fill drawn in the frame.
pub struct FillPipeline {
    pipeline: wgpu::RenderPipeline,
    placement_layout: wgpu::BindGroupLayout,
    uploaded: HashMap<u64, Uploaded>,
    placements: Vec<Placement>,
}

struct Uploaded {
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    index_count: u32,
    origin: Point,
}

struct Placement {
    uniform: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
}

/// Bytes of the `Placement` uniform of fill.wgsl: scale, offset, colour.
const PLACEMENT_SIZE: u64 = 8 * 4;

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
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("polysweep fill"),
            layout: Some(&layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs_main"),
                compilation_options: Default::default(),
                buffers: &[Some(wgpu::VertexBufferLayout {
                    array_stride: 2 * 4,
                    step_mode: wgpu::VertexStepMode::Vertex,
                    attributes: &wgpu::vertex_attr_array![0 => Float32x2],
                })],
            },
            primitive: wgpu::PrimitiveState::default(),
            // egui's render pass has no depth or stencil buffer and one sample (eframe's defaults).
            depth_stencil: None,
            multisample: wgpu::MultisampleState::default(),
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
        });
        render_state
            .renderer
            .write()
            .callback_resources
            .insert(FillPipeline {
                pipeline,
                placement_layout,
                uploaded: HashMap::new(),
                placements: Vec::new(),
            });
    }

    /// Uploads the fills not on the GPU yet, forgets those no longer drawn, and writes each fill's placement.
    fn prepare(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, fills: &Fills) {
        self.uploaded
            .retain(|id, _| fills.layers.iter().any(|(fill, _)| fill.id() == *id));
        for (fill, _) in &fills.layers {
            if fill.triangle_count() > 0 && !self.uploaded.contains_key(&fill.id()) {
                self.uploaded.insert(fill.id(), upload(device, fill));
            }
        }
        while self.placements.len() < fills.layers.len() {
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
        for ((fill, color), placement) in fills.layers.iter().zip(&self.placements) {
            if let Some(uploaded) = self.uploaded.get(&fill.id()) {
                let [scale, offset] = clip_transform(&fills.view, fills.canvas, uploaded.origin);
                let color = color.to_array().map(|c| f32::from(c) / 255.0);
                let floats = [
                    scale[0], scale[1], offset[0], offset[1], color[0], color[1], color[2],
                    color[3],
                ];
                queue.write_buffer(&placement.uniform, 0, &f32_bytes(&floats));
            }
        }
    }
}

/// The fill's triangles on the GPU, as f32 positions relative to the centre of its bounding box.
fn upload(device: &wgpu::Device, fill: &Fill) -> Uploaded {
    let (lo, hi) = fill.points().iter().fold(
        (
            Point::new(f64::INFINITY, f64::INFINITY),
            Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY),
        ),
        |(lo, hi), p| {
            (
                Point::new(lo.x.min(p.x), lo.y.min(p.y)),
                Point::new(hi.x.max(p.x), hi.y.max(p.y)),
            )
        },
    );
    let origin = Point::new((lo.x + hi.x) / 2.0, (lo.y + hi.y) / 2.0);
    let positions: Vec<f32> = (fill.points().iter())
        .flat_map(|p| [(p.x - origin.x) as f32, (p.y - origin.y) as f32])
        .collect();
    let indices: Vec<u8> = fill
        .triangles()
        .iter()
        .flat_map(|i| i.to_le_bytes())
        .collect();
    Uploaded {
        vertices: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("polysweep fill vertices"),
            contents: &f32_bytes(&positions),
            usage: wgpu::BufferUsages::VERTEX,
        }),
        indices: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("polysweep fill indices"),
            contents: &indices,
            usage: wgpu::BufferUsages::INDEX,
        }),
        index_count: fill.triangles().len() as u32,
        origin,
    }
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

/// The fills of one frame, in drawing order, over `canvas` as `view` shows it: an egui paint callback. (One per
/// frame: the placements are the pipeline's, one per layer.)
pub struct Fills {
    pub layers: Vec<(Fill, Color32)>,
    pub view: View,
    pub canvas: Rect,
}

impl Fills {
    pub fn paint(self, painter: &egui::Painter) {
        let canvas = self.canvas;
        painter.add(egui_wgpu::Callback::new_paint_callback(canvas, self));
    }
}

impl CallbackTrait for Fills {
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
        render_pass.set_pipeline(&pipeline.pipeline);
        for ((fill, _), placement) in self.layers.iter().zip(&pipeline.placements) {
            if let Some(uploaded) = pipeline.uploaded.get(&fill.id()) {
                render_pass.set_bind_group(0, &placement.bind_group, &[]);
                render_pass.set_vertex_buffer(0, uploaded.vertices.slice(..));
                render_pass.set_index_buffer(uploaded.indices.slice(..), wgpu::IndexFormat::Uint32);
                render_pass.draw_indexed(0..uploaded.index_count, 0, 0..1);
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
        assert_eq!(entry_points, ["vs_main", "fs_gamma", "fs_linear"]);
    }

    #[test]
    fn the_clip_transform_places_points_where_the_view_does() {
        let view = View {
            center: Point::new(1000.25, -40.5),
            scale: 37.0,
        };
        let canvas = Rect::from_min_max(pos2(100.0, 50.0), pos2(900.0, 650.0));
        let origin = Point::new(1003.0, -42.0);
        let [scale, offset] = clip_transform(&view, canvas, origin);
        for p in [
            Point::new(1000.25, -40.5),
            Point::new(1010.0, -30.0),
            Point::new(990.5, -45.25),
        ] {
            let clip = [
                (p.x - origin.x) as f32 * scale[0] + offset[0],
                (p.y - origin.y) as f32 * scale[1] + offset[1],
            ];
            // Clip space to the canvas's pixels: x from the left edge, y down from the top.
            let screen = Pos2::new(
                canvas.left() + (clip[0] + 1.0) / 2.0 * canvas.width(),
                canvas.top() + (1.0 - clip[1]) / 2.0 * canvas.height(),
            );
            let expected = view.to_screen(canvas, p);
            assert!(
                (screen - expected).length() < 1e-3,
                "{p:?}: {screen:?}, not {expected:?}"
            );
        }
    }
}
