//! The tests of the generated WGSL: the header's constants, the codes, naga's validation,
//! and the `mirrors:` headers of the WGSL files (each named Rust function exists).

use super::*;
use wgpu::naga::valid::Capabilities;

/// The hexadecimal literal read back (as WGSL reads it) is the same f32.
fn parse_hex(text: &str) -> f32 {
    let (sign, rest) = match text.strip_prefix('-') {
        Some(r) => (-1.0, r),
        None => (1.0, text),
    };
    let rest = rest
        .strip_prefix("0x1.")
        .unwrap()
        .strip_suffix('f')
        .unwrap();
    let (mantissa, exp) = rest.split_once('p').unwrap();
    let m = u32::from_str_radix(mantissa, 16).unwrap() as f64 / f64::from(1u32 << 24);
    (sign * (1.0 + m) * 2f64.powi(exp.parse().unwrap())) as f32
}

#[test]
fn hex_literals_are_exact() {
    for x in [
        SAFETY_REL,
        1e-9,
        -0.002_372_558,
        0.9216062,
        1e30,
        1e-30,
        f32::MIN_POSITIVE,
        f32::MAX,
        -3.5,
    ] {
        let text = hex_f32(x);
        assert_eq!(parse_hex(&text).to_bits(), x.to_bits(), "{x:e} as {text}");
    }
    assert_eq!(hex_f32(SAFETY_REL), "0x1.000000p-12f");
    assert_eq!(hex_f32(0.0), "0.0f");
}

/// The header declares each `(name, value)` as `const TC_<name>: <ty> = <literal>;`.
fn assert_declares<T: Copy>(
    header: &str,
    ty: &str,
    literal: fn(T) -> String,
    constants: &[(&str, T)],
) {
    for &(name, value) in constants {
        let line = format!("const TC_{name}: {ty} = {};", literal(value));
        assert!(header.contains(&line), "{line} not in\n{header}");
    }
}

/// The bodies declare no constant by hand (one source: the generated header).
fn assert_no_hand_written_constant(bodies: [&str; 2]) {
    for line in bodies.iter().flat_map(|body| body.lines()) {
        assert!(
            !line.trim_start().starts_with("const "),
            "hand-written: {line}"
        );
    }
}

#[test]
fn every_shared_constant_comes_from_rust() {
    let header = KernelConstants::CPU.header();
    assert_declares(
        &header,
        "f32",
        hex_f32,
        &[
            ("SAFETY_REL", SAFETY_REL),
            ("DISC_NEAR", DISC_NEAR as f32),
            ("NEAR_DOUBLE", NEAR_DOUBLE as f32),
            ("SMALL_ROOT", SMALL_ROOT as f32),
            ("BRACKET", BRACKET as f32),
            ("TRISECT_FIT_0", trisect::FIT[0] as f32),
            ("TRISECT_FIT_5", trisect::FIT[5] as f32),
            ("AXIS_PARALLEL_H2", AXIS_PARALLEL_H2),
        ],
    );
    assert!(header.contains(&format!("const TC_CBRT_SEED: u32 = {CBRT_F32_SEED}u;")));
    assert_no_hand_written_constant([&module_body(), KERNEL_BODY]);
}

/// The generated text parses and validates as WGSL (naga, as wgpu does), with the
/// CPU's constants and with a changed one: no adapter needed.
#[test]
fn the_kernel_validates() {
    for constants in [
        KernelConstants::CPU,
        KernelConstants {
            safety_rel: 1.0 / 1024.0,
            ..KernelConstants::CPU
        },
    ] {
        validate(&constants.source(), Capabilities::default()).unwrap_or_else(|e| panic!("{e}"));
    }
}

/// The module is the kernel's text less its bindings and entry point (one source): it
/// validates alone, declares no binding and no entry point, and names the codes the
/// host decodes with.
#[test]
fn the_kernel_is_the_module_plus_its_bindings() {
    let module = wgsl_module();
    let kernel = kernel_source();
    assert!(kernel.starts_with(&module));
    assert!(kernel.contains(KERNEL_BODY));
    let parsed = validate(&module, Capabilities::default()).unwrap_or_else(|e| panic!("{e}"));
    assert_includable(
        &module,
        &parsed,
        &[
            "torus_intersect",
            "torus_intersect_from_surface",
            "torus_cull_keeps",
        ],
        &[
            "const TORUS_HIT: u32 = 1u;",
            "const TORUS_ESCALATE: u32 = 2u;",
            "const TORUS_CULL_SKALA: u32 = 5u;",
            "const TORUS_CULL_DISCRIMINANT: u32 = 8u;",
            "const TORUS_WHY_NON_FINITE_LINE: u32 = 1u;",
            "const TORUS_WHY_T_ERROR: u32 = 7u;",
            "const TORUS_WHY_ON_SURFACE: u32 = 8u;",
        ],
    );
    assert_prefixed(&parsed, 60);
}

/// What a module a renderer includes must be: no binding and no entry point (the
/// renderer declares its own), the documented `entries` among its functions, and the
/// documented constant `lines` in its text.
fn assert_includable(text: &str, parsed: &wgpu::naga::Module, entries: &[&str], lines: &[&str]) {
    for absent in [
        "@group",
        "@binding",
        "@compute",
        "var<uniform>",
        "var<storage",
    ] {
        assert!(!text.contains(absent), "{absent} in the module");
    }
    assert!(parsed.entry_points.is_empty());
    assert!(parsed.global_variables.is_empty());
    for entry in entries {
        assert!(
            parsed
                .functions
                .iter()
                .any(|(_, f)| f.name.as_deref() == Some(*entry)),
            "{entry}"
        );
    }
    for line in lines {
        assert!(text.contains(line), "{line}");
    }
}

/// The global names of `module`: its functions, constants and structs.
fn global_names(module: &wgpu::naga::Module) -> Vec<String> {
    let functions = module.functions.iter().filter_map(|(_, f)| f.name.clone());
    let constants = module.constants.iter().filter_map(|(_, c)| c.name.clone());
    let types = module
        .types
        .iter()
        .filter(|(_, t)| matches!(t.inner, wgpu::naga::TypeInner::Struct { .. }))
        .filter_map(|(_, t)| t.name.clone());
    functions.chain(constants).chain(types).collect()
}

/// Every global name is the API's (torus_ / Torus / TORUS_) or an internal one
/// (tc_ / Tc / TC_), so none clashes with a renderer's own `miss`, `Line` or `U`; and
/// there are more than `at_least` of them (the check saw the module).
fn assert_prefixed(module: &wgpu::naga::Module, at_least: usize) {
    let prefixed = |name: &str| {
        ["torus_", "Torus", "TORUS_", "tc_", "Tc", "TC_"]
            .iter()
            .any(|p| name.starts_with(p))
    };
    let names = global_names(module);
    assert!(names.len() > at_least, "{names:?}");
    // `__…` are naga's own predeclared types (frexp's result), not the module's.
    let bare: Vec<&String> = names
        .iter()
        .filter(|n| !prefixed(n) && !n.starts_with("__"))
        .collect();
    assert!(
        bare.is_empty(),
        "global names without the module's prefix: {bare:?}"
    );
}

/// `text` parsed and validated as WGSL with `capabilities` (naga, as wgpu does: no
/// adapter needed), or the parse error as naga prints it, or the validation error.
fn validate(text: &str, capabilities: Capabilities) -> Result<wgpu::naga::Module, String> {
    use wgpu::naga;
    let module = naga::front::wgsl::parse_str(text).map_err(|e| e.emit_to_string(text))?;
    naga::valid::Validator::new(naga::valid::ValidationFlags::all(), capabilities)
        .validate(&module)
        .map_err(|e| format!("{e:?}"))?;
    Ok(module)
}

/// The f64 module is the library's f64 pass less its bindings and entry point (one
/// source): it validates alone (with `FLOAT64`), declares no binding and no entry
/// point, names its API with the module's prefixes, and shares no global name with
/// the f32 module, so that both go in one shader in either order.
#[test]
fn the_f64_pass_is_the_f64_module_plus_its_bindings() {
    let module = wgsl_finish_module();
    let pass = finish_source();
    assert!(pass.starts_with(&module));
    assert!(pass.ends_with(FINISH_BODY));
    let parsed = validate(&module, Capabilities::FLOAT64).unwrap_or_else(|e| panic!("{e}"));
    assert_includable(
        &module,
        &parsed,
        &["torus_finish_f64", "torus_finish_wanted"],
        &[
            "const TORUS_F64_FOLLOW: u32 = 0u;",
            "const TORUS_F64_HOST: u32 = 2u;",
            "const TORUS_F64_SURFACE_ALWAYS: u32 = 4u;",
            "const TORUS_F64_STATUS_FRONT: u32 = 1u;",
            "const TORUS_F64_STATUS_HOST: u32 = 4u;",
        ],
    );
    assert_prefixed(&parsed, 40);
    // No name in common with the f32 module (`__…` are naga's own).
    let f32_module = wgpu::naga::front::wgsl::parse_str(&wgsl_module()).expect("parses");
    let f32_names = global_names(&f32_module);
    let common: Vec<String> = global_names(&parsed)
        .into_iter()
        .filter(|n| f32_names.contains(n) && !n.starts_with("__"))
        .collect();
    assert!(common.is_empty(), "declared by both modules: {common:?}");
    // Both, in either order, validate as one shader; a second copy of either clashes.
    let f32_text = wgsl_module();
    for both in [
        format!("{f32_text}\n{module}"),
        format!("{module}\n{f32_text}"),
    ] {
        let parsed = validate(&both, Capabilities::FLOAT64).unwrap_or_else(|e| panic!("{e}"));
        assert_prefixed(&parsed, 100);
    }
    assert!(validate(&format!("{module}\n{module}"), Capabilities::FLOAT64).is_err());
}

/// The one line of `b` that differs from `a`'s (there must be exactly one).
fn one_changed_line<'b>(a: &str, b: &'b str) -> &'b str {
    let differing: Vec<(&str, &str)> = a.lines().zip(b.lines()).filter(|(x, y)| x != y).collect();
    assert_eq!(differing.len(), 1, "{differing:?}");
    differing[0].1
}

/// The f64 finish pass parses and validates as WGSL with naga's `FLOAT64` capability
/// (what `SHADER_F64` enables), with the CPU's constants and with a changed one, and
/// every threshold is the Rust value, to the bit.
#[test]
fn the_f64_finish_pass_validates_and_takes_its_constants_from_rust() {
    use wgpu::naga;
    let cpu = FinishConstants::CPU;
    for constants in [
        cpu,
        FinishConstants {
            near_double: 2e-7,
            ..cpu
        },
    ] {
        let module =
            validate(&constants.source(), Capabilities::FLOAT64).unwrap_or_else(|e| panic!("{e}"));
        assert!(module.entry_points.iter().any(|e| e.name == "finish_main"));
        // naga reads every f64 literal as Rust does: its constant table holds the
        // header's values to the bit.
        let header = constants.header();
        let mut seen = 0;
        for (_, c) in module.constants.iter() {
            let Some(name) = c.name.as_deref() else {
                continue;
            };
            let naga::Expression::Literal(naga::Literal::F64(value)) =
                module.global_expressions[c.init]
            else {
                continue;
            };
            let prefix = format!("const {name}: f64 = ");
            let line = header
                .lines()
                .find(|l| l.starts_with(&prefix))
                .unwrap_or_else(|| panic!("{name} not in the header"));
            let literal = line[prefix.len()..].strip_suffix("lf;").expect("lf;");
            let want: f64 = literal.parse().expect("a decimal");
            assert_eq!(value.to_bits(), want.to_bits(), "{line}: naga {value:e}");
            seen += 1;
        }
        let declared = header.lines().filter(|l| l.contains(": f64 = ")).count();
        assert_eq!(seen, declared, "every f64 constant read back");
    }
    let header = cpu.header();
    assert_declares(
        &header,
        "f64",
        literal_f64,
        &[
            ("FIN_EPS", EPS),
            ("FIN_EIGHT_EPS", 8.0 * EPS),
            ("FIN_SIGN_SURE_EPS", SIGN_SURE * EPS),
            ("FIN_TOUCH_EPS", TOUCH * EPS),
            ("FIN_NEAR_DOUBLE", NEAR_DOUBLE),
            ("FIN_DISC_NEAR", DISC_NEAR),
            ("FIN_SMALL_ROOT", SMALL_ROOT),
            ("FIN_POLISH_BELOW", POLISH_BELOW),
            ("FIN_CHORD_SCALE", 1.0 + CHORD_SLACK),
            ("FIN_OWN_ROOT_REACH", OWN_ROOT_REACH),
            ("FIN_TRISECT_FIT_0", trisect::FIT[0]),
            ("FIN_TRISECT_HALF_RANGE", trisect::HALF_RANGE),
        ],
    );
    assert!(header.contains(&format!("const TC_FIN_CBRT_SEED: u32 = {CBRT_F32_SEED}u;")));
    assert_no_hand_written_constant([FINISH_MODULE_BODY, FINISH_BODY]);
}

/// Changing a Rust constant changes the text in exactly that line, for the f32 kernel and
/// for the f64 pass; the CPU's constants are the text that ships. The kernel's cube-root
/// seed, an integer, is one of its constants too.
#[test]
fn a_changed_constant_changes_exactly_its_line() {
    let (kernel, finish) = (KernelConstants::CPU, FinishConstants::CPU);
    let doubled_safety = KernelConstants {
        safety_rel: kernel.safety_rel * 2.0,
        ..kernel
    };
    let doubled_near_double = FinishConstants {
        near_double: finish.near_double * 2.0,
        ..finish
    };
    // (the text that ships, the CPU's constants', one constant doubled, its new line)
    for (shipped, cpu, changed, line) in [
        (
            kernel_source(),
            kernel.source(),
            doubled_safety.source(),
            "const TC_SAFETY_REL: f32 = 0x1.000000p-11f; // 4.8828125e-4",
        ),
        (
            finish_source(),
            finish.source(),
            doubled_near_double.source(),
            "const TC_FIN_NEAR_DOUBLE: f64 = 2e-7lf;",
        ),
    ] {
        assert_eq!(one_changed_line(&cpu, &changed), line);
        assert_eq!(shipped, cpu);
    }
    let seed = KernelConstants {
        cbrt_seed: kernel.cbrt_seed + 1,
        ..kernel
    };
    assert_ne!(seed.source(), kernel.source());
}

/// The WGSL files of both modules and of the library's two entry points, each with its
/// path under `src/gpu`.
fn wgsl_files() -> Vec<(&'static str, &'static str)> {
    let entry_points = [
        ("wgsl/kernel.wgsl", KERNEL_BODY),
        ("wgsl/finish.wgsl", FINISH_BODY),
    ];
    (MODULE_HEAD.1.iter().chain(CULL_FILES).chain(MODULE_TAIL.1))
        .chain(FINISH_MODULE_FILES.1)
        .copied()
        .chain(entry_points)
        .chain(crate::gpu::scene_bvh::SCENE_FILES)
        .collect()
}

/// The module texts are their files concatenated as they are, in order: the f32 module's
/// head, its culls in the table's order, the generated dispatch, its tail.
#[test]
fn the_bodies_are_their_files_in_order() {
    let text = |files: &[(&str, &str)]| -> String { files.iter().map(|&(_, t)| t).collect() };
    let module = format!(
        "{}{}\n{}\n{}\n{}",
        text(MODULE_HEAD.1),
        crate::gpu::bounds::bounds_wgsl(),
        text(CULL_FILES),
        cull_switch(),
        text(MODULE_TAIL.1)
    );
    assert_eq!(module, module_body());
    let paths: Vec<String> = CULL_FILES.iter().map(|&(p, _)| p.to_string()).collect();
    let want: Vec<String> = GpuCull::ALL
        .iter()
        .map(|c| format!("wgsl/module/culls/{}.wgsl", c.name()))
        .collect();
    assert_eq!(paths, want);
    let finish: String = FINISH_MODULE_FILES
        .1
        .iter()
        .map(|&(_, text)| text)
        .collect();
    assert_eq!(finish, FINISH_MODULE_BODY);
}

/// Every WGSL file's header names, for each of its functions in order, the Rust function
/// it follows: `// mirrors: <WGSL fn> -> crate::<module path>::[<Type>::]<fn>`, or
/// `-> none` for a helper that only WGSL needs (free text may follow). Each named Rust
/// function exists: `fn <fn>` in the file of the longest prefix of the path that is a
/// module of the crate (`src/<path>.rs` or `src/<path>/mod.rs`), which also declares the
/// type, if one is named. So a renamed or moved Rust function fails here, not silently
/// in a comment.
#[test]
fn every_mirrors_line_names_a_rust_function_that_exists() {
    let src = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut named = 0;
    for (path, text) in wgsl_files() {
        let mirrors: Vec<(&str, &str)> = text
            .lines()
            .filter_map(|l| l.strip_prefix("// mirrors: "))
            .map(|l| {
                let (wgsl, rust) = l
                    .split_once(" -> ")
                    .unwrap_or_else(|| panic!("{path}: `{l}` is not `WGSL_FN -> RUST_PATH`"));
                (wgsl.trim(), rust.split_whitespace().next().unwrap_or(""))
            })
            .collect();
        let functions: Vec<&str> = text
            .lines()
            .filter_map(|l| l.strip_prefix("fn "))
            .map(|l| l.split('(').next().expect("a name").trim())
            .collect();
        let listed: Vec<&str> = mirrors.iter().map(|&(wgsl, _)| wgsl).collect();
        assert_eq!(
            listed, functions,
            "{path}: the `mirrors:` lines name its functions, in order"
        );
        for (wgsl, rust) in mirrors {
            if rust == "none" {
                continue;
            }
            let segments: Vec<&str> = rust
                .strip_prefix("crate::")
                .unwrap_or_else(|| panic!("{path}: {wgsl} -> {rust}: not a crate:: path"))
                .split("::")
                .collect();
            let (name, modules) = segments.split_last().expect("a name");
            let (file, types) = (1..=modules.len())
                .rev()
                .find_map(|k| {
                    let dir = modules[..k].iter().fold(src.clone(), |p, s| p.join(s));
                    [dir.with_extension("rs"), dir.join("mod.rs")]
                        .into_iter()
                        .find(|f| f.is_file())
                        .map(|f| (f, &modules[k..]))
                })
                .unwrap_or_else(|| panic!("{path}: {wgsl} -> {rust}: no such module"));
            let code = std::fs::read_to_string(&file).expect("readable");
            assert!(
                code.contains(&format!("fn {name}(")) || code.contains(&format!("fn {name}<")),
                "{path}: {wgsl} -> {rust}: no `fn {name}` in {}",
                file.display()
            );
            for ty in types {
                assert!(
                    [
                        format!("struct {ty}"),
                        format!("enum {ty}"),
                        format!("trait {ty}")
                    ]
                    .iter()
                    .any(|decl| code.contains(decl.as_str())),
                    "{path}: {wgsl} -> {rust}: no type {ty} in {}",
                    file.display()
                );
            }
            named += 1;
        }
    }
    assert!(named >= 50, "only {named} mirrored functions");
}
