//! `gartowen scene`: does base-2^q decorrelation pay off in rendering-style scenes?

use crate::CliError;
use clap::Args;
use gartowen::core::{Claim, PowerOfTwoBase, Scrambler, Width};
use gartowen::external::ExternalScrambler;
use gartowen::seq::SequenceKind;
use gartowen_bench::scene::measure::{standard_methods, SceneMethod};
use gartowen_bench::scene::output::write_scene_report;
use gartowen_bench::scene::report::{comparable_with, read_scene_baseline, run_scenes, ScenePlan};
use gartowen_bench::scene::{all_scenes, scene_by_name, Layout};
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::Arc;

/// Measure rendering-style scenes: RMSE against N for every sampler layout that matters.
///
/// Scenes (each reads only the dimensions its layout names; each has an exact reference):
///   roulette  Russian roulette gating a cosine-sampled bounce (slots roulette:1 bounce:2)
///   direct    MIS direct lighting in a penumbra (light:2 bsdf:2)
///   defocus   pixel × square-aperture defocus × motion blur over an edge (pixel:2 lens:2 time:1)
///   image     a 32×32 image, per-pixel seeds (pixel:2 lens:2 time:1 wavelength:1 light:2
///             bsdf:2 roulette:1 bounce:2)
///
/// By default each scene runs under sobol+owen-oracle, sobol+lk-hash, sz16+art-owen-2,
/// sz16+art-owen-16p, sz16+owen-oracle:base=16 and random points, over layouts that put the
/// first slot at dimension 0 and the others at every start j (same pair, same quad, across
/// quads) plus scattered ones, and reports best/median/worst layout RMSE, time per sample,
/// efficiency, and whether base 16 helps or hurts against binary (Bonferroni-corrected z test).
///
/// Writes scene.md, scene.json and PNG figures into --out. With --baseline, compares with an
/// earlier scene.json and exits 1 when a median- or worst-layout RMSE grew by more than ×1.1
/// and 3 standard errors.
///
/// Examples:
///   gartowen scene --out scenes --quick                      (about 10 s on 2 cores)
///   gartowen scene --out scenes --scene roulette --layout 'roulette=0;bounce=5,6'
///   gartowen scene --out mine --sequence sobol --scramble owen-per-bit-hash
///   gartowen scene --out mine --external ./my_sampler --base 2 --baseline old/scene.json
#[derive(Args, Debug)]
#[command(verbatim_doc_comment)]
pub struct SceneArgs {
    /// Output directory (created if missing).
    #[arg(long)]
    pub out: PathBuf,
    /// Fewer seeds and sizes (16 seeds, N ≤ 4096; the image to N = 64 with one seed per pixel).
    #[arg(long)]
    pub quick: bool,
    /// Scenes to run (repeatable): roulette, direct, defocus, image. Default: all.
    #[arg(long = "scene")]
    pub scenes: Vec<String>,
    /// Your dimension layout for the one --scene: 'slot=DIM[,DIM…];…' naming every slot once
    /// with distinct dimensions 0..15 (e.g. 'light=0,1;bsdf=4,5').
    #[arg(long)]
    pub layout: Option<String>,
    /// Sequence for --scramble and --external: sobol or sz16.
    #[arg(long, default_value = "sz16")]
    pub sequence: String,
    /// Measure this registry scrambler on --sequence instead of the standard set (repeatable).
    #[arg(long)]
    pub scramble: Vec<String>,
    /// Measure an external program speaking the gartowen protocol (32-bit words) on --sequence.
    #[arg(long)]
    pub external: Option<String>,
    /// Scrambling base of the external program (a power of two, 2..=256).
    #[arg(long, default_value_t = 2, requires = "external")]
    pub base: u64,
    /// Seconds to wait for each reply of the external program.
    #[arg(long, default_value_t = 10.0, requires = "external")]
    pub timeout: f64,
    /// Keep the standard methods beside --scramble/--external.
    #[arg(long)]
    pub standard: bool,
    /// An earlier scene.json to compare with (exit 1 on a regression).
    #[arg(long)]
    pub baseline: Option<PathBuf>,
    /// Master seed.
    #[arg(long, default_value_t = 2026)]
    pub seed: u64,
    /// Equivalence margin δ: ART is "equivalent" to Owen of its base in a scene when the 90%
    /// interval of the MSE ratio lies inside [1 − δ, 1 + δ] (0 < δ < 1).
    #[arg(long, default_value_t = gartowen::battery::equivalence::DEFAULT_MARGIN,
          value_parser = super::parse_margin)]
    pub margin: f64,
}

/// Runs `scene`.
pub fn run(a: SceneArgs) -> Result<ExitCode, CliError> {
    if let Some(b) = &a.baseline {
        use crate::paths::{named, refuse_input_inside};
        refuse_input_inside(named("--baseline", b), named("--out", &a.out))?;
    }
    let baseline = match &a.baseline {
        Some(p) => Some(read_scene_baseline(p).map_err(CliError::Usage)?),
        None => None,
    };
    let scenes = if a.scenes.is_empty() {
        all_scenes()
    } else {
        a.scenes
            .iter()
            .map(|n| scene_by_name(n).map_err(|e| CliError::Usage(format!("--scene: {e}"))))
            .collect::<Result<_, _>>()?
    };
    let mut layouts = Vec::new();
    if let Some(text) = &a.layout {
        if scenes.len() != 1 {
            return Err(CliError::Usage(
                "--layout needs exactly one --scene (layouts name a scene's slots)".into(),
            ));
        }
        let l = Layout::parse(text, scenes[0].slots())
            .map_err(|e| CliError::Usage(format!("--layout: {e}")))?;
        layouts.push((scenes[0].name().to_string(), l));
    }
    let registry = gartowen::registry();
    let sequence: SequenceKind = a
        .sequence
        .parse()
        .map_err(|e| CliError::Usage(format!("--sequence {}: {e}", a.sequence)))?;
    let mut methods = Vec::new();
    for r in &a.scramble {
        methods.push(
            SceneMethod::registry(&registry, sequence, r)
                .map_err(|e| CliError::Usage(format!("--scramble {r}: {e}")))?,
        );
    }
    let mut process = None;
    if let Some(command) = &a.external {
        let base = PowerOfTwoBase::from_base(a.base)
            .map_err(|e| CliError::Usage(format!("--base {}: {e}", a.base)))?;
        let p = Arc::new(super::spawn_external(command, base, Width::W32, a.timeout)?);
        process = Some(p.clone());
        let make = Box::new(move |seed| {
            Ok(
                Box::new(ExternalScrambler::new(p.clone(), seed, Claim::NESTED))
                    as Box<dyn Scrambler>,
            )
        });
        methods.push(
            SceneMethod::custom(
                format!("{}+external:{command}", sequence.name()),
                sequence,
                make,
            )
            .map_err(CliError::Usage)?,
        );
    }
    if methods.is_empty() || a.standard {
        methods.extend(standard_methods(&registry));
    }
    let plan = ScenePlan {
        scenes,
        methods,
        layouts,
        quick: a.quick,
        seed: a.seed,
        margin: a.margin,
    };
    if let (Some(b), Some(path)) = (&baseline, &a.baseline) {
        if comparable_with(b, &plan).is_empty() {
            return Err(CliError::Usage(format!(
                "--baseline {}: no scene and method with a common N in this run, so nothing \
                 would be compared (baseline: {})",
                path.display(),
                b.results
                    .iter()
                    .map(|r| format!("{} {}", r.scene, r.method))
                    .collect::<Vec<_>>()
                    .join(", ")
            )));
        }
    }
    // Every argument is checked; an unwritable --out fails now, not after the measurement.
    std::fs::create_dir_all(&a.out)
        .map_err(|e| CliError::Io(format!("cannot create {}: {e}", a.out.display())))?;
    let report = run_scenes(
        &plan,
        &crate::progress::Bar::new("scene [{bar:30}] {pos}/{len} {msg}"),
    );
    if let Some(e) = process.as_ref().and_then(|p| p.failure()) {
        return Err(CliError::External(e.to_string()));
    }
    let report = report.map_err(CliError::Usage)?;
    let staging = gartowen_bench::report::staging_dir(&a.out);
    crate::cleanup::register(&staging);
    let written = write_scene_report(&report, &a.out, baseline.as_ref());
    crate::cleanup::unregister(&staging);
    let regressions = written.map_err(CliError::Io)?;
    crate::outln!(
        "scene report in {} ({} scenes × {} methods, {:.1} s)",
        a.out.display(),
        report.scenes.len(),
        plan.methods.len(),
        report.seconds
    );
    for r in &regressions {
        crate::outln!("REGRESSION {}: {:.4e} -> {:.4e}", r.what, r.before, r.after);
    }
    Ok(if regressions.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}
