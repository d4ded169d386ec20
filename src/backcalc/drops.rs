//! A survey's drops from either kind of basin file ([`read_drops`]: a CSV file, `basins.rs`, or
//! an AASHTO PDDX file, `pddx.rs`, told apart by the first line), and where a PDDX file's drops
//! stood ([`Placement`], [`read_drops_placed`]), which the file does not say in a form liftoff
//! reads: a survey file holds one kind of test as a rule (a pass of interior drops, one of joint
//! drops), and a file of mixed kinds is a CSV file's case, whose `location`, `x_m`, `y_m` and
//! `direction_deg` columns say it drop by drop.

use super::basins::{read_basins, Drop, Location};
use super::pddx::read_pddx;
use crate::error::{Error, Result};

/// Read a survey's drops from a PDDX file or a CSV basin file, told apart by the first line
/// that is not blank or a comment: a `[Section]` heading is PDDX. `source` names the file in
/// errors.
pub fn read_drops(text: &str, source: &str) -> Result<Vec<Drop>> {
    read_drops_placed(text, source, None)
}

/// Where every drop of a PDDX file stood, which the file does not say in a form liftoff reads
/// (without one its drops are interior ones at the template's centre).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placement {
    /// Where on the slab.
    pub location: Location,
    /// The plate's centre in the template's coordinates, m (None: the location's default place,
    /// as a CSV file's drop without `x_m` and `y_m`; joint drops need it).
    pub at: Option<[f64; 2]>,
    /// The sensor line's direction from the x axis, degrees.
    pub direction: f64,
}

impl Placement {
    /// A placement from the front ends' options, each optional (`liftoff backcalc --location
    /// --at --direction`, Python's keywords): None when none is given; else the location
    /// (default interior), the place (default the location's own) and the direction (default 0,
    /// along +x).
    pub fn from_options(
        location: Option<Location>,
        at: Option<[f64; 2]>,
        direction: Option<f64>,
    ) -> Option<Self> {
        (location.is_some() || at.is_some() || direction.is_some()).then(|| Placement {
            location: location.unwrap_or(Location::Interior),
            at,
            direction: direction.unwrap_or(0.0),
        })
    }
}

/// [`read_drops`], a PDDX file's drops placed by `placement`. A CSV file with a placement is
/// refused: its columns say where each drop stood, and two answers to that would be one too
/// many. The placement is checked here (a joint location without its place, a value that is
/// not finite); whether the plate and sensors fall on the template's slab is checked where a
/// drop meets its template (`fit`).
pub fn read_drops_placed(
    text: &str,
    source: &str,
    placement: Option<&Placement>,
) -> Result<Vec<Drop>> {
    // A byte-order mark, as Windows tools write one, is not part of the text.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let first = text
        .lines()
        .map(str::trim)
        .find(|l| !(l.is_empty() || l.starts_with('#') || l.starts_with(';')));
    let pddx = matches!(first, Some(l) if l.starts_with('['));
    let Some(p) = placement else {
        return if pddx {
            read_pddx(text, source)
        } else {
            read_basins(text, source)
        };
    };
    if !pddx {
        return Err(Error::invalid(
            "placement",
            format!(
                "{source} is a CSV basin file, which says where each drop stood in its `location`, `x_m`, `y_m` and `direction_deg` columns; a placement is for the drops of a PDDX file, which does not"
            ),
        ));
    }
    if let Some(at) = p.at.filter(|at| !at.iter().all(|v| v.is_finite())) {
        return Err(Error::invalid(
            "placement.at",
            format!("({}, {}) is not a place on the slab", at[0], at[1]),
        ));
    }
    if !p.direction.is_finite() {
        return Err(Error::invalid(
            "placement.direction",
            format!("{} is not a direction in degrees", p.direction),
        ));
    }
    if p.at.is_none() && matches!(p.location, Location::JointApproach | Location::JointLeave) {
        return Err(Error::invalid(
            "placement.at",
            format!(
                "{} drops need the plate's place on the slab (beside which joint, where along it): give it",
                p.location
            ),
        ));
    }
    let mut drops = read_pddx(text, source)?;
    for d in &mut drops {
        d.location = p.location;
        d.at = p.at;
        d.direction = p.direction;
    }
    Ok(drops)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One station of two drops in SI.
    const FILE: &str = "\
; a survey
[Pavement Deflection Data Exchange File]
PDDXVersionNumber = 2.0
[Units]
LoadPlateRadiusUnits = millimeter
LoadUnits = kilo-Newton
DeflectionUnits = micron
SensorLocationUnits = millimeter
[Device Configuration]
LoadPlateRadius = 150
NumberOfDeflectionSensors = 2
DeflectionSensorXAxisDistances = 0, 305
[Test Location 1]
DropData1 = 40, 100, 90
DropData2 = 50, 125, 112
";

    #[test]
    fn a_placement_puts_every_drop_of_a_pddx_file_and_a_csv_file_refuses_it() {
        let p = Placement {
            location: Location::JointLeave,
            at: Some([0.15, -0.9]),
            direction: 180.0,
        };
        let d = read_drops_placed(FILE, "f.pdx", Some(&p)).expect("placed");
        assert_eq!(d.len(), 2);
        for d in &d {
            assert_eq!(
                (d.location, d.at, d.direction),
                (p.location, p.at, p.direction)
            );
        }
        // Unplaced, the same drops stand at the template's centre as interior ones.
        let plain = read_drops(FILE, "f.pdx").expect("reads");
        assert!(plain
            .iter()
            .all(|d| (d.location, d.at, d.direction) == (Location::Interior, None, 0.0)));
        let err = |text: &str, p: &Placement| match read_drops_placed(text, "f", Some(p)) {
            Err(Error::Invalid { field, message }) => format!("{field}: {message}"),
            other => panic!("{other:?}"),
        };
        let csv = "station,load_kN,d0mm_um,d305mm_um\nA,40,100,90\n";
        assert!(err(csv, &p).starts_with("placement: f is a CSV basin file"));
        let unplaced = Placement { at: None, ..p };
        assert!(err(FILE, &unplaced)
            .starts_with("placement.at: joint-leave drops need the plate's place"));
        // Edge and corner drops have a default place, as a CSV file's do.
        let edge = Placement {
            location: Location::Edge,
            ..unplaced
        };
        assert!(read_drops_placed(FILE, "f", Some(&edge)).is_ok());
        let nowhere = Placement {
            at: Some([f64::NAN, 0.0]),
            ..p
        };
        assert!(err(FILE, &nowhere).starts_with("placement.at: (NaN, 0)"));
    }

    #[test]
    fn a_byte_order_mark_does_not_hide_the_format() {
        let d = read_drops(&format!("\u{feff}{FILE}"), "f.pdx").expect("pddx");
        assert_eq!(d.len(), 2);
        let csv = "\u{feff}station,load_kN,d0mm_um,d305mm_um\nA,40,100,90\n";
        assert_eq!(read_drops(csv, "f.csv").expect("csv")[0].station, "A");
    }

    #[test]
    fn options_make_a_placement_only_when_one_is_given() {
        assert_eq!(Placement::from_options(None, None, None), None);
        assert_eq!(
            Placement::from_options(None, None, Some(90.0)),
            Some(Placement {
                location: Location::Interior,
                at: None,
                direction: 90.0
            })
        );
        assert_eq!(
            Placement::from_options(Some(Location::Corner), Some([1.0, 2.0]), None),
            Some(Placement {
                location: Location::Corner,
                at: Some([1.0, 2.0]),
                direction: 0.0
            })
        );
    }
}
