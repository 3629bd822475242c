//! `torus-cull render`: a shaded picture of a scene and its cull map (PNG).
//!
//! The cull map colours each pixel by what happened to its ray at the tori whose boxes it
//! entered (a `none` traversal, with both culls' verdicts taken at every leaf):
//!
//! | colour | meaning |
//! |---|---|
//! | shaded grey | hit |
//! | orange | reached the quartic under `skala` and missed |
//! | green | rejected only by `skala`: cychosz kept a box, skala rejected it (the hole rays) |
//! | blue | every box it entered was rejected by `cychosz` |
//! | near black | entered no box |

use crate::harness::scene::Scene;
use crate::{Cull, CychoszCull, SkalaCull, intersect};
use std::path::Path;

/// Cull map colours, in the order of [`CullMapCounts`].
pub const COLOURS: [(&str, [u8; 3]); 5] = [
    ("hit", [200, 200, 200]),
    ("quartic, missed", [235, 140, 30]),
    ("rejected only by skala", [40, 180, 80]),
    ("rejected by cychosz", [50, 100, 210]),
    ("no box entered", [18, 18, 24]),
];

/// How many pixels fell in each cull map class.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CullMapCounts {
    /// Rays with a hit.
    pub hit: u64,
    /// Missed although skala sent them to the quartic at some torus.
    pub quartic_missed: u64,
    /// Missed; cychosz kept some box, skala rejected every one.
    pub skala_only: u64,
    /// Missed; cychosz rejected every box entered.
    pub cychosz: u64,
    /// Entered no box.
    pub no_box: u64,
}

/// A rendered image pair, RGB8, row-major.
pub struct Rendered {
    /// Side in pixels.
    pub size: usize,
    /// Lambert-shaded picture with a headlight.
    pub shaded: Vec<u8>,
    /// The cull map.
    pub cull_map: Vec<u8>,
    /// Pixel counts per cull map class.
    pub counts: CullMapCounts,
}

/// Render `scene` at `size`×`size`.
pub fn render(scene: &Scene, size: usize) -> Rendered {
    let rays = scene.camera_rays(size);
    let mut shaded = Vec::with_capacity(size * size * 3);
    let mut cull_map = Vec::with_capacity(size * size * 3);
    let mut counts = CullMapCounts::default();
    for ray in &rays {
        let (mut entered, mut cychosz_kept, mut skala_kept) = (false, false, false);
        let hit = scene.trace_with(ray, |torus, bounds, ray, t_max| {
            entered = true;
            let line = torus.line_to_local(ray);
            cychosz_kept |= CychoszCull.keeps(bounds, line.origin, line.dir);
            skala_kept |= SkalaCull.keeps(bounds, line.origin, line.dir);
            intersect(torus, &ray.with_t_max(t_max)).map_or(f32::INFINITY, |h| h.t)
        });
        let class = match hit {
            Some(_) => 0,
            None if skala_kept => 1,
            None if cychosz_kept => 2,
            None if entered => 3,
            None => 4,
        };
        match class {
            0 => counts.hit += 1,
            1 => counts.quartic_missed += 1,
            2 => counts.skala_only += 1,
            3 => counts.cychosz += 1,
            _ => counts.no_box += 1,
        }
        let pixel = match hit {
            Some((id, _)) => {
                let h = intersect(&scene.tori[id as usize], ray).expect("the traversal's hit");
                let light = -ray.dir().normalize();
                let lambert = h.normal.dot(light).abs();
                let tint = tint(id);
                let shade = |c: f32| ((0.12 + 0.88 * lambert) * c * 255.0).round() as u8;
                let grey = ((0.25 + 0.75 * lambert) * 220.0).round() as u8;
                cull_map.extend([grey, grey, grey]);
                [shade(tint[0]), shade(tint[1]), shade(tint[2])]
            }
            None => {
                cull_map.extend(COLOURS[class].1);
                [24, 26, 34]
            }
        };
        shaded.extend(pixel);
    }
    Rendered {
        size,
        shaded,
        cull_map,
        counts,
    }
}

/// A soft per-torus colour, so neighbouring tori can be told apart.
fn tint(id: u32) -> [f32; 3] {
    let h = id.wrapping_mul(0x9E37_79B9) >> 8;
    let f = |shift: u32| 0.7 + 0.3 * ((h >> shift) & 0xFF) as f32 / 255.0;
    [f(0), f(8), f(16)]
}

/// Encode RGB8 pixels as PNG and write them atomically.
pub fn write_png(path: &Path, size: usize, rgb: &[u8]) -> Result<(), Box<dyn std::error::Error>> {
    let mut bytes = Vec::new();
    {
        let mut encoder = png::Encoder::new(&mut bytes, size as u32, size as u32);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        let mut writer = encoder.write_header()?;
        writer.write_image_data(rgb)?;
    }
    crate::harness::output::write_file(path, &bytes)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(())
}
