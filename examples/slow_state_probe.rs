//! Is the machine's slow state a placement or a time? (docs/results.md, "The slow state
//! is a time, not a place")
//!
//! Times the exact intersection alone (`none`, `total_ns`) of one hole batch, ν = 2, for
//! 8 copies of the torus and the rays, each copy in its own allocation: copy 0, 1, …, 7,
//! then again, 24 cycles in all, each cell the median ns per ray of 40 passes (about
//! 5 ms). If the slow state followed where the data landed, some columns (copies) would
//! be slow in every cycle; if it is a state of the machine in time, whole rows (stretches
//! of time) switch level together.
//!
//!     cargo run --release --example slow_state_probe

use torus_cull::{CullKind, Ray, Torus};
use torus_cull_lab::paired::contender::{Metric, Workset, time_pass};
use torus_cull_lab::workload::{Case, Pose, generate};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let batch = generate(Case::Hole, 2.0, 2000, 7, Pose::Random)?;
    let copies = 8;
    // Boxed and cloned: each copy in its own allocation.
    let tori: Vec<Box<Torus>> = (0..copies).map(|_| Box::new(batch.torus)).collect();
    let rays: Vec<Vec<Ray>> = (0..copies).map(|_| batch.rays.clone()).collect();
    let median_ns = |torus: &Torus, rays: &[Ray]| {
        let set = Workset::new(torus, rays);
        let mut ns: Vec<f64> = (0..40)
            .map(|_| {
                let pass = time_pass(CullKind::NoCull, Metric::TotalNs, &set, 1);
                pass.as_nanos() as f64 / rays.len() as f64
            })
            .collect();
        torus_cull_lab::paired::median(&mut ns)
    };
    println!("ns per ray of the intersection alone; rows: cycles in time, columns: copies");
    for cycle in 0..24 {
        let row: Vec<String> = tori
            .iter()
            .zip(&rays)
            .map(|(torus, r)| format!("{:5.1}", median_ns(torus, r)))
            .collect();
        println!("c{cycle:02} {}", row.join(" "));
    }
    Ok(())
}
