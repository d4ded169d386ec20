//! What `liftoff backcalc` writes and prints: backcalc.csv (a row a drop: the moduli with their
//! 95 % intervals, ℓ, a fitted void's depth, the AREA reading, the misfit, whether the fit
//! converged), basins.csv (a row a sensor: measured, fitted, misfit), intercepts.csv (the
//! intercept method's line at each station with several loads), backcalc.json (the survey, SI), and the charts
//! basins.svg/png (measured against fitted, the first eight drops), moduli.svg/png (the
//! moduli along the survey) and, with joint drops, lte.svg/png (the load transfer by drop). Values are in the template's unit system: SI as MPa/m, MPa, µm,
//! mm and kN; US as pci, ksi, mils, in and lbf.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::chart::{self, BasinChart, BasinCurve, ModuliChart, ModulusSeries};
use super::Staged;
use crate::backcalc::{DropResult, Survey, Unknown};
use crate::error::{Error, Result};
use crate::units::{UnitSystem, INCH, POUND_FORCE};

/// A display unit: its symbol and SI units per unit.
#[derive(Debug, Clone, Copy)]
struct Unit(&'static str, f64);

impl Unit {
    fn of(self, si: f64) -> f64 {
        si / self.1
    }
}

/// The display units of a survey's table, files and charts.
#[derive(Debug, Clone, Copy)]
struct Units {
    k: Unit,
    modulus: Unit,
    deflection: Unit,
    offset: Unit,
    length: Unit,
    load: Unit,
}

fn units(system: UnitSystem) -> Units {
    let psi = POUND_FORCE / (INCH * INCH);
    match system {
        UnitSystem::Si => Units {
            k: Unit("MPa/m", 1e6),
            modulus: Unit("MPa", 1e6),
            deflection: Unit("µm", 1e-6),
            offset: Unit("mm", 1e-3),
            length: Unit("m", 1.0),
            load: Unit("kN", 1e3),
        },
        UnitSystem::Us => Units {
            k: Unit("pci", psi / INCH),
            modulus: Unit("ksi", 1e3 * psi),
            deflection: Unit("mils", 1e-3 * INCH),
            offset: Unit("in", INCH),
            length: Unit("in", INCH),
            load: Unit("lbf", POUND_FORCE),
        },
    }
}

/// The subgrade's name and unit: k on springs, E_s on a solid.
fn subgrade(s: &Survey, u: &Units) -> (&'static str, Unit) {
    if s.subgrade_key == "modulus" {
        ("k", u.k)
    } else {
        ("E_s", u.modulus)
    }
}

/// The fitted (or AREA) value of `what` for a drop, with its interval.
fn value(r: &DropResult, what: Unknown) -> Option<(f64, Option<[f64; 2]>)> {
    match &r.fit {
        Some(f) => f.estimate(what).map(|e| (e.value, e.interval)),
        None => r.area.and_then(|a| match what {
            Unknown::Subgrade => Some((a.subgrade_modulus, None)),
            Unknown::Slab => Some((a.slab_modulus, None)),
            Unknown::Void | Unknown::Joint => None,
        }),
    }
}

fn opt(v: Option<f64>) -> String {
    v.map_or(String::new(), |v| format!("{v:.6e}"))
}

fn csv_drops(s: &Survey, u: &Units) -> String {
    let (sg, sgu) = subgrade(s, u);
    let mut out = format!(
        "station,drop,location,load [{l}],{sg} [{k}],{sg}_low [{k}],{sg}_high [{k}],static_k [{ku}],E [{m}],E_low [{m}],E_high [{m}],ell [{len}],void [{d}],void_low [{d}],void_high [{d}],joint [{m}],joint_low [{m}],joint_high [{m}],lte [-],bending [-],lte_corrected [-],lte_model [-],area_{sg} [{k}],area_E [{m}],area_ell [{len}],area_slab_size [{len}],rms [{d}],largest [{d}],largest_at [{o}],solves,converged,termination\n",
        l = u.load.0,
        k = sgu.0,
        ku = u.k.0,
        m = u.modulus.0,
        len = u.length.0,
        d = u.deflection.0,
        o = u.offset.0,
    );
    for r in &s.drops {
        let sub = value(r, Unknown::Subgrade);
        let slab = value(r, Unknown::Slab);
        let void = value(r, Unknown::Void);
        let joint = value(r, Unknown::Joint);
        let lt = r.load_transfer.as_ref();
        let iv = |v: Option<(f64, Option<[f64; 2]>)>, i: usize, unit: Unit| {
            opt(v.and_then(|(_, iv)| iv).map(|iv| unit.of(iv[i])))
        };
        let f = r.fit.as_ref();
        let _ = writeln!(
            out,
            "{},{},{},{:.6e},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
            r.station,
            r.drop,
            r.location,
            u.load.of(r.load),
            opt(sub.map(|v| sgu.of(v.0))),
            iv(sub, 0, sgu),
            iv(sub, 1, sgu),
            opt(r.static_k.map(|k| u.k.of(k))),
            opt(slab.map(|v| u.modulus.of(v.0))),
            iv(slab, 0, u.modulus),
            iv(slab, 1, u.modulus),
            opt(f.and_then(|f| f.ell).map(|e| u.length.of(e.0))),
            opt(void.map(|v| u.deflection.of(v.0))),
            iv(void, 0, u.deflection),
            iv(void, 1, u.deflection),
            opt(joint.map(|v| u.modulus.of(v.0))),
            iv(joint, 0, u.modulus),
            iv(joint, 1, u.modulus),
            opt(lt.map(|t| t.lte)),
            opt(lt.map(|t| t.bending)),
            opt(lt.map(|t| t.corrected)),
            opt(lt.and_then(|t| t.model)),
            opt(r.area.map(|a| sgu.of(a.subgrade_modulus))),
            opt(r.area.map(|a| u.modulus.of(a.slab_modulus))),
            opt(r.area.map(|a| u.length.of(a.ell))),
            opt(r.area.and_then(|a| a.finite).map(|c| u.length.of(c.size))),
            opt(f.map(|f| u.deflection.of(f.rms))),
            opt(f.map(|f| u.deflection.of(f.largest.0))),
            opt(f.map(|f| u.offset.of(f.largest.1))),
            f.map_or(0, |f| f.solves),
            r.converged(),
            f.map_or("area", |f| f.termination.name()),
        );
    }
    out
}

fn csv_basins(s: &Survey, u: &Units) -> String {
    let mut out = format!(
        "station,drop,offset [{o}],measured [{d}],fitted [{d}],misfit [{d}]\n",
        o = u.offset.0,
        d = u.deflection.0
    );
    for r in &s.drops {
        if let Some(f) = &r.fit {
            for i in 0..f.offsets.len() {
                let _ = writeln!(
                    out,
                    "{},{},{:.6e},{:.6e},{:.6e},{:.6e}",
                    r.station,
                    r.drop,
                    u.offset.of(f.offsets[i]),
                    u.deflection.of(f.measured[i]),
                    u.deflection.of(f.fitted[i]),
                    u.deflection.of(f.fitted[i] - f.measured[i]),
                );
            }
        }
    }
    out
}

fn csv_intercepts(s: &Survey, u: &Units) -> String {
    let mut out = format!(
        "station,location,drops,intercept [{d}],slope [{d}/{l}],void\n",
        d = u.deflection.0,
        l = u.load.0
    );
    for i in &s.intercepts {
        let _ = writeln!(
            out,
            "{},{},{},{:.6e},{:.6e},{}",
            i.station,
            i.location,
            i.drops,
            u.deflection.of(i.intercept),
            u.deflection.of(i.slope * u.load.1),
            i.void
        );
    }
    out
}

/// The drops the basins chart draws.
const CHARTED: usize = 8;

/// Write backcalc.csv, basins.csv, backcalc.json and the charts into `dir` (staged: all or
/// nothing); returns the files written.
pub fn write_backcalc(
    dir: &Path,
    s: &Survey,
    title: &str,
    system: UnitSystem,
) -> Result<Vec<PathBuf>> {
    let u = units(system);
    let mut st = Staged::new(dir)?;
    st.write_text("backcalc.csv", &csv_drops(s, &u))?;
    let json = serde_json::to_string_pretty(s)
        .map_err(|e| Error::numerical("backcalc.json", format!("cannot serialise: {e}")))?;
    st.write_text("backcalc.json", &json)?;
    if !s.intercepts.is_empty() {
        st.write_text("intercepts.csv", &csv_intercepts(s, &u))?;
    }
    if s.drops.iter().any(|r| r.fit.is_some()) {
        st.write_text("basins.csv", &csv_basins(s, &u))?;
        let curves: Vec<BasinCurve> = s
            .drops
            .iter()
            .filter_map(|r| r.fit.as_ref().map(|f| (r, f)))
            .take(CHARTED)
            .map(|(r, f)| {
                let pts = |d: &[f64]| -> Vec<(f64, f64)> {
                    f.offsets
                        .iter()
                        .zip(d)
                        .map(|(&o, &d)| (u.offset.of(o), u.deflection.of(d)))
                        .collect()
                };
                BasinCurve {
                    label: format!(
                        "{}, drop {} ({}){}",
                        r.station,
                        r.drop,
                        r.location,
                        if f.converged { "" } else { " (not converged)" }
                    ),
                    measured: pts(&f.measured),
                    fitted: pts(&f.fitted),
                }
            })
            .collect();
        let fitted = s.drops.iter().filter(|r| r.fit.is_some()).count();
        let shown = if fitted > CHARTED {
            format!(", the first {CHARTED} of {fitted} drops")
        } else {
            String::new()
        };
        chart::write_basins(
            &st.path("basins.svg"),
            &st.path("basins.png"),
            &BasinChart {
                title: &format!("{title} — measured (dots) and fitted (lines) basins{shown}"),
                x_label: &format!("offset from the load plate's centre [{}]", u.offset.0),
                y_label: &format!("deflection [{}]", u.deflection.0),
                curves: &curves,
            },
        )?;
    }
    let (sg, sgu) = subgrade(s, &u);
    let along = |what: Unknown, unit: Unit| -> Vec<(f64, f64, Option<[f64; 2]>)> {
        s.drops
            .iter()
            .enumerate()
            .filter_map(|(i, r)| {
                value(r, what).map(|(v, iv)| {
                    (
                        (i + 1) as f64,
                        unit.of(v),
                        iv.map(|[a, b]| [unit.of(a), unit.of(b)]),
                    )
                })
            })
            .collect()
    };
    let sub_label = format!("{sg} [{}]", sgu.0);
    let slab_label = format!("E of the slab [{}]", u.modulus.0);
    let series = [
        ModulusSeries {
            label: &sub_label,
            points: along(Unknown::Subgrade, sgu),
        },
        ModulusSeries {
            label: &slab_label,
            points: along(Unknown::Slab, u.modulus),
        },
    ];
    let stations: Vec<String> = s.drops.iter().map(|r| r.station.clone()).collect();
    // The load transfer by joint drop, where there are joint drops.
    let joints: Vec<(usize, &crate::backcalc::LoadTransfer)> = s
        .drops
        .iter()
        .enumerate()
        .filter_map(|(i, r)| r.load_transfer.as_ref().map(|t| (i, t)))
        .collect();
    if !joints.is_empty() {
        let names: Vec<String> = joints
            .iter()
            .map(|(i, t)| format!("{} ({})", s.drops[*i].station, t.joint))
            .collect();
        let pct =
            |f: fn(&crate::backcalc::LoadTransfer) -> f64| -> Vec<(f64, f64, Option<[f64; 2]>)> {
                joints
                    .iter()
                    .enumerate()
                    .map(|(k, (_, t))| ((k + 1) as f64, 100.0 * f(t), None))
                    .collect()
            };
        let series = [
            ModulusSeries {
                label: "deflection LTE [%]",
                points: pct(|t| t.lte),
            },
            ModulusSeries {
                label: "LTE × bending correction [%]",
                points: pct(|t| t.corrected),
            },
        ];
        chart::write_moduli(
            &st.path("lte.svg"),
            &st.path("lte.png"),
            &ModuliChart {
                title: &format!("{title} — load transfer by joint drop"),
                series: &series,
                stations: &names,
            },
        )?;
    }
    chart::write_moduli(
        &st.path("moduli.svg"),
        &st.path("moduli.png"),
        &ModuliChart {
            title: &format!(
                "{title} — backcalculated moduli ({}), 95 % intervals",
                s.method
            ),
            series: &series,
            stations: &stations,
        },
    )?;
    st.commit()
}

/// The table `liftoff backcalc` prints: a line a drop, then the totals; `files` the count of
/// files written and their directory.
pub fn backcalc_table(
    title: &str,
    s: &Survey,
    system: UnitSystem,
    files: Option<(usize, &Path)>,
) -> String {
    let u = units(system);
    let (sg, sgu) = subgrade(s, &u);
    let mut out = String::new();
    let _ = writeln!(
        out,
        "liftoff backcalc — {title}: {} drop(s) by {}{}, {} solves in {:.2} s",
        s.drops.len(),
        s.method,
        if s.discarded > 0 {
            format!(" ({} seating drop(s) discarded)", s.discarded)
        } else {
            String::new()
        },
        s.solves,
        s.seconds
    );
    let _ = writeln!(
        out,
        "  {:<18} {:>4} {:<15} {:>22} {:>24} {:>7} {:>8} {:>9}  fit",
        "station",
        "drop",
        "location",
        format!("{sg} [{}] (95 %)", sgu.0),
        format!("E [{}] (95 %)", u.modulus.0),
        format!("ℓ [{}]", u.length.0),
        format!("rms [{}]", u.deflection.0),
        format!("AREA {sg}"),
    );
    let show = |v: Option<(f64, Option<[f64; 2]>)>, unit: Unit| match v {
        Some((v, Some([a, b]))) => format!(
            "{} ({}–{})",
            short(unit.of(v)),
            short(unit.of(a)),
            short(unit.of(b))
        ),
        Some((v, None)) => short(unit.of(v)),
        None => "-".into(),
    };
    for r in &s.drops {
        let f = r.fit.as_ref();
        let _ = writeln!(
            out,
            "  {:<18} {:>4} {:<15} {:>22} {:>24} {:>7} {:>8} {:>9}  {}",
            r.station,
            r.drop,
            r.location.name(),
            show(value(r, Unknown::Subgrade), sgu),
            show(value(r, Unknown::Slab), u.modulus),
            f.map_or(r.area.map(|a| a.ell), |f| f.ell.map(|e| e.0))
                .map_or("-".into(), |e| format!("{:.3}", u.length.of(e))),
            f.map_or("-".into(), |f| short(u.deflection.of(f.rms))),
            r.area
                .map_or("-".into(), |a| short(sgu.of(a.subgrade_modulus))),
            match f {
                Some(f) if f.converged => "converged".to_string(),
                Some(f) => format!("NOT CONVERGED ({}): best point shown", f.termination),
                None => "AREA".into(),
            }
        );
    }
    if let Some(c) = s.drops.iter().find_map(|r| r.area.and_then(|a| a.finite)) {
        let _ = writeln!(
            out,
            "  AREA {sg} corrected to the panel's size (Crovetti 1994; {} {} square: AF_d0 {:.3}, AF_ℓ {:.3}); the infinite slab's reading is in backcalc.json",
            short(u.length.of(c.size)),
            u.length.0,
            c.deflection_factor,
            c.ell_factor
        );
    }
    for r in &s.drops {
        if let Some((v, iv)) = value(r, Unknown::Void) {
            let _ = writeln!(
                out,
                "  {} drop {}: void depth {} {}{}",
                r.station,
                r.drop,
                short(u.deflection.of(v)),
                u.deflection.0,
                iv.map_or(String::new(), |[a, b]| format!(
                    " (95 %: {}–{})",
                    short(u.deflection.of(a)),
                    short(u.deflection.of(b))
                ))
            );
        }
    }
    for r in &s.drops {
        if let Some((v, iv)) = value(r, Unknown::Joint) {
            let _ = writeln!(
                out,
                "  {} drop {}: joint stiffness {} {}{}",
                r.station,
                r.drop,
                short(u.modulus.of(v)),
                u.modulus.0,
                iv.map_or(String::new(), |[a, b]| format!(
                    " (95 %: {}–{})",
                    short(u.modulus.of(a)),
                    short(u.modulus.of(b))
                ))
            );
        }
        if let Some(t) = &r.load_transfer {
            let _ = writeln!(
                out,
                "  {} drop {}: across {} at {} {}: LTE {:.1} %, × bending {:.3} = {:.1} %{}",
                r.station,
                r.drop,
                t.joint,
                short(u.offset.of(t.sensor)),
                u.offset.0,
                100.0 * t.lte,
                t.bending,
                100.0 * t.corrected,
                t.model.map_or(String::new(), |m| format!(
                    "; the fitted model's LTE {:.1} %",
                    100.0 * m
                ))
            );
        }
    }
    for i in &s.intercepts {
        let _ = writeln!(
            out,
            "  {} ({}, {} loads): zero-load intercept {} {}{}",
            i.station,
            i.location,
            i.drops,
            short(u.deflection.of(i.intercept)),
            u.deflection.0,
            if i.void {
                format!(
                    " > {} {}: VOID",
                    short(u.deflection.of(s.void_threshold)),
                    u.deflection.0
                )
            } else {
                " (no void)".into()
            }
        );
    }
    if s.subgrade_key == "modulus" {
        let _ = writeln!(
            out,
            "  k is dynamic; the static k (× {}, AASHTO 1993) is in backcalc.csv",
            s.static_k_factor
        );
    }
    if !s.complete {
        let _ = writeln!(
            out,
            "  INCOMPLETE: {} fit(s) did not converge: {}",
            s.not_converged.len(),
            s.not_converged.join("; ")
        );
    }
    if let Some((n, dir)) = files {
        let _ = writeln!(out, "  written: {n} files in {}", dir.display());
    }
    out
}

/// Four significant digits, no exponent for the moduli's usual sizes.
fn short(v: f64) -> String {
    if v.abs() >= 1000.0 {
        format!("{v:.0}")
    } else if v.abs() >= 10.0 {
        format!("{v:.1}")
    } else {
        format!("{v:.3}")
    }
}
