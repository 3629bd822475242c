//! Is the machine's slow state a placement or a time? (docs/results.md, "The slow state")
//!
//! Times the exact intersection alone (`none`, `total_ns`) of one hole batch, ν = 2, on
//! every pairing of 8 copies of the torus (rows) with 8 copies of the rays (columns),
//! row after row: the median ns per ray of 40 passes each. If the slow state followed
//! where the data landed, whole rows or columns would be slow; if it is a state of the
//! machine in time, the table switches level part-way through, row-major.
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
    println!("ns per ray of the intersection alone; rows: torus copy, columns: rays copy");
    for (i, torus) in tori.iter().enumerate() {
        let row: Vec<String> = rays
            .iter()
            .map(|r| format!("{:5.1}", median_ns(torus, r)))
            .collect();
        println!("t{i} {}", row.join(" "));
    }
    Ok(())
}
