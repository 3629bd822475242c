//! `torus-cull gpu-info`: the adapter wgpu picks, as `key: value` lines a script can read
//! (benches/gpu_device.sh checks it before timing anything).

use crate::console::CliResult;

/// Prints the adapter (name, device type, backend, driver, whether it is a CPU), whether
/// it has `SHADER_F64` and the f64 finish pass, and timestamp queries. Exit 2 with one
/// line where wgpu finds no adapter (or no device, or the kernel does not compile).
#[cfg(feature = "gpu")]
pub(crate) fn run() -> CliResult {
    use crate::console::outln;
    let gpu = torus_cull::gpu::GpuIntersector::new()?;
    let yes = |b: bool| if b { "yes" } else { "no" };
    outln!("adapter: {}", gpu.adapter_name())?;
    outln!("device_type: {:?}", gpu.device_type())?;
    outln!("backend: {:?}", gpu.backend())?;
    outln!("driver: {}", gpu.driver())?;
    outln!("software: {}", yes(gpu.is_software()))?;
    outln!("shader_f64: {}", yes(gpu.has_shader_f64()))?;
    match gpu.device_finish_unavailable() {
        None => outln!("f64_finish_pass: yes")?,
        Some(why) => outln!("f64_finish_pass: no ({why})")?,
    }
    outln!("timestamps: {}", yes(gpu.has_timestamps()))?;
    Ok(std::process::ExitCode::SUCCESS)
}

/// `gpu-info` in a binary built without the feature.
#[cfg(not(feature = "gpu"))]
pub(crate) fn run() -> CliResult {
    Err("gpu-info needs a binary built with the feature gpu: \
         cargo build --release --features gpu"
        .into())
}
