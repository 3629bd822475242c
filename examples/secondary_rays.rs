//! A tiny renderer on the library: primary rays, a shadow ray to one light and one
//! mirror bounce per hit, all from `Torus::spawn`. Counts, per kind of ray, how many the
//! certified f32 path had to escalate to f64, and how many would have hit their own origin
//! as literal rays with `t_min = 0` (what the spawn API prevents); writes the picture.
//!
//! `cargo run --release --example secondary_rays [-- OUT.png]` (default
//! `docs/secondary_rays.png`).

use glam::Vec3;
use std::path::PathBuf;
use torus_cull::{Ray, Torus, intersect, intersect_f32, occluded};
use torus_cull_lab::render::write_png;

const SIZE: usize = 128;

#[derive(Default)]
struct Kind {
    rays: usize,
    escalated: usize,
    literal_self_hits: usize,
    /// Spawned rays answered with a hit within 10⁻³ of their origin.
    spawned_near_hits: usize,
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args()
        .nth(1)
        .map_or_else(|| PathBuf::from("docs/secondary_rays.png"), PathBuf::from);
    let torus = Torus::new(Vec3::ZERO, Vec3::new(0.3, 1.0, 0.2), 2.0, 0.7)?;
    let (eye, light) = (Vec3::new(0.0, 3.0, 7.0), Vec3::new(4.0, 6.0, 3.0));
    let (mut primary, mut shadow, mut bounce) = (Kind::default(), Kind::default(), Kind::default());
    let mut rgb = vec![0u8; SIZE * SIZE * 3];
    for py in 0..SIZE {
        for px in 0..SIZE {
            let (x, y) = (
                (px as f32 + 0.5) / SIZE as f32 * 2.0 - 1.0,
                1.0 - (py as f32 + 0.5) / SIZE as f32 * 2.0,
            );
            let dir = Vec3::new(x * 0.6, y * 0.6 - 0.35, -1.0);
            let ray = Ray::new(eye, dir)?;
            primary.rays += 1;
            let answer = intersect_f32(&torus, &ray);
            primary.escalated += usize::from(answer.escalated);
            let Some(hit) = answer.hit else { continue };
            let at = ray.at(hit.t);
            // Shadow ray to the light, from the surface.
            let to_light = light - at;
            let shadow_ray = torus.spawn(&ray, hit.t, to_light)?.with_t_max(1.0)?;
            shadow.rays += 1;
            let blocked = intersect_f32(&torus, &shadow_ray);
            shadow.escalated += usize::from(blocked.escalated);
            shadow.spawned_near_hits +=
                usize::from(blocked.hit.is_some_and(|h| h.t * to_light.length() < 1e-3));
            let literal = Ray::with_range(at, to_light, 0.0, 1.0)?;
            shadow.literal_self_hits += usize::from(
                intersect(&torus, &literal).is_some_and(|h| h.t * to_light.length() < 1e-3),
            );
            let lit = !occluded(&torus, &shadow_ray);
            // One mirror bounce: does it see the torus again?
            let n = hit.normal;
            let mirror = dir - n * (2.0 * dir.dot(n));
            let bounce_ray = torus.spawn(&ray, hit.t, mirror)?;
            bounce.rays += 1;
            let again = intersect_f32(&torus, &bounce_ray);
            bounce.escalated += usize::from(again.escalated);
            bounce.spawned_near_hits +=
                usize::from(again.hit.is_some_and(|h| h.t * mirror.length() < 1e-3));
            let literal = Ray::new(at, mirror)?;
            bounce.literal_self_hits += usize::from(
                intersect(&torus, &literal).is_some_and(|h| h.t * mirror.length() < 1e-3),
            );
            let diffuse = if lit {
                n.dot(to_light.normalize()).max(0.0)
            } else {
                0.0
            };
            let shade = 0.15 + 0.75 * diffuse + if again.hit.is_some() { 0.1 } else { 0.0 };
            let i = (py * SIZE + px) * 3;
            rgb[i] = (255.0 * shade.min(1.0)) as u8;
            rgb[i + 1] = (200.0 * shade.min(1.0)) as u8;
            rgb[i + 2] = (120.0 * shade.min(1.0)) as u8;
        }
    }
    write_png(&out, SIZE, &rgb)?;
    for (name, k) in [
        ("primary", &primary),
        ("shadow", &shadow),
        ("bounce", &bounce),
    ] {
        println!(
            "{name:8} {:6} rays, {:6} escalated to f64 ({:.1} %); hits within 1e-3 of the \
             origin: {:5} as literal rays (t_min = 0), {} spawned",
            k.rays,
            k.escalated,
            100.0 * k.escalated as f64 / k.rays.max(1) as f64,
            k.literal_self_hits,
            k.spawned_near_hits
        );
    }
    println!("wrote {}", out.display());
    Ok(())
}
