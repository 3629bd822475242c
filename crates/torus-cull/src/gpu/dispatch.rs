//! The one dispatch path of the library's kernels: a compute pipeline and its bind group
//! layout ([`compute_pipeline`]), storage buffers ([`buffer`]), a bind group over them
//! ([`bind_group`]), and [`run`]: compute passes in one command buffer, each result
//! buffer copied to its staging buffer, submitted, mapped ([`map_read`]) and decoded into
//! 32-byte records. [`super::GpuIntersector`] (the single-torus kernel and its f64
//! finish pass) and [`super::GpuScene`] (the BVH traversal) both dispatch through it.
//! The timed kernel (`timing.rs`) records its own passes with timestamps between them,
//! and maps through [`map_read`].

use super::{GpuError, decode_records};
use std::sync::mpsc;

/// A buffer of `size` bytes (at least 16: a zero-sized binding is invalid) for `usage`.
pub(crate) fn buffer(
    device: &wgpu::Device,
    label: &str,
    size: u64,
    usage: wgpu::BufferUsages,
) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size: size.max(16),
        usage,
        mapped_at_creation: false,
    })
}

/// A bind group over `buffers`, buffer k at binding k (the order of the layout's
/// bindings, [`compute_pipeline`]).
pub(crate) fn bind_group(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    label: &str,
    buffers: &[&wgpu::Buffer],
) -> wgpu::BindGroup {
    let entries: Vec<wgpu::BindGroupEntry> = buffers
        .iter()
        .zip(0..)
        .map(|(b, binding)| wgpu::BindGroupEntry {
            binding,
            resource: b.as_entire_binding(),
        })
        .collect();
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some(label),
        layout,
        entries: &entries,
    })
}

/// One compute pass: the pipeline, its bind group (group 0), the workgroups.
pub(crate) struct Pass<'a> {
    pub(crate) pipeline: &'a wgpu::ComputePipeline,
    pub(crate) bind_group: &'a wgpu::BindGroup,
    pub(crate) groups: u32,
}

/// A result to read back: the first `bytes` of `source`, through `staging` (a
/// `MAP_READ | COPY_DST` buffer of at least `bytes`).
pub(crate) struct Read<'a> {
    pub(crate) source: &'a wgpu::Buffer,
    pub(crate) staging: &'a wgpu::Buffer,
    pub(crate) bytes: u64,
}

/// Runs `passes` in order in one command buffer, copies each of `reads` to its staging
/// buffer after them, submits, and returns each read's 32-byte records
/// ([`decode_records`]). Each staging buffer is unmapped again once read, so a cached one
/// can be reused (after an error, make new ones: one may be left mapped).
pub(crate) fn run(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    label: &str,
    passes: &[Pass<'_>],
    reads: &[Read<'_>],
) -> Result<Vec<Vec<[f32; 8]>>, GpuError> {
    let mut encoder =
        device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some(label) });
    for p in passes {
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some(label),
            timestamp_writes: None,
        });
        pass.set_pipeline(p.pipeline);
        pass.set_bind_group(0, p.bind_group, &[]);
        pass.dispatch_workgroups(p.groups, 1, 1);
    }
    for r in reads {
        encoder.copy_buffer_to_buffer(r.source, 0, r.staging, 0, r.bytes);
    }
    queue.submit([encoder.finish()]);
    reads
        .iter()
        .map(|r| {
            let slice = r.staging.slice(..r.bytes);
            map_read(device, &slice)?;
            let records = slice
                .get_mapped_range()
                .map(|view| decode_records(&view).collect())
                .map_err(|e| GpuError::Readback(format!("{e:?}")));
            r.staging.unmap();
            records
        })
        .collect()
}

/// Maps `slice` of a buffer on `device` for reading and waits for it: the one readback
/// the kernels and their timing share.
pub(crate) fn map_read(
    device: &wgpu::Device,
    slice: &wgpu::BufferSlice<'_>,
) -> Result<(), GpuError> {
    let (tx, rx) = mpsc::channel();
    slice.map_async(wgpu::MapMode::Read, move |r| {
        let _ = tx.send(r);
    });
    device
        .poll(wgpu::PollType::wait_indefinitely())
        .map_err(|e| GpuError::Readback(e.to_string()))?;
    rx.recv()
        .map_err(|e| GpuError::Readback(e.to_string()))?
        .map_err(|e| GpuError::Readback(e.to_string()))
}

/// A compute pipeline of the WGSL `source` at `entry_point`, and its bind group layout:
/// binding k is a buffer of type `bindings[k]`, visible to compute. The kernel, the f64
/// finish pass and the scene kernel are built so; a caller wraps this in a validation
/// error scope to get a shader that does not compile on the adapter back as an error.
pub(crate) fn compute_pipeline(
    device: &wgpu::Device,
    label: &str,
    source: String,
    bindings: &[wgpu::BufferBindingType],
    entry_point: &str,
) -> (wgpu::ComputePipeline, wgpu::BindGroupLayout) {
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(&format!("{label} module")),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let entries: Vec<wgpu::BindGroupLayoutEntry> = bindings
        .iter()
        .zip(0..)
        .map(|(&ty, binding)| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty,
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        })
        .collect();
    let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some(&format!("{label} bindings")),
        entries: &entries,
    });
    let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some(&format!("{label} layout")),
        bind_group_layouts: &[Some(&layout)],
        immediate_size: 0,
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(&format!("{label} pipeline")),
        layout: Some(&pipeline_layout),
        module: &module,
        entry_point: Some(entry_point),
        compilation_options: Default::default(),
        cache: None,
    });
    (pipeline, layout)
}
