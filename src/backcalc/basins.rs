//! Deflectometer drops as a CSV file: one row a drop, the units in the column names.
//!
//! ```text
//! station,drop,location,load_kN,radius_mm,d0mm_um,d203mm_um,d305mm_um,d457mm_um,d610mm_um,d914mm_um
//! 0+100,1,interior,40.2,150,262.1,241.0,228.3,206.9,185.2,143.8
//! ```
//!
//! - `station` (required): the test point's name, as the tables repeat it;
//! - `drop` (optional): the drop's number at its station (default: 1, 2, … in file order);
//! - `location` (optional, default `interior`): `interior`, `edge`, `corner`, `joint-approach`
//!   or `joint-leave`;
//! - the load, one of `load_kN`, `load_N`, `load_lbf`, `load_kip`;
//! - the plate's radius (optional, default 150 mm), one of `radius_mm`, `radius_in`, `radius_m`;
//! - where the plate's centre stood on the slab, in the scene's coordinates (optional, both or
//!   neither): `x_m` and `y_m`, or `x_ft` and `y_ft`; and `direction_deg`, the sensor line's
//!   direction from the x axis (default 0);
//! - the sensors, one column each, named `d<offset><unit>_<unit>`: the offset in `mm`, `in` or
//!   `m`, the deflection in `um`, `mils` or `mm` (`d0mm_um`, `d12in_mils`);
//! - the slab's temperature difference at test time, top minus bottom (optional): `dT_C` (K)
//!   or `dT_F` (°F): the curl the drop starts from (the fit adds it to the template's loads).
//!
//! Every drop is checked where it is read, and an error names its station and drop: a load that
//! is not positive, an empty or unreadable sensor, a deflection that is not positive at the
//! plate, deflections that grow away from the load (more than 2 µm and 2 % above the sensor
//! nearer the plate), and a centre deflection per unit load outside 0.2 … 200 µm/kN — a slab
//! of concrete deflects 1 … 10 µm/kN, a weak flexible pavement some 50: outside the window the
//! file's units are wrong (µm read as mm, or mm as µm).

use super::area::Basin;
use crate::error::{Error, Result};
use crate::units::{FOOT, INCH, POUND_FORCE};

/// Where on the slab a drop was made, as the survey records it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Location {
    /// Far from any edge or joint: the AREA method's case.
    Interior,
    /// At a free edge, the sensors along it.
    Edge,
    /// At a slab's corner.
    Corner,
    /// On the approach side of a transverse joint, the sensors across it.
    JointApproach,
    /// On the leave side of a transverse joint.
    JointLeave,
}

crate::choice::names!(Location, Interior => "interior", Edge => "edge", Corner => "corner",
    JointApproach => "joint-approach", JointLeave => "joint-leave");

/// One drop: its basin, where it stood and what it is called.
#[derive(Debug, Clone, PartialEq)]
pub struct Drop {
    /// The station's name.
    pub station: String,
    /// The drop's number at its station, from 1.
    pub drop: usize,
    /// Where on the slab.
    pub location: Location,
    /// The load, the plate and the sensors (SI).
    pub basin: Basin,
    /// The plate's centre in the scene's coordinates, m (None: the location's default place).
    pub at: Option<[f64; 2]>,
    /// The sensor line's direction from the x axis, degrees.
    pub direction: f64,
    /// The slab's temperature difference at test time, top minus bottom, K (None: not
    /// measured).
    pub temperature_difference: Option<f64>,
}

impl Drop {
    /// How errors and tables name the drop: `station 0+100, drop 2`.
    pub fn label(&self) -> String {
        format!("station {}, drop {}", self.station, self.drop)
    }

    /// Check a drop's numbers (see the module's description); the error names the drop and the
    /// column.
    pub fn check(&self) -> Result<()> {
        let b = &self.basin;
        let bad = |column: &str, message: String| {
            Err(Error::invalid(
                format!("{}: {column}", self.label()),
                message,
            ))
        };
        if !(b.load.is_finite() && b.load > 0.0) {
            return bad(
                "load",
                format!("must be a positive force, got {} N", b.load),
            );
        }
        if !(b.radius.is_finite() && b.radius > 0.0) {
            return bad("radius", format!("must be positive, got {} m", b.radius));
        }
        if b.offsets.len() < 2 || b.offsets.len() != b.deflections.len() {
            return bad(
                "sensors",
                format!(
                    "a basin needs two sensors or more, each with a deflection; got {} offsets and {} deflections",
                    b.offsets.len(),
                    b.deflections.len()
                ),
            );
        }
        if b.offsets.windows(2).any(|w| w[1] <= w[0]) || b.offsets[0] < 0.0 {
            return bad(
                "sensors",
                "the sensor offsets must be distinct and not negative".into(),
            );
        }
        if let Some(i) = b.deflections.iter().position(|d| !d.is_finite()) {
            return bad(
                &format!("sensor at {:.0} mm", 1e3 * b.offsets[i]),
                "is missing: every sensor needs a deflection (drop the column if the sensor was off)"
                    .into(),
            );
        }
        let d0 = b.deflections[0];
        if d0 <= 0.0 {
            return bad(
                &format!("sensor at {:.0} mm", 1e3 * b.offsets[0]),
                format!(
                    "the deflection nearest the plate must be positive (downward), got {:.1} µm",
                    1e6 * d0
                ),
            );
        }
        for i in 1..b.deflections.len() {
            let (inner, outer) = (b.deflections[i - 1], b.deflections[i]);
            if outer > inner * 1.02 + 2e-6 {
                return bad(
                    &format!("sensor at {:.0} mm", 1e3 * b.offsets[i]),
                    format!(
                        "deflects {:.1} µm, more than the {:.1} µm nearer the plate: a basin falls away from the load (is a column misplaced or a sensor faulty?)",
                        1e6 * outer,
                        1e6 * inner
                    ),
                );
            }
        }
        let per_kn = 1e6 * d0 / (b.load / 1e3);
        if !(0.2..=200.0).contains(&per_kn) {
            return bad(
                "units",
                format!(
                    "the plate deflects {per_kn:.3} µm per kN, outside the 0.2 … 200 µm/kN of pavements: check the units in the column names (deflections in um, mils or mm; the load in kN, N, lbf or kip)"
                ),
            );
        }
        Ok(())
    }
}

/// A length unit of a column name, m per unit.
fn length_unit(u: &str) -> Option<f64> {
    match u {
        "mm" => Some(1e-3),
        "m" => Some(1.0),
        "in" => Some(INCH),
        "ft" => Some(FOOT),
        _ => None,
    }
}

/// A deflection unit of a sensor column, m per unit.
fn deflection_unit(u: &str) -> Option<f64> {
    match u {
        "um" => Some(1e-6),
        "mils" | "mil" => Some(1e-3 * INCH),
        "mm" => Some(1e-3),
        _ => None,
    }
}

/// A load unit, N per unit.
fn force_unit(u: &str) -> Option<f64> {
    match u {
        "N" => Some(1.0),
        "kN" => Some(1e3),
        "lbf" => Some(POUND_FORCE),
        "kip" => Some(1e3 * POUND_FORCE),
        _ => None,
    }
}

/// What a column holds, with its factor to SI.
#[derive(Debug, Clone, Copy)]
enum Column {
    Station,
    Drop,
    Location,
    Load(f64),
    Radius(f64),
    X(f64),
    Y(f64),
    Direction,
    /// A temperature difference, K per unit.
    Temperature(f64),
    Sensor {
        offset: f64,
        unit: f64,
    },
}

/// What a header names, if anything known.
fn column(name: &str) -> Option<Column> {
    let unit = |prefix: &str, f: fn(&str) -> Option<f64>| name.strip_prefix(prefix).and_then(f);
    match name {
        "station" => return Some(Column::Station),
        "drop" => return Some(Column::Drop),
        "location" => return Some(Column::Location),
        "direction_deg" => return Some(Column::Direction),
        "dT_C" => return Some(Column::Temperature(1.0)),
        "dT_F" => return Some(Column::Temperature(5.0 / 9.0)),
        _ => {}
    }
    if let Some(f) = unit("load_", force_unit) {
        return Some(Column::Load(f));
    }
    if let Some(f) = unit("radius_", length_unit) {
        return Some(Column::Radius(f));
    }
    if let Some(f) = unit("x_", length_unit) {
        return Some(Column::X(f));
    }
    if let Some(f) = unit("y_", length_unit) {
        return Some(Column::Y(f));
    }
    let rest = name.strip_prefix('d')?;
    let (offset, deflection) = rest.split_once('_')?;
    let digits = offset
        .find(|c: char| !(c.is_ascii_digit() || c == '.'))
        .unwrap_or(offset.len());
    let (value, length) = offset.split_at(digits);
    let value: f64 = value.parse().ok()?;
    Some(Column::Sensor {
        offset: value * length_unit(length)?,
        unit: deflection_unit(deflection)?,
    })
}

/// The columns a basin file may have, for the error that meets an unknown one.
const COLUMNS: &str = "station, drop, location, load_kN|load_N|load_lbf|load_kip, radius_mm|radius_in|radius_m, x_m & y_m (or _ft), direction_deg, dT_C|dT_F, and sensors d<offset><mm|in|m>_<um|mils|mm> such as d0mm_um or d12in_mils";

/// A basin file's header: each column's meaning and name, and the sensors — (column, offset
/// m, m per unit) — in the order of their offsets.
struct Header {
    columns: Vec<Column>,
    names: Vec<String>,
    sensors: Vec<(usize, f64, f64)>,
}

/// Read and check the header row's columns (see the module's description).
fn header(names: &csv::StringRecord, source: &str) -> Result<Header> {
    let mut columns = Vec::with_capacity(names.len());
    for h in names {
        match column(h) {
            Some(c) => columns.push(c),
            None => {
                return Err(Error::invalid(
                    format!("{source}: column `{h}`"),
                    format!("is not a basin column; the columns are {COLUMNS}"),
                ))
            }
        }
    }
    let count = |f: fn(&Column) -> bool| columns.iter().filter(|c| f(c)).count();
    let need_one = |what: &str, n: usize| {
        if n == 1 {
            Ok(())
        } else {
            Err(Error::invalid(
                format!("{source}: {what}"),
                format!("needs exactly one column, found {n}; the columns are {COLUMNS}"),
            ))
        }
    };
    need_one("station", count(|c| matches!(c, Column::Station)))?;
    need_one("load", count(|c| matches!(c, Column::Load(_))))?;
    let (xs, ys) = (
        count(|c| matches!(c, Column::X(_))),
        count(|c| matches!(c, Column::Y(_))),
    );
    if xs > 1 || ys > 1 || xs != ys {
        return Err(Error::invalid(
            format!("{source}: x, y"),
            "give the plate's place as one x column and one y column (x_m, y_m), or neither",
        ));
    }
    // Sensors in the order of their offsets.
    let mut sensors: Vec<(usize, f64, f64)> = columns
        .iter()
        .enumerate()
        .filter_map(|(i, c)| match *c {
            Column::Sensor { offset, unit } => Some((i, offset, unit)),
            _ => None,
        })
        .collect();
    sensors.sort_by(|a, b| a.1.total_cmp(&b.1));
    if sensors.len() < 2 {
        return Err(Error::invalid(
            format!("{source}: sensors"),
            format!("a basin needs two sensor columns or more; the columns are {COLUMNS}"),
        ));
    }
    Ok(Header {
        columns,
        names: names.iter().map(str::to_string).collect(),
        sensors,
    })
}

/// One row's drop (checked by the caller): `earlier` counts the drops of a station read
/// before, `line` is the row's line in the file.
fn drop_of(
    record: &csv::StringRecord,
    header: &Header,
    line: u64,
    source: &str,
    earlier: impl Fn(&str) -> usize,
) -> Result<Drop> {
    let text_of = |c: usize| record.get(c).unwrap_or("");
    let station = header
        .columns
        .iter()
        .position(|c| matches!(c, Column::Station))
        .map(text_of)
        .unwrap_or("");
    if station.is_empty() {
        return Err(Error::invalid(
            format!("{source}: line {line}: station"),
            "every drop needs its station's name",
        ));
    }
    let number = |c: usize, what: &str| -> Result<Option<f64>> {
        let t = text_of(c);
        if t.is_empty() {
            return Ok(None);
        }
        t.parse::<f64>().map(Some).map_err(|_| {
            Error::invalid(
                format!("station {station} (line {line}): {what}"),
                format!("`{t}` is not a number"),
            )
        })
    };
    let mut drop = Drop {
        station: station.to_string(),
        drop: earlier(station) + 1,
        location: Location::Interior,
        basin: Basin {
            load: f64::NAN,
            radius: 0.15,
            offsets: header.sensors.iter().map(|s| s.1).collect(),
            deflections: vec![f64::NAN; header.sensors.len()],
        },
        at: None,
        direction: 0.0,
        temperature_difference: None,
    };
    let (mut x, mut y) = (None, None);
    for (c, col) in header.columns.iter().enumerate() {
        let name = &header.names[c];
        match *col {
            Column::Station | Column::Sensor { .. } => {}
            Column::Drop => {
                if let Some(v) = number(c, name)? {
                    if v < 1.0 || v.fract() != 0.0 {
                        return Err(Error::invalid(
                            format!("station {station} (line {line}): drop"),
                            format!("must be a whole number from 1, got {v}"),
                        ));
                    }
                    drop.drop = v as usize;
                }
            }
            Column::Location => {
                let t = text_of(c);
                if !t.is_empty() {
                    drop.location = t.parse().map_err(|e: String| {
                        Error::invalid(format!("station {station} (line {line}): location"), e)
                    })?;
                }
            }
            Column::Load(f) => drop.basin.load = number(c, name)?.map_or(f64::NAN, |v| v * f),
            Column::Radius(f) => {
                if let Some(v) = number(c, name)? {
                    drop.basin.radius = v * f;
                }
            }
            Column::X(f) => x = number(c, name)?.map(|v| v * f),
            Column::Y(f) => y = number(c, name)?.map(|v| v * f),
            Column::Direction => {
                if let Some(v) = number(c, name)? {
                    drop.direction = v;
                }
            }
            Column::Temperature(f) => {
                drop.temperature_difference = number(c, name)?.map(|v| v * f);
            }
        }
    }
    for (k, &(c, _, unit)) in header.sensors.iter().enumerate() {
        drop.basin.deflections[k] = number(c, &header.names[c])?.map_or(f64::NAN, |v| v * unit);
    }
    drop.at = match (x, y) {
        (Some(x), Some(y)) => Some([x, y]),
        (None, None) => None,
        _ => {
            return Err(Error::invalid(
                format!("{}: x, y", drop.label()),
                "give both coordinates of the plate's place, or neither",
            ))
        }
    };
    Ok(drop)
}

/// Read drops from CSV text (see the module's description); `source` names the file in errors.
/// Every drop is [`Drop::check`]ed.
pub fn read_basins(text: &str, source: &str) -> Result<Vec<Drop>> {
    let mut reader = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .comment(Some(b'#'))
        .from_reader(text.as_bytes());
    let names = reader
        .headers()
        .map_err(|e| Error::invalid(source, format!("cannot read the header row: {e}")))?
        .clone();
    let header = header(&names, source)?;
    let mut drops: Vec<Drop> = Vec::new();
    for record in reader.records() {
        let record = record.map_err(|e| Error::invalid(source, e.to_string()))?;
        // The row's line in the file, comments and the header counted.
        let line = record.position().map_or(0, csv::Position::line);
        let earlier = |station: &str| drops.iter().filter(|d| d.station == station).count();
        let drop = drop_of(&record, &header, line, source, earlier)?;
        drop.check()?;
        drops.push(drop);
    }
    if drops.is_empty() {
        return Err(Error::invalid(source, "holds no drop: one row a drop"));
    }
    Ok(drops)
}

#[cfg(test)]
mod tests {
    use super::*;

    const FILE: &str = "station,drop,load_kN,radius_mm,d0mm_um,d305mm_um,d610mm_um,d914mm_um\n\
        A,1,40,150,100,90,75,60\n\
        A,2,50,150,125,112,94,75\n\
        B,,40,150,110,95,80,62\n";

    #[test]
    fn a_file_reads_in_si_with_its_drops_numbered() {
        let d = read_basins(FILE, "f.csv").expect("reads");
        assert_eq!(d.len(), 3);
        assert_eq!((d[2].station.as_str(), d[2].drop), ("B", 1));
        assert!((d[1].basin.load - 5e4).abs() < 1e-9);
        assert!((d[0].basin.deflections[3] - 60e-6).abs() < 1e-15);
        assert!((d[0].basin.offsets[1] - 0.305).abs() < 1e-15);
    }

    #[test]
    fn us_units_convert_by_the_exact_inch_and_pound() {
        let f = "station,load_lbf,radius_in,dT_F,d0in_mils,d12in_mils\nS,9000,5.9,-9,4.0,3.5\n";
        let d = read_basins(f, "f.csv").expect("reads");
        assert!((d[0].basin.load - 9000.0 * 4.448_221_615_260_5).abs() < 1e-6);
        assert!((d[0].basin.deflections[0] - 4.0 * 25.4e-6).abs() < 1e-15);
        assert!((d[0].basin.offsets[1] - 0.3048).abs() < 1e-15);
        // A difference of −9 °F is one of −5 K.
        assert!((d[0].temperature_difference.expect("dT") + 5.0).abs() < 1e-12);
    }

    #[test]
    fn bad_drops_are_named_by_their_station() {
        let err = |f: &str| match read_basins(f, "f.csv") {
            Err(Error::Invalid { field, .. }) => field,
            other => panic!("{other:?}"),
        };
        let head = "station,load_kN,d0mm_um,d305mm_um,d610mm_um\n";
        assert_eq!(
            err(&format!("{head}S1,0,100,90,80\n")),
            "station S1, drop 1: load"
        );
        assert_eq!(
            err(&format!("{head}S1,40,100,,80\n")),
            "station S1, drop 1: sensor at 305 mm"
        );
        assert_eq!(
            err(&format!("{head}S1,40,100,90,95\n")),
            "station S1, drop 1: sensor at 610 mm"
        );
        // Micrometres written as millimetres: 100 mm under 40 kN.
        let mm = "station,load_kN,d0mm_mm,d305mm_mm\nS1,40,100,90\n";
        assert_eq!(err(mm), "station S1, drop 1: units");
        assert_eq!(
            err("station,load_kN,d0mm_um,d305mm_furlongs\nS1,40,100,90\n"),
            "f.csv: column `d305mm_furlongs`"
        );
        // A cell that is not a number, named by its station and its line in the file, the
        // comment lines counted.
        assert_eq!(
            err("# survey\n# day 1\nstation,load_kN,d0mm_um,d305mm_um\nS1,4O,100,90\n"),
            "station S1 (line 4): load_kN"
        );
    }
}
