//! Why the GPU path could not run ([`GpuError`]): one error type for the intersector, the
//! f64 finish, the dispatch and the scene, below all of them.

use std::fmt;

/// The Debian package that gives a machine without a GPU a software Vulkan adapter.
pub const SOFTWARE_VULKAN_PACKAGE: &str = "mesa-vulkan-drivers";

/// Why the GPU path could not run.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum GpuError {
    /// No adapter (no Vulkan, Metal or DX12 device, and no software Vulkan).
    NoAdapter(String),
    /// The adapter refused a device.
    RequestDevice(String),
    /// The kernel did not compile or validate on this adapter.
    Kernel(String),
    /// Reading the results back failed.
    Readback(String),
    /// A scene the GPU BVH ([`super::GpuScene`]) cannot hold; the message names the
    /// limit.
    Scene(String),
    /// A member of the torus family the GPU scene does not take
    /// ([`super::GpuScene::from_family`]): it takes what the certified f32 path takes,
    /// the circular ring members ([`crate::family::Toroid::as_torus`]); `error` says which
    /// member it is (horn, spindle, elliptical tube) and why.
    Member {
        /// The member's index in the slice given.
        index: usize,
        /// Why ([`crate::family::ToroidError::NotCircular`]).
        error: crate::family::ToroidError,
    },
}

impl fmt::Display for GpuError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GpuError::NoAdapter(why) => write!(
                f,
                "no GPU adapter ({why}); on a machine without a GPU install the Debian \
                 package {SOFTWARE_VULKAN_PACKAGE} (Mesa's software Vulkan, lavapipe)"
            ),
            GpuError::RequestDevice(why) => write!(f, "the GPU adapter refused a device: {why}"),
            GpuError::Kernel(why) => write!(f, "the WGSL kernel failed on this adapter: {why}"),
            GpuError::Readback(why) => write!(f, "reading the GPU results back failed: {why}"),
            GpuError::Scene(why) => write!(f, "the GPU scene: {why}"),
            GpuError::Member { index, error } => {
                write!(f, "the GPU scene: family member {index}: {error}")
            }
        }
    }
}

impl std::error::Error for GpuError {}
