use mdr_impact::*;
fn main() {
    for c in catalogue::IMPACTS {
        for (name, h) in validate::prescribed_histories().unwrap() {
            let s = validate::prescribed_refinement(c, &h, 6).unwrap();
            let e: Vec<f64> = s.iter().map(|x| x.2).collect();
            let o = validate::observed_orders(&e);
            println!(
                "{:40} {name:10} {:?} last err {:.1e}",
                c.id,
                o.iter().map(|x| format!("{x:.2}")).collect::<Vec<_>>(),
                e[5]
            );
        }
    }
}
