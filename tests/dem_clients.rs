//! `dem --lammps-version`: the lines each LAMMPS version gets (wall modulus convention, damping
//! keywords), the `damping tsuji` stand-in for the constant-CoR law, the LIGGGHTS keyword order
//! and the command line. The runs in the real codes are `validation/dem_clients/verify.py`
//! (`.ci/run`).

use crate::common;

use common::{run, stderr};

use mdr_impact::apps::curve::{CurveRow, VelocityRange};
use mdr_impact::apps::dem::{
    self, tsuji_alpha, tsuji_input, DemLaw, DemReport, Format, Geometry, HertzContact,
    LammpsVersion, ModulusChoice, LAMMPS_COEFF_RESTITUTION_SINCE, LAMMPS_OLDEST,
    LAMMPS_WALL_MIX_SINCE,
};
use mdr_impact::Error;

/// A polymer ball of the README's size class (SI).
fn contact() -> HertzContact {
    HertzContact::new(4.6e-3, 1.0e-2, 4.0e6).unwrap()
}

/// A report fitted to data made by the viscoelastic law (`A = 1e-4 s`), 0.1 to 10 m/s.
fn report(geometry: Geometry) -> DemReport {
    let c = contact();
    let rows = VelocityRange::parse("0.1:10:8", true)
        .unwrap()
        .values()
        .iter()
        .map(|v| {
            let d = c.impact(DemLaw::Viscoelastic { a: 1e-4 }, *v).unwrap();
            CurveRow {
                v0: *v,
                cor: d.cor,
                contact_time: d.contact_time,
                max_force: 0.0,
                max_compression: 0.0,
                contact_radius_ratio: 0.0,
                indentation_ratio: 0.0,
                wave_transit_ratio: None,
                outside_validity: false,
            }
        })
        .collect();
    dem::fit(rows, true, ModulusChoice::Relaxed, c, geometry, None).unwrap()
}

fn version(s: &str) -> LammpsVersion {
    s.parse().unwrap()
}

/// The emitted line of a law, active or commented out.
fn law_line<'a>(text: &'a str, damping: &str) -> &'a str {
    text.lines()
        .map(|l| l.strip_prefix("# ").unwrap_or(l))
        .filter(|l| l.starts_with("pair_coeff") || l.starts_with("fix wall"))
        .find(|l| l.contains(&format!("damping {damping} ")))
        .unwrap_or_else(|| panic!("no damping {damping} line in\n{text}"))
}

#[test]
fn version_parses_the_date_and_refuses_the_rest() {
    assert_eq!(version("20220106").date(), Some(20220106));
    assert_eq!(LammpsVersion::CURRENT.date(), None);
    for bad in [
        "2022-01-06",
        "220106",
        "7Jan2022",
        "20221306",
        "20220100",
        "",
    ] {
        let e = bad.parse::<LammpsVersion>().unwrap_err();
        assert!(
            matches!(&e, Error::Unsupported(m) if m.contains("--lammps-version")),
            "{bad}: {e:?}"
        );
    }
    // older than the oldest version the lines are written for
    let e = (LAMMPS_OLDEST - 1).to_string().parse::<LammpsVersion>();
    assert!(matches!(e, Err(Error::Unsupported(m)) if m.contains("oldest")));
    // the thresholds
    assert!(version("20220106").legacy_wall_modulus());
    assert!(!version(&LAMMPS_WALL_MIX_SINCE.to_string()).legacy_wall_modulus());
    assert!(!version("20230327").has_coeff_restitution());
    assert!(version(&LAMMPS_COEFF_RESTITUTION_SINCE.to_string()).has_coeff_restitution());
    assert!(LammpsVersion::CURRENT.has_coeff_restitution());
    assert!(!LammpsVersion::CURRENT.legacy_wall_modulus());
}

#[test]
fn format_takes_the_version_for_lammps_only() {
    let f = "lammps".parse::<Format>().unwrap();
    assert_eq!(f, Format::Lammps(LammpsVersion::CURRENT));
    assert_eq!(
        f.with_lammps_version(Some("20220106")).unwrap(),
        Format::Lammps(version("20220106"))
    );
    assert_eq!(f.with_lammps_version(None).unwrap(), f);
    for other in ["liggghts", "json"] {
        let e = other
            .parse::<Format>()
            .unwrap()
            .with_lammps_version(Some("20220106"));
        assert!(matches!(e, Err(Error::Unsupported(m)) if m.contains("--format lammps")));
    }
}

#[test]
fn tsuji_input_inverts_marshall_polynomial() {
    // Marshall (2009) Eq. 53 at its ends
    assert!((tsuji_alpha(0.0) - 1.2728).abs() < 1e-15);
    assert!((tsuji_alpha(1.0) - 3.0e-4).abs() < 1e-12);
    for e_in in [0.12, 0.3, 0.4729098, 0.7, 0.95, 0.999] {
        let gamma = dem::cor_gamma(e_in).unwrap();
        let e = tsuji_input(gamma).unwrap();
        assert!((0.0..=1.0).contains(&e));
        assert!((tsuji_alpha(e) / gamma - 1.0).abs() < 1e-12, "{e_in}: {e}");
    }
    // outside the polynomial's range: gamma above alpha(0) for e_in below 0.1136
    assert_eq!(tsuji_input(dem::cor_gamma(0.11).unwrap()), None);
    assert_eq!(tsuji_input(1.3), None);
    assert_eq!(tsuji_input(1e-4), None);
}

#[test]
fn lammps_2022_wall_gets_two_one_minus_nu_e_star_and_tsuji() {
    let r = report(Geometry::Wall);
    let e_star = r.contact.effective_modulus;
    let text = r.lammps_text_for(version("20220106"));
    assert!(
        !text.contains("damping coeff_restitution limit_damping"),
        "{text}"
    );
    let visco = law_line(&text, "viscoelastic");
    let constant = law_line(&text, "tsuji");
    // E / (2 (1 - nu)) = E* with nu = 0.5: the wall gets E = E*
    let young = format!("{:.6e}", e_star);
    assert!(
        visco.starts_with(&format!(
            "fix wall all wall/gran granular hertz/material {young} "
        )),
        "{visco}"
    );
    assert!(visco.ends_with("damping viscoelastic limit_damping zplane 0.0 NULL"));
    let gamma = dem::cor_gamma(r.constant.cor_input).unwrap();
    let e_tsuji = format!("{:.6e}", tsuji_input(gamma).unwrap());
    assert!(
        constant.contains(&format!("{young} {e_tsuji} 0.5 ")),
        "{constant}"
    );
    assert!(text.contains("# proven on LAMMPS 20220106"));
    assert!(text.contains("# for LAMMPS 20220106;"));
}

#[test]
fn lammps_2022_pair_keeps_the_mixed_modulus() {
    let r = report(Geometry::Pair);
    let text = r.lammps_text_for(version("20220106"));
    let young = format!("{:.6e}", r.contact.dem_young());
    let visco = law_line(&text, "viscoelastic");
    assert!(
        visco.starts_with(&format!("pair_coeff 1 2 hertz/material {young} ")),
        "{visco}"
    );
    assert!(law_line(&text, "tsuji").starts_with("pair_coeff 1 2 hertz/material"));
}

#[test]
fn later_versions_mix_the_wall_like_a_pair() {
    let r = report(Geometry::Wall);
    let young = format!("{:.6e}", r.contact.dem_young());
    // between the granular-model rewrite and coeff_restitution: 1.5 E*, tsuji
    let mid = r.lammps_text_for(version("20230802"));
    assert!(law_line(&mid, "viscoelastic").contains(&format!("hertz/material {young} ")));
    law_line(&mid, "tsuji");
    assert!(mid.contains("written from the LAMMPS sources, not run here"));
    // current: coeff_restitution with the input CoR, the same as lammps_text()
    let now = r.lammps_text();
    assert_eq!(now, r.lammps_text_for(LammpsVersion::CURRENT));
    let constant = law_line(&now, "coeff_restitution");
    assert!(constant.contains(&format!(
        "hertz/material {young} {:.6e} 0.5 ",
        r.constant.cor_input
    )));
    assert!(now.contains("# for current LAMMPS (20240417 or later)"));
}

#[test]
fn liggghts_wall_puts_limit_force_after_the_primitive() {
    let text = report(Geometry::Wall).liggghts_text();
    assert!(text.contains(
        "\nfix wall all wall/gran model hertz tangential history primitive type 2 zplane 0.0 \
         limitForce on\n"
    ));
    assert!(text.contains("# proven on LIGGGHTS-PUBLIC 3.8.0"));
    let pair = report(Geometry::Pair).liggghts_text();
    assert!(!pair.contains("fix wall"));
}

#[test]
fn cli_lammps_version_reaches_the_file_and_bad_ones_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let o = run(
        &[
            "dem",
            "--v0",
            "0.5:5:4",
            "--format",
            "lammps",
            "--lammps-version",
            "20220106",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let file = std::fs::read_to_string(dir.path().join("out/dem_lammps.in")).unwrap();
    assert_eq!(String::from_utf8(o.stdout).unwrap(), file);
    assert!(file.contains("damping tsuji limit_damping"));
    for (format, v) in [("lammps", "2022"), ("liggghts", "20220106")] {
        let dir = tempfile::tempdir().unwrap();
        let o = run(
            &[
                "dem",
                "--v0",
                "0.5:5:4",
                "--format",
                format,
                "--lammps-version",
                v,
            ],
            dir.path(),
        );
        assert!(!o.status.success());
        assert_eq!(stderr(&o).lines().count(), 1, "{}", stderr(&o));
        assert!(stderr(&o).contains("--lammps-version"));
        assert!(!dir.path().join("out").exists());
    }
}
