//! The torus in a parry3d compound beside a ball: a ray cast and a point query through
//! parry's API, answered by the library. `cargo run -p torus-cull --features parry --example parry`

use parry3d::math::{Pose, Vector};
use parry3d::query::{PointQuery, Ray, RayCast};
use parry3d::shape::{Ball, Compound, SharedShape};
use torus_cull::adapters::parry::ParryTorus;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let torus = ParryTorus::new(4.0, 1.0)?;
    let scene = Compound::new(vec![
        (Pose::translation(0.0, 0.0, 0.0), SharedShape::new(torus)),
        (
            Pose::translation(0.0, 5.0, 0.0),
            SharedShape::new(Ball::new(0.5)),
        ),
    ]);
    let down = Ray::new(Vector::new(4.0, 10.0, 0.0), Vector::new(0.0, -1.0, 0.0));
    let hit = scene.cast_ray_and_get_normal(&Pose::identity(), &down, 100.0, true);
    println!("down onto the tube: {hit:?}"); // time of impact 9, normal +y
    let through_hole = Ray::new(Vector::new(0.0, -10.0, 0.0), Vector::new(0.0, 1.0, 0.0));
    println!(
        "up the axis: {:?}",
        scene.cast_ray(&Pose::identity(), &through_hole, 100.0, true)
    ); // the ball, at 14.5
    let d = torus.distance_to_point(&Pose::identity(), Vector::new(4.0, 0.0, 0.0), false);
    println!("signed distance from the core circle: {d}"); // −1
    Ok(())
}
