use mdr_impact::*;
fn main() {
    let m = Material::with_poisson(1e6, 1e7, 1e6, 0.45).unwrap();
    let h = indentation::Prescribed::triangle(1e-6, 1.0).unwrap();
    let r = mdr::indent::response(
        &m.equivalent_relaxation(),
        1e-5,
        &h,
        &[0.5, 1.0, 1.2],
        Default::default(),
    );
    println!("{r:?}");
}
