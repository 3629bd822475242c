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

use crate::scene::Scene;
use std::path::Path;
use torus_cull::{Cull, CychoszCull, SkalaCull, intersect};

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
        let hit = scene.trace_with(ray, |torus, ray, t_max| {
            entered = true;
            let line = torus.line_to_local(ray);
            let bounds = torus.bounds();
            cychosz_kept |= CychoszCull.keeps(bounds, line.origin, line.dir);
            skala_kept |= SkalaCull.keeps(bounds, line.origin, line.dir);
            // t_max is a hit's t or +∞, never NaN.
            let cut = ray.with_t_max(t_max).expect("t_max is not NaN");
            intersect(torus, &cut).map_or(f32::INFINITY, |h| h.t)
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

/// The cull map (`size`×`size`, RGB8) with its key drawn in a strip below it: one row per
/// class, a swatch of its colour and its meaning in a small built-in pixel font. Returns
/// the pixels and the new height (the width stays `size`; on a narrow map the words are
/// cut at its edge, the swatches stay).
pub fn cull_map_with_legend(cull_map: &[u8], size: usize) -> (Vec<u8>, usize) {
    let scale = (size / 256).max(1);
    let row = 8 * scale;
    let height = size + COLOURS.len() * row + 4 * scale;
    let mut rgb = cull_map.to_vec();
    // A white strip.
    rgb.resize(size * height * 3, 255);
    let mut put = |x: usize, y: usize, c: [u8; 3]| {
        if x < size && y < height {
            let i = (y * size + x) * 3;
            rgb[i..i + 3].copy_from_slice(&c);
        }
    };
    for (k, (label, colour)) in COLOURS.iter().enumerate() {
        let top = size + 2 * scale + k * row;
        // The swatch, with a thin dark border so near-white and near-black both show.
        for y in 0..6 * scale {
            for x in 0..6 * scale {
                let edge = x == 0 || y == 0 || x + 1 == 6 * scale || y + 1 == 6 * scale;
                put(
                    2 * scale + x,
                    top + y,
                    if edge { [90, 90, 90] } else { *colour },
                );
            }
        }
        for (n, ch) in label.chars().enumerate() {
            let glyph = glyph(ch);
            for (gy, bits) in glyph.iter().enumerate() {
                for gx in 0..3 {
                    if bits >> (2 - gx) & 1 == 1 {
                        for dy in 0..scale {
                            for dx in 0..scale {
                                put(
                                    10 * scale + n * 4 * scale + gx * scale + dx,
                                    top + scale / 2 + gy * scale + dy,
                                    [0, 0, 0],
                                );
                            }
                        }
                    }
                }
            }
        }
    }
    (rgb, height)
}

/// A 3×5 pixel glyph (rows top to bottom, 3 bits each) of the letters the key uses.
fn glyph(ch: char) -> [u8; 5] {
    match ch.to_ascii_uppercase() {
        'A' => [0b010, 0b101, 0b111, 0b101, 0b101],
        'B' => [0b110, 0b101, 0b110, 0b101, 0b110],
        'C' => [0b011, 0b100, 0b100, 0b100, 0b011],
        'D' => [0b110, 0b101, 0b101, 0b101, 0b110],
        'E' => [0b111, 0b100, 0b110, 0b100, 0b111],
        'H' => [0b101, 0b101, 0b111, 0b101, 0b101],
        'I' => [0b111, 0b010, 0b010, 0b010, 0b111],
        'J' => [0b001, 0b001, 0b001, 0b101, 0b010],
        'K' => [0b101, 0b101, 0b110, 0b101, 0b101],
        'L' => [0b100, 0b100, 0b100, 0b100, 0b111],
        'M' => [0b101, 0b111, 0b111, 0b101, 0b101],
        'N' => [0b110, 0b101, 0b101, 0b101, 0b101],
        'O' => [0b010, 0b101, 0b101, 0b101, 0b010],
        'Q' => [0b010, 0b101, 0b101, 0b110, 0b011],
        'R' => [0b110, 0b101, 0b110, 0b101, 0b101],
        'S' => [0b011, 0b100, 0b010, 0b001, 0b110],
        'T' => [0b111, 0b010, 0b010, 0b010, 0b010],
        'U' => [0b101, 0b101, 0b101, 0b101, 0b111],
        'X' => [0b101, 0b101, 0b010, 0b101, 0b101],
        'Y' => [0b101, 0b101, 0b010, 0b010, 0b010],
        'Z' => [0b111, 0b001, 0b010, 0b100, 0b111],
        ',' => [0b000, 0b000, 0b000, 0b010, 0b100],
        ' ' => [0; 5],
        // Not in any label; a box, so a new label with another letter shows it.
        _ => [0b111, 0b101, 0b101, 0b101, 0b111],
    }
}

/// Encode RGB8 pixels as PNG and write them atomically.
pub fn write_png(path: &Path, size: usize, rgb: &[u8]) -> Result<(), Box<dyn std::error::Error>> {
    write_png_rect(path, size, size, rgb)
}

/// [`write_png`] for a `width`×`height` image.
pub fn write_png_rect(
    path: &Path,
    width: usize,
    height: usize,
    rgb: &[u8],
) -> Result<(), Box<dyn std::error::Error>> {
    let mut bytes = Vec::new();
    {
        let mut encoder = png::Encoder::new(&mut bytes, width as u32, height as u32);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        let mut writer = encoder.write_header()?;
        writer.write_image_data(rgb)?;
    }
    crate::output::write_file(path, &bytes).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 17: the cull map carries its key: a strip below the map with every class's
    /// colour and black text, the map itself unchanged.
    #[test]
    fn the_cull_map_has_a_key_below_it() {
        for size in [64, 512] {
            let map = vec![7u8; size * size * 3];
            let (rgb, height) = cull_map_with_legend(&map, size);
            assert!(height > size);
            assert_eq!(rgb.len(), size * height * 3);
            assert_eq!(&rgb[..map.len()], &map[..]);
            let strip: Vec<[u8; 3]> = rgb[map.len()..]
                .chunks(3)
                .map(|c| [c[0], c[1], c[2]])
                .collect();
            for (label, colour) in COLOURS {
                assert!(strip.contains(&colour), "{size}: no swatch for {label}");
            }
            assert!(strip.contains(&[0, 0, 0]), "{size}: no text");
        }
        // Every letter of every label has a glyph of its own (not the fallback box).
        for (label, _) in COLOURS {
            for ch in label.chars() {
                assert_ne!(glyph(ch), glyph('#'), "{ch:?} in {label}");
            }
        }
    }
}
