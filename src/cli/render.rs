//! `torus-cull render`: a scene's picture and cull map (PNG).

use super::CliResult;
use crate::console::outln;
use crate::whole::Whole;
use std::path::Path;
use std::process::ExitCode;

/// Runs `render`.
pub fn render(
    scene: &str,
    nu: f64,
    out: &Path,
    size: Whole,
    tori: Whole,
    seed: Whole,
) -> CliResult {
    let kind: torus_cull_lab::scene::SceneKind =
        scene.parse().map_err(|e| format!("--scene: {e}"))?;
    check_png_name(out)?;
    let size: usize = size.within("--size", (1, 8192), "")?;
    let tori: usize = tori.within("--tori", (1, 1_000_000), "")?;
    let seed = seed.seed("--seed")?;
    let scene = torus_cull_lab::scene::Scene::build(kind, nu, tori, seed)
        .map_err(|e| format!("--nu: {e}"))?;
    let map_path = out.with_file_name(format!(
        "{}-cullmap.png",
        out.file_stem()
            .map_or("render".into(), |s| s.to_string_lossy())
    ));
    // Both outputs are checked before the picture is drawn.
    for path in [out, map_path.as_path()] {
        torus_cull_lab::output::check_writable(path)
            .map_err(|e| format!("--out {}: {e}", path.display()))?;
    }
    let image = torus_cull_lab::render::render(&scene, size);
    torus_cull_lab::render::write_png(out, size, &image.shaded)?;
    let (map, height) = torus_cull_lab::render::cull_map_with_legend(&image.cull_map, size);
    torus_cull_lab::render::write_png_rect(&map_path, size, height, &map)?;
    let c = image.counts;
    let total = (size * size) as f64;
    outln!("wrote {} and {}", out.display(), map_path.display())?;
    // The cull map's key: its colour, what it means, how many pixels.
    outln!("cull map key (colour, meaning, pixels):")?;
    for (colour, name, n) in [
        ("light grey", "hit", c.hit),
        (
            "orange",
            "reached the quartic and missed (skala)",
            c.quartic_missed,
        ),
        ("green", "rejected only by skala", c.skala_only),
        ("blue", "rejected by cychosz", c.cychosz),
        ("near black", "entered no box", c.no_box),
    ] {
        outln!(
            "  {colour:<12} {name:<40} {n:>8} ({:.1}%)",
            100.0 * n as f64 / total
        )?;
    }
    Ok(ExitCode::SUCCESS)
}

/// `--out` must name a PNG (`.png`, any case): `render` writes PNG bytes, and an `.svg`
/// or `.jpg` name would hold bytes its viewer cannot read. Refused before the picture is
/// drawn; the cull map takes the same extension.
fn check_png_name(out: &Path) -> Result<(), String> {
    let ext = out
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    if ext.as_deref() == Some("png") {
        return Ok(());
    }
    Err(format!(
        "--out {}: render writes PNG images (allowed: a file name ending in .png{})",
        out.display(),
        match ext {
            Some(e) => format!("; .{e} is not written"),
            None => String::new(),
        }
    ))
}
