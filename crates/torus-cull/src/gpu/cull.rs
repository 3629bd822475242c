//! The cull the kernel runs before the intersection ([`GpuCull`]): every cull with a GPU
//! form in the table of culls (`cull/table.rs`), by the kernel's code, and its
//! conversions to and from the CPU's culls.

use crate::cull::BatchCull;
use crate::cull::table::{cull_table, define_gpu_culls};
use crate::{CullKind, Named};
use std::fmt;

cull_table!(define_gpu_culls);

impl GpuCull {
    /// The stable name (as [`crate::CullKind`]'s).
    pub fn name(self) -> &'static str {
        Named::name(self.kind())
    }

    /// The kernel's code for the cull (`Params.config.y`).
    pub(crate) fn code(self) -> u32 {
        GpuCull::ALL
            .iter()
            .position(|&c| c == self)
            .expect("every cull is in ALL") as u32
    }
}

/// Every batch cull runs on the GPU (the table's rows with a lane form have a GPU form).
impl From<BatchCull> for GpuCull {
    fn from(cull: BatchCull) -> GpuCull {
        match GpuCull::try_from(cull.kind()) {
            Ok(gpu) => gpu,
            Err(_) => unreachable!("every batch cull has a GPU form"),
        }
    }
}

impl From<GpuCull> for CullKind {
    fn from(cull: GpuCull) -> CullKind {
        cull.kind()
    }
}

impl fmt::Display for GpuCull {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cull::BATCHED;

    #[test]
    fn every_batch_cull_is_a_gpu_cull_by_the_same_name() {
        assert_eq!(GpuCull::ALL.len(), BATCHED.len());
        for (i, (&gpu, &batch)) in GpuCull::ALL.iter().zip(&BATCHED).enumerate() {
            assert_eq!(GpuCull::from(batch), gpu);
            assert_eq!(gpu.batched(), batch);
            assert_eq!(gpu.kind(), batch.kind());
            assert_eq!(gpu.name(), Named::name(batch.kind()));
            assert_eq!(GpuCull::try_from(batch.kind()), Ok(gpu));
            // The kernel's switch reads the code in this order.
            assert_eq!(gpu.code(), i as u32);
        }
        assert_eq!(
            GpuCull::try_from(CullKind::DiscriminantF64),
            Err(CullKind::DiscriminantF64)
        );
    }

    /// A cull marked as having a GPU form has its case in the WGSL module's generated
    /// cull switch and its function `tc_<name>_keeps` (its file `culls/<name>.wgsl`), and
    /// no other cull has either.
    #[test]
    fn every_gpu_row_has_its_wgsl_function() {
        let source = crate::gpu::wgsl_module();
        let switch = &source[source.find("fn tc_cull_keeps(").expect("the cull switch")..];
        let switch = &switch[..switch.find("\n}\n").expect("its end")];
        assert!(switch.contains("default: {\n            return true;"));
        for kind in CullKind::TIMED {
            let case = format!("case TORUS_CULL_{}:", kind.to_string().to_uppercase());
            assert_eq!(
                switch.contains(&case),
                kind.has_gpu_form(),
                "{kind}: {case}"
            );
            let function = format!("fn tc_{kind}_keeps(");
            assert_eq!(
                source.contains(&function),
                kind.has_gpu_form(),
                "{kind}: {function}"
            );
            assert_eq!(
                GpuCull::try_from(kind).is_ok(),
                kind.has_gpu_form(),
                "{kind}"
            );
        }
        let order: Vec<CullKind> = GpuCull::ALL.iter().map(|c| c.kind()).collect();
        let want: Vec<CullKind> = CullKind::TIMED
            .into_iter()
            .filter(|c| c.has_gpu_form())
            .collect();
        assert_eq!(order, want);
    }
}
