//! Bevy's torus primitive with an isometry: converted to the library's torus, and ray cast
//! with the signature of Bevy's proposed `local_ray_cast`.
//! `cargo run -p torus-cull --features bevy --example bevy`

use bevy_math::{Dir3, Isometry3d, Vec3};
use bevy_shape::{Ray3d, Torus};
use torus_cull::adapters::bevy::{BevyTorus, torus_from_bevy};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let shape = Torus::new(1.0, 4.0); // inner radius 1, outer 4: R = 2.5, r = 1.5
    let iso = Isometry3d::from_translation(Vec3::new(0.0, 0.0, -10.0));
    let posed = torus_from_bevy(&shape, iso)?; // the library's torus, for its other queries
    println!("world box {:?}", posed.world_aabb());
    let torus = BevyTorus::try_from(shape)?;
    let ray = Ray3d::new(Vec3::new(2.5, 10.0, -10.0), Dir3::NEG_Y);
    println!("{:?}", torus.ray_cast(iso, ray, 100.0, false)); // distance 8.5, normal +y
    Ok(())
}
