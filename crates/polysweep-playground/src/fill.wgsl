// The playground's polygons (gpu.rs): fills, the triangles of a region, and outlines, a quad per edge of its
// rings. Both are uploaded once, as positions relative to their origin, placed in the canvas's clip space by a
// uniform, and painted in one premultiplied colour.

struct Placement {
    // clip = position * scale + offset: the view (centre and zoom) and the origin, in the canvas's clip space.
    scale: vec2<f32>,
    offset: vec2<f32>,
    // Premultiplied alpha, gamma-space channels: egui's Color32, so the polygons match the UI's colours.
    color: vec4<f32>,
    // Clip-space units per point (egui's logical pixel) along x and y, and an outline's width in points.
    pixel: vec2<f32>,
    width: f32,
};

@group(0) @binding(0) var<uniform> placement: Placement;

// `across`: how far from an outline's middle line the fragment is, in points; `reach`: how far its quad reaches.
// The outermost point of the quad fades out (a fill has nothing to fade): edges are anti-aliased as egui feathers
// its own lines, since eframe's render pass has no multisampling on the web.
struct Fragment {
    @builtin(position) position: vec4<f32>,
    @location(0) across: f32,
    @location(1) reach: f32,
};

fn coverage(in: Fragment) -> f32 {
    return clamp(in.reach - abs(in.across), 0.0, 1.0);
}

@vertex
fn vs_fill(@location(0) position: vec2<f32>) -> Fragment {
    return Fragment(vec4<f32>(position * placement.scale + placement.offset, 0.0, 1.0), 0.0, 1.0);
}

// An edge from `a` to `b` (one instance per edge) as two triangles, `width` points wide whatever the zoom (and
// half a point more each side, to fade out). No joins: at the hairpin turns of coastlines, mitred joins would shoot
// far out.
@vertex
fn vs_outline(@builtin(vertex_index) corner: u32, @location(0) a: vec2<f32>, @location(1) b: vec2<f32>) -> Fragment {
    let start = a * placement.scale + placement.offset;
    let end = b * placement.scale + placement.offset;
    // The normal in points (clip units are not square), then back to clip units.
    let along = (end - start) / placement.pixel;
    let length = max(sqrt(dot(along, along)), 1e-20);
    let reach = placement.width / 2.0 + 0.5;
    let normal = vec2<f32>(-along.y, along.x) / length * reach * placement.pixel;
    // Corners 0..5: (start, +), (end, +), (end, -), (start, +), (end, -), (start, -).
    let at_end = corner == 1u || corner == 2u || corner == 4u;
    let side = select(-1.0, 1.0, corner == 0u || corner == 1u || corner == 3u);
    return Fragment(vec4<f32>(select(start, end, at_end) + side * normal, 0.0, 1.0), side * reach, reach);
}

// For a framebuffer that stores gamma-space values (WebGL2 and most WebGPU canvases): the colour as it is.
@fragment
fn fs_gamma(in: Fragment) -> @location(0) vec4<f32> {
    return placement.color * coverage(in);
}

// For an sRGB framebuffer, which converts linear values to gamma on write: the colour made linear first.
@fragment
fn fs_linear(in: Fragment) -> @location(0) vec4<f32> {
    let c = placement.color.rgb;
    let lower = c / vec3<f32>(12.92);
    let higher = pow((c + vec3<f32>(0.055)) / vec3<f32>(1.055), vec3<f32>(2.4));
    return vec4<f32>(select(higher, lower, c < vec3<f32>(0.04045)), placement.color.a) * coverage(in);
}
