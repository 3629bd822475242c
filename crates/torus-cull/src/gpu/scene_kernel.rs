//! The scene kernel's compiled entry points ([`Kernel`]), cached per device
//! ([`Kernels`], held by the intersector so that every scene on a device shares them).

use super::GpuError;

/// The library's scene kernel: [`wgsl_scene_module`] at group 0 and `wgsl/scene_kernel.wgsl`.
pub(crate) fn kernel_source(f64: bool) -> String {
    let rays = if f64 { 3 } else { 2 };
    format!(
        "{}\n@group(0) @binding({rays}) var<storage, read_write> torus_scene_rays: array<vec4<f32>>;\n{}",
        super::wgsl_scene_module(0, f64),
        super::scene_bvh::SCENE_FILES[3].1
    )
}

/// A compiled entry point of the scene kernel and its bind group layout.
#[derive(Clone)]
pub(crate) struct Kernel {
    pub(crate) pipeline: wgpu::ComputePipeline,
    pub(crate) layout: wgpu::BindGroupLayout,
}

/// A device's scene kernels by (f64, entry point), compiled once: naga and the driver
/// take about a second for the larger one on lavapipe, which every scene would pay again.
pub(crate) type Kernels = std::sync::Arc<std::sync::Mutex<Vec<(bool, &'static str, Kernel)>>>;

impl Kernel {
    /// `entry` of [`kernel_source`]`(f64)` from `kernels`, compiled there first if it is
    /// not yet (the validation error in words).
    pub(crate) fn get(
        kernels: &Kernels,
        device: &wgpu::Device,
        f64: bool,
        entry: &'static str,
    ) -> Result<Kernel, GpuError> {
        let mut cache = kernels.lock().unwrap_or_else(|e| e.into_inner());
        if let Some((_, _, k)) = cache.iter().find(|(f, e, _)| *f == f64 && *e == entry) {
            return Ok(k.clone());
        }
        let kernel = Kernel::compile(device, f64, entry)?;
        cache.push((f64, entry, kernel.clone()));
        Ok(kernel)
    }

    /// `entry` of [`kernel_source`]`(f64)`, or the validation error in words.
    fn compile(device: &wgpu::Device, f64: bool, entry: &str) -> Result<Kernel, GpuError> {
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        use wgpu::BufferBindingType as B;
        let mut bindings = vec![B::Storage { read_only: true }; if f64 { 3 } else { 2 }];
        bindings.push(B::Storage { read_only: false });
        let (pipeline, layout) = super::compute_pipeline(
            device,
            "torus-cull scene",
            kernel_source(f64),
            &bindings,
            entry,
        );
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(GpuError::Kernel(format!("the scene kernel ({entry}): {e}")));
        }
        Ok(Kernel { pipeline, layout })
    }
}
