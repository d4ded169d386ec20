//! How `examples/fwd-basins.csv` and `examples/fwd-void.csv` were made: the bundled surveys'
//! basins are synthetic, computed by liftoff's own model of `example:fwd-panel` at known
//! moduli, with 1 µm of Gaussian noise on every sensor — so that what `liftoff backcalc` finds
//! can be held against the truth.
//!
//! - fwd-basins.csv: three stations of two drops each (a seating drop, then the test drop),
//!   interior, edge and corner; the subgrade softer at station 3+000.
//! - fwd-void.csv (argument `void`): two corners, each with drops of 27 (seating), 40, 53 and
//!   71 kN, in unbonded contact on the panel's self-weight: a sound one, and one over a 0.5 mm
//!   void 0.6 m × 0.6 m under the corner.
//!
//! - fwd-joint.csv (argument `joint`, template `example:fwd-joint`): drops of 40 kN on the
//!   approach side of the aggregate joint T1 (the plate's edge at the joint, the sensors across
//!   it) at three places along it, the joint's stiffness AGG = 80, 40 and 15 MN/m² (E = 32 GPa,
//!   k = 70 MN/m³).
//!
//! `cargo run --release --example fwd_basins > examples/fwd-basins.csv`
//! `cargo run --release --example fwd_basins -- void > examples/fwd-void.csv`
//! `cargo run --release --example fwd_basins -- joint > examples/fwd-joint.csv`

use liftoff::backcalc::{model_basin, Basin, Drop, FitOptions, Location};
use liftoff::scene::SceneFile;
use liftoff::Monitor;

/// A station: its name, where its drops are, k (N/m³), a void's depth under the corner (m),
/// the drops' loads (N).
type Station = (&'static str, Location, f64, Option<f64>, Vec<f64>);

const SENSORS_MM: [f64; 9] = [
    0.0, 203.0, 305.0, 457.0, 610.0, 914.0, 1219.0, 1524.0, 1829.0,
];

fn main() -> Result<(), liftoff::Error> {
    let template = SceneFile::example("fwd-panel")?;
    // xorshift and Box–Muller, seeded: the file is the same on every run.
    let mut state: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut normal = move || {
        let mut u = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            ((state >> 11) as f64 + 0.5) / (1u64 << 53) as f64
        };
        let (a, b) = (u(), u());
        (-2.0 * a.ln()).sqrt() * (std::f64::consts::TAU * b).cos()
    };
    let mode = std::env::args().nth(1).unwrap_or_default();
    if mode == "joint" {
        return joint(normal);
    }
    let void = mode == "void";
    let stations: Vec<Station> = if void {
        println!(
            "# Synthetic basins: liftoff's model of example:fwd-panel in unbonded contact on its"
        );
        println!(
            "# self-weight, E = 32 GPa, k = 45 MN/m³, 1 µm of Gaussian noise; corner 5+000 over a"
        );
        println!(
            "# 0.5 mm void, 0.6 m × 0.6 m; `cargo run --release --example fwd_basins -- void`."
        );
        println!("# Drop 1 of each station seats the plate.");
        vec![
            (
                "4+000",
                Location::Corner,
                4.5e7,
                None,
                vec![27e3, 40e3, 53e3, 71e3],
            ),
            (
                "5+000",
                Location::Corner,
                4.5e7,
                Some(5e-4),
                vec![27e3, 40e3, 53e3, 71e3],
            ),
        ]
    } else {
        println!("# Synthetic basins: liftoff's model of example:fwd-panel (bonded, 48 × 48 elements) at");
        println!(
            "# E = 32 GPa and k = 70 MN/m³ (station 3+000: k = 45 MN/m³), 1 µm of Gaussian noise;"
        );
        println!("# made by `cargo run --release --example fwd_basins`. Drop 1 of each station seats the plate.");
        vec![
            ("1+000", Location::Interior, 7.0e7, None, vec![27e3, 40e3]),
            ("2+000", Location::Edge, 7.0e7, None, vec![27e3, 40e3]),
            ("3+000", Location::Corner, 4.5e7, None, vec![27e3, 40e3]),
        ]
    };
    let header: Vec<String> = SENSORS_MM.iter().map(|o| format!("d{o:.0}mm_um")).collect();
    println!(
        "station,drop,location,load_kN,radius_mm,{}",
        header.join(",")
    );
    for (station, location, k, depth, loads) in stations {
        let mut t = template.clone();
        if let Some(p) = t.plate.as_mut() {
            p.youngs_modulus = 32e9;
        }
        if let Some(f) = t.foundation.as_mut() {
            f.soil.insert(
                "modulus".into(),
                liftoff::foundation::soil::KeyValue::Number(k),
            );
        }
        if void {
            t.solver.contact = liftoff::method::Contact::Unbonded;
        }
        if let Some(d) = depth {
            t.void.push(liftoff::scene::VoidSpec {
                x: [-2.3, -1.7],
                y: [-1.85, -1.25],
                depth: d,
            });
        }
        for (i, load) in loads.into_iter().enumerate() {
            let d = Drop {
                station: station.into(),
                drop: i + 1,
                location,
                basin: Basin {
                    load,
                    radius: 0.15,
                    offsets: SENSORS_MM.iter().map(|o| o / 1e3).collect(),
                    deflections: Vec::new(),
                },
                at: None,
                direction: 0.0,
                temperature_difference: None,
            };
            let w = model_basin(&t, &d, &FitOptions::default(), &Monitor::NONE)?;
            let cells: Vec<String> = w
                .iter()
                .map(|w| format!("{:.1}", 1e6 * w + normal()))
                .collect();
            println!(
                "{station},{},{location},{:.1},150,{}",
                i + 1,
                load / 1e3,
                cells.join(",")
            );
        }
    }
    Ok(())
}

/// fwd-joint.csv: approach-side drops at the joint of `example:fwd-joint`.
fn joint(mut normal: impl FnMut() -> f64) -> Result<(), liftoff::Error> {
    let template = SceneFile::example("fwd-joint")?;
    println!(
        "# Synthetic basins: liftoff's model of example:fwd-joint (bonded, 96 × 48 elements) at"
    );
    println!("# E = 32 GPa, k = 70 MN/m³ and the joint's AGG = 80, 40, 15 MN/m² at stations 6, 7, 8+000;");
    println!("# 1 µm of Gaussian noise; `cargo run --release --example fwd_basins -- joint`.");
    let header: Vec<String> = SENSORS_MM.iter().map(|o| format!("d{o:.0}mm_um")).collect();
    println!(
        "station,location,load_kN,radius_mm,x_m,y_m,{}",
        header.join(",")
    );
    for (station, agg, y) in [
        ("6+000", 8e7, -0.9),
        ("7+000", 4e7, 0.0),
        ("8+000", 1.5e7, 0.9),
    ] {
        let mut t = template.clone();
        if let Some(p) = t.plate.as_mut() {
            p.youngs_modulus = 32e9;
        }
        if let Some(f) = t.foundation.as_mut() {
            f.soil.insert(
                "modulus".into(),
                liftoff::foundation::soil::KeyValue::Number(7e7),
            );
        }
        t.joint[0].stiffness = Some(agg);
        let d = Drop {
            station: station.into(),
            drop: 1,
            location: Location::JointApproach,
            basin: Basin {
                load: 40e3,
                radius: 0.15,
                offsets: SENSORS_MM.iter().map(|o| o / 1e3).collect(),
                deflections: Vec::new(),
            },
            at: Some([-0.15, y]),
            direction: 0.0,
            temperature_difference: None,
        };
        let w = model_basin(&t, &d, &FitOptions::default(), &Monitor::NONE)?;
        let cells: Vec<String> = w
            .iter()
            .map(|w| format!("{:.1}", 1e6 * w + normal()))
            .collect();
        println!(
            "{station},joint-approach,40.0,150,-0.15,{y},{}",
            cells.join(",")
        );
    }
    Ok(())
}
