//! The covered maps' settings (src/contact/maps/surface.rs) against what they cost and how accurate
//! they are: for each case, its rectangle of x = ln s and y = ln η (5 mm cover, R = 66.5 mm), then
//! per variant `v=PW,NX0,EW,NY0,RATIO` (panel width in decades of s, start degree in s, panel width
//! in decades of η, start degree in η with 0 = chosen per panel, node tolerance / map tolerance) a
//! Markdown row: layer solves, final panels (n_x×n_y), wall time, the surface's estimate
//! (interpolation + Λ_xΛ_y·nodes), the largest true error at `--nref` random points of the
//! rectangle against layer solves at 1e−6, and their ratio.
//!
//! Cases (`--set`): `idler` (default) the conveyor-idler scene's maps (0 and 20 °C, 1–6 m/s,
//! 5–20 kN/m) of the four synthetic compounds of the test-data module, fitted from their synthetic
//! DMA exports; `bench` the 30 × 30 × 10 grid of `cargo bench --bench maps` on EMS-CA and TRIOS.
//! `--tol T` the map tolerance (1e−3). Extra tables: `--line` the Chebyshev coefficients of ln φ and
//! ln λ along the rectangle's middle lines at degree 32 (how fast they decay in s and in η);
//! `--nodecost` CPU ms of one layer node solve at tolerances 1e−3 … 1e−6 (one thread);
//! `--warm` CPU ms per node cold and from warm starts.
//! Run: `RAYON_NUM_THREADS=2 cargo bench --bench maps_covered -- --set idler v=4,8,2,0,0.01`.
use std::path::PathBuf;
use std::time::Instant;
use viscoroll::contact::maps::{covered_map, CoveredProblem, MapQuery, MapSettings};
use viscoroll::pipeline::{fit_files, fit_measurement, FitOptions};
use viscoroll::testdata::SplitMix64;
use viscoroll::testdata::{dma_csv, dma_rows, realistic_compounds, DmaProtocol};

#[path = "support/cpu.rs"]
mod cpu;
use cpu::cpu_s;

fn log_spaced(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| (a.ln() + (b.ln() - a.ln()) * i as f64 / (n - 1) as f64).exp())
        .collect()
}

struct Case {
    name: String,
    creep: viscoroll::CreepSpectrum,
    queries: Vec<MapQuery>,
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let which = args
        .iter()
        .position(|a| a == "--set")
        .and_then(|i| args.get(i + 1))
        .cloned()
        .unwrap_or("idler".into());
    let tol: f64 = args
        .iter()
        .position(|a| a == "--tol")
        .and_then(|i| args.get(i + 1))
        .and_then(|v| v.parse().ok())
        .unwrap_or(1e-3);
    let nref: usize = args
        .iter()
        .position(|a| a == "--nref")
        .and_then(|i| args.get(i + 1))
        .and_then(|v| v.parse().ok())
        .unwrap_or(30);
    let variants: Vec<String> = args
        .iter()
        .filter(|a| a.starts_with("v="))
        .map(|a| a[2..].to_string())
        .collect();
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data");
    let mut cases = Vec::new();
    let radius_m = 0.0665;
    if which == "idler" {
        for base in realistic_compounds() {
            let csv = dma_csv(&dma_rows(&base, &DmaProtocol::default()));
            let m = viscoroll::dma::read_bytes(
                &[(format!("{}.csv", base.name), csv.into_bytes())],
                &Default::default(),
            )
            .expect("reads");
            let fit = fit_measurement(&base.name, &m, &FitOptions::default()).expect("fits");
            let creep = fit.creep.clone().unwrap();
            let mut queries = Vec::new();
            for t in [0.0, 20.0] {
                let a_t = 10f64.powf(fit.shift_law.log10_a_t(t));
                for v in [1.0, 6.0] {
                    for n in [5e3, 2e4] {
                        queries.push(MapQuery {
                            radius_m,
                            load_n_per_m: n,
                            speed_m_s: v,
                            a_t,
                        });
                    }
                }
            }
            cases.push(Case {
                name: base.name.clone(),
                creep,
                queries,
            });
        }
    } else {
        for (name, file) in [
            ("ems-ca", "pyvisco-ems-ca/freq_Eplexor_raw.xls"),
            ("trios", "trios-aresg2-lims/frequency_sweep_tts.txt"),
        ] {
            let fit = fit_files(name, &[root.join(file)], &FitOptions::default()).expect("fits");
            let creep = fit.creep.clone().unwrap();
            let mut queries = Vec::new();
            for k in 0..10 {
                let a_t = 10f64.powf(fit.shift_law.log10_a_t(-40.0 + 10.0 * k as f64));
                for &v in &log_spaced(0.5, 40.0, 30) {
                    for &n in &log_spaced(2e3, 5e4, 30) {
                        queries.push(MapQuery {
                            radius_m,
                            load_n_per_m: n,
                            speed_m_s: v,
                            a_t,
                        });
                    }
                }
            }
            cases.push(Case {
                name: name.into(),
                creep,
                queries,
            });
        }
    }
    println!("\n| case | variant | solves | panels | time (s) | estimate (interp + node) | true max err | worst/est |");
    println!("|---|---|---|---|---|---|---|---|");
    for c in &cases {
        let p = CoveredProblem::new(&c.creep, None, 5e-3).unwrap();
        let xs: Vec<f64> = c
            .queries
            .iter()
            .map(|q| {
                p.reduced
                    .reduced_time_s(q.radius_m, q.load_n_per_m, q.speed_m_s, q.a_t)
                    .ln()
            })
            .collect();
        let ys: Vec<f64> = c
            .queries
            .iter()
            .map(|q| p.reduced_thickness(q.radius_m, q.load_n_per_m).ln())
            .collect();
        let r = |v: &[f64]| {
            (
                v.iter().copied().fold(f64::INFINITY, f64::min),
                v.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            )
        };
        let (xr, yr) = (r(&xs), r(&ys));
        println!(
            "{}: x = ln s in [{:.2}, {:.2}] ({:.2} decades), y = ln eta in [{:.3}, {:.3}]",
            c.name,
            xr.0,
            xr.1,
            (xr.1 - xr.0) / std::f64::consts::LN_10,
            yr.0,
            yr.1
        );
        if args.iter().any(|a| a == "--line") {
            let n = 32;
            for (dir, (lo, hi)) in [("x", xr), ("y", yr)] {
                let pts: Vec<(f64, f64)> = (0..=n)
                    .map(|k| {
                        let t = 0.5 * (lo + hi)
                            + 0.5 * (hi - lo) * (std::f64::consts::PI * k as f64 / n as f64).cos();
                        if dir == "x" {
                            (t, 0.5 * (yr.0 + yr.1))
                        } else {
                            (0.5 * (xr.0 + xr.1), t)
                        }
                    })
                    .collect();
                use rayon::prelude::*;
                {
                    let ntol = 1e-5;
                    let v: Vec<(f64, f64)> = pts
                        .par_iter()
                        .map(|&(x, y)| {
                            let nd = p.node(x, y, ntol).unwrap();
                            (nd.ln_phi, nd.ln_lambda)
                        })
                        .collect();
                    let cp = viscoroll::special::chebyshev::lobatto_coefficients(
                        &v.iter().map(|a| a.0).collect::<Vec<_>>(),
                    );
                    let cl = viscoroll::special::chebyshev::lobatto_coefficients(
                        &v.iter().map(|a| a.1).collect::<Vec<_>>(),
                    );
                    println!(
                        "{} along {dir} node tol {ntol:e}: ln phi coeffs {:?}",
                        c.name,
                        cp.iter().map(|c| format!("{c:.1e}")).collect::<Vec<_>>()
                    );
                    println!(
                        "{} along {dir} node tol {ntol:e}: ln lam coeffs {:?}",
                        c.name,
                        cl.iter().map(|c| format!("{c:.1e}")).collect::<Vec<_>>()
                    );
                }
            }
        }
        if args.iter().any(|a| a == "--nodecost") {
            let pts: Vec<(f64, f64)> = (0..9)
                .map(|k| {
                    (
                        xr.0 + (xr.1 - xr.0) * (k % 3) as f64 / 2.0,
                        yr.0 + (yr.1 - yr.0) * (k / 3) as f64 / 2.0,
                    )
                })
                .collect();
            for ntol in [1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 1e-6] {
                let t0 = Instant::now();
                let mut est = 0.0f64;
                for _ in 0..3 {
                    for &(x, y) in &pts {
                        est = est.max(p.node(x, y, ntol).unwrap().error_estimate);
                    }
                }
                println!(
                    "{}: node tol {ntol:e}: {:.2} ms per node, largest estimate {est:.1e}",
                    c.name,
                    t0.elapsed().as_secs_f64() * 1e3 / 27.0
                );
            }
        }
        if args.iter().any(|a| a == "--warm") {
            let n = 16;
            let xs: Vec<f64> = (0..=n)
                .map(|k| {
                    0.5 * (xr.0 + xr.1)
                        + 0.5 * (xr.1 - xr.0) * (std::f64::consts::PI * k as f64 / n as f64).cos()
                })
                .collect();
            let ys: Vec<f64> = (0..=5)
                .map(|k| {
                    0.5 * (yr.0 + yr.1)
                        + 0.5 * (yr.1 - yr.0) * (std::f64::consts::PI * k as f64 / 5.0).cos()
                })
                .collect();
            let pts: Vec<(f64, f64)> = xs
                .iter()
                .flat_map(|&x| ys.iter().map(move |&y| (x, y)))
                .collect();
            let m = pts.len() as f64;
            let c0 = cpu_s();
            let exact: Vec<f64> = pts
                .iter()
                .map(|&(x, y)| p.node(x, y, 1e-4).unwrap().ln_lambda.exp())
                .collect();
            let cold = cpu_s() - c0;
            let c0 = cpu_s();
            for (&(x, y), &l) in pts.iter().zip(&exact) {
                p.node_from(x, y, 1e-4, Some((l, f64::NAN))).unwrap();
            }
            let ex = cpu_s() - c0;
            let c0 = cpu_s();
            for (i, &(x, y)) in pts.iter().enumerate() {
                let h = if i % 6 == 0 {
                    None
                } else {
                    Some((exact[i - 1], f64::NAN))
                };
                p.node_from(x, y, 1e-4, h).unwrap();
            }
            let wy = cpu_s() - c0;
            let c0 = cpu_s();
            for (i, &(x, y)) in pts.iter().enumerate() {
                let h = if i < 6 {
                    None
                } else {
                    Some((exact[i - 6], f64::NAN))
                };
                p.node_from(x, y, 1e-4, h).unwrap();
            }
            let wx = cpu_s() - c0;
            println!("{}: CPU ms per node: cold {:.2}, exact-λ start {:.2}, previous-in-y start {:.2}, previous-in-x start {:.2}", c.name, cold * 1e3 / m, ex * 1e3 / m, wy * 1e3 / m, wx * 1e3 / m);
        }
        let mut rng = SplitMix64::new(7);
        let refs: Vec<(f64, f64, f64, f64)> = (0..nref)
            .map(|_| {
                let x = xr.0 + (xr.1 - xr.0) * rng.uniform();
                let y = yr.0 + (yr.1 - yr.0) * rng.uniform();
                (x, y, 0.0, 0.0)
            })
            .collect();
        use rayon::prelude::*;
        let refs: Vec<(f64, f64, f64, f64)> = refs
            .par_iter()
            .map(|&(x, y, _, _)| {
                let n = p.node(x, y, 1e-6).expect("ref");
                (x, y, n.ln_phi, n.ln_lambda)
            })
            .collect();
        for v in &variants {
            // v = "pw,nx0,ew,ny0,ntr"  (panel width decades, start degree x, eta width decades, ny0, node tol ratio)
            let f: Vec<f64> = v.split(',').map(|t| t.parse().unwrap()).collect();
            let settings = MapSettings {
                tol,
                panel_width: f[0] * std::f64::consts::LN_10,
                start_degree: f[1] as usize,
                eta_panel_width: f[2] * std::f64::consts::LN_10,
                eta_start_degree: f[3] as usize,
                node_tol_ratio: f[4],
                ..MapSettings::default()
            };
            let t0 = Instant::now();
            let (_, s) = covered_map(&p, &c.queries, &settings).expect("builds");
            let time = t0.elapsed().as_secs_f64();
            let mut worst = 0.0f64;
            for &(x, y, lp, ll) in &refs {
                let (phi, lam) = s.eval(x, y).unwrap();
                worst = worst.max((phi.ln() - lp).abs()).max((lam.ln() - ll).abs());
            }
            let shapes: Vec<String> = s
                .panel_shapes()
                .iter()
                .map(|(_, (nx, ny))| format!("{nx}×{ny}"))
                .collect();
            println!(
                "| {} | {v} | {} | {} | {time:.2} | {:.1e} ({:.1e} + {:.1e}) | {worst:.1e} | {:.2} |",
                c.name, s.solves, shapes.join(" "), s.error_estimate, s.interpolation_estimate, s.node_error_bound, worst / s.error_estimate
            );
            if !s.warnings.is_empty() {
                println!("warnings: {:?}", s.warnings);
            }
        }
    }
}
