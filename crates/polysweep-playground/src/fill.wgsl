// The playground's polygon fills (gpu.rs): the triangles of a fill (fill.rs), uploaded once as positions relative
// to the fill's origin, placed in the canvas's clip space by a uniform, and painted in one premultiplied colour.

struct Placement {
    // clip = position * scale + offset: the view (centre and zoom) and the fill's origin, in the canvas's clip space.
    scale: vec2<f32>,
    offset: vec2<f32>,
    // Premultiplied alpha, gamma-space channels: egui's Color32, so fills match the UI's colours.
    color: vec4<f32>,
};

@group(0) @binding(0) var<uniform> placement: Placement;

@vertex
fn vs_main(@location(0) position: vec2<f32>) -> @builtin(position) vec4<f32> {
    return vec4<f32>(position * placement.scale + placement.offset, 0.0, 1.0);
}

// For a framebuffer that stores gamma-space values (WebGL2 and most WebGPU canvases): the colour as it is.
@fragment
fn fs_gamma() -> @location(0) vec4<f32> {
    return placement.color;
}

// For an sRGB framebuffer, which converts linear values to gamma on write: the colour made linear first.
@fragment
fn fs_linear() -> @location(0) vec4<f32> {
    let c = placement.color.rgb;
    let lower = c / vec3<f32>(12.92);
    let higher = pow((c + vec3<f32>(0.055)) / vec3<f32>(1.055), vec3<f32>(2.4));
    return vec4<f32>(select(higher, lower, c < vec3<f32>(0.04045)), placement.color.a);
}
