//! liftoff as a library: a scene (TOML text; or a path, a bundled name, a parsed value) solved.
use liftoff::{scene::Overrides, Monitor, Outcome, Source};

const SCENE: &str = r#"
[plate]
length = 6.0
width = 4.0
thickness = 0.25
youngs_modulus = 30e9
poissons_ratio = 0.2
[foundation]
model = "winkler"
modulus = 5e7
[[load]]
kind = "point"
x = 1.5
y = 1.0
force = 2.0e5
"#;

fn main() -> liftoff::Result<()> {
    let problem = liftoff::load(&Source::Toml(SCENE), &Overrides::default())?;
    if let Outcome::Single(a) = liftoff::run(&problem, &Monitor::NONE)? {
        let s = &a.summary;
        println!("{}: {}", s.method, s.status);
        println!(
            "w_max {:.2} mm, contact {:.0} %",
            1e3 * s.w_max,
            100.0 * s.contact_fraction
        );
    }
    Ok(())
}
